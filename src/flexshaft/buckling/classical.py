"""Classical (Kirchhoff-Love) laminated-shell torsional buckling: Donnell or Sanders kinematics.

Strain-displacement relations (x axial, y = R theta circumferential, w outward), with the
bracketed terms kept by Sanders (1959, 1963) and dropped by Donnell:

    eps_x = u,x      eps_y = v,y + w/R      gamma_xy = u,y + v,x
    kappa_x = -w,xx  kappa_y = -w,yy [+ v,y/R]  kappa_xy = -2 w,xy [+ (3 v,x - u,y)/(2R)]
    beta_x = -w,x    beta_y = -w,y [+ v/R]

Donnell's relations overestimate the stiffness of the n = 2 mode that governs long tubes: the
long-tube torque is 2/sqrt(3) times the Sanders (and Timoshenko & Gere) value, so Sanders is the
default. No transverse shear deformation: UNCONSERVATIVE for soft-matrix FMC (see
:mod:`flexshaft.buckling.shear`).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from flexshaft.buckling._common import (
    Kinematics,
    axial_integrals,
    default_terms,
    extreme_torques,
    helix_minima,
    real_helix_torques,
    shell_stiffness,
)
from flexshaft.laminate import Laminate

__all__ = ["classical_helix_torque", "classical_galerkin_matrices", "classical_buckling", "helix_operators"]

#: log-spaced axial wavenumbers around eta = n/R searched on the infinite tube
_LOG_K_OFFSETS = np.linspace(-8.0, 3.0, 45)

# rows of the strain operators
_EPS_X, _EPS_Y, _GAMMA, _KAPPA_X, _KAPPA_Y, _KAPPA_XY, _BETA_X, _BETA_Y = range(8)


# Infinite cylinder: a single helical harmonic exp(i(k x + n theta)) solves the equations exactly


def helix_operators(radius: float, n, k, kinematics: str) -> NDArray[np.complex128]:
    """Strain rows (8) x (U, V, W) for the harmonics exp(i(k x + n theta)); shape
    ``broadcast(n, k).shape + (8, 3)`` ((8, 3) for scalars)."""
    n, k = np.broadcast_arrays(np.asarray(n, dtype=float), np.asarray(k, dtype=float))
    eta = n / radius
    sanders = 1.0 if kinematics == "sanders" else 0.0
    B = np.zeros(n.shape + (8, 3), dtype=complex)
    B[..., _EPS_X, 0] = 1j * k
    B[..., _EPS_Y, 1], B[..., _EPS_Y, 2] = 1j * eta, 1.0 / radius
    B[..., _GAMMA, 0], B[..., _GAMMA, 1] = 1j * eta, 1j * k
    B[..., _KAPPA_X, 2] = k * k
    B[..., _KAPPA_Y, 1], B[..., _KAPPA_Y, 2] = sanders * 1j * eta / radius, eta * eta
    B[..., _KAPPA_XY, 0] = -sanders * 1j * eta / (2.0 * radius)
    B[..., _KAPPA_XY, 1] = sanders * 1.5j * k / radius
    B[..., _KAPPA_XY, 2] = 2.0 * k * eta
    B[..., _BETA_X, 2] = -1j * k
    B[..., _BETA_Y, 1], B[..., _BETA_Y, 2] = sanders / radius, -1j * eta
    return B


#: Phases of the helix's dofs (U, V, W) that make its operator's rows real or imaginary
_HELIX_PHASES = (1j, 1j, 1.0)


def _helix_torques(C: NDArray[np.float64], radius: float, n, k, kinematics: str) -> NDArray[np.float64]:
    """(..., 2): positive-sense torque and negative-sense magnitude [N m] of each helix
    exp(i(k x + n theta)) (inf: none); one real 3x3 solve with two right-hand sides per helix
    (:func:`~flexshaft.buckling._common.real_helix_torques`)."""
    return real_helix_torques(helix_operators(radius, n, k, kinematics), _HELIX_PHASES, C, radius)


def classical_helix_torque(
    laminate: Laminate, radius: float, kinematics: Kinematics = "sanders", n_max: int = 40
) -> dict[str, tuple[float, int, float]]:
    """Critical torques of an infinitely long classical tube, minimised over 2 <= n <= n_max and k.

    The minimum over k is found for every n at once on a log grid (45 points over
    k = n/R e^[-8, 3], either sign), refined by golden-section search within one grid step of
    the best point (:func:`~flexshaft.buckling._common.helix_minima`: to 5.5e-5 in log k,
    relative error of order 1e-9).

    Returns ``{"positive": (T, n, k), "negative": (|T|, n, k)}`` (T [N m], k [rad/m]).
    """
    C = shell_stiffness(laminate)
    n = np.arange(2, int(n_max) + 1)
    torques, wavenumbers = helix_minima(
        lambda n_, k_: _helix_torques(C, radius, n_, k_, kinematics), radius, n, _LOG_K_OFFSETS
    )
    best = {}
    for sense, key in enumerate(("positive", "negative")):
        i = int(np.argmin(torques[:, sense]))
        found = np.isfinite(torques[i, sense])
        best[key] = (
            float(torques[i, sense]),
            int(n[i]) if found else 0,
            float(wavenumbers[i, sense]) if found else 0.0,
        )
    return best


# Finite length, simply supported: Ritz with axial sine/cosine series


def _ritz_operators(
    radius: float, length: float, n: int, n_terms: int, kinematics: str
) -> tuple[NDArray[np.complex128], NDArray[np.complex128], NDArray[np.int_]]:
    """Strain rows (8) x dofs, split into the sin and cos parts, and the axial index of each dof.

    dofs: U_0..U_M (cos), V_1..V_M (sin), W_1..W_M (sin).
    """
    M = n_terms
    m_u, m_vw = np.arange(0, M + 1), np.arange(1, M + 1)
    m = np.concatenate([m_u, m_vw, m_vw])
    u, v, w = slice(0, M + 1), slice(M + 1, 2 * M + 1), slice(2 * M + 1, 3 * M + 1)
    xi_u, xi = m_u * np.pi / length, m_vw * np.pi / length
    eta = n / radius
    sanders = 1.0 if kinematics == "sanders" else 0.0
    Bs = np.zeros((8, m.size), dtype=complex)
    Bc = np.zeros((8, m.size), dtype=complex)
    Bs[_EPS_X, u] = -xi_u  # d/dx cos = -xi sin
    Bs[_EPS_Y, v], Bs[_EPS_Y, w] = 1j * eta, 1.0 / radius
    Bc[_GAMMA, u], Bc[_GAMMA, v] = 1j * eta, xi
    Bs[_KAPPA_X, w] = xi**2
    Bs[_KAPPA_Y, w], Bs[_KAPPA_Y, v] = eta**2, sanders * 1j * eta / radius
    Bc[_KAPPA_XY, w] = -2j * eta * xi
    Bc[_KAPPA_XY, v] = sanders * 1.5 * xi / radius
    Bc[_KAPPA_XY, u] = -sanders * 0.5j * eta / radius
    Bc[_BETA_X, w] = -xi
    Bs[_BETA_Y, w], Bs[_BETA_Y, v] = -1j * eta, sanders / radius
    return Bs, Bc, m


def _series(m: NDArray[np.int_]) -> list[tuple[slice, slice]]:
    """(dofs, axial indices) of each run of consecutive axial indices in ``m``: one field's series."""
    edges = np.concatenate([[0], np.flatnonzero(np.diff(m) != 1) + 1, [m.size]])
    return [(slice(a, b), slice(int(m[a]), int(m[b - 1]) + 1)) for a, b in zip(edges[:-1], edges[1:])]


def _same_index_pairs(series: list[tuple[slice, slice]]) -> tuple[NDArray[np.int_], ...]:
    """(a, b, m): every pair of dofs a, b with the same axial index m."""
    pairs = []
    for dofs_a, m_a in series:
        for dofs_b, m_b in series:
            m = np.arange(max(m_a.start, m_b.start), min(m_a.stop, m_b.stop))
            pairs.append((dofs_a.start + m - m_a.start, dofs_b.start + m - m_b.start, m))
    return tuple(np.concatenate(column) for column in zip(*pairs))


def assemble_ritz(
    Bs: NDArray, Bc: NDArray, m: NDArray[np.int_], C: NDArray[np.float64], radius: float, length: float
) -> tuple[NDArray, NDArray]:
    """K [N m] and G per unit torque [-] from sin/cos strain rows; the last two rows are beta_x, beta_y.

    The rows are complex, or real (:func:`real_ritz`), and K, G of their type.

    K = sum over (p, q) in {sin, cos}^2 of (B_p^H C B_q) * I_pq with the axial integrals I_pq
    (:func:`~flexshaft.buckling._common.axial_integrals`). The same-parity integrals vanish
    unless both dofs have the same axial index m (orthogonal sines, orthogonal cosines): those
    two terms are summed on those pairs only. The cos-sin term is the conjugate transpose of the
    sin-cos one (C symmetric, I_cs = I_sc^T). The load matrix is built the same way from the
    rotation rows. The dofs come in series of consecutive axial indices (one per field), so the
    integrals of a pair of series are a block of those of m = 0..max(m): the products are
    weighted block by block, and the load's outer products only where the rotation rows have
    entries, without an integral matrix over all the dofs.
    """
    integrals = axial_integrals(np.arange(int(m.max()) + 1), length)
    I_sc = integrals[(0, 1)]
    series = _series(m)
    area = 2.0 * np.pi * radius
    n_strains = C.shape[0]
    Bs_, Bc_ = Bs[:n_strains], Bc[:n_strains]
    CBs, CBc = (area * C) @ Bs_, (area * C) @ Bc_
    K, cos_sin = Bs_.conj().T @ CBc, Bc_.conj().T @ CBs  # the sin-cos term and its conjugate transpose
    for dofs_a, m_a in series:
        for dofs_b, m_b in series:
            K[dofs_a, dofs_b] *= I_sc[m_a, m_b]
            cos_sin[dofs_a, dofs_b] *= I_sc[m_b, m_a].T
    K += cos_sin
    a, b, same = _same_index_pairs(series)  # the same-parity terms
    I_ss, I_cc = integrals[(0, 0)][same, same], integrals[(1, 1)][same, same]
    K[a, b] += (
        np.einsum("ip,ip->p", Bs_[:, a].conj(), CBs[:, b]) * I_ss
        + np.einsum("ip,ip->p", Bc_[:, a].conj(), CBc[:, b]) * I_cc
    )
    # G = -(P + P^H) / (2 pi R^2) area, P = sum over (p, q) of outer(beta_x,p^*, beta_y,q) I_pq
    (bx_s, by_s), (bx_c, by_c) = Bs[-2:], Bc[-2:]
    scale = -area / (2.0 * np.pi * radius**2)
    G = np.zeros(K.shape, dtype=np.result_type(Bs, Bc))
    for x, y, sin_first in ((bx_s, by_c, True), (bx_c, by_s, False)):
        for dofs_a, m_a in (series_ for series_ in series if np.any(x[series_[0]])):
            for dofs_b, m_b in (series_ for series_ in series if np.any(y[series_[0]])):
                I = I_sc[m_a, m_b] if sin_first else I_sc[m_b, m_a].T
                block = np.multiply.outer(x[dofs_a].conj(), y[dofs_b]) * (scale * I)
                G[dofs_a, dofs_b] += block
                G[dofs_b, dofs_a] += block.conj().T

    def same_index(a, b):
        return bx_s[a].conj() * by_s[b] * I_ss + bx_c[a].conj() * by_c[b] * I_cc

    G[a, b] += scale * (same_index(a, b) + same_index(b, a).conj())
    return K, G


#: Powers of i, exact: i^m = _I_POWERS[m % 4]
_I_POWERS = np.array([1.0, 1j, -1.0, -1j])
#: Phase of each field's Ritz coefficients (U, V, W) in the real basis of :func:`real_ritz`
_FIELD_PHASES = (1j, 1.0, 1j)


def real_ritz(
    Bs: NDArray[np.complex128],
    Bc: NDArray[np.complex128],
    m: NDArray[np.int_],
    C: NDArray[np.float64],
    radius: float,
    length: float,
    field_phases: tuple[complex, ...],
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.complex128]]:
    """:func:`assemble_ritz`'s K [N m] and G [-] in a basis where they are real, and its phases d.

    The harmonic e^{i n theta} makes the y-derivatives imaginary and the x-derivatives of the
    sine and cosine series stay real. Take each dof times d = phase(field) i^m (``field_phases``:
    one per series of dofs, in their order U, V, W, ...; :data:`_FIELD_PHASES` here and in
    :mod:`~flexshaft.buckling.shear`) and, apart from i^m, the sin part's membrane-bending rows
    are imaginary and its transverse shear and rotation rows real, the cos part's the other way
    round. The same-parity integrals pair equal m (factor 1: products within one part, real),
    the sin-cos ones m of opposite parity, whose factor i^(m_b - m_a) = +-i makes the products
    across the parts real. So D^H K D and D^H G D, D = diag(d) unitary, are real symmetric with
    the pencil's eigenvalues. Every entry of B D is real or imaginary (the other part an exact
    zero), and two entries that meet in a nonzero product (C and the integral nonzero) are both
    real or both imaginary; Re + Im of each entry (the entry times 1 or -i) therefore gives the
    same products conj(a) b, and :func:`assemble_ritz` of those real rows gives D^H K D and
    D^H G D directly: the assembly and the eigen-solves run in real arithmetic. Needs C without
    coupling between the membrane-bending and transverse shear rows
    (:func:`~flexshaft.buckling._common.shell_stiffness`). Returns ``(K, G, d)``; a mode's
    coefficients in the dofs of :func:`assemble_ritz` are d a.
    """
    d = np.concatenate(
        [phase * _I_POWERS[m[dofs] % 4] for phase, (dofs, _) in zip(field_phases, _series(m), strict=True)]
    )
    rows_s, rows_c = Bs * d, Bc * d
    K, G = assemble_ritz(rows_s.real + rows_s.imag, rows_c.real + rows_c.imag, m, C, radius, length)
    return K, G, d


def classical_galerkin_matrices(
    laminate: Laminate, radius: float, length: float, n: int, n_terms: int, kinematics: Kinematics = "sanders"
) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """Ritz stiffness K [N m] and load matrix G per unit torque for harmonic n; K a = T G a.

    dofs (U_0..U_M, V_1..V_M, W_1..W_M); both matrices complex Hermitian, K positive definite.
    """
    Bs, Bc, m = _ritz_operators(radius, length, n, n_terms, kinematics)
    return assemble_ritz(Bs, Bc, m, shell_stiffness(laminate), radius, length)


def ritz_mode(
    K: NDArray[np.float64], G: NDArray[np.float64], torque: float, w: slice, phases: NDArray[np.complex128]
) -> NDArray[np.complex128]:
    """W coefficients (slice ``w`` of the dofs) of the mode of K a = T G a at the signed T = torque,
    with K, G in the real basis of :func:`real_ritz` (``phases`` its d): d a, normalised to max 1."""
    lu = scipy.linalg.lu_factor(K - torque * (1.0 - 1e-9) * G)
    vector = np.random.default_rng(0).standard_normal(int(K.shape[0])).astype(complex)
    for _ in range(4):
        vector = scipy.linalg.lu_solve(lu, G @ vector)
        vector /= np.linalg.norm(vector)
    coefficients = vector[w] * phases[w]
    return coefficients / coefficients[np.argmax(np.abs(coefficients))]


def classical_buckling(
    laminate: Laminate, radius: float, length: float, kinematics: Kinematics, n_terms: int | None, n_max: int
) -> dict:
    """Ritz minimisation over n of the classical shell, both senses.

    Returns a dict with, per sense key ``True`` (positive) / ``False`` (negative), the tuple
    (torque [N m], n, W coefficients of the mode), and ``"n_terms"``.
    """
    if n_terms is None:
        helix = classical_helix_torque(laminate, radius, kinematics)
        M = default_terms(max(abs(helix["positive"][2]), abs(helix["negative"][2])), length)
    else:
        M = int(n_terms)
    C = shell_stiffness(laminate)

    def matrices(n: int) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.complex128]]:
        Bs, Bc, m = _ritz_operators(radius, length, n, M, kinematics)
        return real_ritz(Bs, Bc, m, C, radius, length, _FIELD_PHASES)

    best = {True: (np.inf, 0), False: (np.inf, 0)}  # sense (positive?) -> (torque, n)
    for n in range(2, n_max + 1):
        torques = extreme_torques(*matrices(n)[:2])
        for positive, torque in zip((True, False), torques):
            if torque < best[positive][0]:
                best[positive] = (torque, n)
        if all(np.isfinite(t) and n >= n_best + 3 for t, n_best in best.values()):
            break
    w = slice(2 * M + 1, 3 * M + 1)
    out: dict = {"n_terms": M}
    for positive, (torque, n_best) in best.items():
        if np.isfinite(torque):
            K, G, phases = matrices(n_best)
            mode = ritz_mode(K, G, torque if positive else -torque, w, phases)
        else:
            mode = np.full(M, np.nan, dtype=complex)
        out[positive] = (float(torque), n_best, mode)
    return out

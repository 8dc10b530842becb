"""Shared pieces of the torsional buckling models: checks, stiffness, axial integrals, eigenvalues."""

from __future__ import annotations

from typing import Literal

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from flexshaft.laminate import Laminate, abd_matrices, transverse_shear_stiffness

__all__ = [
    "ShellTheory",
    "Kinematics",
    "shell_stiffness",
    "check_inputs",
    "axial_integrals",
    "default_terms",
    "extreme_torques",
    "helix_grid",
    "helix_minima",
    "rank_two_torques",
    "real_helix_torques",
    "THEORIES",
    "KINEMATICS",
]

#: Shell theory: classical Kirchhoff-Love, or first-order shear deformation (Reissner-Mindlin).
ShellTheory = Literal["shear", "classical"]
#: Kinematic relations: Sanders' first approximation, or Donnell's shallow-shell relations.
Kinematics = Literal["sanders", "donnell"]
THEORIES = ("shear", "classical")
KINEMATICS = ("sanders", "donnell")


def shell_stiffness(laminate: Laminate, theory: ShellTheory = "classical") -> NDArray[np.float64]:
    """Storage stiffness of the wall [N/m, N, N m].

    ``"classical"``: 6x6 [[A, B], [B, D]] relating (N, M) to (eps, kappa). ``"shear"``: 8x8, the
    same block followed by the transverse shear stiffness [[A55, A45], [A45, A44]] relating
    (Q_x, Q_y) to (gamma_xz, gamma_yz) (:func:`flexshaft.laminate.transverse_shear_stiffness`).
    """
    A, B, D = (matrix.real for matrix in abd_matrices(laminate.storage))
    membrane_bending = np.block([[A, B], [B, D]])
    if theory == "classical":
        return membrane_bending
    C = np.zeros((8, 8))
    C[:6, :6] = membrane_bending
    C[6:, 6:] = transverse_shear_stiffness(laminate.storage).real
    return C


def check_inputs(radius: float, theory: str, kinematics: str, length: float = 1.0) -> None:
    """Refuse a non-positive radius or length [m] and unknown theory or kinematics names."""
    for name, value in (("radius", radius), ("length", length)):
        if not np.isfinite(value) or value <= 0.0:
            raise ValueError(f"{name} must be positive and finite [m], got {value!r}")
    if theory not in THEORIES:
        raise ValueError(f"theory must be 'shear' or 'classical', got {theory!r}")
    if kinematics not in KINEMATICS:
        raise ValueError(f"kinematics must be 'sanders' or 'donnell', got {kinematics!r}")


def axial_integrals(m: NDArray[np.int_], length: float) -> dict[tuple[int, int], NDArray[np.float64]]:
    """int_0^L f(m_a pi x/L) g(m_b pi x/L) dx for f, g in (sin, cos); keys (0=sin, 1=cos)."""
    ma, mb = m[:, None], m[None, :]
    same = ma == mb
    odd = (ma + mb) % 2 == 1
    denominator = np.where(odd, ma * ma - mb * mb, 1)
    sin_cos = np.where(odd, 2.0 * length / np.pi * ma / denominator, 0.0)
    return {
        (0, 0): np.where(same & (ma > 0), length / 2.0, 0.0),
        (1, 1): np.where(same, np.where(ma == 0, length, length / 2.0), 0.0),
        (0, 1): sin_cos,
        (1, 0): sin_cos.T,
    }


def default_terms(axial_wavenumber: float, length: float) -> int:
    """Axial terms M for a helix of ``axial_wavenumber`` [rad/m] on ``length`` [m], plus end correction."""
    return int(np.clip(np.ceil(1.25 * abs(axial_wavenumber) * length / np.pi) + 16, 24, 400))


def extreme_torques(K: NDArray, G: NDArray) -> tuple[float, float]:
    """Smallest positive torque and smallest negative-torque magnitude of K a = T G a [N m].

    K is Hermitian positive definite, G Hermitian (both complex, or both real symmetric). The
    torque loads only the dofs where G has entries (the rotations' v and w terms of the Ritz
    series): the nonzero eigenvalues mu = 1/T of the pencil (G, K) are those of (G_kk, S) with
    S = K_kk - K_kr K_rr^-1 K_rk the Schur complement of K on those dofs k (eliminate the rest r,
    on which G a = 0: K_rr a_r = -K_rk a_k). That pencil is 40-50 % of the size, about a fifth of
    the work of the full one. K is scaled to unit diagonal (symmetric diagonal equilibration) for
    the factorization, and S is formed as K_kk - W^H W with W = L^-1 K_rk (K_rr = L L^H): one
    triangular solve and a rank-k update of the lower triangle (BLAS zherk or dsyrk), the only
    one the eigen-solver reads.
    """
    loaded = np.any(G != 0.0, axis=0)
    if not loaded.any():
        return np.inf, np.inf
    scale = 1.0 / np.sqrt(np.diag(K).real)
    k, r = np.flatnonzero(loaded), np.flatnonzero(~loaded)

    def scaled(matrix, rows, columns):
        return matrix[np.ix_(rows, columns)] * np.outer(scale[rows], scale[columns])

    S, G_kk = np.asfortranarray(scaled(K, k, k)), scaled(G, k, k)
    if r.size:
        # cho_factor leaves the upper triangle as it was; solve_triangular reads the lower one only
        L, _ = scipy.linalg.cho_factor(scaled(K, r, r), lower=True, check_finite=False)
        W = scipy.linalg.solve_triangular(L, scaled(K, r, k), lower=True, check_finite=False)
        # S -= W^H W on the lower triangle only (half a product), the one eigh reads
        rank_k_update = scipy.linalg.blas.zherk if np.iscomplexobj(W) else scipy.linalg.blas.dsyrk
        S = rank_k_update(-1.0, W, beta=1.0, c=S, trans=2, lower=1, overwrite_c=1)
    # scipy-stubs 1.17.1.5 types the eigvals_only overloads' driver without the generalized
    # drivers ("gv", "gvd", "gvx"), which scipy accepts for a (G, S) pair
    mu = scipy.linalg.eigh(G_kk, S, lower=True, eigvals_only=True, driver="gvd", check_finite=False)  # type: ignore[call-overload]
    return (1.0 / mu[-1] if mu[-1] > 0.0 else np.inf), (-1.0 / mu[0] if mu[0] < 0.0 else np.inf)


def rank_two_torques(K: NDArray, beta_x: NDArray, beta_y: NDArray, radius: float) -> NDArray[np.float64]:
    """(..., 2): positive-sense torque and negative-sense magnitude [N m] of stacked helices.

    The load matrix has rank 2: G = -c (x y^H + y x^H) with x = conj(beta_x), y = conj(beta_y)
    (the rotation rows of the helix's strain operator), c = 1/(2 pi R^2). The nonzero
    eigenvalues mu = 1/T of K^-1 G are those of the 2x2 matrix -c J S, S = W^H K^-1 W,
    W = [x, y], J = [[0, 1], [1, 0]]: mu = -c (rho -/+ sqrt(rho^2 + det S)) with rho = Re S_01.
    So T+ = 1/(c (sqrt(rho^2 + d) - rho)) and T- = 1/(c (sqrt(rho^2 + d) + rho)), one solve
    with two right-hand sides per helix. ``K`` (..., m, m), ``beta_x``, ``beta_y`` (..., m),
    complex or real.
    """
    W = np.stack([beta_x.conj(), beta_y.conj()], axis=-1)  # (..., m, 2)
    S = np.swapaxes(W.conj(), -1, -2) @ np.linalg.solve(K, W)
    rho = S[..., 0, 1].real
    root = np.sqrt(rho**2 + np.maximum((S[..., 0, 0] * S[..., 1, 1]).real - np.abs(S[..., 0, 1]) ** 2, 0.0))
    c = 1.0 / (2.0 * np.pi * radius**2)
    with np.errstate(divide="ignore"):
        positive = np.where(root - rho > 0.0, 1.0 / (c * (root - rho)), np.inf)
        negative = np.where(root + rho > 0.0, 1.0 / (c * (root + rho)), np.inf)
    return np.stack([positive, negative], axis=-1)


def real_helix_torques(
    B: NDArray[np.complex128], phases: tuple[complex, ...], C: NDArray[np.float64], radius: float
) -> NDArray[np.float64]:
    """:func:`rank_two_torques` of stacked helices from their operator, in real arithmetic [N m].

    ``B`` (..., rows, dofs): the strain rows of ``C`` then beta_x, beta_y, for the harmonics
    exp(i(k x + n theta)), whose derivatives are all imaginary. Taken times ``phases`` (one per
    dof: i for u, v and the normal's rotations, 1 for w), every row of B is real or imaginary:
    the membrane-bending rows real, the transverse shear rows and the rotations imaginary, and
    C couples rows of one kind only. Re + Im of each entry (the other
    part an exact zero) is then the row times 1 or -i, a unit factor that cancels in
    K = B^H C B and in S = W^H K^-1 W: so K and W are real, with the torques of the complex
    ones (a real basis change), and the solves run in real arithmetic.
    """
    rows = B * np.asarray(phases)
    real = rows.real + rows.imag
    strains = real[..., : C.shape[0], :]
    K = np.swapaxes(strains, -1, -2) @ (C @ strains)
    return rank_two_torques(K, real[..., -2, :], real[..., -1, :], radius)


#: Torque evaluations of the golden-section refinement: the bracket of ±1 grid step shrinks by
#: 0.618 with each after the first two, to 2 × 0.618^19 = 2.2e-4 of the grid step (5.5e-5 in log k
#: on the 0.25 grids here, as fine as the final spacing of the zoom search it replaced).
_GOLDEN_STEPS = 21
_GOLDEN = (np.sqrt(5.0) - 1.0) / 2.0


#: Signs of the axial wavenumber: the helix leaning either way, searched together
_HANDS = np.array([1.0, -1.0])


def helix_grid(
    torques, radius: float, n: NDArray[np.int_], log_k_offsets: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The torques of :func:`helix_minima`'s log grid, both signs of k, in one call of ``torques``:
    ``(log_k, values)``, log_k (len(n), len(offsets)) and values (2, len(n), len(offsets), 2)
    (sign of k: +, -; then n, log k, sense)."""
    n = np.atleast_1d(np.asarray(n, dtype=int))
    log_k = np.log(n / radius)[:, None] + log_k_offsets[None, :]
    return log_k, torques(n[:, None], _HANDS[:, None, None] * np.exp(log_k))


def helix_minima(
    torques,
    radius: float,
    n: NDArray[np.int_],
    log_k_offsets: NDArray[np.float64],
    refine: bool = True,
    grid: tuple[NDArray[np.float64], NDArray[np.float64]] | None = None,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Minimum over the axial wavenumber k of an endless tube's helix torques, per n.

    ``torques(n, k)`` gives the (..., 2) torques (positive sense, negative-sense magnitude) of
    the helices exp(i(k x + n theta)), broadcast over n and k. The minimum is found on the log
    grid k = n/R exp(log_k_offsets), either sign of k (``grid``: those values, when already
    computed by :func:`helix_grid`), and, with ``refine``, by golden-section search in log k
    within one grid step of the best point. The bracket shrinks to 2.2e-4 of the grid step
    (:data:`_GOLDEN_STEPS`), which leaves a relative error of order 1e-9 at a smooth minimum.
    Both signs of k, all n and both senses are searched together (one call of ``torques`` per
    step), each on its own bracket.

    Returns ``(torques, wavenumbers)``, each (len(n), 2): the minimum torque of each sense
    [N m] and its signed axial wavenumber [rad/m] (the positive one on a tie).
    """
    n = np.atleast_1d(np.asarray(n, dtype=int))
    hands, rows, senses = np.arange(2)[:, None, None], np.arange(n.size)[None, :, None], np.arange(2)[None, None, :]
    step = log_k_offsets[1] - log_k_offsets[0]
    log_k, values = grid if grid is not None else helix_grid(torques, radius, n, log_k_offsets)
    best = np.argmin(values, axis=2)  # (hand, n, sense)
    centre, value = log_k[rows, best], values[hands, rows, best, senses]
    if refine:

        def own(x):  # each (hand, n, sense)'s torque at its own log k
            return torques(n[:, None], _HANDS[:, None, None] * np.exp(x))[hands, rows, senses, senses]

        a, b = centre - step, centre + step
        x1, x2 = b - _GOLDEN * (b - a), a + _GOLDEN * (b - a)
        f1, f2 = own(x1), own(x2)
        for x, f in ((x1, f1), (x2, f2)):
            better = f < value
            centre, value = np.where(better, x, centre), np.where(better, f, value)
        for _ in range(_GOLDEN_STEPS - 2):
            left = f1 < f2  # the minimum is in [a, x2]
            a, b = np.where(left, a, x1), np.where(left, x2, b)
            kept_x, kept_f = np.where(left, x1, x2), np.where(left, f1, f2)
            new_x = np.where(left, b - _GOLDEN * (b - a), a + _GOLDEN * (b - a))
            new_f = own(new_x)
            better = new_f < value
            centre, value = np.where(better, new_x, centre), np.where(better, new_f, value)
            x1, f1 = np.where(left, new_x, kept_x), np.where(left, new_f, kept_f)
            x2, f2 = np.where(left, kept_x, new_x), np.where(left, kept_f, new_f)
    negative = value[1] < value[0]  # the negative sign of k only when strictly lower
    wavenumbers = np.where(negative, -np.exp(centre[1]), np.where(value[0] < np.inf, np.exp(centre[0]), 0.0))
    return np.where(negative, value[1], value[0]), wavenumbers

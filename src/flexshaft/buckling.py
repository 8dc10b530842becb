"""Torsional buckling of a thin laminated circular tube with simply supported ends.

Model
-----
Thin shell of radius R (mid-surface), length L, laminate stiffness A, B, D (storage parts),
loaded by a torque T about the axis, which gives the uniform membrane shear flow
N_xy = T / (2 pi R^2) (membrane pre-buckling state; the pre-buckling rotations are neglected).
x is axial, y = R theta circumferential, w outward; ply angles are measured from x towards y, so a
positive torque (vector along +x on the end x = L) puts +45 deg fibres in tension.

Kinematics are either Donnell's shallow-shell relations or Sanders' (1959, 1963) first-approximation
relations, which keep the v/R terms in the rotations and curvature changes:

    eps_x = u,x      eps_y = v,y + w/R      gamma_xy = u,y + v,x
    kappa_x = -w,xx  kappa_y = -w,yy [+ v,y/R]  kappa_xy = -2 w,xy [+ (3 v,x - u,y)/(2R)]
    beta_x = -w,x    beta_y = -w,y [+ v/R]

(bracketed terms: Sanders only). The second variation of the energy is
1/2 int [eps kappa]^T [[A, B], [B, D]] [eps kappa] dA + int N_xy beta_x beta_y dA. Donnell's
relations overestimate the stiffness of the n = 2 mode that governs long tubes: the long-tube
torque is 2/sqrt(3) times the Sanders (and Timoshenko & Gere) value, so Sanders is the default.

Solution
--------
Rayleigh-Ritz (Galerkin) with a full Fourier harmonic e^{i n theta} around the circumference
(n >= 2) and sine/cosine series along the axis,

    u = sum_{m=0}^{M} U_m cos(m pi x/L),  v = sum_{m=1}^{M} V_m sin(m pi x/L),
    w = sum_{m=1}^{M} W_m sin(m pi x/L),

which satisfy the essential conditions v = w = 0 at both ends; N_x = M_x = 0 are natural
(classical simple support "SS3", as in Batdorf's solutions). The first-derivative terms of the
torsion load and of the 16/26 stiffnesses couple odd and even m, so a helical mode is built
from many axial terms; the complex circumferential harmonic lets the helix lean either way, and
the extreme eigenvalues of K a = T G a of either sign give the critical torque of each sense.
The search runs over n until the load has clearly risen past its minimum. The number of axial
terms defaults to a value from the axial wavenumber of the infinite-cylinder helical mode.

Assumptions and limits: classical (Kirchhoff-Love) shell, linear pre-buckling state, perfect
geometry (no knock-down factor), no transverse shear deformation. The last is UNCONSERVATIVE for
soft-matrix FMC (the thesis used Bauchau's shear-deformable shell): when N_xy approaches the wall's
transverse shear stiffness k G_TT t, short-wave shear crimping governs, T ~ 2 pi R^2 k G_TT t.

References
----------
Donnell, L. H. (1933). Stability of thin-walled tubes under torsion. NACA Report 479.
Batdorf, S. B., Stein, M., Schildcrout, M. (1947). Critical stress of thin-walled cylinders in
torsion. NACA TN 1344.
Sanders, J. L. (1963). Nonlinear theories for thin shells. Q. Appl. Math. 21, 21-36.
Timoshenko, S. P. and Gere, J. M. (1961). *Theory of Elastic Stability*, 2nd ed., sec. 11.12.
Jones, R. M. (2006). *Buckling of Bars, Plates, and Shells*, Bull Ridge, ch. 7.
Bauchau, O. A., Krafchack, T. M. and Hayes, J. F. (1988). Torsional buckling analysis and
damage tolerance of graphite/epoxy shafts. J. Compos. Mater. 22, 258-270.
Ocalan, M. (2002). MS thesis, Penn State, sec. 2.7.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import scipy.linalg
import scipy.optimize
from numpy.typing import ArrayLike, NDArray

from .laminate import Laminate, abd_matrices

__all__ = [
    "ShellTheory", "BucklingResult", "shell_stiffness", "galerkin_matrices",
    "infinite_cylinder_torque", "torsional_buckling_torque", "buckling_safety_factor",
]

ShellTheory = Literal["donnell", "sanders"]

# rows of the strain operators
_EPS_X, _EPS_Y, _GAMMA, _KAPPA_X, _KAPPA_Y, _KAPPA_XY, _BETA_X, _BETA_Y = range(8)


def shell_stiffness(laminate: Laminate) -> NDArray[np.float64]:
    """6x6 storage stiffness [[A, B], [B, D]] relating (N, M) to (eps, kappa) [N/m, N, N m]."""
    A, B, D = (matrix.real for matrix in abd_matrices(laminate.storage))
    return np.block([[A, B], [B, D]])


def _check(radius: float, theory: str, length: float = 1.0) -> None:
    for name, value in (("radius", radius), ("length", length)):
        if not np.isfinite(value) or value <= 0.0:
            raise ValueError(f"{name} must be positive and finite [m], got {value!r}")
    if theory not in ("donnell", "sanders"):
        raise ValueError(f"theory must be 'donnell' or 'sanders', got {theory!r}")


# Infinite cylinder: a single helical harmonic exp(i(k x + n theta)) solves the equations exactly


def _helix_operators(radius: float, n: int, k: float, theory: str) -> NDArray[np.complex128]:
    """Strain rows (8) x (U, V, W) for the harmonic exp(i(k x + n theta))."""
    eta = n / radius
    sanders = 1.0 if theory == "sanders" else 0.0
    B = np.zeros((8, 3), dtype=complex)
    B[_EPS_X, 0] = 1j * k
    B[_EPS_Y, 1], B[_EPS_Y, 2] = 1j * eta, 1.0 / radius
    B[_GAMMA, 0], B[_GAMMA, 1] = 1j * eta, 1j * k
    B[_KAPPA_X, 2] = k * k
    B[_KAPPA_Y, 1], B[_KAPPA_Y, 2] = sanders * 1j * eta / radius, eta * eta
    B[_KAPPA_XY, 0] = -sanders * 1j * eta / (2.0 * radius)
    B[_KAPPA_XY, 1] = sanders * 1.5j * k / radius
    B[_KAPPA_XY, 2] = 2.0 * k * eta
    B[_BETA_X, 2] = -1j * k
    B[_BETA_Y, 1], B[_BETA_Y, 2] = sanders / radius, -1j * eta
    return B


def _helix_torques(C: NDArray[np.float64], radius: float, n: int, k: float, theory: str) -> tuple[float, float]:
    """Positive-sense torque and negative-sense magnitude [N m] of the helix exp(i(k x + n theta))."""
    B = _helix_operators(radius, n, k, theory)
    K = B[:6].conj().T @ C @ B[:6]
    P = np.outer(B[_BETA_X].conj(), B[_BETA_Y])
    G = -(P + P.conj().T) / (2.0 * np.pi * radius**2)
    mu = scipy.linalg.eigvalsh(G, K)
    return (1.0 / mu[-1] if mu[-1] > 0.0 else np.inf), (-1.0 / mu[0] if mu[0] < 0.0 else np.inf)


def infinite_cylinder_torque(
    laminate: Laminate, radius: float, theory: ShellTheory = "sanders", n_max: int = 40
) -> dict[str, tuple[float, int, float]]:
    """Critical torques of an infinitely long tube, minimised over n >= 2 and axial wavenumber.

    The exact Donnell/Sanders solution for L -> infinity (no end conditions): a single harmonic
    exp(i(k x + n theta)). ``radius`` [m] is the mid-surface radius.

    Returns
    -------
    dict
        ``{"positive": (T, n, k), "negative": (|T|, n, k)}`` with T [N m], n the circumferential
        wave number and k the signed axial wavenumber [rad/m] of the critical helix.
    """
    _check(radius, theory)
    C = shell_stiffness(laminate)
    best = {"positive": (np.inf, 0, 0.0), "negative": (np.inf, 0, 0.0)}
    for n in range(2, n_max + 1):
        for index, key in enumerate(("positive", "negative")):
            for hand in (1.0, -1.0):

                def load(log_k: float) -> float:
                    return _helix_torques(C, radius, n, hand * np.exp(log_k), theory)[index]

                log_grid = np.log(n / radius) + np.linspace(-8.0, 3.0, 45)
                values = np.array([load(x) for x in log_grid])
                i = int(np.argmin(values))
                if not np.isfinite(values[i]):
                    continue
                lo, hi = log_grid[max(i - 1, 0)], log_grid[min(i + 1, log_grid.size - 1)]
                found = scipy.optimize.minimize_scalar(
                    load, bounds=(lo, hi), method="bounded", options={"xatol": 1e-7}
                )
                if found.fun < best[key][0]:
                    best[key] = (float(found.fun), n, hand * float(np.exp(found.x)))
        if n > max(best["positive"][1], best["negative"][1]) + 3:
            break
    return best


# Finite length, simply supported: Ritz with axial sine/cosine series


def _axial_integrals(m: NDArray[np.int_], length: float) -> dict[tuple[int, int], NDArray[np.float64]]:
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


def _ritz_operators(
    radius: float, length: float, n: int, n_terms: int, theory: str
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
    sanders = 1.0 if theory == "sanders" else 0.0
    Bs = np.zeros((8, m.size), dtype=complex)
    Bc = np.zeros((8, m.size), dtype=complex)
    Bs[_EPS_X, u] = -xi_u                                   # d/dx cos = -xi sin
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


def galerkin_matrices(
    laminate: Laminate,
    radius: float,
    length: float,
    n: int,
    n_terms: int,
    theory: ShellTheory = "sanders",
) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """Ritz stiffness K and load matrix G per unit torque for harmonic n; buckling: K a = T G a.

    ``radius`` [m] is the mid-surface radius, ``length`` [m] the span between the simple supports,
    ``n`` >= 2 the circumferential wave number and ``n_terms`` = M the number of axial terms.

    Returns
    -------
    K : ndarray, shape (3M+1, 3M+1)
        Complex Hermitian positive definite stiffness [N m] for dofs (U_0..U_M, V_1..V_M, W_1..W_M).
    G : ndarray, same shape
        Complex Hermitian load matrix per unit torque [-].
    """
    Bs, Bc, m = _ritz_operators(radius, length, n, n_terms, theory)
    integrals = _axial_integrals(m, length)
    C = shell_stiffness(laminate)
    parts = (Bs, Bc)
    area = 2.0 * np.pi * radius
    K = np.zeros((m.size, m.size), dtype=complex)
    P = np.zeros_like(K)
    for p in (0, 1):
        for q in (0, 1):
            I = integrals[(p, q)]
            K += (parts[p][:6].conj().T @ C @ parts[q][:6]) * I
            P += np.outer(parts[p][_BETA_X].conj(), parts[q][_BETA_Y]) * I
    G = -(P + P.conj().T) * area / (2.0 * np.pi * radius**2)
    return area * K, G


def _extreme_torques(K: NDArray[np.complex128], G: NDArray[np.complex128]) -> tuple[float, float]:
    """Smallest positive torque and smallest negative-torque magnitude of K a = T G a [N m]."""
    mu = scipy.linalg.eigh(G, K, eigvals_only=True, driver="gvd")
    return (1.0 / mu[-1] if mu[-1] > 0.0 else np.inf), (-1.0 / mu[0] if mu[0] < 0.0 else np.inf)


def _mode(K: NDArray[np.complex128], G: NDArray[np.complex128], torque: float) -> NDArray[np.complex128]:
    """W_1..W_M of the mode of K a = T G a at the signed eigenvalue T = torque (inverse iteration)."""
    lu = scipy.linalg.lu_factor(K - torque * (1.0 - 1e-9) * G)
    vector = np.random.default_rng(0).standard_normal(K.shape[0]).astype(complex)
    for _ in range(4):
        vector = scipy.linalg.lu_solve(lu, G @ vector)
        vector /= np.linalg.norm(vector)
    w = vector[-((K.shape[0] - 1) // 3):]
    return w / w[np.argmax(np.abs(w))]


@dataclass(frozen=True, eq=False)
class BucklingResult:
    """Critical torques of a simply supported laminated tube, both senses.

    Attributes
    ----------
    torque_positive, torque_negative : float
        Critical torque magnitude [N m] for the positive sense (the one that puts +45 deg fibres
        in tension) and the negative sense.
    n_positive, n_negative : int
        Circumferential wave numbers of the critical modes.
    axial_half_waves_positive, axial_half_waves_negative : int
        Axial wave parameter: index m of the largest sine term of w in the critical mode
        (the helix has about m half-waves along L).
    mode_positive, mode_negative : ndarray, complex
        Ritz coefficients W_1..W_M of w, normalised to max |W_m| = 1; the mode is
        w = Re(sum_m W_m sin(m pi x/L) e^{i n theta}).
    n_terms : int
        Number of axial terms M used.
    theory : str
        Kinematic relations used ("sanders" or "donnell").
    """

    torque_positive: float
    torque_negative: float
    n_positive: int
    n_negative: int
    axial_half_waves_positive: int
    axial_half_waves_negative: int
    mode_positive: NDArray[np.complex128]
    mode_negative: NDArray[np.complex128]
    n_terms: int
    theory: str

    @property
    def critical_torque(self) -> float:
        """The lower of the two senses [N m]."""
        return min(self.torque_positive, self.torque_negative)


def _default_terms(laminate: Laminate, radius: float, length: float, theory: str) -> int:
    """Enough axial terms to carry the infinite-cylinder helix plus its end correction."""
    helix = infinite_cylinder_torque(laminate, radius, theory)
    k = max(abs(helix["positive"][2]), abs(helix["negative"][2]))
    return int(np.clip(np.ceil(1.25 * k * length / np.pi) + 16, 24, 400))


def torsional_buckling_torque(
    laminate: Laminate,
    radius: float,
    length: float,
    *,
    theory: ShellTheory = "sanders",
    n_terms: int | None = None,
    n_max: int = 200,
) -> BucklingResult:
    """Critical torsional buckling torque of a simply supported laminated tube, both senses.

    Parameters
    ----------
    laminate : Laminate
        Wall laminate; the storage parts of A, B, D are used.
    radius : float
        Mid-surface radius [m] (for a shaft, (D_o - t)/2).
    length : float
        Length between the simple supports [m].
    theory : {"sanders", "donnell"}
        Kinematic relations (see the module docstring).
    n_terms : int, optional
        Number of axial sine terms M; default from the infinite-cylinder helix wavenumber.
    n_max : int
        Largest circumferential wave number tried [-].

    Returns
    -------
    BucklingResult
    """
    _check(radius, theory, length)
    M = _default_terms(laminate, radius, length, theory) if n_terms is None else int(n_terms)
    if M < 1:
        raise ValueError(f"n_terms must be >= 1, got {n_terms!r}")
    best = {True: (np.inf, 0), False: (np.inf, 0)}  # sense (positive?) -> (torque, n)
    for n in range(2, n_max + 1):
        torques = _extreme_torques(*galerkin_matrices(laminate, radius, length, n, M, theory))
        for positive, torque in zip((True, False), torques):
            if torque < best[positive][0]:
                best[positive] = (torque, n)
        if all(np.isfinite(t) and n >= n_best + 3 for t, n_best in best.values()):
            break
    modes = {
        positive: _mode(*galerkin_matrices(laminate, radius, length, n_best, M, theory), torque if positive else -torque)
        if np.isfinite(torque) else np.full(M, np.nan, dtype=complex)
        for positive, (torque, n_best) in best.items()
    }
    return BucklingResult(
        torque_positive=float(best[True][0]),
        torque_negative=float(best[False][0]),
        n_positive=best[True][1],
        n_negative=best[False][1],
        axial_half_waves_positive=int(np.argmax(np.abs(modes[True]))) + 1,
        axial_half_waves_negative=int(np.argmax(np.abs(modes[False]))) + 1,
        mode_positive=modes[True],
        mode_negative=modes[False],
        n_terms=M,
        theory=theory,
    )


def buckling_safety_factor(
    result: BucklingResult, torque: ArrayLike, *, signed: bool = False
) -> NDArray[np.float64]:
    """Torsional buckling safety factor T_cr / |T| (thesis sec. 3.2.4).

    Parameters
    ----------
    result : BucklingResult
    torque : array_like
        Applied torque [N m].
    signed : bool
        If True, the sign of ``torque`` selects the sense (positive as in :class:`BucklingResult`);
        if False (default, conservative when the handedness of the drive is not known), the
        weaker sense is used.

    Returns
    -------
    ndarray
        T_cr / |T| [-]; inf for zero torque.
    """
    torque = np.asarray(torque, dtype=float)
    if signed:
        critical = np.where(torque >= 0.0, result.torque_positive, result.torque_negative)
    else:
        critical = np.full(torque.shape, result.critical_torque)
    magnitude = np.abs(torque)
    return np.divide(critical, magnitude, out=np.full(np.shape(magnitude), np.inf), where=magnitude > 0.0)

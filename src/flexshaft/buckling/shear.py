"""Shear-deformable (first-order, Reissner-Mindlin) laminated-shell torsional buckling.

Kinematics
----------
The normal rotates independently of the mid-surface (rotations phi_x, phi_y), Sanders'
first-approximation shell with transverse shear (Reddy 2004, sec. 10.2; bracketed terms Sanders
only, dropped for Donnell):

    eps_x = u,x    eps_y = v,y + w/R    gamma_xy = u,y + v,x
    kappa_x = phi_x,x   kappa_y = phi_y,y   kappa_xy = phi_x,y + phi_y,x [+ (v,x - u,y)/(2R)]
    gamma_xz = w,x + phi_x    gamma_yz = w,y + phi_y [- v/R]
    beta_x = -w,x    beta_y = -w,y [+ v/R]       (mid-surface rotations, in the load term)

Energy 1/2 int [eps kappa]^T [[A, B], [B, D]] [eps kappa] + [gamma]^T A_s [gamma] dA + int N_xy
beta_x beta_y dA, A_s = k sum Q_s,k t_k from the plies' G_13, G_23
(:func:`flexshaft.laminate.transverse_shear_stiffness`). With gamma_xz = gamma_yz = 0 imposed,
phi_x = -w,x and phi_y = -w,y [+ v/R] and the classical shell of
:mod:`flexshaft.buckling.classical` is recovered exactly (A_s -> infinity).

Ritz series: u, phi_x ~ cos(m pi x/L) (m >= 0); v, w, phi_y ~ sin(m pi x/L) (m >= 1), each times
e^{i n theta}: v = w = phi_y = 0 at both ends, N_x = M_x = 0 natural (simple support SS3, the
end ring keeps its shape). phi_x spans the same space as w,x, so the classical limit has no
locking.

Shear crimping
--------------
For waves much shorter than the radius and the wall's bending wavelength the only stiffness left
is transverse shear: a short wave w = exp(i(k x + eta y)) stores A55 k^2 + 2 A45 k eta + A44 eta^2
per |w|^2 while the shear flow N_xy does work 2 N_xy k eta (phi cancels the bending, u and v the
membrane strain up to O(1/eta^2)). Minimised over k/eta, the buckling shear flow tends to

    N_xy -> sqrt(A44 A55) -/+ A45,   T_crimp = 2 pi R^2 (sqrt(A44 A55) -/+ A45),

upper sign for the positive torque sense. For an isotropic transverse shear stiffness this is
the classical shear-crimping load N_xy = k G t of sandwich and soft-core walls (Allen 1969,
ch. 8; Vinson 1999). It is the limit n -> infinity of the buckling torque curve; where the curve
falls towards it from above (soft matrix: FMC), the wall buckles at wavelengths of the order of
its thickness, outside any thin-shell model, and the limit value is the critical torque.

Search and governing mode
-------------------------
For each torque sense:

1. *global helical* branch: the Ritz solution for n = 2, 3, ... up to its first local minimum
   over n (the long-wave helix that the classical shell also finds);
2. *short-wave* branch: T_crimp, and every n above the global branch up to n_max (default: the
   circumferential half-wavelength pi R/n reaches the wall thickness) whose infinite-tube value
   (a lower bound of the simply supported tube at that n) lies below the best so far is solved
   (Ritz; the infinite-tube value where the tube holds more than ~100 axial half-waves, its
   end effect being negligible there and the value conservative).

The critical torque is the lowest. It is reported as governed by ``"global helical"`` when the
first local minimum is the lowest, else by ``"shear crimping"`` (a shorter-wave mode whose load is
set by the transverse shear stiffness; n is None when the n -> infinity limit T_crimp governs).

References
----------
Reddy, J. N. (2004). *Mechanics of Laminated Composite Plates and Shells*, 2nd ed., CRC, ch. 10.
Bauchau, O. A., Krafchack, T. M. and Hayes, J. F. (1988). Torsional buckling analysis and
damage tolerance of graphite/epoxy shafts. J. Compos. Mater. 22, 258-270.
Allen, H. G. (1969). *Analysis and Design of Structural Sandwich Panels*, Pergamon, ch. 8.
Vinson, J. R. (1999). *The Behavior of Sandwich Structures of Isotropic and Composite Materials*,
Technomic, sec. 7 (shear crimping).
"""

from __future__ import annotations

import functools

import numpy as np
from numpy.typing import NDArray

from flexshaft.buckling._common import (
    Kinematics,
    default_terms,
    extreme_torques,
    helix_grid,
    helix_minima,
    real_helix_torques,
    shell_stiffness,
)
from flexshaft.buckling.classical import assemble_ritz, real_ritz, ritz_mode
from flexshaft.laminate import Laminate, transverse_shear_stiffness

__all__ = ["crimping_torques", "shear_helix_curve", "shear_helix_torque", "shear_galerkin_matrices", "shear_buckling"]

# rows of the strain operators; dofs (U, V, W, PHI_X, PHI_Y)
_EPS_X, _EPS_Y, _GAMMA, _KAPPA_X, _KAPPA_Y, _KAPPA_XY, _GAMMA_XZ, _GAMMA_YZ, _BETA_X, _BETA_Y = range(10)
_U, _V, _W, _PX, _PY = range(5)
#: Phase of each field's Ritz coefficients (U, V, W, PHI_X, PHI_Y) in the real basis of
#: :func:`~flexshaft.buckling.classical.real_ritz`
_FIELD_PHASES = (1j, 1.0, 1j, 1j, 1.0)
#: Phases of the helix's dofs (U, V, W, PHI_X, PHI_Y) that make its operator's rows real or imaginary
_HELIX_PHASES = (1j, 1j, 1.0, 1j, 1j)
#: log-spaced axial wavenumbers around eta = n/R searched on the infinite tube
_LOG_K_OFFSETS = np.linspace(-8.0, 6.0, 57)
#: Above this many axial terms the infinite-tube value is used at that n: the tube then holds
#: about 100 or more axial half-waves and its simply supported ends raise the load by < 1e-4
#: (measured on the baseline FMC tube, see tests/test_buckling.py)
_MAX_RITZ_TERMS = 140


def crimping_torques(laminate: Laminate, radius: float) -> tuple[float, float]:
    """Shear-crimping limits (positive sense, negative-sense magnitude) [N m].

    T = 2 pi R^2 (sqrt(A44 A55) -/+ A45) with the storage transverse shear stiffness;
    ``radius`` [m] is the mid-surface radius.
    """
    As = transverse_shear_stiffness(laminate.storage).real
    root = np.sqrt(As[0, 0] * As[1, 1])
    scale = 2.0 * np.pi * radius**2
    return float(scale * (root - As[0, 1])), float(scale * (root + As[0, 1]))


# Infinite cylinder: the helix exp(i(k x + n theta)), batched over (n, k)


def _helix_operators(radius: float, n: NDArray, k: NDArray, kinematics: str) -> NDArray[np.complex128]:
    """Strain rows (10) x dofs (5) for harmonics exp(i(k x + n theta)); shape n.shape + (10, 5)."""
    n, k = np.broadcast_arrays(np.asarray(n, dtype=float), np.asarray(k, dtype=float))
    eta = n / radius
    s = 1.0 if kinematics == "sanders" else 0.0
    B = np.zeros(n.shape + (10, 5), dtype=complex)
    B[..., _EPS_X, _U] = 1j * k
    B[..., _EPS_Y, _V], B[..., _EPS_Y, _W] = 1j * eta, 1.0 / radius
    B[..., _GAMMA, _U], B[..., _GAMMA, _V] = 1j * eta, 1j * k
    B[..., _KAPPA_X, _PX] = 1j * k
    B[..., _KAPPA_Y, _PY] = 1j * eta
    B[..., _KAPPA_XY, _PX], B[..., _KAPPA_XY, _PY] = 1j * eta, 1j * k
    B[..., _KAPPA_XY, _V], B[..., _KAPPA_XY, _U] = s * 0.5j * k / radius, -s * 0.5j * eta / radius
    B[..., _GAMMA_XZ, _W], B[..., _GAMMA_XZ, _PX] = 1j * k, 1.0
    B[..., _GAMMA_YZ, _W], B[..., _GAMMA_YZ, _PY], B[..., _GAMMA_YZ, _V] = 1j * eta, 1.0, -s / radius
    B[..., _BETA_X, _W] = -1j * k
    B[..., _BETA_Y, _W], B[..., _BETA_Y, _V] = -1j * eta, s / radius
    return B


def _helix_torques(C: NDArray[np.float64], radius: float, n: NDArray, k: NDArray, kinematics: str) -> NDArray:
    """(..., 2): positive-sense torque and negative-sense magnitude [N m] of each helix (inf: none);
    one real 5x5 solve with two right-hand sides per helix
    (:func:`~flexshaft.buckling._common.real_helix_torques`)."""
    return real_helix_torques(_helix_operators(radius, n, k, kinematics), _HELIX_PHASES, C, radius)


def _helix_function(laminate: Laminate, radius: float, kinematics: str):
    """``torques(n, k)`` of the endless shear-deformable tube, as :func:`helix_minima` takes it."""
    C = shell_stiffness(laminate, "shear")
    return lambda n, k: _helix_torques(C, radius, n, k, kinematics)


def shear_helix_curve(
    laminate: Laminate, radius: float, n: NDArray[np.int_], kinematics: Kinematics = "sanders", refine: bool = True
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Infinite shear-deformable tube: critical torques and axial wavenumbers per n.

    The minimum over k is found on a log grid (57 points over k = n/R e^[-8, 6], either sign)
    and, with ``refine``, by golden-section search within one grid step of the best point, to
    5.5e-5 in log k: a relative error of order 1e-9 at a smooth minimum
    (:func:`~flexshaft.buckling._common.helix_minima`). Batched over all n.

    Parameters
    ----------
    n : array of int
        Circumferential wave numbers (>= 2).
    refine : bool
        Zoom in on each minimum (else: the log grid value).

    Returns
    -------
    torques : ndarray, shape (len(n), 2)
        Minimum over k of the (positive, negative-magnitude) torque [N m].
    wavenumbers : ndarray, shape (len(n), 2)
        Signed axial wavenumber [rad/m] of each minimum.
    """
    return helix_minima(_helix_function(laminate, radius, kinematics), radius, n, _LOG_K_OFFSETS, refine)


def shear_helix_torque(
    laminate: Laminate, radius: float, kinematics: Kinematics = "sanders", n_max: int = 40
) -> dict[str, tuple[float, int, float]]:
    """Minimum over 2 <= n <= n_max and k of the infinite shear-deformable tube.

    Returns ``{"positive": (T, n, k), "negative": (|T|, n, k)}`` (T [N m], k [rad/m]).
    """
    n = np.arange(2, n_max + 1)
    torques, wavenumbers = shear_helix_curve(laminate, radius, n, kinematics)
    out = {}
    for sense, key in enumerate(("positive", "negative")):
        i = int(np.argmin(torques[:, sense]))
        out[key] = (float(torques[i, sense]), int(n[i]), float(wavenumbers[i, sense]))
    return out


# Finite length, simply supported: Ritz


def _ritz_operators(
    radius: float, length: float, n: int, n_terms: int, kinematics: str
) -> tuple[NDArray[np.complex128], NDArray[np.complex128], NDArray[np.int_]]:
    """Strain rows (10) x dofs split into sin and cos parts, and the axial index of each dof.

    dofs: U_0..U_M (cos), V_1..V_M, W_1..W_M (sin), PHI_X_0..PHI_X_M (cos), PHI_Y_1..PHI_Y_M (sin).
    """
    M = n_terms
    m_c, m_s = np.arange(0, M + 1), np.arange(1, M + 1)
    m = np.concatenate([m_c, m_s, m_s, m_c, m_s])
    edges = np.cumsum([0, M + 1, M, M, M + 1, M])
    u, v, w, px, py = (slice(a, b) for a, b in zip(edges[:-1], edges[1:]))
    xi_c, xi = m_c * np.pi / length, m_s * np.pi / length
    eta = n / radius
    s = 1.0 if kinematics == "sanders" else 0.0
    Bs = np.zeros((10, m.size), dtype=complex)
    Bc = np.zeros((10, m.size), dtype=complex)
    Bs[_EPS_X, u] = -xi_c  # d/dx cos = -xi sin
    Bs[_EPS_Y, v], Bs[_EPS_Y, w] = 1j * eta, 1.0 / radius
    Bc[_GAMMA, u], Bc[_GAMMA, v] = 1j * eta, xi
    Bs[_KAPPA_X, px] = -xi_c
    Bs[_KAPPA_Y, py] = 1j * eta
    Bc[_KAPPA_XY, px], Bc[_KAPPA_XY, py] = 1j * eta, xi
    Bc[_KAPPA_XY, v], Bc[_KAPPA_XY, u] = s * 0.5 * xi / radius, -s * 0.5j * eta / radius
    Bc[_GAMMA_XZ, w], Bc[_GAMMA_XZ, px] = xi, 1.0
    Bs[_GAMMA_YZ, w], Bs[_GAMMA_YZ, py], Bs[_GAMMA_YZ, v] = 1j * eta, 1.0, -s / radius
    Bc[_BETA_X, w] = -xi
    Bs[_BETA_Y, w], Bs[_BETA_Y, v] = -1j * eta, s / radius
    return Bs, Bc, m


def shear_galerkin_matrices(
    laminate: Laminate, radius: float, length: float, n: int, n_terms: int, kinematics: Kinematics = "sanders"
) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """Ritz stiffness K [N m] and load matrix G per unit torque for harmonic n; K a = T G a.

    dofs (U_0..U_M, V_1..V_M, W_1..W_M, PHI_X_0..PHI_X_M, PHI_Y_1..PHI_Y_M), size 5M + 2.
    """
    Bs, Bc, m = _ritz_operators(radius, length, n, n_terms, kinematics)
    return assemble_ritz(Bs, Bc, m, shell_stiffness(laminate, "shear"), radius, length)


def shear_buckling(
    laminate: Laminate, radius: float, length: float, kinematics: Kinematics, n_terms: int | None, n_max: int | None
) -> dict:
    """Search of the module docstring, both senses.

    Returns a dict with ``"n_terms"`` (largest M used), ``"crimping"`` (T+, T-), and per sense key
    ``True`` (positive) / ``False`` (negative): ``{"torque", "n", "mode", "half_waves",
    "governing", "global_torque", "global_n"}`` (``global_n`` None when the torque falls with n
    all the way to n_max: no global minimum).
    """
    if n_max is None:
        n_max = max(int(np.floor(np.pi * radius / laminate.thickness)), 12)
    crimping = crimping_torques(laminate, radius)
    n_all = np.arange(2, n_max + 1)
    # grid minima over k for every n: an upper estimate of the endless tube's minimum (within ~2 %;
    # the screen allows 5 %), refined on first use for every n at once
    helix_torques = _helix_function(laminate, radius, kinematics)
    grid = helix_grid(helix_torques, radius, n_all, _LOG_K_OFFSETS)
    coarse, wavenumbers = helix_minima(helix_torques, radius, n_all, _LOG_K_OFFSETS, refine=False, grid=grid)
    curve: dict[int, tuple[float, float]] = {}  # n -> (T+, T-) [N m]
    used_terms: dict[int, int] = {}  # n -> M, for the n solved by Ritz
    refined: list[NDArray[np.float64]] = []

    def helix(n: int) -> NDArray[np.float64]:
        """Refined endless-tube torques (T+, T-) at n; refines the wavenumbers too."""
        if not refined:
            torques, wavenumbers[:] = helix_minima(helix_torques, radius, n_all, _LOG_K_OFFSETS, grid=grid)
            refined.append(torques)
        return refined[0][n - 2]

    C = shell_stiffness(laminate, "shear")

    @functools.lru_cache(maxsize=2)  # the governing n's matrices again for its mode, both senses
    def ritz(n: int, M: int) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.complex128]]:
        """K, G in the real basis and its phases (:func:`~flexshaft.buckling.classical.real_ritz`)."""
        Bs, Bc, m = _ritz_operators(radius, length, n, M, kinematics)
        return real_ritz(Bs, Bc, m, C, radius, length, _FIELD_PHASES)

    def terms(n: int) -> int:
        if n_terms is not None:
            return int(n_terms)
        return default_terms(float(np.max(np.abs(wavenumbers[n - 2]))), length)

    def solve(n: int) -> tuple[float, float]:
        """Ritz torques at n; the infinite-tube values where the tube holds too many half-waves."""
        if n not in curve:
            M = terms(n)
            if M <= _MAX_RITZ_TERMS or n_terms is not None:
                curve[n], used_terms[n] = extreme_torques(*ritz(n, M)[:2]), M
            else:
                curve[n] = (float(helix(n)[0]), float(helix(n)[1]))
        return curve[n]

    # 1. global helical branch: the first local minimum over n of each sense
    global_n: dict[int, int | None] = {0: None, 1: None}
    falling = {0: True, 1: True}
    last = 2
    for n in map(int, n_all):
        solve(n)
        last = n
        for sense in (0, 1):
            if falling[sense] and n > 2 and curve[n][sense] > curve[n - 1][sense]:
                global_n[sense], falling[sense] = n - 1, False
        if not any(falling.values()):
            break
    best = {}
    for sense in (0, 1):
        n_global = global_n[sense]
        T_global = np.inf if n_global is None else curve[n_global][sense]
        best[sense] = (
            (T_global, n_global, "global") if T_global <= crimping[sense] else (crimping[sense], None, "crimp")
        )
        # n above this sense's first minimum already solved while the other sense still fell (or,
        # for a sense still falling at n_max, every n solved): short-wave candidates too (the
        # loop below starts after them)
        for n in range(2 if n_global is None else n_global + 1, last + 1):
            if curve[n][sense] < best[sense][0]:
                best[sense] = (curve[n][sense], n, "short")

    # 2. short-wave branch: n above the global branch whose infinite-tube lower bound is lower
    for n in range(last + 1, n_max + 1):
        candidates = [s for s in (0, 1) if coarse[n - 2, s] < 1.05 * best[s][0]]
        if not candidates or not any(helix(n)[s] < best[s][0] for s in candidates):
            continue
        solve(n)
        for s in candidates:
            if curve[n][s] < best[s][0]:
                best[s] = (curve[n][s], n, "short")

    out: dict = {"crimping": crimping, "n_terms": max(used_terms.values(), default=0)}
    for sense, positive in ((0, True), (1, False)):
        torque, n_best, branch = best[sense]
        mode, half_waves = np.full(1, np.nan, dtype=complex), None
        if n_best in used_terms and np.isfinite(torque):
            M = used_terms[n_best]
            K, G, phases = ritz(n_best, M)
            mode = ritz_mode(K, G, torque if positive else -torque, slice(2 * M + 1, 3 * M + 1), phases)
            half_waves = int(np.argmax(np.abs(mode))) + 1
        elif n_best is not None:
            half_waves = int(round(abs(wavenumbers[n_best - 2, sense]) * length / np.pi))
        n_global = global_n[sense]
        out[positive] = {
            "torque": float(torque),
            "n": n_best,
            "mode": mode,
            "half_waves": half_waves,
            "governing": "global helical" if branch == "global" else "shear crimping",
            "global_torque": np.inf if n_global is None else float(curve[n_global][sense]),
            "global_n": n_global,
        }
    return out

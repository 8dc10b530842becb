"""Critical torsional buckling torque of a simply supported laminated tube: the public entry point."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from flexshaft.buckling._common import Kinematics, ShellTheory, check_inputs
from flexshaft.buckling.classical import classical_buckling, classical_galerkin_matrices, classical_helix_torque
from flexshaft.buckling.shear import shear_buckling, shear_galerkin_matrices, shear_helix_torque
from flexshaft.laminate import Laminate

__all__ = [
    "BucklingResult",
    "galerkin_matrices",
    "infinite_cylinder_torque",
    "torsional_buckling_torque",
    "buckling_safety_factor",
]


@dataclass(frozen=True, eq=False)
class BucklingResult:
    """Critical torques of a simply supported laminated tube, both senses.

    Attributes
    ----------
    torque_positive, torque_negative : float
        Critical torque magnitude [N m] for the positive sense (the one that puts +45 deg fibres
        in tension) and the negative sense.
    n_positive, n_negative : int or None
        Circumferential wave numbers of the critical modes; None when the shear-crimping limit
        (n -> infinity) governs.
    axial_half_waves_positive, axial_half_waves_negative : int or None
        Axial wave parameter: index m of the largest sine term of w in the critical mode
        (the helix has about m half-waves along L; from the infinite-tube wavenumber, |k| L/pi,
        where that solution was used); None for the crimping limit.
    mode_positive, mode_negative : ndarray, complex
        Ritz coefficients W_1..W_M of w, normalised to max |W_m| = 1; the mode is
        w = Re(sum_m W_m sin(m pi x/L) e^{i n theta}); NaN for the crimping limit.
    governing_positive, governing_negative : str
        ``"global helical"`` (the first local minimum over n, the long-wave helix) or
        ``"shear crimping"`` (a shorter-wave mode set by the transverse shear stiffness, or its
        limit T_crimp); see :mod:`flexshaft.buckling.shear`.
    global_torque_positive, global_torque_negative : float
        Torque of the global helical mode [N m] (equal to the critical torque when it governs).
    global_n_positive, global_n_negative : int or None
        Its circumferential wave number (None, with an infinite torque, when the torque keeps
        falling with n up to n_max: no long-wave minimum).
    crimping_torque_positive, crimping_torque_negative : float
        Shear-crimping limit 2 pi R^2 (sqrt(A44 A55) -/+ A45) [N m]; inf for the classical shell.
    n_terms : int
        Number of axial terms M used (the largest, for the shear theory).
    theory : str
        ``"shear"`` (first-order shear deformation) or ``"classical"`` (Kirchhoff-Love).
    kinematics : str
        ``"sanders"`` or ``"donnell"``.
    radius, length : float
        Mid-surface radius and length between the supports [m].
    """

    torque_positive: float
    torque_negative: float
    n_positive: int | None
    n_negative: int | None
    axial_half_waves_positive: int | None
    axial_half_waves_negative: int | None
    mode_positive: NDArray[np.complex128]
    mode_negative: NDArray[np.complex128]
    governing_positive: str
    governing_negative: str
    global_torque_positive: float
    global_torque_negative: float
    global_n_positive: int | None
    global_n_negative: int | None
    crimping_torque_positive: float
    crimping_torque_negative: float
    n_terms: int
    theory: str
    kinematics: str
    radius: float
    length: float

    @property
    def critical_torque(self) -> float:
        """The lower of the two senses [N m]."""
        return min(self.torque_positive, self.torque_negative)

    @property
    def governing(self) -> str:
        """Governing mode of the weaker sense (``"global helical"`` or ``"shear crimping"``)."""
        return self.governing_positive if self.torque_positive <= self.torque_negative else self.governing_negative

    @property
    def critical_n(self) -> int | None:
        """Circumferential wave number of the weaker sense (None: crimping limit)."""
        return self.n_positive if self.torque_positive <= self.torque_negative else self.n_negative

    @property
    def crimping_torque(self) -> float:
        """The lower shear-crimping limit of the two senses [N m]."""
        return min(self.crimping_torque_positive, self.crimping_torque_negative)

    @property
    def global_torque(self) -> float:
        """The lower global-helical torque of the two senses [N m]."""
        return min(self.global_torque_positive, self.global_torque_negative)


def _half_waves(mode: NDArray[np.complex128]) -> int | None:
    return None if not np.all(np.isfinite(mode)) else int(np.argmax(np.abs(mode))) + 1


def torsional_buckling_torque(
    laminate: Laminate,
    radius: float,
    length: float,
    *,
    theory: ShellTheory = "shear",
    kinematics: Kinematics = "sanders",
    n_terms: int | None = None,
    n_max: int | None = None,
) -> BucklingResult:
    """Critical torsional buckling torque of a simply supported laminated tube, both senses.

    Parameters
    ----------
    laminate : Laminate
        Wall laminate; the storage parts of A, B, D (and of G_13, G_23 for the shear theory).
    radius : float
        Mid-surface radius [m] (for a shaft, (D_o - t)/2).
    length : float
        Length between the simple supports [m].
    theory : {"shear", "classical"}
        First-order shear-deformable shell (default; :mod:`flexshaft.buckling.shear`) or the
        classical Kirchhoff-Love shell (:mod:`flexshaft.buckling.classical`).
    kinematics : {"sanders", "donnell"}
        Kinematic relations.
    n_terms : int, optional
        Number of axial terms M; default from the infinite-tube helix wavenumber.
    n_max : int, optional
        Largest circumferential wave number tried [-]; default 200 (classical) or the n at which
        the half-wavelength pi R/n reaches the wall thickness (shear; at least 12).

    Returns
    -------
    BucklingResult
    """
    check_inputs(radius, theory, kinematics, length)
    if n_terms is not None and int(n_terms) < 1:
        raise ValueError(f"n_terms must be >= 1, got {n_terms!r}")
    if n_max is not None and int(n_max) < 2:
        raise ValueError(f"n_max must be >= 2, got {n_max!r}")
    if theory == "classical":
        found = classical_buckling(laminate, radius, length, kinematics, n_terms, 200 if n_max is None else int(n_max))
        senses = {
            positive: {
                "torque": torque,
                "n": n,
                "mode": mode,
                "half_waves": _half_waves(mode),
                "governing": "global helical",
                "global_torque": torque,
                "global_n": n,
            }
            for positive, (torque, n, mode) in ((p, found[p]) for p in (True, False))
        }
        crimping = (np.inf, np.inf)
    else:
        found = shear_buckling(laminate, radius, length, kinematics, n_terms, n_max)
        senses = {positive: found[positive] for positive in (True, False)}
        crimping = found["crimping"]
    plus, minus = senses[True], senses[False]
    return BucklingResult(
        torque_positive=plus["torque"],
        torque_negative=minus["torque"],
        n_positive=plus["n"],
        n_negative=minus["n"],
        axial_half_waves_positive=plus["half_waves"],
        axial_half_waves_negative=minus["half_waves"],
        mode_positive=plus["mode"],
        mode_negative=minus["mode"],
        governing_positive=plus["governing"],
        governing_negative=minus["governing"],
        global_torque_positive=plus["global_torque"],
        global_torque_negative=minus["global_torque"],
        global_n_positive=plus["global_n"],
        global_n_negative=minus["global_n"],
        crimping_torque_positive=float(crimping[0]),
        crimping_torque_negative=float(crimping[1]),
        n_terms=found["n_terms"],
        theory=theory,
        kinematics=kinematics,
        radius=float(radius),
        length=float(length),
    )


def infinite_cylinder_torque(
    laminate: Laminate,
    radius: float,
    *,
    theory: ShellTheory = "shear",
    kinematics: Kinematics = "sanders",
    n_max: int = 40,
) -> dict[str, tuple[float, int, float]]:
    """Critical torques of an infinitely long tube, minimised over 2 <= n <= n_max and axial wavenumber.

    The exact solution for L -> infinity (no end conditions): a single harmonic
    exp(i(k x + n theta)). ``radius`` [m] is the mid-surface radius. For the shear theory the
    minimum over all n is the crimping limit (n -> infinity); this returns the minimum up to n_max.

    Returns
    -------
    dict
        ``{"positive": (T, n, k), "negative": (|T|, n, k)}`` with T [N m], n the circumferential
        wave number and k the signed axial wavenumber [rad/m] of the critical helix.
    """
    check_inputs(radius, theory, kinematics)
    if theory == "classical":
        return classical_helix_torque(laminate, radius, kinematics, n_max)
    return shear_helix_torque(laminate, radius, kinematics, n_max)


def galerkin_matrices(
    laminate: Laminate,
    radius: float,
    length: float,
    n: int,
    n_terms: int,
    *,
    theory: ShellTheory = "shear",
    kinematics: Kinematics = "sanders",
) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """Ritz stiffness K [N m] and load matrix G per unit torque for harmonic n; buckling: K a = T G a.

    ``radius`` [m] is the mid-surface radius, ``length`` [m] the span between the simple supports,
    ``n`` >= 2 the circumferential wave number and ``n_terms`` = M the number of axial terms.
    Classical dofs (U_0..U_M, V_1..V_M, W_1..W_M); shear dofs add PHI_X_0..PHI_X_M, PHI_Y_1..PHI_Y_M.
    Both matrices are complex Hermitian, K positive definite.
    """
    check_inputs(radius, theory, kinematics, length)
    if theory == "classical":
        return classical_galerkin_matrices(laminate, radius, length, n, n_terms, kinematics)
    return shear_galerkin_matrices(laminate, radius, length, n, n_terms, kinematics)


def buckling_safety_factor(result: BucklingResult, torque: ArrayLike, *, signed: bool = False) -> NDArray[np.float64]:
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

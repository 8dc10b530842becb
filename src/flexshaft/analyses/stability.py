"""Whirl stability with internal (rotating) damping (thesis chapter 4, rebuilt).

The damped eigenvalues are tracked over speed exactly as in the Campbell diagram
(:mod:`flexshaft.analyses.campbell`), with the model's internal-damping model applied to every
mode at its own frequency (:mod:`flexshaft.analyses.loss`):

* ``method="hysteretic"`` (default): the exact hysteretic law. With ``internal_damping =
  "rotating"`` the shaft's lateral loss follows the whirl relative to the spin, so above a
  forward mode's frequency it becomes the circulatory stiffness ``K''_lat S`` that drives the
  mode unstable unless the fixed-frame damping (tailboom, bearings, actuators) outweighs it.
  With ``"thesis"`` (fixed-frame complex stiffness) the loss never destabilises.
* ``method="viscous"``: the thesis's own chapter-4 model: the shaft's loss as a viscous
  damping ``C_i = K''/ω_ref`` in the rotating frame at one reference frequency for every mode,
  i.e. ``C_i`` plus the circulatory ``Ω C_i S`` in the fixed frame (Zorzi & Nelson 1977), the
  boom's loss as ``K''_boom/ω_ref``.

The hysteretic eigenvalues. The loss weights depend on a mode s only through the side of the
synchronous line, σ = sgn(Im s − Ω), so the eigenproblem is linear on each side and its
eigenvalues are exactly the roots of the "above" problem with Im s ≥ Ω and of the "below"
problem with 0 < Im s ≤ Ω (:mod:`flexshaft.analyses.hysteretic_roots`, which derives this and
the Jeffcott rotor's closed form). Each tracked mode continues both sides' roots and keeps
the one consistent with its side; a mode with two consistent roots (a fold within O(η²)ω of
its synchronous crossing) reports the less stable, one with none the root on the line. So the
verdict is a property of the eigenvalue set, never of which root an iteration reached first:
it does not change with the BLAS kernels' round-off.

The onset speed is the first crossing of Re(s) from stable to unstable, counting a mode as
unstable only when its damping ratio is below ``−`` :data:`STABILITY_TOLERANCE` (round-off of
an undamped mode is ~1e-13); the crossing found on the speed grid is then solved for the
speed where that mode's damping ratio changes sign (regula falsi, each evaluation the mode
followed back from its first unstable speed): a zero crossing, or with the rotating-frame loss
the jump where the mode's consistent root passes from one side of the line to the other (the
hysteretic Jeffcott rotor: Ω = ω_d). Once the grid brackets a crossing, the onset does not
depend on the grid spacing as long as the mode can be followed across the bracket: where the
root at a trial speed is not the mode of the bracket's unstable end (a wide bracket on an
anisotropic rotor, whose whirl changes shape with speed), the mode is followed down the bracket
in sub-steps (down to 1/1024 of it) and the crossing solved in the sub-step where it changes
sign; only a mode lost even then falls back to the linear interpolation of the grid's damping
ratios, which does depend on the grid. A window of instability that opens and closes between
two grid speeds, both stable, is not seen (the coarse baseline on ``flexshaft stability
--max-rpm 1e5 --n-speeds 2``: stable at 0 and 1e5 rpm, unstable from 3126 rpm to below 1e5):
the grid must resolve the speeds of interest (``--n-speeds``; the verdict's whirl speeds,
:class:`~flexshaft.resolution.Resolution`).

Divergence. A real eigenvalue s > 0 (an aperiodic instability: e.g. a magnetic bearing whose
negative stiffness k_s exceeds its control stiffness, or C = 0) is no oscillatory mode and is
not tracked; at every speed the state matrix is also searched for such roots
(:func:`~flexshaft.analyses.eigen.divergent_roots`). The largest is reported per speed as
:attr:`StabilityResult.divergence` [1/s] and the first divergent speed counts as an onset
(``onset_kind = "divergence"``), never silently dropped.

References
----------
Zorzi, E. S., Nelson, H. D. (1977). Finite element simulation of rotor-bearing systems with
internal damping. J. Eng. Power 99, 71-76.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Literal

import numpy as np

from flexshaft.analyses.campbell import EigenvalueCurves, TrackedModes, check_speeds, default_basis_size, track_modes
from flexshaft.analyses.continuation import mode_root
from flexshaft.analyses.datasets import curves_dataset
from flexshaft.analyses.eigen import ReducedModel, newton, reduce, spectrum
from flexshaft.analyses.eigen_error import (
    EIGENVALUE_TOLERANCE,
    accuracy_text,
    check_tolerance,
    tracked_to_accuracy,
    with_error_estimate,
)
from flexshaft.analyses.guards import (
    RefusedInputError,
    check_count,
    check_finite_array,
    check_model,
    check_speed,
    require_finite,
)
from flexshaft.analyses.loss import viscous_equivalent
from flexshaft.analyses.results import ResultMixin, html_table
from flexshaft.assembly.model import Model
from flexshaft.assembly.model import rotation_generator as _rotation_generator
from flexshaft.parallel.threads import single_blas_thread
from flexshaft.plot.stability import log_decrement_figure, real_parts_figure
from flexshaft.units import hz_to_rpm, rad_s_to_rpm, rpm_to_rad_s

__all__ = [
    "DampingModel",
    "LOWEST_REFERENCE_FREQUENCY",
    "STABILITY_TOLERANCE",
    "StabilityResult",
    "rotation_generator",
    "stability",
    "onset_speed",
]

DampingModel = Literal["hysteretic", "viscous"]
#: A mode is unstable when its damping ratio ζ = −Re(s)/|s| is below −STABILITY_TOLERANCE.
STABILITY_TOLERANCE = 1e-9

#: Lowest reference frequency ω_ref of the viscous model [rad/s] (0.001 Hz): its damping
#: η K/ω_ref grows as 1/ω_ref, and far below any natural frequency it overflows the
#: eigen-solution (1e-300 rad/s ended in LAPACK's "illegal value"); 0.001 Hz runs on the
#: embedded designs. ``flexshaft stability --reference-hz`` holds the same floor in Hz, converted
#: the way the command converts its value (0.001 Hz through rpm), so 0.001 Hz itself is taken.
LOWEST_REFERENCE_FREQUENCY = rpm_to_rad_s(hz_to_rpm(1e-3))


def rotation_generator(model: Model):
    """S of the model's DOF map (see :func:`flexshaft.assembly.model.rotation_generator`)."""
    return _rotation_generator(model.dofs)


@dataclass(frozen=True)
class StabilityResult(EigenvalueCurves, ResultMixin):
    """Tracked eigenvalues over speed with the onset of instability.

    Attributes
    ----------
    speeds : ndarray
        Ω [rad/s].
    eigenvalues : ndarray
        (n_speeds, n_modes) s [rad/s]; Re(s) > 0 is unstable.
    whirl : ndarray of str
        Whirl label per point ("none" for torsional and axial modes).
    damping_model : str
        "hysteretic" or "viscous" (the method).
    onset_speed : float or None
        Lowest speed where a tracked mode turns unstable [rad/s] (None: stable throughout).
    unstable_mode : int or None
        Tracked index of that mode (None for a divergence).
    onset_shape : ndarray or None
        Its shape (full DOF vector) at the first unstable speed.
    kind : ndarray of str
        Mode kind per point.
    internal_damping : str
        The model's internal-damping model.
    reference_frequency : float or None
        ω_ref of the viscous method [rad/s].
    divergence : ndarray or None
        Largest real unstable root per speed [1/s] (0 where there is none), (n_speeds,).
    onset_kind : {"oscillatory", "divergence"} or None
        Whether the onset is a tracked mode with Re(s) > 0 or a real root (None: stable).
    error_estimate : ndarray or None
        Estimated relative error |s* − s|/|s| of each tracked eigenvalue against the full
        (unreduced) eigenproblem, (n_speeds, n_modes) (:mod:`flexshaft.analyses.eigen_error`).
    tolerance : float or None
        The accuracy the basis was chosen for (None: a basis given by the caller).
    basis_size : int or None
        Number of basis vectors used.
    """

    speeds: np.ndarray
    eigenvalues: np.ndarray
    whirl: np.ndarray
    damping_model: str
    onset_speed: float | None
    unstable_mode: int | None
    onset_shape: np.ndarray | None
    kind: np.ndarray | None = None
    internal_damping: str = "rotating"
    reference_frequency: float | None = None
    divergence: np.ndarray | None = None
    onset_kind: str | None = None
    error_estimate: np.ndarray | None = None
    tolerance: float | None = None
    basis_size: int | None = None

    plots = {"log_decrement": "plot_log_decrement", "real_part": "plot_real_parts"}

    def __repr__(self) -> str:
        top = rad_s_to_rpm(self.speeds[-1])
        onset = "stable" if self.onset_speed is None else f"onset {rad_s_to_rpm(self.onset_speed):.0f} rpm"
        if self.onset_kind == "divergence":
            onset += " (divergence)"
        return (
            f"StabilityResult({onset} up to {top:.0f} rpm, {self.eigenvalues.shape[1]} modes, "
            f"{self.damping_model} method, internal damping {self.internal_damping!r}{accuracy_text(self)})"
        )

    def _repr_html_(self) -> str:
        return html_table(self.SUMMARY_COLUMNS, self.mode_summary(), title=repr(self))

    def to_dataset(self):
        """Tracked eigenvalues over speed with the onset speed (xarray)."""

        attrs = {"method": self.damping_model, "onset_kind": getattr(self, "onset_kind", "whirl") or "none"}
        if self.onset_speed is not None:
            attrs.update(onset_speed=float(self.onset_speed), onset_speed_units="rad/s")
        if self.unstable_mode is not None:  # None at a divergence (a real root, no tracked mode)
            attrs.update(unstable_mode=int(self.unstable_mode) + 1)
        if self.reference_frequency is not None:
            attrs.update(reference_frequency=float(self.reference_frequency), reference_frequency_units="rad/s")
        return with_error_estimate(curves_dataset(self, "whirl stability", **attrs), self)

    @property
    def stability_margin(self) -> np.ndarray:
        """Smallest damping ratio over the tracked modes at each speed (negative: unstable;
        −1 where a divergent real root exists)."""
        margin = self.damping_ratios.min(axis=1)
        if self.divergence is not None:
            margin = np.where(self.divergence > 0, -1.0, margin)
        return margin

    @property
    def divergent(self) -> bool:
        """True when a real unstable root exists at some analysed speed."""
        return self.divergence is not None and bool(np.any(self.divergence > 0))

    def onset_description(self) -> str | None:
        """E.g. "mode 6, forward whirl" or "divergence" (None when stable)."""
        if self.onset_speed is None:
            return None
        if self.onset_kind == "divergence" or self.unstable_mode is None:
            return "divergence (real root)"
        return f"mode {self.unstable_mode + 1}, {self.onset_whirl} whirl"

    @property
    def onset_whirl(self) -> str | None:
        """Whirl of the mode that turns unstable ("forward", "backward", ...) at the first
        analysed speed at or above the onset, where it is first unstable (the speed of
        ``onset_shape``); None when stable or at a divergence. The one label the report, the
        verdict and results.json give."""
        if self.onset_speed is None or self.onset_kind == "divergence" or self.unstable_mode is None:
            return None
        k = self.at_speed(self.onset_speed)
        k = min(k + 1, self.speeds.size - 1) if self.speeds[k] < self.onset_speed else k
        return str(self.whirl[k, self.unstable_mode])

    def plot_log_decrement(self, ax=None, *, label: str = "this design", **kwargs):
        """Log decrement of every tracked mode against speed [rpm], the onset marked. Keywords
        (``operating_rpm``, ``required``) go to :func:`flexshaft.plot.stability.log_decrement_figure`."""

        onset = None if self.onset_speed is None else rad_s_to_rpm(self.onset_speed)
        text = self.onset_description()
        return log_decrement_figure(
            rad_s_to_rpm(self.speeds),
            {label: self.log_decrements},
            {label: onset},
            ax=ax,
            onset_text={label: text} if text else None,
            whirl={label: self.whirl},
            **kwargs,
        )

    def plot_real_parts(self, ax=None, *, label: str = "this design", **kwargs):
        """Re(s) of every tracked mode against speed [rpm] (thesis figures 4.2-4.4), onset marked."""

        onset = None if self.onset_speed is None else rad_s_to_rpm(self.onset_speed)
        return real_parts_figure(
            rad_s_to_rpm(self.speeds), {label: self.real_parts}, onset_rpm={label: onset}, ax=ax, **kwargs
        )

    def at_speed(self, speed: float) -> int:
        """Index of the analysed speed nearest ``speed`` [rad/s]."""
        return int(np.argmin(np.abs(self.speeds - speed)))


def onset_speed(
    speeds, eigenvalues, tolerance: float = STABILITY_TOLERANCE
) -> tuple[float | None, int | None, int | None]:
    """First crossing into instability: ``(speed, mode, index of the first unstable speed)``.

    A point is unstable when ζ = −Re(s)/|s| < −``tolerance``; the crossing speed is
    interpolated linearly in ζ between the last stable and the first unstable speed.
    """
    speeds = check_finite_array("speeds", speeds, "rad/s")
    eigenvalues = check_finite_array("eigenvalues", eigenvalues, "rad/s")
    if eigenvalues.ndim != 2 or eigenvalues.shape[0] != speeds.size:
        raise ValueError(f"eigenvalues must be (speeds, modes) = ({speeds.size}, n) (got {eigenvalues.shape})")
    if not (np.isfinite(tolerance) and tolerance >= 0):
        raise ValueError(f"tolerance must be a finite number >= 0 (got {tolerance!r})")
    with np.errstate(invalid="ignore", divide="ignore"):  # s = 0 (a rigid-body root) has ζ = NaN: never unstable
        zeta = -eigenvalues.real / np.abs(eigenvalues)
    best: tuple[float | None, int | None, int | None] = (None, None, None)
    for m in range(zeta.shape[1]):
        pos = np.flatnonzero(zeta[:, m] < -tolerance)
        if pos.size == 0:
            continue
        k = pos[0]
        if k == 0:
            crossing = float(speeds[0])
        else:
            a, b = zeta[k - 1, m], zeta[k, m]
            t = a / (a - b) if a != b else 1.0
            crossing = float(speeds[k - 1] + np.clip(t, 0.0, 1.0) * (speeds[k] - speeds[k - 1]))
        if best[0] is None or crossing < best[0]:
            best = (crossing, m, int(k))
    return best


@single_blas_thread
def stability(
    model: Model,
    speeds,
    n_modes: int = 12,
    damping_model: DampingModel = "hysteretic",
    reference_frequency: float | None = None,
    basis_size: int | None = None,
    reduced: ReducedModel | None = None,
    tolerance: float = EIGENVALUE_TOLERANCE,
    estimate: bool = True,
) -> StabilityResult:
    """Eigenvalues of the linearised driveline with internal damping over speed.

    Parameters
    ----------
    speeds : array_like
        Ω [rad/s], increasing.
    n_modes : int
        Tracked modes.
    damping_model : {"hysteretic", "viscous"}
        The method (module docstring).
    reference_frequency : float or None
        ω_ref [rad/s] of the viscous method; default: the lowest basis frequency whose mode is
        more than 50 % shaft (the first shaft bending mode at rest).
    basis_size : int or None
        A plain modal basis of this size (default: the enriched basis chosen for ``tolerance``).
    reduced : ReducedModel or None
        A precomputed reduction of ``model`` to reuse (e.g. across derivative gains).
    tolerance : float
        Relative eigenvalue accuracy against the full (unreduced) eigenproblem the basis is
        chosen for when neither ``basis_size`` nor ``reduced`` is given
        (:func:`~flexshaft.analyses.eigen_error.tracked_to_accuracy`); the estimate reached is
        :attr:`StabilityResult.error_estimate`.
    estimate : bool
        With ``basis_size`` or ``reduced`` given: estimate the eigenvalues' errors (default), or
        not (``error_estimate`` None: e.g. :func:`flexshaft.thesis.whirl.gain_stability_map`,
        which keeps only the onset and the margin at the operating speed of each grid point and
        never reported an estimate). The basis chosen for ``tolerance`` is always estimated.
    """
    check_model(model)
    speeds = check_speeds(speeds)
    n_modes = check_count(n_modes, "n_modes")
    if damping_model not in ("hysteretic", "viscous"):
        raise ValueError(f"damping_model must be 'hysteretic' or 'viscous', got {damping_model!r}")
    if reference_frequency is not None:
        reference_frequency = check_speed(reference_frequency, "reference_frequency", positive=True)
        if reference_frequency < LOWEST_REFERENCE_FREQUENCY:
            raise RefusedInputError(
                f"reference_frequency must be >= {LOWEST_REFERENCE_FREQUENCY:.6g} rad/s (0.001 Hz): the viscous "
                f"model's damping η K/ω_ref grows as 1/ω_ref and overflows far below any natural frequency "
                f"(got {reference_frequency!r})"
            )
    if basis_size is not None:
        basis_size = check_count(basis_size, "basis_size")
    tolerance = check_tolerance(tolerance)
    ref = None
    weights = None  # the viscous method's loss weights at a speed (None: hysteretic)
    if damping_model == "viscous":
        if reference_frequency is not None:
            ref = float(reference_frequency)
        else:  # on the basis the caller gave, else on the plain default one
            ref = _first_shaft_frequency(model, reduced or reduce(model, basis_size or _plain_basis(n_modes)))
        weights = functools.partial(viscous_equivalent, ref)

    def track(red: ReducedModel, at: np.ndarray, start: TrackedModes | None) -> TrackedModes:
        if weights is not None:
            return track_modes(model, red, at, int(n_modes), refine_loss=False, viscous=weights, start=start)
        return track_modes(model, red, at, int(n_modes), start=start)

    red, tracked, errors = tracked_to_accuracy(
        model, speeds, int(n_modes), track, basis_size, tolerance, viscous=weights, reduced=reduced, estimate=estimate
    )
    eig = tracked.eigenvalues
    require_finite("stability eigenvalues", eig)
    onset, mode, k = onset_speed(speeds, eig)
    shape = None
    if onset is not None and mode is not None and k is not None:  # the three are set together
        if k > 0:
            onset = _refine_onset(red, speeds, tracked, mode, k, weights)
        shape = model.dofs.expand(red.shapes(tracked.states[k][:, mode]))
    kind = None if onset is None else "oscillatory"
    divergence = np.zeros(speeds.size)
    first = None
    for i, speed in enumerate(speeds if red.may_diverge else ()):
        viscous = weights(speed) if weights is not None else None
        _, _, Y_div, roots = spectrum(red, speed, viscous) if viscous is not None else spectrum(red, speed)
        if roots.size:
            divergence[i] = roots[0]
            if first is None:
                first = (i, Y_div[:, 0])
    if first is not None and (onset is None or speeds[first[0]] <= onset):
        onset, mode, kind = float(speeds[first[0]]), None, "divergence"
        shape = model.dofs.expand(red.shapes(first[1]))
    return StabilityResult(
        speeds,
        eig,
        tracked.whirl,
        damping_model,
        onset,
        mode,
        shape,
        tracked.kind,
        model.internal_damping,
        ref,
        divergence,
        kind,
        errors,
        None if basis_size is not None or reduced is not None else tolerance,
        red.size,
    )


def _plain_basis(n_modes: int) -> int:
    """The plain modal basis of earlier versions (the viscous method's reference frequency)."""
    return max(default_basis_size(n_modes), 48)


def _refine_onset(red: ReducedModel, speeds, tracked, mode: int, k: int, viscous) -> float:
    """Speed where the tracked ``mode``'s damping ratio crosses zero between speeds[k−1] and
    speeds[k] (Illinois regula falsi; converged to 1e-7 of the speed). Each evaluation follows
    the mode back from its unstable end, speeds[k], whose shape identifies it (MAC ≥ 0.8,
    :func:`_mode_at`): Newton's method on the viscous problem, or with the hysteretic loss the
    mode's consistent root (:func:`~flexshaft.analyses.continuation.mode_root`, both sides of
    the synchronous line). Where the root jumps between the two sides (the hysteretic Jeffcott rotor: stable
    just below the forward frequency, unstable just above), the bracket closes on the jump.

    When an evaluation cannot follow the mode from the bracket's end (on a wide bracket the
    mode's shape at the trial speed can differ too much from the end's to identify it: the
    anisotropic overhung rotor of tests/test_onset_wide_bracket_reference.py on [0, 4000]
    rad/s, overlap 0.66 < 0.8; hysteretic, tests/test_onset_refinement_anisotropic_reference.py
    on [0, 8000]), the mode is followed from speeds[k] down to speeds[k−1] in
    sub-steps (:func:`_follow_down`, each root seeded by and checked against the last) and the
    regula falsi is solved again in the lowest sub-step where its damping ratio changes sign.
    Only when that fails too (no sub-step of 1/1024 of the bracket follows the mode, or the mode
    followed down is already unstable at speeds[k−1]) is the result the first regula falsi's:
    the linear interpolation of the grid's damping ratios, or its last trial speed."""
    a, b = float(speeds[k - 1]), float(speeds[k])
    sa, sb = tracked.eigenvalues[k - 1, mode], tracked.eigenvalues[k, mode]
    yb = tracked.states[k][:, mode]
    estimate, found = _regula_falsi(red, a, b, sa, sb, yb, viscous)
    if found:
        return estimate
    bracket = _follow_down(red, a, b, sb, yb, viscous)
    if bracket is None:
        return estimate
    return _regula_falsi(red, *bracket, viscous)[0]


def _zeta(s: complex) -> float:
    return -s.real / abs(s)


def _mode_at(red: ReducedModel, speed: float, guess: complex, y, viscous) -> tuple[complex, np.ndarray, bool]:
    """The root at ``speed`` of the mode with shape ``y``, from ``guess``: ``(s, y, found)``.

    Newton's method on the viscous problem, or the hysteretic mode's consistent root
    (:func:`~flexshaft.analyses.continuation.mode_root`); either counts as the mode only when
    its MAC with ``y`` is at least 0.8. ``mode_root``'s own test, MAC ≥ 0.25
    (:data:`~flexshaft.analyses.hysteretic_roots.SAME_MODE_MAC`), is too weak across a wide
    bracket: on the anisotropic rotor of tests/test_onset_refinement_anisotropic_reference.py
    the regula falsi on [0, 8000] rad/s took another mode's roots (MAC 0.43) and settled on a
    false jump, 428 rad/s instead of 322.1."""
    if viscous is None:
        s, vec, found = mode_root(red, speed, guess, y)
    else:
        s, vec, found = newton(red, speed, guess, y, viscous=viscous(speed))
    return s, vec, found and abs(np.vdot(y, vec)) ** 2 >= 0.8 * np.vdot(y, y).real * np.vdot(vec, vec).real


def _regula_falsi(red: ReducedModel, a: float, b: float, sa: complex, sb: complex, yb, viscous) -> tuple[float, bool]:
    """:func:`_refine_onset`'s regula falsi on [a, b] (stable at a, unstable at b with shape
    ``yb``): ``(speed, found)``, found False when a trial speed's root is not the mode (the
    speed is then the linear interpolation, or the last trial speed whose root was)."""
    a0, b0 = a, b
    za, zb = _zeta(sa), _zeta(sb)
    estimate = a + za / (za - zb) * (b - a) if za != zb else b
    side = 0
    for _ in range(80):
        c = a + za / (za - zb) * (b - a) if za != zb else 0.5 * (a + b)
        t = (c - a0) / (b0 - a0)
        guess = sa + t * (sb - sa)
        sc, _, found = _mode_at(red, c, guess, yb, viscous)
        if not found:
            return float(estimate), False
        zc = _zeta(sc)
        estimate = c
        if b - a <= 1e-7 * b or zc == 0.0:
            break
        if zc < 0:
            b, zb = c, zc
            if side == -1:
                za *= 0.5
            side = -1
        else:
            a, za = c, zc
            if side == +1:
                zb *= 0.5
            side = +1
    return float(estimate), True


#: Most evaluations :func:`_follow_down` makes (2 × 1024 + 7 in the worst case of exact steps).
_FOLLOW_EVALUATIONS = 2 * 1024 + 16


def _follow_down(
    red: ReducedModel, a: float, b: float, sb: complex, yb, viscous
) -> tuple[float, float, complex, complex, np.ndarray] | None:
    """The mode followed from its unstable end b down to a in sub-steps (first 1/8 of the
    bracket, halved where a step's root is not the last step's mode, doubled back after a
    success, at least 1/1024): the lowest sub-bracket ``(a', b', s(a'), s(b'), y(b'))`` where
    its damping ratio falls below −:data:`STABILITY_TOLERANCE`, or None (lost, unstable at a,
    or a bracket too narrow for a sub-step to move the speed).

    Cost: at most 1024 successful sub-steps (each at least 1/1024 of the bracket) and one
    failed step per success (the doubled step lost, then halved back) plus the seven halvings
    from 1/8 to 1/1024: ~2 × 1024 evaluations of :func:`_mode_at` in the worst case, and
    never more than :data:`_FOLLOW_EVALUATIONS` (rounding on a bracket of a few ulp)."""
    largest = (b - a) / 8
    step = largest
    speed, s, y = b, sb, yb
    path = [(speed, s, y)]
    evaluations = 0
    while speed > a:
        below = max(speed - step, a)
        if below >= speed or evaluations >= _FOLLOW_EVALUATIONS:  # speed − step rounds to speed
            return None
        evaluations += 1
        s_new, y_new, found = _mode_at(red, below, s, y, viscous)
        if not found:
            step *= 0.5
            if step < (b - a) / 1024:
                return None
            continue
        speed, s, y = below, s_new, y_new
        path.append((speed, s, y))
        step = min(2 * step, largest)
    path.reverse()  # increasing speed, path[0] at a
    unstable = [i for i, (_, s, _) in enumerate(path) if _zeta(s) < -STABILITY_TOLERANCE]
    if unstable[0] == 0:
        return None
    (lo, s_lo, _), (hi, s_hi, y_hi) = path[unstable[0] - 1], path[unstable[0]]
    return lo, hi, s_lo, s_hi, y_hi


def _first_shaft_frequency(model: Model, red: ReducedModel) -> float:
    ns = 6 * model.dofs.n_shaft_nodes
    Phi_full = model.dofs.expand(red.Phi)
    Mphi = model.M @ Phi_full
    shaft = np.einsum("ij,ij->j", Phi_full[:ns], Mphi[:ns]) / np.einsum("ij,ij->j", Phi_full, Mphi)
    k = np.flatnonzero(shaft > 0.5)
    return float(np.sqrt(red.w2[k[0] if k.size else 0]))

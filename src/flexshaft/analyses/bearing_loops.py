r"""Robustness of the magnetic-bearing loops: sensitivity peak, gain and phase margins.

One loop is one control axis (v or w) of one active bearing. Its open loop, broken at the
controller, is ``L(s) = G(s) P(s)``: the feedback law ``G = k_i A(s) C(s)`` (controller, amplifier
lag, current gain; :class:`~flexshaft.assembly.model.Actuator`) times the plant P, the
displacement at the loop's sensor per unit force of its magnet, of the rotor-boom structure with
every *other* loop closed and this magnet's negative stiffness k_s in place (ISO 14839-3
measures each axis with the other loops closed). The sensitivity function is ``S = 1/(1 + L)``
and the complementary sensitivity ``T = L/(1 + L) = 1 − S``.

No loop is opened to compute it. With every loop closed the dynamic stiffness is
``Z_c = Z_o + G a sᵀ`` (a, s the loop's actuation and sensing rows, Z_o the same structure with
this axis open), so by the Sherman-Morrison formula the closed-loop receptance
``P_c = sᵀ Z_c⁻¹ a`` is ``P/(1 + G P)`` and

.. math:: T = G P_c,\qquad S = 1 - G P_c,\qquad L = \frac{G P_c}{1 - G P_c}.

One banded solve per frequency (:mod:`flexshaft.analyses.banded`) with one right-hand side per
loop gives every loop at once. The determinant lemma gives the same function as a ratio of
characteristic determinants, ``S = det Z_o/det Z_c``: its poles are the closed-loop
eigenvalues, its zeros the open-loop ones (tests/test_loop_robustness.py checks both).

Margins (:func:`loop_margins`, on any L(iω)):

* **Sensitivity peak** max |S(iω)|, the inverse of the smallest distance of L(iω) to −1, graded
  by ISO 14839-3 in zones (:data:`ISO_14839_ZONE_LIMITS`, :func:`sensitivity_zone`): A below 3
  (9.5 dB), B below 4 (12 dB), C below 5 (14 dB), D above (the zone limits as the project's
  design notes quote them; the standard's own text was not available to check here).
* **Gain margins** at each phase crossover ω_pc (L real and negative): the factor 1/|L| that
  puts L on −1. A crossover with |L| < 1 gives an upper margin (the gain may rise by it); one
  with |L| > 1 a lower margin (a loop around an open-loop-unstable magnet, k_s > 0, fails if its
  gain *falls*: at ω = 0 the PD loop has L(0) = −k_i K_p/k_s). In dB, ``20 log10(1/|L|)``:
  positive for the smallest upper margin, negative for the lower one closest to 0 dB.
* **Phase margin** at each gain crossover ω_gc (|L| = 1): the rotation ``180° − |arg L|`` that
  puts L on −1; the smallest over the crossovers.

The margins measure the distance to instability of a loop that is closed-loop stable; whether
it is, the eigen-analysis says (:mod:`flexshaft.analyses.stability`,
:mod:`flexshaft.analyses.root_stability`).

Frequency grid. |S| = det Z_o/det Z_c peaks only near the closed-loop poles: a lightly damped
pole s = −ζω_n + iω_d makes a peak at ω_d of half-power width 2ζω_n, far narrower than any
affordable logarithmic grid. The grid is therefore a coarse logarithmic one over
``frequency_range`` (``n_points``, 200 by default: 2.2 % steps over 0.1 Hz-2 kHz) plus, for every
closed-loop pole with ζ < :data:`RESOLVED_DAMPING` in the range, the points ω_d and
ω_d ± ζ ω_n/2: each such peak is sampled at its top and at its half width (the screening
resolution samples the top only: ``peak_samples``). The poles are those of the
loss-free closed loop (:func:`~flexshaft.analyses.root_stability.closed_loop_poles`) or the
caller's (``poles``: the every-root check's; above the highest of them, the undamped natural
frequencies with a nominal ζ = 1e-3). Refinement on the loop function itself (golden-section
search, regula falsi): the local maxima of |S| within :data:`PEAK_WINDOW` of the
largest grid value or more than twice a neighbour (a peak the grid under-resolves: a pole
beside a zero of S moves the peak off the pole), the gain crossovers whose phase margin
interpolated on the grid is within :data:`MARGIN_WINDOW_DEG` of the smallest, the phase
crossovers whose gain margin is within :data:`MARGIN_WINDOW_DB` of the smallest of its kind,
and any crossover whose bracket turns the phase by more than 30° (a resonance inside it).
tests/test_loop_robustness.py checks the result against a 5000-point grid refined everywhere.

The refinements of all loops advance together, one banded sweep a round
(:func:`~flexshaft.analyses.local_projection.lockstep`), each on a four-unknown projected model
of its interval built from the grid's own solutions, and each result is checked by one full
solve (:mod:`flexshaft.analyses.local_projection`: accepted when the two agree to 1e-9, else
the model is enriched or the refinement repeated on full solves; the values reported are the
full model's). A crossover that fails its first check is not refined further when it cannot
set a margin (:func:`_release_rule`): from the full L at the checked frequency and the
projected model's first two derivatives there, a trusted Newton step bounds how far the
crossover lies and how much L and the phase margin change on the way (times
:data:`RELEASE_SAFETY`); a crossing whose Re L stays positive is no phase crossover, and a gain
crossover whose phase margin stays :data:`MARGIN_WINDOW_DEG` above another's of the same loop is
not the smallest. Such a crossover keeps its checked frequency (within one Newton step of it,
in :attr:`LoopMargins.gain_crossovers`); the margins are those of the crossovers refined to the
end. On the tuned design this halves the refinements' full solves (147 to 75).
tests/test_loop_projection.py compares the margins with full solves at every step,
tests/test_bearing_loops_accuracy.py on the embedded designs at every envelope point and on
poor loops.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.banded import solver_for
from flexshaft.analyses.guards import check_count, check_model, check_speed, require_finite
from flexshaft.analyses.local_projection import (
    LocalModels,
    RefinementTask,
    golden_maximum,
    illinois_root,
    lockstep,
    projected_refinements,
    window_of,
)
from flexshaft.analyses.root_stability import closed_loop_poles
from flexshaft.assembly.model import Model

__all__ = [
    "DEFAULT_FREQUENCY_RANGE",
    "ISO_14839_ZONE_LIMITS",
    "MARGIN_WINDOW_DB",
    "MARGIN_WINDOW_DEG",
    "PEAK_WINDOW",
    "RESOLVED_DAMPING",
    "BearingLoop",
    "LoopMargins",
    "bearing_loops",
    "loop_margins",
    "sensitivity_zone",
]

#: Upper limits of the sensitivity peak |S|max of ISO 14839-3's zones A, B and C (above: D).
ISO_14839_ZONE_LIMITS = (3.0, 4.0, 5.0)
#: Frequency range [Hz] of the loop analysis by default: the boom's first modes (~5 Hz) and the
#: controller's integrator corner (~1 Hz) above the low end, the amplifier and derivative-filter
#: corners (0.5-1 kHz) below the high end (assumed; the mesh should resolve the modes there).
DEFAULT_FREQUENCY_RANGE = (0.1, 2000.0)
_AXES = ("v", "w")
#: Closed-loop poles below this damping ratio get grid points at their peak (module docstring);
#: above it the coarse grid resolves the peak (half-power width 2ζ ≥ 40 % of the frequency).
RESOLVED_DAMPING = 0.2
#: Local maxima of |S| at least this fraction of the largest grid value are refined.
PEAK_WINDOW = 0.8
#: Gain crossovers whose interpolated phase margin is within this of the smallest are refined [deg].
MARGIN_WINDOW_DEG = 3.0
#: Phase crossovers whose interpolated gain margin is within this of the smallest are refined [dB].
MARGIN_WINDOW_DB = 2.0
#: Largest relative change of the slope over the Newton step from a checked frequency to its
#: crossover for the release rule to trust the step (:func:`_release_rule`).
NEWTON_TRUST = 0.1
#: Factor on the bound of the change of the phase margin or of L over that step.
RELEASE_SAFETY = 10.0
#: Offsets k of the grid points ω_d + k ζ ω_n around a lightly damped pole, by the number of
#: points per pole (``peak_samples``): its top and half width, or its top only.
_AROUND = {3: (-0.5, 0.0, 0.5), 1: (0.0,)}


def sensitivity_zone(peak: float) -> str:
    """ISO 14839-3 zone ``"A"``, ``"B"``, ``"C"`` or ``"D"`` of a sensitivity peak |S|max."""
    if not (np.isfinite(peak) and peak >= 0):
        raise ValueError(f"the sensitivity peak must be a finite number >= 0 (got {peak!r})")
    for zone, limit in zip("ABC", ISO_14839_ZONE_LIMITS):
        if peak < limit:
            return zone
    return "D"


@dataclass(frozen=True)
class LoopMargins:
    """Robustness of one loop (module docstring).

    Attributes
    ----------
    peak_sensitivity : float
        max |S(iω)| [-].
    peak_frequency : float
        Frequency of that peak [Hz].
    gain_margin_upper_db : float
        Smallest upper gain margin [dB] (> 0; inf when L never crosses −180° with |L| < 1).
    gain_margin_lower_db : float
        Lower gain margin closest to 0 dB [dB] (< 0; −inf when none).
    phase_margin_deg : float
        Smallest phase margin [deg] over the gain crossovers (inf when |L| never crosses 1).
    phase_crossovers : tuple of float
        Frequencies where L is real and negative [Hz] (0 for a crossover at ω = 0); refined
        where they may set a gain margin, interpolated on the grid elsewhere.
    gain_crossovers : tuple of float
        Frequencies where |L| = 1 [Hz] (refined where they may set the phase margin,
        interpolated on the grid or, where a first check showed that they cannot, within one
        Newton step elsewhere: module docstring).
    phase_margin_frequency : float or None
        The gain crossover of the smallest phase margin [Hz] (None without one).
    gain_margin_frequency : float or None
        The phase crossover of :attr:`gain_margin_db` [Hz] (None without one).
    """

    peak_sensitivity: float
    peak_frequency: float
    gain_margin_upper_db: float
    gain_margin_lower_db: float
    phase_margin_deg: float
    phase_crossovers: tuple[float, ...]
    gain_crossovers: tuple[float, ...]
    phase_margin_frequency: float | None = None
    gain_margin_frequency: float | None = None

    @property
    def peak_sensitivity_db(self) -> float:
        """20 log10 |S|max [dB]."""
        return float(20.0 * np.log10(self.peak_sensitivity))

    @property
    def zone(self) -> str:
        """ISO 14839-3 zone of the sensitivity peak."""
        return sensitivity_zone(self.peak_sensitivity)

    @property
    def gain_margin_db(self) -> float:
        """The gain margin nearer 0 dB, with its sign (inf when there is none)."""
        upper, lower = self.gain_margin_upper_db, self.gain_margin_lower_db
        return upper if upper <= -lower else lower


def loop_margins(loop: Callable[[np.ndarray], np.ndarray], omegas, static_gain: float | None = None) -> LoopMargins:
    """Sensitivity peak and margins of a loop function on a frequency grid, refined.

    Parameters
    ----------
    loop : callable
        ``loop(ω)`` → L(iω) for an array of frequencies ω [rad/s] (complex array).
    omegas : array_like
        Increasing grid of frequencies > 0 [rad/s]; the peaks and crossovers are searched on it
        and refined between its points (those that may set a margin, module docstring): a
        lightly damped peak must have a grid point near its top.
    static_gain : float or None
        L(0) when finite (a loop without integral action): a negative L(0) is a phase
        crossover at ω = 0.
    """
    w = np.asarray(omegas, dtype=float)
    if w.ndim != 1 or w.size < 3 or not np.all(np.isfinite(w)) or np.any(w <= 0) or np.any(np.diff(w) <= 0):
        raise ValueError("omegas must be an increasing grid of at least 3 finite frequencies > 0 rad/s")
    L = np.asarray(loop(w), dtype=complex)
    require_finite("loop function", L)
    tasks, finish = _refinements(w, L, static_gain)
    return finish(lockstep([t.start() for t in tasks], lambda x, _: np.asarray(loop(x), dtype=complex)))


def _imag(value: complex) -> float:
    return value.imag


def _log_abs(value: complex) -> float:
    return float(np.log(abs(value)))


def _crossover(f: Callable[[complex], float], w: np.ndarray, L: np.ndarray, k: int) -> RefinementTask:
    """The refinement of the root of f(L) between grid points k and k + 1 to 1e-8 ω relative."""
    bracket = float(w[k]), float(w[k + 1]), complex(L[k]), complex(L[k + 1]), 1e-8 * float(w[k])
    role = "gain" if f is _log_abs else "phase"
    return RefinementTask("root", k, k + 1, functools.partial(illinois_root, f, *bracket), role)


def _release_rule(tasks: Sequence[RefinementTask], loop_of: np.ndarray) -> Callable[..., np.ndarray]:
    """The rule by which a crossover checked by a full solve near it is not refined further
    (module docstring): ``settle`` of
    :func:`~flexshaft.analyses.local_projection.projected_refinements`.

    With the full model's L at the checked frequency ω₁ and the projected model's derivatives
    in x = ln ω there, the crossover lies a Newton step δ from ω₁ (δ = −ln|L|/Re g with
    g = d ln L/dx for |L| = 1, δ = −Im L/Im L' for Im L = 0); the step is trusted where the
    slope changes by at most :data:`NEWTON_TRUST` of itself over it (|g'δ| or |L''δ|). Then
    L moves by at most |L'δ| + |L''|δ² on the way to the crossover and its phase by
    |gδ| + |g'|δ², which :data:`RELEASE_SAFETY` multiplies:

    * a phase crossing whose Re L stays positive by that much is no phase crossover (it sets
      no gain margin);
    * a gain crossover whose phase margin, less that much, exceeds by :data:`MARGIN_WINDOW_DEG`
      the upper end of another crossover's of the same loop (the same bound, or the refined
      value) is not the smallest.

    Either keeps (ω₁, L(iω₁)): the margins are those of the crossovers refined to the end."""
    bounds: dict[int, tuple[float, float]] = {}  # gain crossover -> its phase margin's range [deg]

    def settle(which, omegas, values, slopes, curvatures, accepted) -> np.ndarray:
        release = np.zeros(len(which), dtype=bool)
        with np.errstate(all="ignore"):
            for n, i in enumerate(which):
                L, dL, d2L = complex(values[n]), complex(slopes[n]), complex(curvatures[n])
                if tasks[i].role == "gain":
                    pm = 180.0 - abs(float(np.degrees(np.angle(L))))
                    g, dg = dL / L, (d2L * L - dL * dL) / (L * L)
                    step = abs(np.log(abs(L)) / g.real)
                    spread = RELEASE_SAFETY * float(np.degrees(abs(g) * step + abs(dg) * step * step))
                    if accepted[n]:
                        spread = 0.0
                    elif not (abs(dg) * step <= NEWTON_TRUST * abs(g.real) and np.isfinite(spread)):
                        spread = np.inf
                    bounds[int(i)] = (pm - spread, pm + spread)
                elif tasks[i].role == "phase" and not accepted[n]:
                    step = abs(L.imag / dL.imag)
                    change = RELEASE_SAFETY * (abs(dL) * step + abs(d2L) * step * step)
                    trusted = abs(d2L) * step <= NEWTON_TRUST * abs(dL.imag)
                    release[n] = bool(trusted and np.isfinite(change) and L.real > change)
        for n, i in enumerate(which):
            if tasks[i].role != "gain" or accepted[n]:
                continue
            others = [bounds[j][1] for j in bounds if j != i and loop_of[j] == loop_of[i]]
            release[n] = bool(others) and bounds[int(i)][0] > min(others) + MARGIN_WINDOW_DEG
        return release

    return settle


def _refinements(
    w: np.ndarray, L: np.ndarray, static_gain: float | None
) -> tuple[list[RefinementTask], Callable[[list], LoopMargins]]:
    """The refinements :func:`loop_margins` needs from the loop function ``L`` on the grid ``w``
    [rad/s], and the function that makes the margins of their results (in the same order)."""
    S = np.abs(1.0 / (1.0 + L))

    def s_of(value: complex) -> float:
        return abs(1.0 / (1.0 + value))

    peak, peak_w = float(S.max()), float(w[np.argmax(S)])
    tasks: list[RefinementTask] = []
    for k in np.flatnonzero((S[1:-1] >= S[:-2]) & (S[1:-1] >= S[2:])) + 1:
        if S[k] < PEAK_WINDOW * peak and S[k] < 2.0 * min(S[k - 1], S[k + 1]):
            continue  # neither near the top nor under-resolved (a neighbour below half of it)
        bracket = float(np.log(w[k - 1])), float(np.log(w[k + 1])), 1e-6
        tasks.append(RefinementTask("peak", int(k) - 1, int(k) + 1, functools.partial(golden_maximum, s_of, *bracket)))
    n_peaks = len(tasks)

    phase = np.angle(L)
    turn = np.abs(np.angle(L[1:] / L[:-1]))  # phase change across each interval [rad]
    sharp = turn > np.radians(30.0)

    # phase crossovers: L real and negative between two grid points
    crossings = [
        k for k in np.flatnonzero(np.sign(L.imag[:-1]) * np.sign(L.imag[1:]) < 0) if L.real[k] < 0 or L.real[k + 1] < 0
    ]
    estimates: list[tuple[float, complex]] = []  # (ω [rad/s], L(iω)) at each phase crossover
    for k in crossings:
        t = L.imag[k] / (L.imag[k] - L.imag[k + 1])
        estimates.append((w[k] + t * (w[k + 1] - w[k]), L[k] + t * (L[k + 1] - L[k])))
    margins = np.array([20.0 * np.log10(1.0 / max(abs(v), 1e-300)) for _, v in estimates])
    best_upper = margins[margins > 0].min(initial=np.inf)
    best_lower = margins[margins < 0].max(initial=-np.inf)
    phase_refined = []
    for k, gm in zip(crossings, margins):
        near = (gm > 0 and gm <= best_upper + MARGIN_WINDOW_DB) or (gm < 0 and gm >= best_lower - MARGIN_WINDOW_DB)
        phase_refined.append(bool(near or sharp[k]))
        if phase_refined[-1]:
            tasks.append(_crossover(_imag, w, L, int(k)))

    # gain crossovers: |L| = 1
    log_l = np.log(np.abs(L))
    brackets = np.flatnonzero(np.sign(log_l[:-1]) * np.sign(log_l[1:]) < 0)
    estimate_pm = []
    for k in brackets:
        t = log_l[k] / (log_l[k] - log_l[k + 1])
        angle = phase[k] + t * np.angle(L[k + 1] / L[k])
        estimate_pm.append(180.0 - abs(float(np.degrees(np.angle(np.exp(1j * angle))))))
    smallest = min(estimate_pm, default=np.inf)
    gain_refined = []
    for k, pm in zip(brackets, estimate_pm):
        gain_refined.append(bool(pm <= smallest + MARGIN_WINDOW_DEG or sharp[k]))
        if gain_refined[-1]:
            tasks.append(_crossover(_log_abs, w, L, int(k)))

    def finish(results: list) -> LoopMargins:
        top, top_w = peak, peak_w
        for x, value in results[:n_peaks]:
            if value > top:
                top, top_w = float(value), float(np.exp(x))
        done = iter(results[n_peaks:])
        phase_w, phase_l = [], []
        if static_gain is not None and np.isfinite(static_gain) and static_gain < 0:
            phase_w.append(0.0)
            phase_l.append(abs(static_gain))
        for (x, value), refined in zip(estimates, phase_refined):
            if refined:
                x, value = next(done)
            if value.real < 0:
                phase_w.append(x)
                phase_l.append(abs(value))
        gain_w, phase_margins = [], []
        for k, pm, refined in zip(brackets, estimate_pm, gain_refined):
            if refined:
                x, value = next(done)
                pm = 180.0 - abs(float(np.degrees(np.angle(value))))
            else:
                t = log_l[k] / (log_l[k] - log_l[k + 1])
                x = w[k] + t * (w[k + 1] - w[k])
            gain_w.append(x)
            phase_margins.append(pm)
        return _margins(top, top_w, phase_w, phase_l, gain_w, phase_margins)

    return tasks, finish


def _margins(
    peak: float, peak_w: float, phase_w: list, phase_l: list, gain_w: list, phase_margins: list
) -> LoopMargins:
    """:class:`LoopMargins` of the refined peak, phase crossovers (ω, |L|) and gain crossovers
    (ω, phase margin), frequencies in [rad/s]."""
    margins_db = 20.0 * np.log10(1.0 / np.asarray(phase_l)) if phase_l else np.zeros(0)
    upper = margins_db[margins_db > 0]
    lower = margins_db[margins_db < 0]
    gm_upper = float(upper.min()) if upper.size else float("inf")
    gm_lower = float(lower.max()) if lower.size else float("-inf")
    governing = gm_upper if gm_upper <= -gm_lower else gm_lower
    gm_frequency = None
    if np.isfinite(governing):
        gm_frequency = float(phase_w[int(np.argmin(np.abs(margins_db - governing)))] / (2.0 * np.pi))
    pm_index = int(np.argmin(phase_margins)) if phase_margins else None
    return LoopMargins(
        peak_sensitivity=peak,
        peak_frequency=peak_w / (2.0 * np.pi),
        gain_margin_upper_db=gm_upper,
        gain_margin_lower_db=gm_lower,
        phase_margin_deg=float(phase_margins[pm_index]) if pm_index is not None else float("inf"),
        phase_crossovers=tuple(float(x / (2.0 * np.pi)) for x in phase_w),
        gain_crossovers=tuple(float(x / (2.0 * np.pi)) for x in gain_w),
        phase_margin_frequency=None if pm_index is None else float(gain_w[pm_index] / (2.0 * np.pi)),
        gain_margin_frequency=gm_frequency,
    )


@dataclass(frozen=True)
class BearingLoop:
    """One control axis of one active bearing at one spin speed.

    Attributes
    ----------
    actuator : str
        The bearing's name.
    axis : {"v", "w"}
        The control axis (lateral direction y or z).
    speed : float
        Spin speed Ω [rad/s].
    margins : LoopMargins
        Sensitivity peak, zone, gain and phase margins.
    frequencies : ndarray
        The grid [Hz].
    sensitivity : ndarray
        S(iω) on the grid (complex).
    """

    actuator: str
    axis: str
    speed: float
    margins: LoopMargins
    frequencies: np.ndarray
    sensitivity: np.ndarray


def _natural_frequencies(model: Model, low: float, high: float) -> np.ndarray:
    """Undamped natural frequencies of (K + K_a, M) in (low, high] [rad/s] (dense, only those
    eigenvalues computed; empty above 900 free DOFs)."""
    free = model.dofs.free
    if free.size > 900:
        return np.zeros(0)
    import scipy.linalg as la

    K = (model.K + model.Kp)[free][:, free].toarray()
    M = model.M[free][:, free].toarray()
    # scipy-stubs types the eigvals_only overloads without the generalized drivers, which scipy accepts
    w2 = la.eigh(K, M, eigvals_only=True, subset_by_value=(low * low, high * high), driver="gvx")  # type: ignore[call-overload]
    return np.sqrt(np.clip(w2, 0.0, None))


def _grid(model: Model, frequency_range, n_points: int, poles: np.ndarray, around=_AROUND[3]) -> np.ndarray:
    """Logarithmic grid [rad/s] with points at the peaks of the lightly damped ``poles``
    (module docstring); above the highest pole given, at the undamped natural frequencies with
    a nominal width of 1e-3 (poles of a truncated basis)."""
    low, high = 2 * np.pi * frequency_range[0], 2 * np.pi * frequency_range[1]
    grid = [np.geomspace(low, high, n_points)]
    poles = np.asarray(poles, dtype=complex)
    poles = poles[(poles.imag > 0) & np.isfinite(poles)]
    top = float(np.max(np.abs(poles), initial=0.0))
    if top < high:
        natural = _natural_frequencies(model, top, high)
        natural = natural[(natural > top) & (natural < high)]
        poles = np.concatenate([poles, natural * (-1e-3 + 1j)])
    natural = np.abs(poles)
    zeta = -poles.real / np.where(natural > 0, natural, 1.0)
    light = (np.abs(zeta) < RESOLVED_DAMPING) & (poles.imag > low) & (poles.imag < high)
    if light.any():
        width = np.maximum(np.abs(zeta[light]) * natural[light], 1e-9 * natural[light])
        grid.append((poles.imag[light][:, None] + np.outer(width, around)).ravel())
    out = np.unique(np.concatenate(grid))
    out = out[(out >= low) & (out <= high)]
    # points closer than 1e-7 relative (the same pole of both lateral planes) are one: a
    # near-duplicate would split a local maximum between two points and narrow its bracket
    return out[np.concatenate([[True], np.diff(out) > 1e-7 * out[1:]])]


def bearing_loops(
    model: Model,
    speed: float | None = None,
    frequency_range: tuple[float, float] = DEFAULT_FREQUENCY_RANGE,
    n_points: int = 200,
    poles=None,
    projected: bool = True,
    peak_samples: int = 3,
) -> tuple[BearingLoop, ...]:
    """Sensitivity function and margins of both control axes of every active bearing.

    Parameters
    ----------
    speed : float or None
        Spin speed Ω [rad/s] (default the operating speed; the gyroscopic and circulatory
        terms couple the axes and the bearings at speed).
    frequency_range : (float, float)
        Lowest and highest frequency [Hz], 0 < low < high.
    n_points : int
        Points of the logarithmic grid (before the points at the closed-loop poles).
    poles : array_like or None
        Closed-loop roots at ``speed`` [rad/s] (e.g. :attr:`RootStability.roots
        <flexshaft.analyses.root_stability.RootStability.roots>` at it); default those of the
        loss-free closed loop (:func:`~flexshaft.analyses.root_stability.closed_loop_poles`).
    projected : bool
        Refine the peaks and crossovers on small projected models of their intervals, each
        result checked against a full solve (:mod:`flexshaft.analyses.local_projection`); False:
        a full solve at every refinement step (the reference the tests compare with).
    peak_samples : {3, 1}
        Grid points per lightly damped pole: at its top and half width (3), or at its top only
        (1: the screening's; the refinement brackets the peak between the neighbouring grid
        points instead, and the margins of the embedded designs agree with those of 3 to 2e-8,
        tests/test_loop_robustness.py).

    Returns
    -------
    tuple of BearingLoop
        In the order of the actuators, v before w.

    Raises
    ------
    ValueError
        For a model without active bearings or a bad range.
    """
    check_model(model)
    speed = check_speed(model.speed if speed is None else speed)
    n_points = check_count(n_points, "n_points", minimum=3)
    if peak_samples not in _AROUND:
        raise ValueError(f"peak_samples must be 3 or 1 (got {peak_samples!r})")
    low, high = (float(v) for v in frequency_range)
    if not (np.isfinite(low) and np.isfinite(high) and 0 < low < high):
        raise ValueError(f"frequency_range must be 0 < low < high [Hz] (got {frequency_range!r})")
    if not model.actuators:
        raise ValueError("the model has no active bearing: no control loop to assess")
    solver = solver_for(model)
    free = solver.free
    rows = [(a, j) for a in model.actuators for j in range(2)]
    rhs = np.column_stack([a.lateral_rows[j].toarray().ravel()[free] for a, j in rows]).astype(complex)
    sense = np.vstack([a.sensing_rows[j].toarray().ravel()[free] for a, j in rows])

    def gains(omegas: np.ndarray) -> np.ndarray:
        laws = [a.feedback_gain(1j * omegas) for a in model.actuators]  # both axes of a bearing share it
        return np.array([laws[k // 2] for k in range(len(rows))])

    def closed(omegas: np.ndarray, keep: list | None = None) -> np.ndarray:
        """G P_c (= T) of every loop at ω [rad/s]: (n_loops, n_omegas); the solutions are
        appended to ``keep`` when given."""
        X = list(solver.sweep([(float(x), speed) for x in omegas], rhs))
        if keep is not None:
            keep.extend(X)
        Pc = np.stack([np.einsum("ij,ji->i", sense, x) for x in X], axis=1)
        return gains(omegas) * Pc

    if poles is None:
        poles = closed_loop_poles(model, speed)
    grid = _grid(model, (low, high), n_points, poles, _AROUND[peak_samples])
    responses: list[np.ndarray] = []
    T_grid = closed(grid, responses if projected else None)
    static = None if any(a.integrates for a in model.actuators) else closed(np.array([0.0]))[:, 0].real
    L_grid = T_grid / (1.0 - T_grid)
    plans, owner = [], []
    for k in range(len(rows)):
        gain0 = None if static is None else float(static[k] / (1.0 - static[k]))
        plans.append(_refinements(grid, L_grid[k], gain0))
        owner += [k] * len(plans[-1][0])
    loop_of = np.array(owner, dtype=np.intp)
    tasks = [task for refinements, _ in plans for task in refinements]

    def evaluate(omegas: np.ndarray, which: np.ndarray, keep: list | None = None) -> np.ndarray:
        """L(iω) of each task's loop at its ω: one banded sweep a loop, with that loop's actuation
        only; its responses (n_free,) are appended to ``keep`` in the order of ``omegas``."""
        loops = loop_of[which]
        T = np.empty(omegas.size, dtype=complex)
        columns: list = [None] * omegas.size
        for k in np.unique(loops):
            at = np.flatnonzero(loops == k)
            for i, x in zip(at, solver.sweep([(float(omegas[i]), speed) for i in at], rhs[:, k])):
                columns[i] = x
            T[at] = gains(omegas[at])[k] * np.array([sense[k] @ columns[i] for i in at])
        if keep is not None:
            keep.extend(columns)
        return T / (1.0 - T)

    if projected and tasks:

        def local_models(windows: Sequence[Sequence[int]], active: np.ndarray) -> LocalModels:
            return LocalModels(solver, speed, responses, windows, loop_of[active], rhs, sense, gains)

        windows = [list(window_of(task.lo, task.hi, grid.size)) for task in tasks]
        settle = _release_rule(tasks, loop_of)
        results = projected_refinements(tasks, evaluate, local_models, windows, settle)
    else:
        results = lockstep([task.start() for task in tasks], evaluate)
    out, first = [], 0
    for k, (actuator, j) in enumerate(rows):
        refinements, finish = plans[k]
        margins = finish(results[first : first + len(refinements)])
        first += len(refinements)
        out.append(BearingLoop(actuator.name, _AXES[j], float(speed), margins, grid / (2 * np.pi), 1.0 - T_grid[k]))
    return tuple(out)

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

The margins (sensitivity peak and ISO 14839-3 zone, gain and phase margins) and which peaks and
crossovers are refined between the grid points: :mod:`flexshaft.analyses.loop_margins`. The
margins measure the distance to instability of a loop that is closed-loop stable; whether it
is, the eigen-analysis says (:mod:`flexshaft.analyses.stability`,
:mod:`flexshaft.analyses.root_stability`).

The frequency grid: :mod:`flexshaft.analyses.loop_grid`, a logarithmic one with points at the
lightly damped closed-loop poles, those of the loss-free closed loop
(:func:`~flexshaft.analyses.root_stability.closed_loop_poles`) or the caller's (``poles``: the
every-root check's), and above them at the natural frequencies of the blocks of Z the loops'
rows touch (:meth:`~flexshaft.analyses.banded.BandedHarmonicSolver.coupled`: not the shaft's uncoupled torsion
and axial motion, whose modes are no poles of S). tests/test_loop_robustness.py checks the
result against a 5000-point grid refined everywhere.

The refinements of all loops advance together, one banded sweep a round
(:func:`~flexshaft.analyses.local_projection.lockstep`), each on a four-unknown projected model
of its interval built from the grid's own solutions, and each result is checked by one full
solve (:mod:`flexshaft.analyses.local_projection`: accepted when the two agree to 1e-9, else
the model is enriched or the refinement repeated on full solves; the values reported are the
full model's). A crossover that fails its first check is not refined further when it cannot
set a margin (:func:`~flexshaft.analyses.loop_margins.release_rule`). On the tuned design this
halves the refinements' full solves (147 to 75). No loop is solved twice at one frequency: the
check solve at a refined peak gives the second round its L there, and a refinement run again on
an enriched model that lands where its check was reuses that solve (the baseline's operating
point: 105 of 673 solves). tests/test_loop_projection.py compares the
margins with full solves at every step, tests/test_bearing_loops_accuracy.py on the embedded
designs at every envelope point and on poor loops. A second round on full solves
(:class:`~flexshaft.analyses.loop_margins.MarginPlan`) refines the crossovers the first one's
results bring into the margins' window and those a refined peak reveals inside a grid interval;
with it the default and screening grids agree with a 1000-point grid refined everywhere to 7e-8
on the embedded designs at every envelope point (tests/test_loop_robustness.py: the
baseline's cold point, where the grid alone misread a phase margin 4.5 times too large).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.banded import SingularSystemError, solver_for
from flexshaft.analyses.guards import check_count, check_model, check_speed
from flexshaft.analyses.local_projection import LocalModels, lockstep, projected_refinements, window_of
from flexshaft.analyses.loop_grid import AROUND, frequency_grid
from flexshaft.analyses.loop_margins import LoopMargins, refinements, release_rule
from flexshaft.analyses.response import static_response
from flexshaft.analyses.root_stability import closed_loop_poles
from flexshaft.assembly.model import Model

__all__ = ["DEFAULT_FREQUENCY_RANGE", "BearingLoop", "bearing_loops"]

#: Frequency range [Hz] of the loop analysis by default: the boom's first modes (~5 Hz) and the
#: controller's integrator corner (~1 Hz) above the low end, the amplifier and derivative-filter
#: corners (0.5-1 kHz) below the high end (assumed; the mesh should resolve the modes there).
DEFAULT_FREQUENCY_RANGE = (0.1, 2000.0)
_AXES = ("v", "w")


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


def _static_closed(model: Model, rows: list, speed: float, within: np.ndarray) -> np.ndarray:
    """T = G P_c of every loop at ω = 0 when a bearing integrates, nan for a loop whose own law
    integrates (its L(0) is infinite: no crossover at 0). An integrating bearing holds its sensed
    displacement at zero at ω = 0 (:func:`~flexshaft.analyses.response.static_response`), so a
    finite loop beside it has the finite L(0) of that constrained static problem (a PD bearing
    beside a PID one: its lower gain margin at ω = 0; the solve at ω = 0 of the loops' banded
    solver is singular there). It is solved on the loops' blocks ``within`` (free-DOF mask): a
    driveline free to twist is singular as a whole but not in its lateral blocks. A singular
    static problem gives nan too (no crossover read)."""
    if all(a.integrates for a, _ in rows):
        return np.full(len(rows), np.nan)
    loads = np.column_stack([a.lateral_rows[j].toarray().ravel() for a, j in rows])
    try:
        q = static_response(model, loads, speed, within=within)
    except SingularSystemError:
        return np.full(len(rows), np.nan)
    return np.array(
        [
            np.nan if a.integrates else float(a.feedback.static_gain * (a.sensing_rows[j] @ q[:, k])[0])
            for k, (a, j) in enumerate(rows)
        ]
    )


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
    if peak_samples not in AROUND:
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
    # the natural frequencies of blocks of Z that no loop's rows touch are no poles of S (loop_grid)
    visible = solver.coupled(np.flatnonzero(np.any(rhs != 0, axis=1) | np.any(sense != 0, axis=0)))
    grid = frequency_grid(model, (low, high), n_points, poles, AROUND[peak_samples], visible)
    responses: list[np.ndarray] = []
    T_grid = closed(grid, responses if projected else None)
    if any(a.integrates for a in model.actuators):
        static = _static_closed(model, rows, speed, visible)
    else:
        static = closed(np.array([0.0]))[:, 0].real
    L_grid = T_grid / (1.0 - T_grid)
    plans, owner = [], []
    for k in range(len(rows)):
        gain0 = None if not np.isfinite(static[k]) else float(static[k] / (1.0 - static[k]))
        plans.append(refinements(grid, L_grid[k], gain0))
        owner += [k] * len(plans[-1][0])
    loop_of = np.array(owner, dtype=np.intp)
    tasks = [task for loop_tasks, _ in plans for task in loop_tasks]

    def evaluate(omegas: np.ndarray, which: np.ndarray, keep: list | None = None) -> np.ndarray:
        """L(iω) of each task's loop at its ω: one banded sweep a loop, with that loop's actuation
        only; its responses (n_free,) are appended to ``keep`` in the order of ``omegas``."""
        return on_loops(omegas, loop_of[which], keep)

    solved: dict[tuple[float, int], np.ndarray] = {}  # (ω, loop) -> its full response

    def on_loops(omegas: np.ndarray, loops: np.ndarray, keep: list | None = None) -> np.ndarray:
        """L(iω) of loop ``loops[i]`` at ``omegas[i]`` (:func:`evaluate`'s). A loop's response
        at a frequency solved before is reused, not solved again (the check solve of a refined
        peak is the second round's L there; a refinement redone on full solves starts where
        its check solves were): the same ω, the same right-hand side, the same solution."""
        T = np.empty(omegas.size, dtype=complex)
        columns: list = [None] * omegas.size
        for k in np.unique(loops):
            at = np.flatnonzero(loops == k)
            new = list(dict.fromkeys(float(omegas[i]) for i in at if (float(omegas[i]), int(k)) not in solved))
            for x, column in zip(new, solver.sweep([(x, speed) for x in new], rhs[:, k])):
                solved[(x, int(k))] = column
            for i in at:
                columns[i] = solved[(float(omegas[i]), int(k))]
            law = model.actuators[k // 2].feedback_gain(1j * omegas[at])  # the loop's own law (gains')
            T[at] = law * np.array([sense[k] @ columns[i] for i in at])
        if keep is not None:
            keep.extend(columns)
        return T / (1.0 - T)

    if projected and tasks:

        def local_models(windows: Sequence[Sequence[int]], active: np.ndarray) -> LocalModels:
            return LocalModels(solver, speed, responses, windows, loop_of[active], rhs, sense, gains)

        windows = [list(window_of(task.lo, task.hi, grid.size)) for task in tasks]
        settle = release_rule(tasks, loop_of)
        results = projected_refinements(tasks, evaluate, local_models, windows, settle)
    else:
        results = lockstep([task.start() for task in tasks], evaluate)
    # the second round (loop_margins.MarginPlan), on full solves: the crossovers the first round's
    # results bring into the margins' window, and those a refined peak reveals inside an interval
    peaks = np.flatnonzero([task.kind == "peak" for task in tasks])
    at_peaks = on_loops(np.exp([results[i][0] for i in peaks]), loop_of[peaks]) if peaks.size else np.zeros(0, complex)
    second, second_loop, first = [], [], 0
    for k in range(len(rows)):
        loop_tasks, plan = plans[k]
        mine = loop_of[peaks] == k
        more = plan.second_round(results[first : first + len(loop_tasks)], at_peaks[mine])
        second.append(more)
        second_loop += [k] * len(more)
        first += len(loop_tasks)
    which_loop = np.array(second_loop, dtype=np.intp)
    flat = [task for more in second for task in more]
    found = lockstep([task.start() for task in flat], lambda x, which: on_loops(x, which_loop[which]))
    out, first, first_second = [], 0, 0
    for k, (actuator, j) in enumerate(rows):
        loop_tasks, plan = plans[k]
        pairs = zip(second[k], found[first_second : first_second + len(second[k])])
        margins = plan(results[first : first + len(loop_tasks)], list(pairs))
        first += len(loop_tasks)
        first_second += len(second[k])
        out.append(BearingLoop(actuator.name, _AXES[j], float(speed), margins, grid / (2 * np.pi), 1.0 - T_grid[k]))
    return tuple(out)

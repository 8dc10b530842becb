r"""Receptances near a few frequencies from small projected models, checked against the full one.

The bearing loops (:mod:`flexshaft.analyses.bearing_loops`) refine their sensitivity peaks and
crossovers between two grid points: a golden-section search or regula falsi takes 10-25
evaluations of the closed-loop receptance ``P_c(ω) = Bₛᵀ Z(ω, Ω)⁻¹ Bₐ`` inside one small
interval, each a banded solve of the whole model. Inside such an interval the response lives
in the span of the responses at the nearby grid points: with ``X_j = Z(ω_j)⁻¹ Bₐ`` at the
grid points of a window around the interval and V an orthonormal basis of their columns, the
Galerkin model

.. math:: Z_V(ω) = Vᴴ Z(ω, Ω) V = \sum_k w_k(ω)\, Vᴴ T_k V,\qquad
          P_V(ω) = Bₛᵀ V\, Z_V(ω)⁻¹\, Vᴴ Bₐ

(T_k the stored terms of Z, :meth:`~flexshaft.analyses.banded.BandedHarmonicSolver.project`)
reproduces P_c exactly at every grid point of the window (the full solution lies in the span:
the projected model interpolates, as a rational Krylov model with those shifts does) and,
between them, to within the distance of the true response from the span. A window of four
grid points carries the poles that shape a narrow interval; a refinement follows one loop,
whose receptance needs the response to its own actuation column only, so its model has four
unknowns, and every interval's model is solved at once.

The model is not trusted (:func:`projected_refinements`): the full model is solved again at
each refined frequency, and the refinement is accepted only when the projected value agrees
with it to :data:`LOCAL_TOLERANCE` (relative); the value kept is the full model's. One that
fails is refined again on its model enriched with that full solution (the model then
interpolates there too: an adaptive rational-Krylov step), at most :data:`ENRICHMENTS` times,
then with full solves at every step.

The refinement steps are coroutines (:func:`golden_maximum`, :func:`illinois_root`): each
yields a frequency and is sent L(iω) there, so :func:`lockstep` advances many of them with one
evaluation of all their frequencies a round (one banded sweep, or one batched small solve).
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Generator, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from flexshaft.analyses.banded import BandedHarmonicSolver

__all__ = [
    "ENRICHMENTS",
    "GOLDEN",
    "LOCAL_TOLERANCE",
    "WINDOW",
    "LocalModels",
    "Refinement",
    "RefinementTask",
    "golden_maximum",
    "illinois_root",
    "lockstep",
    "projected_refinements",
    "window_of",
]

#: Largest relative difference between the projected and the full closed-loop function at a
#: refined frequency for the refinement on the projected model to be accepted. The
#: refinements themselves stop at 1e-6 (peaks, in log ω) and 1e-8 (crossovers, relative ω): a
#: function accurate to 1e-9 moves a crossover by about 1e-9/|d ln L/d ln ω| relative, below
#: their own tolerance wherever L turns at least 0.1 per unit of ln ω.
LOCAL_TOLERANCE = 1e-9
#: Grid points whose responses span an interval's basis.
WINDOW = 4
#: Times an interval whose projected result fails the check is refined again on its model
#: enriched with the full solution there, before it is refined on the full model.
ENRICHMENTS = 3


def window_of(lo: int, hi: int, size: int) -> np.ndarray:
    """The :data:`WINDOW` consecutive grid indices (of ``size``) around the interval from grid
    point ``lo`` to ``hi``: centred on it, shifted to stay inside the grid."""
    width = min(WINDOW, size)
    start = lo - (width - (hi - lo + 1)) // 2
    start = min(max(start, 0), size - width)
    return np.arange(start, start + width)


class LocalModels:
    """Projected closed-loop models of many intervals (module docstring).

    Parameters
    ----------
    solver : BandedHarmonicSolver
        The model's solver.
    speed : float
        Spin speed Ω [rad/s].
    responses : sequence of ndarray
        Full solutions ``Z(ω_j)⁻¹ Bₐ`` (n_free, n_loops) at the grid points.
    windows : sequence of sequences of int
        Each interval's indices into ``responses`` (:func:`window_of`); all of one length.
        :meth:`enriched` adds a response to a basis.
    loops : sequence of int
        The loop (column of ``rhs``, row of ``sense``) each interval refines: its basis holds
        that loop's responses only.
    rhs, sense : ndarray
        Actuation columns Bₐ (n_free, n_loops) and sensing rows Bₛᵀ (n_loops, n_free).
    gains : callable
        ``gains(ω)`` → the feedback laws G(iω) of every loop (n_loops, n_ω).
    """

    def __init__(
        self,
        solver: BandedHarmonicSolver,
        speed: float,
        responses: Sequence[np.ndarray],
        windows: Sequence[Sequence[int]],
        loops: Sequence[int] | np.ndarray,
        rhs: np.ndarray,
        sense: np.ndarray,
        gains: Callable[[np.ndarray], np.ndarray],
    ):
        self.solver, self.speed, self.gains = solver, float(speed), gains
        self.loops = np.asarray(loops, dtype=np.intp)
        self._rhs, self._sense = rhs, sense
        stacked = np.stack(
            [np.column_stack([responses[j][:, k] for j in window]) for window, k in zip(windows, self.loops)]
        )
        bases, _ = np.linalg.qr(stacked)  # (m, n_free, r), orthonormal columns
        self._set(bases, solver.project(bases))  # (m, n_terms, r, r)

    def _set(self, bases: np.ndarray, terms: np.ndarray) -> None:
        self.bases, self.terms = bases, terms
        a = self._rhs[:, self.loops].T.conj()[:, None, :]  # (m, 1, n_free)
        self.inputs = (a @ bases)[:, 0, :].conj()  # Vᴴ a
        self.outputs = (self._sense[self.loops][:, None, :] @ bases)[:, 0, :]  # sᵀ V

    def enriched(self, intervals: np.ndarray, columns: np.ndarray) -> LocalModels:
        """The models of ``intervals`` with one more basis vector each: ``columns`` (n_free,
        len(intervals)) the full responses of each interval's loop at a new frequency. The
        column is orthogonalised against the basis (classical Gram-Schmidt, twice) and only its
        row and column of the projected terms are computed (``[V q]ᴴ T_k q`` and ``qᴴ T_k V``).

        Raises
        ------
        numpy.linalg.LinAlgError
            When a column lies in its basis's span to working precision (it cannot enrich it).
        """
        intervals = np.asarray(intervals, dtype=np.intp)
        Q = self.bases[intervals]  # (m, n_free, r)
        q = np.asarray(columns, dtype=complex).T[:, :, None].copy()  # (m, n_free, 1)
        size = np.linalg.norm(q[:, :, 0], axis=1)
        for _ in range(2):
            q -= Q @ (q.conj().transpose(0, 2, 1) @ Q).conj().transpose(0, 2, 1)  # Q Qᴴ q
        norm = np.linalg.norm(q[:, :, 0], axis=1)
        if not np.all(norm > 1e-13 * size):
            raise np.linalg.LinAlgError("a new response lies in its projected model's basis")
        q /= norm[:, None, None]
        r = Q.shape[2]
        basis = np.concatenate([Q, q], axis=2)
        column = self.solver.project_pairs(basis, q)  # [V q]ᴴ T_k q: (m, n_terms, r + 1, 1)
        row = self.solver.project_pairs(q, Q)  # qᴴ T_k V: (m, n_terms, 1, r)
        terms = np.empty((Q.shape[0], column.shape[1], r + 1, r + 1), dtype=complex)
        terms[:, :, :r, :r] = self.terms[intervals]
        terms[:, :, :, r] = column[..., 0]
        terms[:, :, r, :r] = row[:, :, 0]
        out = object.__new__(LocalModels)
        out.solver, out.speed, out.gains = self.solver, self.speed, self.gains
        out.loops, out._rhs, out._sense = self.loops[intervals], self._rhs, self._sense
        out._set(basis, terms)
        return out

    def closed(self, omegas: np.ndarray, intervals: np.ndarray) -> np.ndarray:
        """T = G P_c of the loop of interval ``intervals[i]`` at ``omegas[i]`` [rad/s] on that
        interval's model (complex array)."""
        omegas = np.asarray(omegas, dtype=float)
        weights = self.solver.term_weights(omegas, np.full(omegas.size, self.speed))
        Z = np.einsum("ik,ikab->iab", weights, self.terms[intervals])
        y = np.linalg.solve(Z, self.inputs[intervals][..., None])[..., 0]
        Pc = np.einsum("ir,ir->i", self.outputs[intervals], y)
        return self.gains(omegas)[self.loops[intervals], np.arange(omegas.size)] * Pc


#: A refinement step: it yields a frequency ω [rad/s] and is sent L(iω) there.
Refinement = Generator[float, complex, Any]


def illinois_root(
    f: Callable[[complex], float], a: float, b: float, la: complex, lb: complex, tol: float
) -> Refinement:
    """A root of ``f(L(iω))`` between ``a`` and ``b`` (L there ``la``, ``lb``; f of opposite
    signs) to ``tol``: the Illinois variant of regula falsi (superlinear; scipy.optimize is not
    imported by a run). Returns (ω, L(iω)) at the root."""
    fa, fb = f(la), f(lb)
    side = 0
    last: tuple[float, complex] = (np.nan, 0j)
    for _ in range(100):
        c = b - fb * (b - a) / (fb - fa) if fb != fa else 0.5 * (a + b)
        lc = yield c
        last = (c, lc)
        fc = f(lc)
        if fc == 0 or abs(b - a) <= tol:
            return c, lc
        if (fc > 0) == (fb > 0):
            b, fb = c, fc
            if side == -1:
                fa *= 0.5
            side = -1
        else:
            a, fa = c, fc
            if side == +1:
                fb *= 0.5
            side = +1
        if abs(b - a) <= tol:
            break
    x = b - fb * (b - a) / (fb - fa) if fb != fa else 0.5 * (a + b)
    return x, (last[1] if x == last[0] else (yield x))


#: The golden section's inverse ratio (√5 − 1)/2 of a bracket's step.
GOLDEN = (np.sqrt(5.0) - 1.0) / 2.0


def golden_maximum(f: Callable[[complex], float], a: float, b: float, tol: float) -> Refinement:
    """(log ω, f(L(iω))) of the largest value of a unimodal ``f`` of L on log ω in [a, b],
    golden-section search to ``tol``."""
    c, d = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
    fc = f((yield float(np.exp(c))))
    fd = f((yield float(np.exp(d))))
    while b - a > tol:
        if fc >= fd:
            b, d, fd = d, c, fc
            c = b - GOLDEN * (b - a)
            fc = f((yield float(np.exp(c))))
        else:
            a, c, fc = c, d, fd
            d = a + GOLDEN * (b - a)
            fd = f((yield float(np.exp(d))))
    return (c, fc) if fc >= fd else (d, fd)


def lockstep(tasks: Sequence[Refinement], evaluate: Callable[[np.ndarray, np.ndarray], np.ndarray]) -> list:
    """Run refinement steps together: at each round every unfinished step's frequency is
    evaluated in one call ``evaluate(ω, task index)`` → L(iω) (one banded sweep for them all);
    the steps are those run one after another, so are their results."""
    results: list = [None] * len(tasks)
    pending: dict[int, float] = {}

    def advance(i: int, value: complex | None) -> None:
        try:
            pending[i] = next(tasks[i]) if value is None else tasks[i].send(value)
        except StopIteration as stop:
            results[i] = stop.value
            pending.pop(i, None)

    for i in range(len(tasks)):
        advance(i, None)
    while pending:
        keys = np.array(list(pending))
        values = evaluate(np.array([pending[i] for i in keys]), keys)
        for i, value in zip(keys, values):
            advance(int(i), complex(value))
    return results


@dataclass(frozen=True)
class RefinementTask:
    """One refinement of :func:`~flexshaft.analyses.loop_margins.refinements`: a ``"peak"``
    (its result (ln ω, |S|)), a ``"root"`` (its result (ω, L)) or, in the margins' second
    round, a ``"dip"`` (its result a list of (ω, L):
    :func:`~flexshaft.analyses.loop_dips.dip_crossovers`) between grid points ``lo`` and
    ``hi``; ``start()`` makes its steps; ``role`` says what a root is of (``"gain"``: |L| = 1,
    ``"phase"``: Im L = 0), for the caller's release rule (:func:`projected_refinements`)."""

    kind: str
    lo: int
    hi: int
    start: Callable[[], Refinement]
    role: str = ""


def _on_local(local: LocalModels, omegas: np.ndarray, intervals: np.ndarray) -> np.ndarray:
    """L(iω) on the projected models of ``intervals``."""
    T = local.closed(omegas, intervals)
    return T / (1.0 - T)


#: Step in ln ω of the central differences that give the derivatives d L/d ln ω and
#: d²L/d ln ω² of a projected model at a refined frequency (the release rule's): the model is a
#: smooth rational function of ω; the round-off of the second difference, 4e-16/h² = 4e-6
#: of |L|, is far below what the rule reads (it needs the derivatives to a few per cent).
SLOPE_STEP = 1e-5


def projected_refinements(
    tasks: Sequence[RefinementTask],
    evaluate: Callable[..., np.ndarray],
    local_models: Callable[[Sequence[Sequence[int]], np.ndarray], LocalModels],
    windows: Sequence[Sequence[int]],
    settle: Callable[..., np.ndarray] | None = None,
) -> list:
    """The refinements on the projected models of their intervals, each checked by one full
    solve at its result (:mod:`flexshaft.analyses.local_projection`): the full model's value is
    returned. A refinement whose projected value differs from it by more than
    :data:`LOCAL_TOLERANCE` is run again with that solution added to its basis
    (:meth:`LocalModels.enriched`: the model then interpolates there too), at most
    :data:`ENRICHMENTS` times; then on the full model, as is one whose projected model gives no
    finite frequency, is singular, or cannot be enriched. ``local_models(windows, tasks)``
    makes the first models, ``windows[i]`` the grid responses of task i's first basis;
    ``evaluate(ω, tasks, keep)`` solves the full model at each task's ω and appends the
    response of the task's loop (n_free,) to ``keep``.

    ``settle(tasks, ω, L, dL/d ln ω, d²L/d ln ω², accepted)``, when given, is called after each
    round's checks with every checked task, its frequency, the full model's L there, the
    projected model's first two derivatives there and whether the check passed; it returns which tasks that failed may
    keep that result instead of being refined further (the caller's rule: a crossover that
    cannot set a margin, :func:`~flexshaft.analyses.loop_margins.release_rule`)."""
    # a dip's search returns a list of crossings, not one (ω, L): it runs on full solves
    assert all(task.kind != "dip" for task in tasks), "dip searches are not projected"
    results: list = [None] * len(tasks)
    active = np.arange(len(tasks))
    fallback: list[int] = []  # refined on the full model at the end
    local = None
    for round_ in range(ENRICHMENTS + 1):
        if not active.size:
            break
        try:
            with np.errstate(all="ignore"):
                if local is None:
                    local = local_models([windows[int(i)] for i in active], active)
                found = lockstep([tasks[int(i)].start() for i in active], functools.partial(_on_local, local))
        except np.linalg.LinAlgError:  # a singular projected model: refine these on the full one
            break
        at = np.array([np.exp(x) if tasks[int(i)].kind == "peak" else x for i, (x, _) in zip(active, found)])
        finite = np.isfinite(at) & (at >= 0)  # a projected model gone astray is refined on full solves
        fallback += [int(i) for i in active[~finite]]
        checked: list[np.ndarray] = []
        full = np.full(at.size, np.nan, dtype=complex)
        full[finite] = evaluate(at[finite], active[finite], checked)
        slot = np.cumsum(finite) - 1  # where each checked solution was appended
        passed = np.zeros(at.size, dtype=bool)
        for n, (i, (_, value), exact) in enumerate(zip(active, found, full)):
            if finite[n]:
                exact = abs(1.0 / (1.0 + exact)) if tasks[int(i)].kind == "peak" else exact
                passed[n] = abs(value - exact) <= LOCAL_TOLERANCE * abs(exact)
        released = np.zeros(at.size, dtype=bool)
        if settle is not None and finite.any():
            where = np.flatnonzero(finite)
            h = SLOPE_STEP
            shifted = np.concatenate([at[where] * np.exp(h), at[where], at[where] * np.exp(-h)])
            with np.errstate(all="ignore"):
                up, mid, down = np.split(_on_local(local, shifted, np.tile(where, 3)), 3)
            slope, curvature = (up - down) / (2.0 * h), (up - 2.0 * mid + down) / (h * h)
            released[where] = settle(active[where], at[where], full[where], slope, curvature, passed[where])
        retry = []
        for n, (i, (x, _), exact) in enumerate(zip(active, found, full)):
            if not finite[n]:
                continue
            if passed[n] or released[n]:
                results[int(i)] = (x, abs(1.0 / (1.0 + exact)) if tasks[int(i)].kind == "peak" else exact)
            else:
                retry.append(n)
        new = [checked[slot[n]] for n in retry]
        active = active[retry]
        if active.size and round_ < ENRICHMENTS:  # the model enriched with the full solution there
            columns = np.column_stack(new)
            try:
                with np.errstate(all="ignore"):
                    local = local.enriched(np.array(retry, dtype=np.intp), columns)
            except np.linalg.LinAlgError:
                break
    fallback += [int(i) for i in active]
    if fallback:
        which = np.array(fallback)
        redone = lockstep([tasks[i].start() for i in fallback], lambda omegas, k: evaluate(omegas, which[k]))
        for j, result in zip(fallback, redone):
            results[j] = result
    return results

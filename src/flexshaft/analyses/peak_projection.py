r"""The unbalance response near one critical speed from a small projected model, checked by full solves.

A critical speed's amplification factor needs its peak sampled finely: each round of
:func:`~flexshaft.analyses.separation.resolve_peak` evaluates the synchronous response at 41 new
speeds across the peak, and a peak takes two to four rounds, each speed a banded solve of the
whole model (:mod:`flexshaft.analyses.banded`). Across one peak the response lives in the span
of a few responses around it: with ``X_j = Z(Ω_j, Ω_j)⁻¹ Q₁`` at a few speeds Ω_j near the peak
(Q₁ the imbalance load per Ω², Z the dynamic stiffness at ω = Ω) and V an orthonormal basis of
them, the Galerkin model

.. math:: Vᴴ Z(Ω, Ω) V\, y = Ω² Vᴴ Q₁,\qquad q ≈ V y

(a rational Krylov model with those shifts) reproduces the response exactly at each Ω_j and,
between them, to within the distance of the true response from the span: a peak shaped by one
mode pair is carried by three responses across it.

The model is not trusted (:class:`ProjectedOrbit`): in every round the full model is solved again
at the samples that make the peak's reported numbers (every local maximum and minimum of the
projected orbit with its neighbours, the ends, and the two samples on each side of each
maximum's half-power level, where the bandwidth is interpolated: :func:`_checked_samples`), and the
round is accepted only when the projected orbit agrees there with the full one to
:data:`PEAK_TOLERANCE` (relative); the values kept there are the full model's. A round that
fails is evaluated again on its model enriched with those full solutions (the model then
interpolates there too), at most :data:`PEAK_ENRICHMENTS` times, then with full solves at every
speed. tests/test_peak_projection.py compares the critical speeds and amplification factors
with the all-full refinement; tests/test_spinup_projection.py does too with the models started
from the spin-up scan's reduced basis (:class:`PeakBasis`), as an assessment does.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg

from flexshaft.analyses.banded import BandedHarmonicSolver, solver_for
from flexshaft.analyses.response import orbit_amplitude
from flexshaft.assembly.model import Model

__all__ = ["PEAK_ENRICHMENTS", "PEAK_TOLERANCE", "PeakBasis", "ProjectedOrbit"]

#: Largest relative difference between the projected and the full orbit at a checked sample for a
#: round to be accepted. A critical speed is resolved to a 20th of its half-power bandwidth and
#: its AF to about 0.5 % (:func:`~flexshaft.analyses.separation.resolve_peak`): an orbit accurate
#: to 1e-7 moves the interpolated half-power speeds and the vertex by ~1e-7 relative, far below
#: that. It cannot be much smaller: near a peak of amplification ~50-2000 the full banded solve
#: itself, and the projected model's, carry round-off of κ(Z) ε ≈ 1e-10-1e-9 (the two were
#: seen to disagree by up to 6e-8 with the span holding the full solution there).
PEAK_TOLERANCE = 1e-7
#: Times a round that fails the check is evaluated again on an enriched model before it is
#: evaluated with full solves.
PEAK_ENRICHMENTS = 3
#: Columns of the basis whose R-factor diagonal falls below this fraction of the largest are
#: dropped (a response already in the span).
_RANK_TOLERANCE = 1e-12


class ProjectedOrbit:
    """Orbit amplitude [m] at one shaft node under one imbalance case, over speed, from a
    projected model of the response near a peak (module docstring).

    Parameters
    ----------
    model : Model
        The assembled model.
    load : ndarray
        Imbalance load per Ω² on the full DOF vector (ndof,) [N s²].
    rows : (int, int)
        The node's v and w DOF indices.
    speeds : array_like
        Speeds [rad/s] whose full responses start the basis (e.g. the scan's samples around the
        peak).
    basis : ndarray or PeakBasis, optional
        Columns (n_free, r) on the free DOFs that start the basis instead (e.g. the spin-up scan's
        reduced basis, :mod:`flexshaft.analyses.sweep_projection`: no full solve to start), or
        a :class:`PeakBasis` of them already projected (shared by the peaks of one scan).

    Calling it with new speeds [rad/s] returns the orbit there (checked as the module docstring
    says); ``full_solves`` counts the banded solves it made.
    """

    def __init__(self, model: Model, load: np.ndarray, rows: tuple[int, int], speeds, basis=None) -> None:
        self.solver = solver_for(model)
        free = self.solver.free
        local = np.full(model.dofs.size, -1, dtype=np.intp)
        local[free] = np.arange(free.size)
        self.rows = local[np.asarray(rows, dtype=np.intp)]
        if np.any(self.rows < 0):
            raise ValueError("the orbit's DOFs must be free")
        self.rhs = np.asarray(load, dtype=complex)[free]
        self.full_solves = 0
        self.columns: list[np.ndarray] = []
        if isinstance(basis, PeakBasis):
            self.columns.extend(basis.columns)
            self._use(basis.basis, basis.terms)
        elif basis is None:
            self._enrich(np.asarray(speeds, dtype=float))
        else:
            self._enrich(np.zeros(0), np.asarray(basis, dtype=complex))

    def _full(self, speeds: np.ndarray) -> np.ndarray:
        """Full responses Z(Ω, Ω)⁻¹ Ω² Q₁ (n_free, n_speeds)."""
        self.full_solves += speeds.size
        return np.column_stack(
            [x * s * s for x, s in zip(self.solver.sweep([(s, s) for s in speeds], self.rhs), speeds)]
        )

    def _orbit(self, q: np.ndarray) -> np.ndarray:
        return orbit_amplitude(q[self.rows[0]], q[self.rows[1]])

    def _enrich(self, speeds: np.ndarray, solutions: np.ndarray | None = None) -> None:
        """Add the full responses at ``speeds`` to the basis and project the model on it."""
        X = self._full(speeds) if solutions is None else solutions
        self.columns.extend(X.T)
        self._use(*_projection(self.solver, self.columns))

    def _use(self, basis: np.ndarray, terms: np.ndarray) -> None:
        """Take ``basis`` V (n_free, r) with the projected terms Vᴴ T_k V (n_terms, r, r)."""
        self.basis = basis
        self.terms = terms
        self.inputs = basis.conj().T @ self.rhs
        self.outputs = basis[self.rows]  # (2, r)

    def projected(self, speeds: np.ndarray) -> np.ndarray:
        """Orbit [m] at ``speeds`` on the projected model (NaN where it is singular)."""
        weights = self.solver.term_weights(speeds, speeds)
        r = self.basis.shape[1]
        Z = (weights @ self.terms.reshape(-1, r * r)).reshape(-1, r, r)
        try:
            y = np.linalg.solve(Z, np.broadcast_to(self.inputs, (speeds.size, self.inputs.size))[..., None])[..., 0]
        except np.linalg.LinAlgError:
            return np.full(speeds.size, np.nan)
        q = (y * (speeds * speeds)[:, None]) @ self.outputs.T  # (n_speeds, 2)
        return orbit_amplitude(q[:, 0], q[:, 1])

    def __call__(self, speeds) -> np.ndarray:
        speeds = np.asarray(speeds, dtype=float)
        if speeds.size == 0:
            return np.zeros(0)
        exact: dict[int, float] = {}  # the samples solved in full in this call: their values
        for _ in range(PEAK_ENRICHMENTS + 1):
            values = self.projected(speeds)
            if not np.all(np.isfinite(values)):
                break
            for i, v in exact.items():
                values[i] = v
            fresh = np.array([i for i in _checked_samples(values) if i not in exact], dtype=np.intp)
            if fresh.size == 0:
                return values
            X = self._full(speeds[fresh])
            full = self._orbit(X)
            agree = np.all(np.abs(values[fresh] - full) <= PEAK_TOLERANCE * np.abs(full))
            exact.update(zip(fresh.tolist(), full.tolist()))
            if agree:
                values[fresh] = full
                return values
            self._enrich(speeds[fresh], X)  # the model then interpolates there: evaluate again
        return self._orbit(self._full(speeds))


class PeakBasis:
    """A basis that starts many :class:`ProjectedOrbit` of one model (e.g. one per critical
    speed of a scan), orthonormalised and projected once: ``columns`` (n_free, r) on the free
    DOFs, e.g. the spin-up scan's reduced basis (:mod:`flexshaft.analyses.sweep_projection`)."""

    def __init__(self, model: Model, columns: np.ndarray, rank_tolerance: float = _RANK_TOLERANCE) -> None:
        self.columns = list(np.asarray(columns, dtype=complex).T)
        self.basis, self.terms = _projection(solver_for(model), self.columns, rank_tolerance)


def _projection(
    solver: BandedHarmonicSolver, columns: list[np.ndarray], rank_tolerance: float = _RANK_TOLERANCE
) -> tuple[np.ndarray, np.ndarray]:
    """An orthonormal basis V of the span of ``columns`` (each normalised first; directions whose
    R-factor diagonal falls below ``rank_tolerance`` of the largest dropped) and the projected
    terms Vᴴ T_k V (n_terms, r, r) of the solver's Z."""
    A = np.column_stack(columns)
    A = A / np.maximum(np.linalg.norm(A, axis=0), np.finfo(float).tiny)
    # pivoted: dropping a column of an unpivoted Q would drop its share of every later column
    Q, R, _ = scipy.linalg.qr(A, mode="economic", pivoting=True, check_finite=False)
    diag = np.abs(np.diag(R))
    V = Q[:, : max(int(np.count_nonzero(diag > rank_tolerance * diag[0])), 1)]
    return V, solver.project(V[None])[0]


def _checked_samples(values: np.ndarray) -> np.ndarray:
    """Indices of the samples that make a peak's numbers
    (:func:`~flexshaft.analyses.separation.resolve_peak`): every local maximum and minimum with
    its two neighbours (the parabolic vertex, a flanking minimum above the half-power level),
    and around each local maximum the two samples on each side of its half-power level
    (max/√2), where the bandwidth is interpolated. A sample the projected model gets wrong
    enough to make or unmake an extremum is itself an extremum of one curve, so checked."""
    n = values.size
    inner = np.arange(1, n - 1)
    maxima = inner[(values[1:-1] >= values[:-2]) & (values[1:-1] >= values[2:])]
    minima = inner[(values[1:-1] <= values[:-2]) & (values[1:-1] <= values[2:])]
    ends = [k for k in (0, n - 1) if n > 0]
    out: set[int] = set(ends)
    for m in np.concatenate([maxima, minima, [int(np.argmax(values))]]).astype(int):
        out.update((m - 1, m, m + 1))
    for m in list(maxima) + [int(np.argmax(values))]:
        level = values[m] / np.sqrt(2.0)
        below = np.flatnonzero(values[:m] < level)
        if below.size:
            out.update((int(below[-1]), int(below[-1]) + 1))
        above = np.flatnonzero(values[m + 1 :] < level)
        if above.size:
            out.update((m + int(above[0]), m + 1 + int(above[0])))
    return np.array(sorted(k for k in out if 0 <= k < n), dtype=np.intp)

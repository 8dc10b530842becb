r"""The synchronous imbalance response over a whole speed scan from a greedy reduced basis, checked.

A spin-up scan solves ``Z(Ω, Ω) q(Ω) = Ω² Q₁`` (Z the dynamic stiffness at ω = Ω,
:mod:`flexshaft.analyses.banded`; Q₁ the imbalance load per Ω², one column per load case) at a
few hundred speeds, one banded factorisation each. Over the scan the responses live in a space of
small dimension: each critical speed adds the one or two mode shapes that peak there, and the
rest varies slowly. :func:`imbalance_sweep` builds that space greedily (a reduced basis):

0. The load cases are reduced to their linearly independent columns (the ``worst`` placement's
   in/anti-phase patterns are combinations of a few bay forces); those are solved and the cases
   combined from their responses afterwards (the response is linear in the load).
1. Full solutions at 13 speeds spread over the scan (:data:`_INITIAL_SNAPSHOTS`), orthonormalised
   with column pivoting (V); the Galerkin model ``Vᴴ Z(Ω, Ω) V y = Ω² Vᴴ Q₁``, ``q ≈ V y``, is
   evaluated at every speed of the scan. Z is a sum of fixed sparse terms with scalar weights
   (:meth:`~flexshaft.analyses.banded.BandedHarmonicSolver.term_weights`); over the scan the
   weights span few functions of Ω (a PD-controlled driveline with hysteretic loss: 1, Ω and
   Ω²), so they are compressed once (:class:`_Terms`: an SVD of the weight table with every
   term scaled by its size, the tail dropped below :data:`_WEIGHT_RANK` of ‖Z‖), and the reduced
   model is a sum of p (3 on the embedded designs) small matrices: one dense r × r solve per
   speed (r ≈ 20-30 on the embedded designs, ~15 µs, against ~200 µs for a banded solve of the
   baseline's full model).
2. Where to solve next: the full model's residual ``r(Ω) = Ω² Q₁ − Z V y`` is computed exactly
   and cheaply at every speed (``Z V y = Σ_j c_j(Ω) (T_j V) y``: its norm is that of ``R u(Ω)``
   with R the triangular factor of ``[T_1 V … T_p V, Q₁]``, no factorisation of Z), times the
   model's own amplification ``‖y‖/‖Ω² Vᴴ Q₁‖`` as a proxy of ‖Z⁻¹‖. Each round solves the full
   model at the (at most 16, :data:`_SNAPSHOTS_PER_ROUND`) largest local maxima of that indicator,
   always including its largest, and enriches the basis.
3. The error estimate, at every speed, is twice (:data:`_SAFETY`) the change of the outputs the
   checks read between the model before and after the round's enrichment (a hierarchical
   estimate; the first "before" is the model on the scan's two ends): the shaft's orbits (v, w
   at every node) and each magnetic bearing's actuation and sensing displacements, each group
   relative to its own peak over the scan. The scan is accepted when it is below ``tolerance``
   everywhere. At the speeds just solved in full the change *is* the previous model's true
   error (the new model reproduces the full solution there), so acceptance means that the full
   model, solved where the previous model's residual indicator was worst, agreed with it, and
   that adding those solutions moved no output anywhere by more than the tolerance. With e_old
   and e_new the two models' errors, the change c satisfies ``|e_old − e_new| ≤ c ≤ e_old +
   e_new``; once an enrichment at least halves the error (the Galerkin error is quasi-optimal
   and the span's distance from the response falls geometrically as the basis takes in the
   peaks' modes), ``2c`` bounds e_old, within a factor 3, and so bounds e_new too. The returned
   values are the enriched model's (the full solutions where computed); the estimate is then a
   bound, usually a loose one: tests/test_spinup_projection.py measured ``2c`` between 1.9 and
   2.1 times e_old, and e_new at the full solutions' round-off (1e-11 of the peak) once accepted.

Why this estimate and not ``‖Z⁻¹‖ ‖r‖``: a sharp ‖Z(Ω)⁻¹‖ at every speed would cost a
factorisation per speed, which is what the projection avoids, and its cheap proxies are
neither bounds nor sharp (on the tuned design ``‖r‖/σ_min(Vᴴ Z V)`` was between 0.06 and 1e3
times the true error: the residual is Galerkin-orthogonal to the basis, which holds the
resonant modes). The residual is kept for the choice of speeds, where only its ranking matters.

It is not trusted where it cannot be:

* a scan of fewer than :data:`_SMALLEST_SCAN` speeds, or one not increasing, is solved in full;
* a reduced model singular or non-finite at any speed, a basis of more than
  :data:`_LARGEST_BASIS` columns (its dense solves would cost about the banded ones), or a
  greedy that would need full solves at more than :data:`_FULL_FRACTION` of the speeds before it
  is accepted, gives way to full solves at every speed not yet solved (those already solved are
  kept);
* a speed where the reduced model's sensitivity to the excitation frequency,
  ``κ_ω = ω ‖Zr⁻¹ (∂Zr/∂ω) y‖ / ‖y‖`` (the full solver's resonance measure,
  :mod:`flexshaft.analyses.banded`), exceeds a tenth of ``1/RESONANCE_TOLERANCE`` is solved in
  full (κ_ω peaks with the response: it is evaluated at the local maxima of ‖y‖ and their
  neighbours): a near-undamped resonance is then reported
  (:class:`~flexshaft.analyses.banded.ResonanceWarning` or
  :class:`~flexshaft.analyses.banded.SingularSystemError`) exactly as by the all-full sweep.

:data:`SWEEP_TOLERANCE` is 1e-8, ten times below the 1e-7 (relative to each quantity's peak over
the scan) to which tests/test_spinup_projection.py holds every number the checks read against
the all-full sweep (orbits, actuator orbits and forces, critical speeds and amplification
factors): the margin covers an actuator force, the displacement times a law whose magnitude
changes by less than that factor over a scan. It costs nothing here (convergence is geometric:
on the embedded designs the rounds that reach 1e-4 reach 1e-8 too, 43-45 full solves at
SCREENING and at REPORT) and stays well above round-off (the banded solution and SuperLU's
agree to ~1e-11 of the peak); a critical speed is resolved to a 20th of its bandwidth and its
AF to 0.5 %, far coarser than either.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg
import scipy.sparse as sp

from flexshaft.analyses.banded import RESONANCE_TOLERANCE, BandedHarmonicSolver, solver_for
from flexshaft.analyses.guards import check_finite_array, check_model, check_spin_speeds, require_finite
from flexshaft.analyses.response import HarmonicResponse
from flexshaft.assembly.model import Model

__all__ = ["SWEEP_TOLERANCE", "SweepResult", "imbalance_sweep"]

#: Largest change of an output (relative to its peak over the scan) the last enrichment may make
#: for the scan to be accepted (module docstring).
SWEEP_TOLERANCE = 1e-8
#: Speeds solved in full to start the basis (evenly spread, the ends included).
_INITIAL_SNAPSHOTS = 13
#: Most speeds solved in full per round (the largest local maxima of the indicator).
_SNAPSHOTS_PER_ROUND = 16
#: Scans shorter than this are solved in full (the rounds would cost more than they save).
_SMALLEST_SCAN = 40
#: Fraction of the speeds beyond which the greedy gives way to full solves.
_FULL_FRACTION = 0.4
#: Largest reduced basis: the dense solve costs ∝ r³ per speed (~15 µs at r = 30), and at
#: r ≈ 60 the three or four evaluations of a scan cost about a banded solve of the baseline's 343
#: free DOFs (~0.2 ms) per speed (a design with many independent load cases or many criticals in
#: its scan is solved in full).
_LARGEST_BASIS = 48
#: Columns of the snapshot matrix whose R-factor diagonal falls below this fraction of the largest
#: are dropped (a solution already in the span).
_RANK_TOLERANCE = 1e-12
#: Singular values of the scaled weight table below this fraction of the largest are dropped.
_WEIGHT_RANK = 1e-14
#: Factor on the change of the outputs that makes the error estimate (module docstring).
_SAFETY = 2.0
#: Fraction of ``1/RESONANCE_TOLERANCE`` above which a speed's reduced κ_ω sends it to a full solve.
_RESONANCE_MARGIN = 0.1


@dataclass(frozen=True)
class SweepResult:
    """The imbalance response over a scan with its error estimate.

    Attributes
    ----------
    response : HarmonicResponse
        Complex amplitudes (ndof, n_cases, n_speeds) [m, rad].
    error_estimate : ndarray
        Estimated error of the checked outputs at each speed, relative to each output group's
        peak over the scan [-] (n_speeds,); 0 where solved in full (module docstring).
    full : ndarray of bool
        The speeds solved in full (n_speeds,).
    basis_size : int
        Columns of the final reduced basis (0: every speed solved in full).
    rounds : int
        Greedy rounds (enrichments) made.
    basis : ndarray or None
        The final reduced basis V (n_free, basis_size) on the free DOFs, orthonormal: every
        response of the scan lies in its span (but those solved in full after the last
        enrichment, near an undamped resonance); None when every speed was solved in full.
    """

    response: HarmonicResponse
    error_estimate: np.ndarray
    full: np.ndarray
    basis_size: int
    rounds: int
    basis: np.ndarray | None = None
    _previous: tuple | None = None

    @property
    def previous(self) -> HarmonicResponse | None:
        """The reduced model before the last enrichment, at every speed (the values whose error
        the estimate measures, for the tests; None when every speed was solved in full)."""
        if self._previous is None:
            return None
        basis, coordinates, free, combination = self._previous
        q = np.zeros_like(np.asarray(self.response))
        q[free] = _cases(np.matmul(basis, coordinates).transpose(1, 2, 0), combination)
        r = self.response
        return HarmonicResponse(q, r.frequencies, r.spin_speeds, r.dofs, r.excitation, r.internal_damping)

    @property
    def full_solves(self) -> int:
        """Banded solves made (one per speed solved in full, for all load cases at once)."""
        return int(np.count_nonzero(self.full))


def _term_stack(solver: BandedHarmonicSolver) -> tuple[sp.csr_matrix, np.ndarray]:
    """Every non-zero term of the solver's Z stacked (n_terms n_free, n_free), in the free-DOF
    ordering, and each term's largest |entry| (1 for none)."""
    stack = solver.term_stack
    sizes = np.zeros(len(solver.term_names))
    coo = stack.tocoo()
    np.maximum.at(sizes, coo.row // solver.n, np.abs(coo.data))
    return stack, np.where(sizes > 0, sizes, 1.0)


class _Terms:
    """Z(Ω, Ω) over a scan as ``Σ_j c_j(Ω) T'_j``: coefficients c (n_speeds, p) and the
    combinations B (p, n_terms) of the terms T_k with ``term_weights ≈ c B`` to
    :data:`_WEIGHT_RANK` of ‖Z‖ (each term scaled by its largest entry before the SVD, so that a
    small weight on a large term is kept); and which terms make ∂Z/∂ω = −2ωM + i(ΩG + C), for the
    resonance measure."""

    def __init__(self, solver: BandedHarmonicSolver, speeds: np.ndarray):
        names = solver.term_names
        self.stack, sizes = _term_stack(solver)
        u, s, vh = np.linalg.svd(solver.term_weights(speeds, speeds) * sizes, full_matrices=False)
        p = max(int(np.count_nonzero(s > _WEIGHT_RANK * s[0])), 1) if s.size and s[0] > 0 else 1
        self.coefficients = u[:, :p] * s[:p]
        self.combos = vh[:p] / sizes
        self.derivative = [names.index(x) if x in names else None for x in ("M", "G", "C")]
        self.p = p
        self.n = solver.n

    def apply(self, V: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``T'_j V`` (p, n, r) and ``M V, G V, C V`` (3, n, r; zero for an absent term)."""
        products = (self.stack @ V).reshape(-1, self.n, V.shape[1])
        merged = np.tensordot(self.combos, products, axes=1)
        zero = np.zeros_like(products[0])
        return merged, np.stack([zero if k is None else products[k] for k in self.derivative])


def _output_rows(model: Model, free: np.ndarray) -> list[sp.csr_matrix]:
    """The outputs the checks read, by group, on the free DOFs: the shaft's v and w at every
    node, and each magnetic bearing's actuation and sensing displacements."""
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    rows = np.concatenate([dm.shaft(nodes, "v"), dm.shaft(nodes, "w")])
    select = sp.csr_matrix((np.ones(rows.size), (np.arange(rows.size), rows)), shape=(rows.size, dm.size))
    groups = [select]
    for a in model.actuators:
        groups.append(a.lateral_rows.tocsr())
        if not a.collocated:
            groups.append(a.sensing_rows.tocsr())
    return [g[:, free].tocsr() for g in groups]


class _ReducedModel:
    """The Galerkin model on the span of the full solutions computed so far."""

    def __init__(self, terms: _Terms, snapshots: np.ndarray, rhs: np.ndarray):
        A = snapshots / np.maximum(np.linalg.norm(snapshots, axis=0), np.finfo(float).tiny)
        # pivoted: the columns kept span every snapshot but the dropped part (without pivoting,
        # dropping a column of Q would drop its share of every later snapshot too)
        Q, R, _ = scipy.linalg.qr(A, mode="economic", pivoting=True, check_finite=False)
        diag = np.abs(np.diag(R))
        self.V = Q[:, : max(int(np.count_nonzero(diag > _RANK_TOLERANCE * diag[0])), 1)]
        merged, derivative = terms.apply(self.V)
        self.reduced = np.matmul(self.V.conj().T, merged)  # (p, r, r)
        self.derivative = np.matmul(self.V.conj().T, derivative)  # (3, r, r)
        self.inputs = self.V.conj().T @ rhs  # (r, c)
        # the residual's norm: ‖[T_1 V … T_p V, Q₁] u‖ = ‖R u‖ (QR of the stacked products,
        # when an indicator is asked for)
        self._stacked = np.concatenate([merged.transpose(1, 0, 2).reshape(rhs.shape[0], -1), rhs], axis=1)

    @property
    def size(self) -> int:
        return self.V.shape[1]

    def matrices(self, coefficients: np.ndarray) -> np.ndarray:
        """The reduced dynamic stiffness ``Vᴴ Z V`` at each speed (n_speeds, r, r)."""
        r = self.size
        return (coefficients @ self.reduced.reshape(self.reduced.shape[0], r * r)).reshape(-1, r, r)

    def solve(self, coefficients: np.ndarray, speeds: np.ndarray) -> np.ndarray:
        """Reduced coordinates y (n_speeds, r, c) of Ω² Q₁ (LinAlgError when singular)."""
        y = np.linalg.solve(self.matrices(coefficients), self.inputs[None] * (speeds * speeds)[:, None, None])
        if not np.all(np.isfinite(y)):
            raise np.linalg.LinAlgError("the reduced model is singular")
        return y

    def indicator(self, coefficients: np.ndarray, speeds: np.ndarray, y: np.ndarray) -> np.ndarray:
        """‖r(Ω)‖ ‖y‖ / ‖Ω² Vᴴ Q₁‖ at each speed (largest over the load cases): where to solve next."""
        p, c = coefficients.shape[1], y.shape[2]
        u = np.concatenate(
            [coefficients[:, j, None, None] * y for j in range(p)]
            + [np.broadcast_to(-(speeds * speeds)[:, None, None] * np.eye(c), (speeds.size, c, c))],
            axis=1,
        )  # (n_speeds, p r + c, c)
        R = np.linalg.qr(self._stacked, mode="r")
        residual = np.linalg.norm(np.matmul(R, u), axis=1)  # (n_speeds, c)
        load = np.linalg.norm(self.inputs, axis=0)[None] * (speeds * speeds)[:, None]
        gain = np.linalg.norm(y, axis=1) / np.maximum(load, np.finfo(float).tiny)
        return (residual * gain).max(axis=1)

    def sensitivity(self, coefficients, speeds: np.ndarray, y: np.ndarray) -> np.ndarray:
        """κ_ω = ω ‖Zr⁻¹ (∂Zr/∂ω) y‖ / ‖y‖ at each speed (largest over the load cases), with
        ∂Z/∂ω = −2ωM + i(ΩG + C) at ω = Ω."""
        M, G, C = self.derivative
        dZ = -2 * speeds[:, None, None] * M + 1j * (speeds[:, None, None] * G + C)
        dy = np.linalg.solve(self.matrices(coefficients), dZ @ y)
        size = np.linalg.norm(y, axis=1)
        change = np.linalg.norm(dy, axis=1)
        return speeds * (change / np.maximum(size, np.finfo(float).tiny)).max(axis=1)


def _local_maxima(values: np.ndarray) -> np.ndarray:
    """Indices of the local maxima of ``values`` (the ends included), largest first."""
    n = values.size
    padded = np.concatenate([[-np.inf], values, [-np.inf]])
    peaks = np.flatnonzero((padded[1:-1] >= padded[:-2]) & (padded[1:-1] >= padded[2:]) & (values > 0))
    return peaks[np.argsort(-values[peaks], kind="stable")] if n else peaks


def imbalance_sweep(model: Model, speeds, loads_per_speed_squared, tolerance: float = SWEEP_TOLERANCE) -> SweepResult:
    """The synchronous response to ``Ω² Q₁ e^{iΩt}`` at every speed of a scan, from a greedy
    reduced basis checked by full solves (module docstring).

    Parameters
    ----------
    speeds : array_like
        Spin speeds Ω [rad/s], increasing (the excitation frequency equals the speed).
    loads_per_speed_squared : ndarray
        Q₁ (ndof, n_cases) [N s²], e.g. from :func:`flexshaft.assembly.loads.imbalance_loads`.
    tolerance : float
        Largest estimated error of the checked outputs, relative to each one's peak over the scan.

    Returns
    -------
    SweepResult
        The response (ndof, n_cases, n_speeds) [m, rad] with its error estimate.
    """
    check_model(model)
    speeds = check_spin_speeds(speeds)
    Q = check_finite_array("loads_per_speed_squared", loads_per_speed_squared, "N s²")
    if Q.ndim != 2 or Q.shape[0] != model.dofs.size:
        raise ValueError(f"loads_per_speed_squared must have shape ({model.dofs.size}, ncases) (got {Q.shape})")
    if not (np.isfinite(tolerance) and 0 < tolerance < 1):
        raise ValueError(f"tolerance must be in (0, 1) (got {tolerance!r})")
    solver = solver_for(model)
    free = solver.free
    # the cases are combinations of their independent loads (the "worst" placement's in/anti-phase
    # patterns of a few bay forces): those are solved, the cases combined from them
    rhs, combination = _independent(Q[free].astype(complex))
    ns = speeds.size
    X = np.zeros((solver.n, rhs.shape[1], ns), dtype=complex)  # full solutions where computed
    full = np.zeros(ns, dtype=bool)

    def solve_full(indices) -> None:
        indices = np.asarray(indices, dtype=np.intp)
        points = [(s, s) for s in speeds[indices]]
        for k, x in zip(indices, solver.sweep(points, rhs)):
            X[:, :, k] = x * speeds[k] ** 2
        full[indices] = True

    result = None
    if ns >= _SMALLEST_SCAN and np.all(np.diff(speeds) > 0) and np.any(rhs):
        result = _greedy(model, solver, speeds, rhs, combination, X, full, solve_full, tolerance)
    if result is None:  # every speed not yet solved, in full
        solve_full(np.flatnonzero(~full))
        result = X, None, np.zeros(ns), None, 0
    q, q_previous, estimate, basis, rounds = result

    def response(values):
        out = np.zeros((model.dofs.size, Q.shape[1], ns), dtype=complex)
        out[free] = _cases(values, combination)
        require_finite("imbalance response", out)
        return HarmonicResponse(out, speeds, speeds, model.dofs, "imbalance", model.internal_damping)

    previous = None if q_previous is None else (*q_previous, free, combination)
    q = np.where(full[None, None, :], X, q)
    size = 0 if basis is None else basis.shape[1]
    return SweepResult(response(q), np.where(full, 0.0, estimate), full, size, rounds, basis, previous)


def _independent(loads: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Independent columns B of ``loads`` (n, c) and C (k, c) with ``loads = B C`` (pivoted QR,
    rank to 1e-12; B = loads and C = I when they all are, or when B C misses by more than
    round-off)."""
    c = loads.shape[1]
    if c == 1:
        return loads, np.eye(1)
    _, R, order = scipy.linalg.qr(loads, mode="economic", pivoting=True, check_finite=False)
    diag = np.abs(np.diag(R))
    k = max(int(np.count_nonzero(diag > _RANK_TOLERANCE * diag[0])), 1) if diag[0] > 0 else c
    if k == c:
        return loads, np.eye(c)
    B = loads[:, np.sort(order[:k])]
    C = np.linalg.lstsq(B, loads, rcond=None)[0]
    if np.abs(B @ C - loads).max() > 1e-13 * np.abs(loads).max():
        return loads, np.eye(c)
    return B, C


def _cases(values: np.ndarray, combination: np.ndarray) -> np.ndarray:
    """(…, k, n_speeds) responses to the independent loads -> (…, c, n_speeds) of the cases."""
    if combination.shape[0] == combination.shape[1] and np.array_equal(combination, np.eye(combination.shape[0])):
        return values
    return np.swapaxes(np.swapaxes(values, -1, -2) @ combination, -1, -2)


def _greedy(model, solver, speeds, rhs, combination, X, full, solve_full, tolerance):
    """The rounds of :func:`imbalance_sweep`: (q (n, c, n_speeds), the previous model's basis
    and coordinates, estimate, the final basis, rounds), or None when the projection gives way to
    full solves."""
    ns, n, c = speeds.size, solver.n, rhs.shape[1]
    terms = _Terms(solver, speeds)
    coefficients = terms.coefficients
    groups = _output_rows(model, solver.free)
    solve_full(np.unique(np.linspace(0, ns - 1, _INITIAL_SNAPSHOTS).round().astype(np.intp)))

    def evaluate(snapshots: np.ndarray):
        """The reduced model on the full solutions at ``snapshots``, its coordinates at every
        speed and the outputs (each group (rows, c, n_speeds); the full values where solved)."""
        reduced = _ReducedModel(terms, X[:, :, snapshots].reshape(n, -1), rhs)
        if reduced.size > _LARGEST_BASIS:  # its solves would cost about as much as the full ones
            raise np.linalg.LinAlgError("the reduced basis is too large")
        y = reduced.solve(coefficients, speeds)
        values = []
        for g in groups:
            v = np.matmul(g @ reduced.V, y).transpose(1, 2, 0)
            v[:, :, full] = (g @ X[:, :, full].reshape(n, -1)).reshape(g.shape[0], c, -1)
            values.append(_cases(v, combination))
        return reduced, y, values

    try:
        # the first "previous" model: the ends of the scan alone
        previous = evaluate(np.array([0, ns - 1]))
        rounds = 0
        while True:
            current = evaluate(np.flatnonzero(full))
            estimate = np.zeros(ns)
            for new, old in zip(current[2], previous[2]):
                peak = np.abs(new).max()
                if peak > 0:
                    estimate = np.maximum(estimate, _SAFETY * np.abs(new - old).max(axis=(0, 1)) / peak)
            if estimate.max() <= tolerance:
                break
            reduced, y, _ = current
            indicator = reduced.indicator(coefficients, speeds, y)
            indicator[full] = 0.0
            chosen = _local_maxima(indicator)[:_SNAPSHOTS_PER_ROUND]
            if chosen.size == 0 or np.count_nonzero(full) + chosen.size > _FULL_FRACTION * ns:
                return None
            solve_full(chosen)
            previous = current
            rounds += 1
    except np.linalg.LinAlgError:  # a reduced model singular at some speed, or too large
        return None
    reduced, y, _ = current
    # κ_ω peaks with the response: measured at the local maxima of ‖y‖ and their neighbours
    peaks = _local_maxima(np.linalg.norm(y, axis=1).max(axis=1))
    at = np.unique(np.clip(np.concatenate([peaks - 1, peaks, peaks + 1]), 0, ns - 1))
    kappa = reduced.sensitivity(coefficients[at], speeds[at], y[at])
    resonant = at[(kappa * RESONANCE_TOLERANCE > _RESONANCE_MARGIN) & ~full[at]]
    if resonant.size:  # near an undamped resonance: the full solver's checks decide
        solve_full(resonant)
    q = np.matmul(reduced.V, y).transpose(1, 2, 0)
    return q, (previous[0].V, previous[1]), estimate, reduced.V, rounds

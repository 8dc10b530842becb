"""The bearing loops' refinement on projected models (issue 30, point 2) against full solves.

* The projected model of an interval interpolates: at the grid points whose responses span its
  basis it reproduces the full model's closed-loop function (Galerkin on a basis that holds the
  exact solution), to the conditioning of the small solve.
* The margins refined on projected models (each checked by a full solve at its result) against
  the same refinements with a full banded solve at every step, on the tuned design (collocated
  PD bearings) and on the tuned driveline with the non-collocated PID magnet: the steps stop at
  1e-6 in ln ω (peaks) and 1e-8 ω (crossovers) on either function, and the two functions agree
  to LOCAL_TOLERANCE (1e-9) at every accepted result.
* With the check made impossible to pass (tolerance 0) every refinement falls back to full
  solves, and the result is the full computation's exactly.
"""

from __future__ import annotations

import numpy as np
import pytest
from magnet_loops import default_loops, loops, magnetic_tuned_model

import flexshaft.analyses.local_projection as lp
from flexshaft.analyses.banded import solver_for
from flexshaft.analyses.local_projection import LocalModels, window_of
from flexshaft.assembly import build_model
from flexshaft.design import tuned_design


def _tuned_model():
    return build_model(tuned_design().model_copy(update={"envelope": None}))


def _full_loops(make):
    """The reference: ``bearing_loops(make(), projected=False)``, a full banded solve at every
    step, computed once for the tests that compare with it (it reads no patched setting;
    tests/magnet_loops.py)."""
    return default_loops(make, projected=False)


def _margins(loops):
    return [
        (
            lp_.margins.peak_sensitivity,
            lp_.margins.peak_frequency,
            lp_.margins.gain_margin_upper_db,
            lp_.margins.gain_margin_lower_db,
            lp_.margins.phase_margin_deg,
            lp_.margins.phase_margin_frequency,
        )
        for lp_ in loops
    ]


def test_window_is_four_grid_points_around_the_interval_inside_the_grid():
    assert list(window_of(10, 11, 100)) == [9, 10, 11, 12]
    assert list(window_of(9, 11, 100)) == [9, 10, 11, 12]
    assert list(window_of(0, 1, 100)) == [0, 1, 2, 3]
    assert list(window_of(98, 99, 100)) == [96, 97, 98, 99]
    assert list(window_of(0, 2, 3)) == [0, 1, 2]


def _loops_of(model):
    """The four loops of ``model``'s two magnets as the bearing loops set them up: the solver,
    the actuation columns and sensing rows on the free DOFs, the feedback gains at ω [rad/s]
    and the operating speed."""
    solver = solver_for(model)
    free = solver.free
    rows = [(a, j) for a in model.actuators for j in range(2)]
    rhs = np.column_stack([a.lateral_rows[j].toarray().ravel()[free] for a, j in rows]).astype(complex)
    sense = np.vstack([a.sensing_rows[j].toarray().ravel()[free] for a, j in rows])

    def gains(w):
        return np.array([a.feedback_gain(1j * w) for a, _ in rows])

    return solver, rhs, sense, gains, model.speed


def test_projected_model_interpolates_the_full_one_at_its_window():
    """At the four grid points of a window (one of them beside a lightly damped pole) the
    projected closed-loop function equals the full banded solve: the full solution lies in
    the basis, so the Galerkin solution is it. Tolerance 1e-9 relative: the four responses are
    nearly parallel (2 % apart in frequency), so the QR basis and the 4×4 solve lose about
    κ ≈ 1e5 of the 1e-16 working precision."""
    solver, rhs, sense, gains, speed = _loops_of(_tuned_model())
    omegas = 2 * np.pi * np.array([40.0, 40.5, 41.0, 41.5, 300.0, 305.0, 310.0, 316.0])
    X = list(solver.sweep([(w, speed) for w in omegas], rhs))

    full = np.stack([np.einsum("ij,ji->i", sense, x) for x in X], axis=1) * gains(omegas)
    windows = [[0, 1, 2, 3], [4, 5, 6, 7], [0, 1, 2, 3]]
    loops = [0, 3, 2]
    local = LocalModels(solver, speed, X, windows, loops, rhs, sense, gains)
    for interval, (window, loop) in enumerate(zip(windows, loops)):
        T = local.closed(omegas[window], np.full(len(window), interval))
        assert np.abs(T - full[loop, window]).max() <= 1e-9 * np.abs(full[loop, window]).max()


def test_an_enriched_model_is_the_model_of_the_enlarged_basis():
    """LocalModels.enriched adds one response to each basis (Gram-Schmidt, and only the new row
    and column of the projected terms): the Galerkin model depends on the span alone, so it is
    the model built from scratch (QR) on the five responses, and it interpolates the full model
    at the added frequency too. Tolerance 1e-9 relative, as for the interpolation above (nearly
    parallel responses: the small solves lose about κ ≈ 1e5 of the working precision)."""
    solver, rhs, sense, gains, speed = _loops_of(_tuned_model())
    omegas = 2 * np.pi * np.array([40.0, 40.5, 41.0, 41.5, 40.77, 300.0, 305.0, 310.0, 316.0, 307.3])
    X = list(solver.sweep([(w, speed) for w in omegas], rhs))

    loops = np.array([0, 3])
    local = LocalModels(solver, speed, X, [[0, 1, 2, 3], [5, 6, 7, 8]], loops, rhs, sense, gains)
    added = [4, 9]
    enriched = local.enriched(np.array([0, 1]), np.column_stack([X[j][:, k] for j, k in zip(added, loops)]))
    scratch = LocalModels(solver, speed, X, [[0, 1, 2, 3, 4], [5, 6, 7, 8, 9]], loops, rhs, sense, gains)
    full = np.stack([np.einsum("ij,ji->i", sense, x) for x in X], axis=1) * gains(omegas)
    for interval, (j, k) in enumerate(zip(added, loops)):
        probe = omegas[j] * np.array([0.97, 0.99, 1.0, 1.004, 1.02])
        which = np.full(probe.size, interval)
        got, expected = enriched.closed(probe, which), scratch.closed(probe, which)
        assert np.abs(got - expected).max() <= 1e-9 * np.abs(expected).max()
        at = enriched.closed(omegas[[j]], np.array([interval]))[0]
        assert abs(at - full[k, j]) <= 1e-9 * abs(full[k, j])
    with pytest.raises(np.linalg.LinAlgError, match="basis"):  # a response already in the span
        local.enriched(np.array([0]), X[1][:, [0]])


@pytest.mark.parametrize("make", [_tuned_model, magnetic_tuned_model], ids=["tuned PD", "PID magnet"])
def test_projected_refinement_matches_full_solves_at_every_step(make):
    """Projected against full refinements (module docstring): the peak |S| and the margins to
    1e-7 relative (a peak value at a frequency δ = 1e-6 in ln ω off its top differs by about
    (δ/ζ)²/2, below 1e-7 for ζ >= 0.003; a crossover moves by the function's 1e-9 over its
    slope, and the margin with it), the peak frequency to 2e-6 (the golden-section tolerance
    on either function)."""
    fast = default_loops(make)  # shared with tests/test_loop_robustness.py (the PID magnet)
    full = _full_loops(make)
    for a, b in zip(_margins(fast), _margins(full)):
        assert a[0] == pytest.approx(b[0], rel=1e-7)
        assert a[1] == pytest.approx(b[1], rel=2e-6)
        for x, y in zip(a[2:], b[2:]):
            if y is None or not np.isfinite(y):
                assert x == y
            else:
                assert x == pytest.approx(y, rel=1e-7)
    for a, b in zip(fast, full):  # the grid and its values are the full model's in both
        np.testing.assert_array_equal(a.sensitivity, b.sensitivity)


def test_a_failed_check_falls_back_to_full_solves(monkeypatch):
    """LOCAL_TOLERANCE = 0 and no enrichment: every projected result is rejected and, unless
    the release rule shows that it cannot set a margin, refined again with full solves, the
    same steps as ``projected=False``: identical margins."""
    monkeypatch.setattr(lp, "LOCAL_TOLERANCE", 0.0)
    monkeypatch.setattr(lp, "ENRICHMENTS", 0)
    assert _margins(loops(_tuned_model)) == _margins(_full_loops(_tuned_model))


def test_a_projected_model_gone_astray_falls_back_to_full_solves(monkeypatch):
    """A projected model that returns NaN (standing in for a singular or useless compression)
    fails the check: no full solve at a non-finite frequency, the refinements are repeated on
    full solves, and the margins are the full computation's exactly."""
    monkeypatch.setattr(LocalModels, "closed", lambda self, omegas, intervals: np.full(len(omegas), np.nan + 0j))
    assert _margins(loops(_tuned_model)) == _margins(_full_loops(_tuned_model))


def test_projected_terms_sum_to_the_projected_dynamic_stiffness():
    """Σ_k w_k(ω, Ω) Vᴴ T_k V (BandedHarmonicSolver.project, term_weights) against Vᴴ Z(ω, Ω) V
    from the assembled sparse Z, for random complex bases at two (ω, Ω): the same sum in
    another order, so to round-off of |Z| |V|² (1e-12 relative to the largest entry)."""
    model = _tuned_model()
    solver = solver_for(model)
    rng = np.random.default_rng(3)
    V = rng.standard_normal((2, solver.n, 5)) + 1j * rng.standard_normal((2, solver.n, 5))
    terms = solver.project(V)
    for omega, speed in ((2 * np.pi * 37.0, model.speed), (2 * np.pi * 900.0, 0.3 * model.speed)):
        weights = solver.term_weights([omega], [speed])[0]
        Z = solver.sparse_matrix(omega, speed).toarray()[np.ix_(solver.inverse, solver.inverse)]
        for m in range(2):
            expected = V[m].conj().T @ Z @ V[m]
            got = np.einsum("k,kab->ab", weights, terms[m])
            assert np.abs(got - expected).max() <= 1e-12 * np.abs(expected).max()
    U = rng.standard_normal((2, solver.n, 3)) + 1j * rng.standard_normal((2, solver.n, 3))
    pairs = solver.project_pairs(U, V)  # Uᴴ T_k V, a (3, 5) block for each of the two pairs
    omega, speed = 2 * np.pi * 37.0, model.speed
    Z = solver.sparse_matrix(omega, speed).toarray()[np.ix_(solver.inverse, solver.inverse)]
    weights = solver.term_weights([omega], [speed])[0]
    for m in range(2):
        expected = U[m].conj().T @ Z @ V[m]
        got = np.einsum("k,kab->ab", weights, pairs[m])
        assert np.abs(got - expected).max() <= 1e-12 * np.abs(expected).max()

"""The spin-up scan from a greedy reduced basis over speed, against the all-full sweep.

:mod:`flexshaft.analyses.sweep_projection` solves the synchronous imbalance response at a few
dozen speeds of a scan and evaluates a Galerkin model on their span at every other speed,
accepted when the last enrichment moved no checked output by more than ``SWEEP_TOLERANCE``
(1e-8 of its peak). The reference is the same scan with a full banded solve at every speed
(``spinup_response(..., projected=False)``; the banded solver is itself checked against dense
solves in tests/test_response.py, and here against SuperLU).

Designs: the three embedded ones (tuned at its own point, baseline = Table 3.1, the segmented
aluminium ``current``), the thesis's tuned layup with a 1 mm wall (AF up to 148), the baseline
with its loss factors divided by 100 (lightly damped: AF 5e3 to 1e6) and with no loss at all
(undamped: every peak is a resonance).

Tolerance: 1e-7 of each quantity's peak over the scan, for every number the checks read (the
worst-case orbit along the shaft, each actuator's relative orbit and force, the critical speeds,
amplification factors and peak orbits found on the scan). It is ten times the projection's own
acceptance level (the margin covers a force, the displacement times a law whose magnitude
changes by less than that factor over the scan) and far below what the checks resolve (a
critical speed to a 20th of its bandwidth, AF to 0.5 %); two direct solvers (banded LU, SuperLU)
agree to ~1e-11 of the peak (test below), so it is far above round-off. Not for the undamped
design's amplification factors: an undamped peak's true AF is infinite, and the finite value a
sampled computation returns (1.5e10) is set by round-off; both computations must only put it
beyond 1/RESONANCE_TOLERANCE (a half-power bandwidth below the natural frequencies' accuracy).
"""

from __future__ import annotations

import sys
import warnings

import numpy as np
import pytest
import scipy.sparse.linalg as spla
from conftest import shared_result

from flexshaft.analyses import sweep_projection
from flexshaft.analyses.banded import RESONANCE_TOLERANCE, ResonanceWarning, solver_for
from flexshaft.analyses.criticals import lateral_critical_speeds, scan_critical_speeds
from flexshaft.analyses.response import imbalance_response
from flexshaft.analyses.spinup_response import spinup_response
from flexshaft.analyses.sweep_projection import imbalance_sweep
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import baseline_design, with_overrides
from flexshaft.design.io import embedded_design
from flexshaft.resolution import REPORT, SCREENING
from flexshaft.thesis.designs import thesis_tuned_design

#: Largest difference from the all-full sweep, relative to each quantity's peak (module docstring).
TOLERANCE = 1e-7
#: Round-off of the full solution relative to the peak: two direct solvers differ by ~1e-11.
FLOOR = 1e-10


def _losses(scale: float) -> dict:
    """Overrides scaling the baseline's material loss factors by ``scale`` (0: no loss)."""
    return {
        "materials.t700_adiprene.loss_E_L": 3.0e-4 * scale,
        "materials.t700_adiprene.loss_E_T": 0.12 * scale,
        "materials.t700_adiprene.loss_G_LT": 0.12 * scale,
        "materials.t700_adiprene.temperature_table": None,
        "materials.al6061_t6.loss_factor": 1e-3 * scale,
        "materials.boom_aluminium.loss_factor": 0.02 * scale,
    }


def _design(name: str):
    if name in ("tuned", "baseline", "current"):
        return embedded_design(name).model_copy(update={"envelope": None})
    if name.endswith("worst"):  # every in/anti-phase pattern of the bay forces: 4 or 16 load cases
        plain = embedded_design(name.split()[0]).model_copy(update={"envelope": None})
        return with_overrides(plain, {"loads.imbalance_placement": "worst"})
    if name == "thin wall":
        return with_overrides(thesis_tuned_design(), {"shaft.wall_thickness": 1.0e-3})
    return with_overrides(baseline_design(), _losses(0.01 if name == "light loss" else 0.0))


_MODELS: dict = {}


def _model(name: str):
    if name not in _MODELS:
        _MODELS[name] = build_model(_design(name))
    return _MODELS[name]


DESIGNS = ["tuned", "baseline", "current", "thin wall", "light loss", "no loss"]
CASES = [(name, SCREENING) for name in DESIGNS + ["baseline worst"]] + [("tuned", REPORT), ("light loss", REPORT)]


_SCANS: dict = {}
_SWEEPS: dict = {}  # the projected scans' SweepResult (its full_solves), by the key of _SCANS


def _scan(name: str, resolution, projected: bool):
    """The spin-up scan of design ``name`` at ``resolution``'s speeds, all-full or projected,
    computed once for the tests that read it (the scan test, the critical speeds, the undamped
    resonance and the error estimate's reference: the same computation each; CPU budget,
    issue 23). The projected one only where the sweep's settings are not patched."""
    key = (name, resolution.name, projected)
    if key not in _SCANS:
        model = _model(name)
        scan_module = sys.modules[spinup_response.__module__]
        sweeps = []

        def recorded(*args, **kwargs):  # the projected scan's own sweep, kept for its full-solve count
            sweeps.append(imbalance_sweep(*args, **kwargs))
            return sweeps[-1]

        scan_module.imbalance_sweep = recorded
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ResonanceWarning)
                _SCANS[key] = spinup_response(model, resolution.spin_speeds(model.speed), projected=projected)
        finally:
            scan_module.imbalance_sweep = imbalance_sweep
        _SWEEPS[key] = sweeps[0] if sweeps else None
    return _SCANS[key]


def _scans(name: str, resolution):
    """(all-full, projected) spin-up scans of ``name`` at ``resolution`` (:func:`_scan`)."""
    return _scan(name, resolution, False), _scan(name, resolution, True)


def _close(a, b, what: str) -> None:
    a, b = np.asarray(a), np.asarray(b)
    scale = np.abs(b).max()
    worst = np.abs(a - b).max() / scale
    assert worst <= TOLERANCE, f"{what}: {worst:.1e} of its peak"


@pytest.mark.parametrize("name, resolution", CASES, ids=lambda v: v if isinstance(v, str) else v.name)
def test_scan_matches_the_all_full_sweep(name, resolution):
    model = _model(name)
    speeds = resolution.spin_speeds(model.speed)
    full, fast = _scans(name, resolution)
    assert full.error_estimate is None and fast.error_estimate is not None
    _close(fast.envelope, full.envelope, "worst-case orbit along the shaft")
    _close(fast.orbits, full.orbits, "orbits of every load case")
    for actuator in full.actuator_displacement:
        _close(fast.actuator_displacement[actuator], full.actuator_displacement[actuator], f"{actuator} orbit")
        _close(fast.actuator_force[actuator], full.actuator_force[actuator], f"{actuator} force")
    # the worst case is the same wherever the two largest cases are told apart at all
    top = np.sort(full.orbits.max(axis=0), axis=0)
    distinct = top[-1] > (1 + 1e-6) * top[-2] if top.shape[0] > 1 else np.ones(speeds.size, dtype=bool)
    assert np.array_equal(fast.worst_case[distinct], full.worst_case[distinct])
    # it did project: a small fraction of the speeds solved in full (the scan's own sweep's
    # count), and the scan's estimate is 0 at each of them (its documented contract)
    sweep = _SWEEPS[(name, resolution.name, True)]
    assert 0 < sweep.full_solves <= 0.25 * speeds.size, sweep.full_solves
    assert np.all(fast.error_estimate[sweep.full] == 0.0)
    assert np.all(fast.error_estimate <= sweep_projection.SWEEP_TOLERANCE)


def _reference_criticals(name: str):
    """The all-full reference of the critical speeds on the screening scan of ``name``: the full
    scan, a full solve at every refinement speed (the resonances the scan steps over seeded from
    the synchronous roots on its full responses' span)."""
    model, scan = _model(name), _scan(name, SCREENING, False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResonanceWarning)
        return lateral_critical_speeds(
            model, top=SCREENING.scan_top, scan=(scan.speeds, scan.orbits), projected=False, responses=scan.response
        )


def _undamped_reference_criticals(factory):
    """:func:`_reference_criticals` of the undamped design, once per session: the critical-speed
    test compares with it and the undamped-resonance test scans at its first speed (2.6 s of CPU;
    issue 23's budget, tests/conftest.py)."""
    return shared_result(factory, "spinup_projection_no_loss_criticals", lambda: _reference_criticals("no loss"))


@pytest.mark.parametrize("name", DESIGNS)
def test_critical_speeds_on_the_projected_scan_match(name, tmp_path_factory):
    model = _model(name)
    projected = _scan(name, SCREENING, True)
    full = _undamped_reference_criticals(tmp_path_factory) if name == "no loss" else _reference_criticals(name)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResonanceWarning)
        scan = projected
        assert scan.basis is not None
        # as the assessment's spin-up task: the peaks' models start from the scan's reduced
        # basis; and from the scan's responses around each peak (when there is no basis)
        seeded = [
            scan_critical_speeds(model, scan.speeds, scan.orbits, SCREENING.scan_top, scan.response, basis)
            for basis in (scan.basis, None)
        ]
    for fast in (s.criticals for s in seeded):
        assert full is not None and fast is not None and len(fast) == len(full) >= 3
        for a, b in zip(fast, full):
            assert a.speed == pytest.approx(b.speed, rel=TOLERANCE)
            if name == "no loss":
                # undamped: the true AF is infinite, and a finite one is a half-power bandwidth
                # below 1e-5 of the speed, beyond the accuracy of the natural frequencies
                # (RESONANCE_TOLERANCE): its digits are round-off (1.5e10 here, differing by
                # 7e-4 between the two computations with numpy 1.26 / scipy 1.16): both must
                # read the peak as beyond that accuracy
                assert min(a.amplification_factor, b.amplification_factor) > 1 / RESONANCE_TOLERANCE
            else:
                assert a.amplification_factor == pytest.approx(b.amplification_factor, rel=TOLERANCE)
            assert a.location.get("af_method") == b.location.get("af_method")
            assert a.location.get("detail") == b.location.get("detail")
            if np.isfinite(b.amplification_factor):  # an undamped peak's orbit is the sample's, set by 1/δ
                # undamped, the orbit at a sample a relative distance δ ≈ 1/AF from the resonance
                # is ∝ 1/δ, and the two computations place the resonance apart by its round-off
                # (1e-14 of the speed at most, 100 ulps): the orbit moves by 1e-14 AF relative
                rel = max(TOLERANCE, 1e-14 * b.amplification_factor) if name == "no loss" else TOLERANCE
                expected = pytest.approx(b.location.get("peak_orbit", 0.0), rel=rel)
                assert a.location.get("peak_orbit", 0.0) == expected


def _errors(model, speeds, response, reference) -> np.ndarray:
    """Largest error of the checked outputs at each speed, relative to each group's peak."""
    free = model.dofs.free
    out = np.zeros(speeds.size)
    for rows in sweep_projection._output_rows(model, free):
        a = (rows @ np.asarray(response)[free].reshape(free.size, -1)).reshape(rows.shape[0], -1, speeds.size)
        b = (rows @ np.asarray(reference)[free].reshape(free.size, -1)).reshape(rows.shape[0], -1, speeds.size)
        out = np.maximum(out, np.abs(a - b).max(axis=(0, 1)) / np.abs(b).max())
    return out


@pytest.mark.parametrize("name", ["tuned", "light loss"])
def test_error_estimate_bounds_the_true_error(name, monkeypatch):
    """The estimate is twice the change the last enrichment made: for the model before it, a
    bound within a factor 3 of its true error once the enrichment at least halves the error
    (|e_old − e_new| ≤ change ≤ e_old + e_new); for the returned model, a bound (to the full
    solution's round-off). Small rounds (5 starting speeds, 3 per round) stop the greedy at
    several accuracies to see it at errors well above round-off."""
    monkeypatch.setattr(sweep_projection, "_INITIAL_SNAPSHOTS", 5)
    monkeypatch.setattr(sweep_projection, "_SNAPSHOTS_PER_ROUND", 3)
    model = _model(name)
    speeds = SCREENING.spin_speeds(model.speed)
    loads = imbalance_loads(model)
    reference = _scan(name, SCREENING, False).response  # imbalance_response(model, speeds, loads)
    checked = 0
    for tolerance in (1e-2, 1e-4, 1e-6, 1e-8):
        sweep = imbalance_sweep(model, speeds, loads, tolerance=tolerance)
        assert sweep.previous is not None
        estimate = sweep.error_estimate
        error = _errors(model, speeds, sweep.response, reference)
        assert np.all(error <= estimate + FLOOR)  # the returned values
        assert error.max() <= max(tolerance, FLOOR)
        before = _errors(model, speeds, sweep.previous, reference)
        seen = ~sweep.full & (before > 100 * FLOOR)
        assert np.all(estimate[seen] >= before[seen])
        assert np.all(estimate[seen] <= 10 * before[seen])
        checked += np.count_nonzero(seen)
    assert checked > 50  # the comparison saw errors above round-off at many speeds


def test_full_solutions_agree_with_superlu_to_round_off():
    """The floor the comparisons allow: the banded LU against SuperLU on the same Z(Ω, Ω)."""
    model = _model("tuned")
    solver = solver_for(model)
    speeds = SCREENING.spin_speeds(model.speed)[::20]
    rhs = imbalance_loads(model)[solver.free].astype(complex)
    weights = solver.term_weights(speeds, speeds)
    banded = np.stack(list(solver.sweep([(s, s) for s in speeds], rhs)), axis=-1)
    superlu = np.stack([spla.spsolve(solver.term_matrix(w).tocsc(), rhs).reshape(rhs.shape) for w in weights], axis=-1)
    assert np.abs(banded - superlu).max() <= FLOOR * np.abs(superlu).max()


def test_an_undamped_resonance_on_the_scan_is_reported_as_by_full_solves(tmp_path_factory):
    """A scan speed at an undamped resonance (the first critical speed of the all-full scan and
    refinement, :func:`_undamped_reference_criticals`): the all-full sweep warns there (the
    response changes completely within the natural frequencies' accuracy), and so does the
    projection, which solves such a speed in full."""
    model = _model("no loss")
    speeds = SCREENING.spin_speeds(model.speed)
    criticals = _undamped_reference_criticals(tmp_path_factory)
    resonance = criticals[0].speed
    assert criticals[0].amplification_factor == float("inf")
    speeds = np.sort(np.append(speeds, resonance))
    loads = imbalance_loads(model)
    with pytest.warns(ResonanceWarning, match="undamped resonance"):
        imbalance_response(model, speeds, loads)
    with pytest.warns(ResonanceWarning, match="undamped resonance"):
        sweep = imbalance_sweep(model, speeds, loads)
    assert sweep.full[np.searchsorted(speeds, resonance)]


def test_short_or_unordered_scans_are_solved_in_full():
    model = _model("baseline")
    loads = imbalance_loads(model)
    short = np.linspace(10.0, 600.0, 30)
    sweep = imbalance_sweep(model, short, loads)
    assert sweep.full.all() and sweep.previous is None and not sweep.error_estimate.any()
    assert np.array_equal(np.asarray(sweep.response), np.asarray(imbalance_response(model, short, loads)))
    unordered = np.linspace(600.0, 10.0, 80)
    assert imbalance_sweep(model, unordered, loads).full.all()


def test_many_independent_load_cases_are_solved_in_full():
    """The segmented driveline's 16 in/anti-phase patterns of 5 bay forces: the cases are
    combined from the responses to the 5 independent loads (exactly: the response is linear in
    the load), and a basis spanning all five would cost more than the full solves it saves."""
    model = _model("current worst")
    loads = imbalance_loads(model)
    speeds = SCREENING.spin_speeds(model.speed)
    sweep = imbalance_sweep(model, speeds, loads)
    assert loads.shape[1] == 16 and sweep.full.all()
    reference = np.asarray(imbalance_response(model, speeds, loads))
    assert np.abs(np.asarray(sweep.response) - reference).max() <= FLOOR * np.abs(reference).max()


@pytest.mark.parametrize(
    "speeds, loads, tolerance, match",
    [
        (np.linspace(1, 10, 50), np.zeros((3, 1)), 1e-8, "loads_per_speed_squared must have shape"),
        (np.linspace(1, 10, 50), None, 0.0, "tolerance must be in"),
        (np.array([1.0, np.nan]), None, 1e-8, "speeds"),
    ],
)
def test_bad_input_is_refused(speeds, loads, tolerance, match):
    model = _model("baseline")
    loads = imbalance_loads(model) if loads is None else loads
    with pytest.raises(ValueError, match=match):
        imbalance_sweep(model, speeds, loads, tolerance=tolerance)

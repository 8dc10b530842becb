"""The one recipe that judges a design (flexshaft.verdict.assess): what ``flexshaft check``
estimates is what ``flexshaft run`` computes, the assessment is frozen and typed, and Monte-Carlo
judges the actuators' limits as the verdict does.

References: the arrays the assessment actually holds (their sizes) for the size estimate's
counts; the verdict's own evidence (each active bearing's gap and force capacity) for the
Monte-Carlo limits, and its samples for the exceedance by counting.
"""

from __future__ import annotations

import dataclasses
import typing

import numpy as np
import pytest

from flexshaft.assembly.size import problem_size
from flexshaft.design import Design, design_from_dict, tuned_design, with_overrides
from flexshaft.resolution import REPORT, SCREENING
from flexshaft.verdict.assess import Assessment, assess

#: The tuned design with a coarse mesh (the counts do not depend on it; the run is faster).
SMALL = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}


@pytest.fixture(scope="module")
def design() -> Design:
    """The tuned design with a coarse mesh, over one point of its envelope (CPU budget, issue 23:
    each point is a whole assessment; none of these tests is about combining points): the
    standard day, where the report's resolution is the least converged of the four points
    (measured with this mesh: FINE moves the actuator force by 8.7e-4 of itself at the standard
    day, at most 7.3e-4 at the others)."""
    data = with_overrides(tuned_design(), SMALL).model_dump()
    data["envelope"]["points"] = [p for p in data["envelope"]["points"] if p["name"] == "standard_day"]
    return design_from_dict(data)


@pytest.fixture(scope="module")
def report_assessment(design) -> Assessment:
    return assess(design, REPORT)


@pytest.fixture(scope="module")
def screening_assessment(design) -> Assessment:
    return assess(design, SCREENING)


def _scan_speeds(a: Assessment) -> int:
    """The spin-up response's scan speeds: its samples less those added to them
    (flexshaft.analyses.spinup_response.with_speeds): the refined critical speeds (each a peak
    between the scan's samples), the operating speed and the highest operating speed (where
    the spin-up checks end)."""
    peaks = [c.speed for c in a.criticals.criticals if np.isfinite(c.amplification_factor)]
    operating = a.model.design.operating
    ends = [operating.speed_rad_s, operating.speed_limits[1]]
    added = [*peaks, *ends]
    assert np.isin(added, a.spinup.speeds).all()
    return int(np.count_nonzero(~np.isin(a.spinup.speeds, added)))


def test_the_size_estimate_counts_what_the_run_computes(report_assessment):
    """`flexshaft check` estimates `flexshaft run` from the same Resolution the run computes
    with: its counts of spin-up, Campbell and whirl speeds, modes and DOFs are the sizes of the
    arrays the run's assessment holds."""
    a = report_assessment
    size = problem_size(a.design, "run", REPORT)
    assert size.n_speeds == _scan_speeds(a) and a.spinup.speeds.size == a.spinup.response.shape[2]
    assert size.campbell_speeds == a.campbell.speeds.size
    assert size.whirl_speeds == a.stability.speeds.size
    # at the operating speed as many more as it takes to hold n_modes lateral whirl modes and
    # every mode below the whirl-damping check's scope (the onset requirement's speed, 92 Hz on
    # the tuned design: 14 lateral modes; tests/test_whirl_damping_frequency_scope_reference.py)
    assert size.n_modes == a.modes_at_rest.eigenvalues.size <= (a.modes_at_speed.kind == "lateral").sum()
    assert size.dofs == a.model.dofs.size and size.free_dofs == a.model.dofs.free.size
    assert size.load_cases == a.spinup.response.shape[1]


def test_the_screening_estimate_counts_the_screening_assessment(design, screening_assessment):
    a = screening_assessment
    size = problem_size(design, "assess", SCREENING)
    assert size.n_speeds == _scan_speeds(a) and size.whirl_speeds == a.stability.speeds.size
    assert size.campbell_speeds == 0 and a.campbell is None and a.modes_at_rest is None
    # the estimate of the run adds the thesis studies to the same assessment's
    assert problem_size(design, "run", SCREENING).time_seconds > size.time_seconds


def test_an_assessment_is_frozen_and_typed(report_assessment):
    """Every field has a real type (no `object`, `Any`, bare `dict` or `list`) and none can be
    reassigned after construction."""
    hints = typing.get_type_hints(Assessment)
    loose = {typing.Any, object, dict, list}
    for f in dataclasses.fields(Assessment):
        assert hints[f.name] not in loose, f"Assessment.{f.name}: {hints[f.name]}"
    with pytest.raises(dataclasses.FrozenInstanceError):
        report_assessment.verdict = None
    assert isinstance(report_assessment.notes, tuple)


def test_montecarlo_judges_the_actuators_limits_as_the_verdict(design, screening_assessment):
    """Each active bearing's gap and force capacity in the Monte-Carlo exceedances are those the
    verdict's actuator checks hold its peaks against, and a sample exceeds when some bearing's
    static + peak value passes its own limit (counted here from the per-bearing outputs)."""
    pytest.importorskip("xarray")
    from flexshaft.montecarlo import run_montecarlo

    evidence = {ev.name: ev for ev in screening_assessment.evidence.actuators}
    result = run_montecarlo(design, 12, seed=5, grade_mm_s=40.0, n_speeds=20, strength=False, progress=False)
    assert set(result.limits) == set(evidence)
    for name, lim in result.limits.items():
        assert (lim.gap, lim.force_capacity) == (evidence[name].gap, evidence[name].force_capacity)
    ds = result.dataset
    over = np.zeros(ds.sizes["sample"], bool)
    for name, lim in result.limits.items():
        over |= ds[f"actuator_excursion_{name}"].values > lim.gap
        excursion = ds[f"actuator_orbit_{name}"].values
        assert np.all(ds[f"actuator_excursion_{name}"].values >= excursion)  # the static offset is added
    assert result.gap_exceedance[0] == np.mean(over)


def test_the_report_resolution_has_converged(report_assessment):
    """FINE halves every grid spacing of REPORT: no status changes and no checked value moves by
    more than 1e-3 of itself. The bound is the refinement's: each resonance peak found on the
    scan is refined until its half-power band holds 20 samples, which fixes AF and the peak to
    about 0.1 % (docs/requirements.md); the other values do not depend on the grids (measured
    here at the standard day: the actuator orbit and force move by 7.4e-4 and 8.7e-4, the
    separation by 1.3e-5, the others by less than 1e-10). FINE's grids without what only the
    report shows (its Campbell diagram, the report detail): no check reads them (the verdict does
    not depend on them, flexshaft.resolution), and they are a third of FINE's cost (CPU budget,
    issue 23)."""
    from dataclasses import replace

    from flexshaft.resolution import FINE

    fine = assess(report_assessment.design, replace(FINE, campbell_speeds=0, report_detail=False))
    for coarse, finer in zip(report_assessment.verdict.checks, fine.verdict.checks):
        assert (coarse.key, coarse.status) == (finer.key, finer.status)
        if coarse.value is not None:
            assert finer.value == pytest.approx(coarse.value, rel=1e-3), coarse.key


def test_a_screening_assessment_makes_a_report_without_the_report_detail(screening_assessment, tmp_path):
    """The report formats any assessment: at SCREENING it has no Campbell diagram, no modes at
    rest and the self-heating alone, and its results.json carries the assessment's verdict."""
    import json

    from flexshaft.report.driveline import write_run_report
    from flexshaft.report.results_json import json_ready

    a = screening_assessment
    write_run_report(a, tmp_path)
    data = json.loads((tmp_path / "results.json").read_text())
    assert data["verdict"] == json_ready(a.verdict.to_dict())
    assert data["modes_at_rest"] == [] and data["critical_speeds"] == []
    assert (tmp_path / "imbalance_response.png").is_file() and not (tmp_path / "campbell.png").exists()

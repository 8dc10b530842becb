"""The thesis studies' definitions that no physics test pins: the units of the headline
numbers, the order of stacked stability-map rows, the sign of the critical ply's angle.

References (derived, no golden number of flexshaft):

* rpm = 60·Ω/(2π) (the definition of the unit): a spin-up peak at Ω = 2π·1800/60 rad/s is
  reported as 1800 rpm (to 1e-12: one multiplication);
* :func:`~flexshaft.thesis.whirl.stack_maps` concatenates rows in the order given (its
  docstring): K_p row k of the stack is row k's onset and margin, hand-built maps below;
* the critical ply of a (α/−α/−α/α) tube is one of its plies, signed: ±α, and the one the
  Tsai-Wu check of :func:`~flexshaft.analyses.shaft_strength.shaft_safety_factor` names on the
  static response (external loads + torque, the study's definition, study 1 runs without
  imbalance). At α = 60° on the baseline it is the −60° ply, so a lost sign shows.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from flexshaft.analyses.response import static_response
from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly.loads import external_static_load, torque_load
from flexshaft.design import baseline_design, with_overrides
from flexshaft.sweep.study import Point
from flexshaft.thesis.design_studies import DesignStudies, headline
from flexshaft.thesis.ply_angle import critical_ply_outputs, one_angle_layup
from flexshaft.thesis.whirl import StabilityMap, stack_maps


def _rad_s(rpm: float) -> float:
    return 2.0 * math.pi * rpm / 60.0


def test_headline_peak_speeds_are_in_rpm():
    """The headline's peak speeds: Ω [rad/s] shown as 60 Ω/(2π) rpm, to 1e-12."""
    r = DesignStudies(
        design_name="x",
        resolution="coarse",
        operating_speed=_rad_s(6000.0),
        peak_speed_before=_rad_s(1800.0),
        peak_speed_after=_rad_s(2400.0),
    )
    out = headline(r)
    assert out["peak_speed_before_rpm"] == pytest.approx(1800.0, rel=1e-12)
    assert out["peak_speed_after_rpm"] == pytest.approx(2400.0, rel=1e-12)


def _row(kp: float, onset, margin) -> StabilityMap:
    return StabilityMap(np.array([kp]), np.array([0.0, 1e3]), np.array([onset]), np.array([margin]), 900.0)


def test_stacked_maps_keep_each_rows_gains_with_its_values():
    """Rows stacked in the given order: K_p row k holds row k's own onset and margin (exact)."""
    rows = [_row(3e5, [100.0, np.nan], [0.01, 0.02]), _row(2e6, [300.0, 400.0], [0.03, 0.04])]
    out = stack_maps(rows)
    np.testing.assert_array_equal(out.kp, [3e5, 2e6])
    np.testing.assert_array_equal(out.onset_speed, [[100.0, np.nan], [300.0, 400.0]])
    np.testing.assert_array_equal(out.margin_at_operating, [[0.01, 0.02], [0.03, 0.04]])
    assert out.max_speed == 900.0


def test_critical_ply_angle_is_the_signed_ply_the_tsai_wu_check_names():
    """Study 1 at α = 60° (baseline, coarse 18/12 mesh, no imbalance): the critical ply is ±60°,
    and exactly the one (with its sign) Tsai-Wu names on the static response; here −60°."""
    design = with_overrides(
        baseline_design(),
        {"mesh.shaft_elements": 18, "mesh.boom_elements": 12, "loads.eccentricity": 0.0, **one_angle_layup(60.0)},
    )
    point = Point(0, {}, {}, design)
    out = critical_ply_outputs(point)
    model = point.model
    r = shaft_safety_factor(model, static_response(model, external_static_load(model) + torque_load(model)))
    assert abs(out["critical_ply_angle"]) == pytest.approx(60.0, abs=1e-9)
    assert out["critical_ply_angle"] == pytest.approx(r.ply_angle_deg, abs=1e-9)
    assert out["critical_ply_angle"] < 0.0
    assert out["sigma1"] == pytest.approx(r.stresses[0], rel=1e-12)
    assert out["sigma2"] == pytest.approx(r.stresses[1], rel=1e-12)


@pytest.mark.parametrize("resolution", ["report", "full"])
def test_wall_grids_are_in_metres_around_the_thesis_best_wall(resolution):
    """Study 3's walls [m] (docs/studies.md: the report's nine walls from 1 mm; the module's
    docstring: 23 at full resolution) span 0.5-6 mm and hold the thesis's best wall, 3 mm
    (THESIS["best_wall_m"]): a mm→m slip puts them 10x off."""
    from flexshaft.thesis.design_studies import STUDY_GRIDS, THESIS

    walls = np.asarray(STUDY_GRIDS[resolution]["walls"])
    assert walls.size == {"report": 9, "full": 23}[resolution]
    assert 0.5e-3 - 1e-12 <= walls.min() and walls.max() == pytest.approx(6e-3, rel=1e-12)
    assert np.isclose(walls, THESIS["best_wall_m"], rtol=1e-12).any()


def test_surface_gains_are_those_of_thesis_figures_3_13_and_3_14():
    """The two frequency-response surfaces are the thesis's figures 3.13 (K_p 2e6, K_d 1170) and
    3.14 (K_p 3e5, K_d 1170), as docs/thesis-reproduction.md's claims 10 and 11 quote them
    (the second, lower K_p damps the resonance the first excites): parsed from that table."""
    from pathlib import Path

    from flexshaft.thesis.spinup_maps import SURFACE_GAINS

    text = (Path(__file__).resolve().parent.parent / "docs" / "thesis-reproduction.md").read_text()
    quoted = {}
    for fig in ("3.13", "3.14"):
        (row,) = [line for line in text.splitlines() if f"(fig. {fig})" in line and line.startswith("|")]
        kp, kd = re.search(r"K_p ([0-9.e+]+), K_d ([0-9.]+)", row).groups()
        quoted[fig] = (float(kp), float(kd))
    assert tuple(SURFACE_GAINS) == (quoted["3.13"], quoted["3.14"])


def test_tuned_gains_are_the_smallest_refined_peak_not_the_smallest_sampled(monkeypatch):
    """Thesis §3.3's criterion on the refined peaks: on the hand-made map of
    tests/test_spinup_tuning_selection.py (stubs; within the gap the sampled peaks are 2, 3,
    4 ... mm), the best sampled pair (1e5 N/m, 100 N s/m) hides a resonance between samples,
    refined to 6 mm, while (1e5, 1000) refines to 3.5 mm: the tuned pair is (1e5, 1000), 3.5 mm
    (every other pair's refined peak is its sampled one, at least 4 mm)."""
    from types import SimpleNamespace

    from test_spinup_tuning_selection import GAP, KD, KP, ORBIT, PEAK, _curves

    from flexshaft.assembly.model import Controller
    from flexshaft.thesis import spinup_maps

    rec = SimpleNamespace(
        n_actuators=2, speeds=np.array([100.0]), shaft_x=np.array([0.0]), actuator_names=("amb_1", "amb_2")
    )
    smap = SimpleNamespace(
        kp=KP, kd=KD, shaft_peak=PEAK, actuator_displacement_peak=ORBIT, to_arrays=lambda: SimpleNamespace(attrs={})
    )
    refined = {2e-3: 6e-3, 3e-3: 3.5e-3}

    def refine(model, law, speeds, curve):
        return refined.get(float(curve.max()), float(curve.max())), 100.0

    monkeypatch.setattr(spinup_maps, "spinup_speeds", lambda model, n: None)
    monkeypatch.setattr(spinup_maps, "clustered_receptance", lambda model, laws, speeds: rec)
    monkeypatch.setattr(spinup_maps, "spinup_map", lambda model, kp, kd, receptance: smap)
    monkeypatch.setattr(spinup_maps, "spinup_curves", _curves)
    monkeypatch.setattr(spinup_maps, "_refined_peak", refine)
    model = SimpleNamespace(actuators=[SimpleNamespace(controller=Controller.pd(1e6, 1000.0))] * 2)
    out = spinup_maps.spinup_studies(model, {"map_speeds": 10, "map_kp": KP, "map_kd": KD}, GAP)
    assert out["gains_after"] == (1e5, 1000.0)
    assert out["peak_after"] == 3.5e-3


def test_ply_angle_study_flag_selects_the_thesis_load_set(monkeypatch):
    """``ply_angle_study(added_loads=False)`` evaluates the thesis's load set (no centrifugal
    hoop stress): doubling speed and power (same torque T = P/Ω, same external loads) leaves its
    safety factor unchanged (to 1e-12, the same solve); flexshaft's added hoop stress (∝ Ω²)
    would move it by 14 % on this design (tests/test_thesis_study_outputs_reference.py). The
    study's point function is taken from the Study handed to the sweep engine (not run: CPU)."""
    from flexshaft.thesis import ply_angle

    monkeypatch.setattr(ply_angle, "run_sweep", lambda study, **run: study)
    study = ply_angle.ply_angle_study([45.0], added_loads=False)
    design = with_overrides(
        baseline_design(), {"mesh.shaft_elements": 18, "mesh.boom_elements": 12, "loads.eccentricity": 0.0}
    )
    faster = with_overrides(
        design, {"operating.speed_rpm": 2 * design.operating.speed_rpm, "operating.power": 2 * design.operating.power}
    )
    slow, fast = (study.evaluate(Point(0, {}, {}, d))["safety_factor"] for d in (design, faster))
    assert fast == pytest.approx(slow, rel=1e-12)


def test_gain_study_safety_factor_is_the_worst_imbalance_case():
    """Study 4's safety factor with the imbalance (thesis §3.2: the worst load case at Ω_op):
    the smallest Tsai-Wu factor over the four 'worst'-placement cases (in/anti-phase bays), to
    1e-12 (the same solves), on the baseline's 1.7 mm wall (coarse) where the cases differ and
    the first case is not the worst."""
    from flexshaft.analyses.response import imbalance_response
    from flexshaft.assembly.loads import imbalance_loads
    from flexshaft.thesis.gain import _actuator_outputs

    design = with_overrides(
        baseline_design(),
        {
            "mesh.shaft_elements": 18,
            "mesh.boom_elements": 12,
            "shaft.wall_thickness": 0.0017,
            "loads.imbalance_placement": "worst",
        },
    )
    point = Point(0, {}, {}, design)
    model = point.model
    q_static = static_response(model, external_static_load(model) + torque_load(model))
    q = imbalance_response(model, [model.speed], imbalance_loads(model))[:, :, 0]
    cases = np.array([shaft_safety_factor(model, q_static, q[:, c]).safety_factor for c in range(q.shape[1])])
    assert cases.size == 4 and cases[0] > (1 + 1e-6) * cases.min()
    assert _actuator_outputs(point)["safety_factor"] == pytest.approx(cases.min(), rel=1e-12)

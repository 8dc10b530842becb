"""The thesis studies' definitions on stand-ins, each answer written by hand (no model is
solved; milliseconds). What each study reports is defined by its docstring and
docs/studies.md; the stand-ins return numbers chosen so that a different definition gives a
different answer.

References:

* study 3 (:mod:`flexshaft.thesis.wall`): the frequency is the shaft's first lateral mode's
  "damped natural frequency at rest" (the function's docstring): the modes are asked at
  Ω = 0; the spin-up peak is the largest shaft orbit over the scan ("peak shaft orbit during
  spin-up"): of a curve 1, 3, 2 mm it is 3 mm, not the last sample; the forced response runs
  over "the spin-up scan's range of the report resolution", SLOW_START to ``scan_top`` × Ω_op
  (:class:`~flexshaft.resolution.Resolution`: 0.02 to 1.30 Ω_op), not the whirl analysis's
  1.5 Ω_op;
* study 1 (:mod:`flexshaft.thesis.ply_angle`): the static loads are the external loads plus the
  transmitted torque (:func:`~flexshaft.thesis.strength.strength_outputs`: "static (external
  loads + torque)"); the thesis's load set leaves out both added loads, the centrifugal hoop
  stress (speed 0) and the thermal residual stress; ``dominant_stress`` codes 0 σ1, 1 σ2,
  2 τ12 (docs/studies.md, "Thesis studies");
* study 2 (:mod:`flexshaft.thesis.two_angles`): α is the first angle of (α/−α/β/−β)s, β the
  second; on a 1 × 2 grid α = (0), β = (0, 90) the map is 1 × 2;
* the stability map (:func:`~flexshaft.thesis.whirl.gain_stability_map`): the margin at the
  operating speed is read at the nearest sample (12 rad/s between samples 10 and 20: 10; 18 rad/s:
  20), on the per-point path (that each K_d is the point's whole derivative gain, the shared
  basis built at K_d = 0, is checked on a real model with a design K_d of 500 N s/m in
  tests/test_gain_stability_map_reference.py);
* the wall task of :mod:`flexshaft.thesis.design_studies` names a best wall at either end of
  the range studied (its note: "the safety factor is monotonic there"), the wall in the note's
  parenthesis in the unit its label names, mm (1 mm → "(1 mm)", 4 mm → "(4 mm)");
* study 5 (:mod:`flexshaft.thesis.buckling_sweep`) refuses a shaft that is not one laminated
  tube (its docstring: the laminated-shell model's domain): a metal one, and a laminated one
  in two segments;
* the strength check with imbalance is the worst load case
  (:func:`~flexshaft.thesis.strength.strength_outputs`, its docstring: "worst load case").
"""

from __future__ import annotations

import re
from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.resolution import REPORT, SLOW_START
from flexshaft.sweep.study import SweepError
from flexshaft.thesis import design_studies, ply_angle, two_angles, wall, whirl


def test_wall_frequency_is_asked_at_rest(monkeypatch):
    asked = []

    def fake_modes(model, speed, n):
        asked.append(speed)
        return SimpleNamespace(
            kind=np.array(["lateral"]),
            shares=SimpleNamespace(shaft_lateral=np.array([0.9])),
            frequencies=np.array([40.0 if speed == 0.0 else 35.0]),
        )

    monkeypatch.setattr(wall, "modes", fake_modes)
    assert wall.shaft_first_lateral_frequency(SimpleNamespace(speed=300.0)) == 40.0
    assert asked == [0.0]


def test_wall_spinup_output_is_the_largest_orbit_of_the_scan(monkeypatch):
    monkeypatch.setattr(wall, "shaft_first_lateral_frequency", lambda model: 40.0)
    monkeypatch.setattr(wall, "spinup_speeds", lambda model, n: np.array([1.0, 2.0, 3.0]))
    monkeypatch.setattr(wall, "clustered_receptance", lambda *args, **kw: None)
    monkeypatch.setattr(
        wall, "spinup_curves", lambda rec, laws: SimpleNamespace(shaft_peak=np.array([1e-3, 3e-3, 2e-3]))
    )
    model = SimpleNamespace(actuators=[SimpleNamespace(controller=None)], shaft=SimpleNamespace(laminate=None))
    out = wall._wall_outputs(SimpleNamespace(model=model, axes={}))
    assert out["spinup_peak_deflection"] == 3e-3
    assert out["natural_frequency_1"] == 40.0


def test_forced_response_spans_the_spin_up_scan(monkeypatch):
    monkeypatch.setattr(
        wall, "build_model", lambda design: SimpleNamespace(speed=200.0, actuators=[SimpleNamespace(controller=None)])
    )
    monkeypatch.setattr(wall, "with_overrides", lambda design, ov: design)
    monkeypatch.setattr(wall, "actuator_receptance", lambda model, speeds: speeds)
    monkeypatch.setattr(wall, "spinup_curves", lambda rec, laws: SimpleNamespace(shaft_peak=np.asarray(rec)))
    out = wall.forced_response(None, (0.001, 0.004), 5)
    speeds = np.linspace(0.02, 1.30, 5) * 200.0
    assert (SLOW_START, REPORT.scan_top) == (0.02, 1.30)
    np.testing.assert_allclose(out.coords["speed"].values, speeds, rtol=1e-15)
    assert out["shaft_peak"].dims == ("wall_thickness", "speed")
    np.testing.assert_allclose(out["shaft_peak"].values, [speeds, speeds], rtol=1e-15)


def _ply_stand_ins(monkeypatch, dominant: str):
    seen = {}

    def safety(model, q, *args, **kwargs):
        seen["q"], seen["kwargs"] = q, kwargs
        return SimpleNamespace(
            safety_factor=2.0, stresses=(1.0, 2.0, 3.0), ply_angle_deg=-45.0, x=0.5, dominant_stress=dominant
        )

    monkeypatch.setattr(ply_angle, "external_static_load", lambda model: np.array([1.0, 0.0]))
    monkeypatch.setattr(ply_angle, "torque_load", lambda model: np.array([0.0, 10.0]))
    monkeypatch.setattr(ply_angle, "static_response", lambda model, load: load)
    monkeypatch.setattr(ply_angle, "shaft_safety_factor", safety)
    return seen


@pytest.mark.parametrize(("dominant", "code"), [("sigma1", 0.0), ("sigma2", 1.0), ("tau12", 2.0)])
def test_ply_study_loads_and_dominant_stress_code(monkeypatch, dominant, code):
    seen = _ply_stand_ins(monkeypatch, dominant)
    point = SimpleNamespace(model=None)
    out = ply_angle.critical_ply_outputs(point)
    np.testing.assert_array_equal(seen["q"], [1.0, 10.0])  # external + torque
    # the model's own speed and flexshaft's thermal residual stress (both by default)
    assert seen["kwargs"].get("thermal_residual", True) is True and seen["kwargs"].get("speed") != 0.0
    assert out["dominant_stress"] == code
    assert (out["sigma1"], out["sigma2"], out["tau12"]) == (1.0, 2.0, 3.0)
    ply_angle.critical_ply_outputs_thesis_loads(point)
    assert seen["kwargs"]["speed"] == 0.0 and seen["kwargs"]["thermal_residual"] is False


def test_two_angle_axes_are_alpha_then_beta(monkeypatch):
    monkeypatch.setattr(two_angles, "run_sweep", lambda study, **run: study)
    study = two_angles.two_angle_study([0.0], [0.0, 90.0])
    assert [v.name for v in study.variables] == ["alpha", "beta"]
    assert list(study.variables[0].values) == [0.0] and list(study.variables[1].values) == [0.0, 90.0]
    assert study.shape == (1, 2)


@pytest.mark.parametrize(("operating", "nearest"), [(12.0, 10.0), (18.0, 20.0)])
def test_stability_map_reads_the_margin_at_the_nearest_speed(monkeypatch, operating, nearest):
    """Margin = speed at each sample: 12 rad/s reads 10 (not the next sample up, 20), 18 reads 20
    (not the sample below, 10)."""
    speeds = np.array([0.0, 10.0, 20.0, 30.0])
    monkeypatch.setattr(whirl, "with_overrides", lambda design, ov: ov)
    monkeypatch.setattr(whirl, "build_model", lambda design: SimpleNamespace(speed=operating, actuators=[]))
    # K_d in the law's states: each point's own model (the shared basis is
    # tests/test_gain_stability_map_reference.py's)
    monkeypatch.setattr(whirl, "_kd_only_damps", lambda design, model: False)
    monkeypatch.setattr(whirl, "reduce", lambda *args, **kw: None)
    monkeypatch.setattr(
        whirl, "stability", lambda model, s, *args, **kw: SimpleNamespace(onset_speed=None, stability_margin=s * 1.0)
    )
    design = SimpleNamespace(bearings=[SimpleNamespace(kind="active", kd=500.0)])
    smap = whirl.gain_stability_map(design, [1e6], [0.0, 300.0], speeds)
    np.testing.assert_array_equal(smap.margin_at_operating, [[nearest, nearest]])
    assert np.isnan(smap.onset_speed).all()


@pytest.mark.parametrize("best", [0, 3])
def test_best_wall_at_either_end_is_noted(monkeypatch, best):
    sf = np.array([1.0, 2.0, 3.0, 4.0])[:: 1 if best == 3 else -1]
    walls = np.array([1.0, 2.0, 3.0, 4.0]) * 1e-3
    ds = {"safety_factor": SimpleNamespace(values=sf)}
    monkeypatch.setattr(
        design_studies,
        "wall_thickness_study",
        lambda walls_, design, **run: type("DS", (dict,), {"wall_thickness": SimpleNamespace(values=walls)})(ds),
    )
    out = design_studies._wall_task(None, walls, {}, True)
    assert out["best_wall"] == walls[best] and out["best_wall_safety_factor"] == 4.0
    assert "end of the range" in out["notes"][0]
    m = re.search(r"\(([0-9.eE+-]+) mm\)", out["notes"][0])
    assert m and float(m[1]) == pytest.approx(walls[best] * 1e3)  # the note's label is mm


def test_buckling_sweep_refuses_a_metal_or_a_segmented_shaft():
    from flexshaft.design import baseline_design, with_overrides
    from flexshaft.thesis.buckling_sweep import buckling_study

    base = baseline_design()
    metal = with_overrides(base, {"shaft.material": "al6061_t6", "shaft.layup": None})
    mid = 0.5 * (base.shaft.x_start + base.shaft.x_end)
    halves = [
        {"name": "fwd", "x_start": base.shaft.x_start, "x_end": mid},
        {"name": "aft", "x_start": mid, "x_end": base.shaft.x_end},
    ]
    segmented = with_overrides(base, {"shaft.segments": halves})  # laminated, in two segments
    assert segmented.segmented and segmented.shaft_material.kind == "lamina"
    for design in (metal, segmented):
        with pytest.raises(SweepError, match="not one laminated tube"):
            buckling_study([0.002], design=design, progress=False)


def test_strength_with_imbalance_is_the_worst_of_every_load_case(monkeypatch):
    """Four load cases whose stand-in safety factors are 5, 3, 7, 2 (the last the worst): the
    total is 2 (the strength_outputs docstring: the "worst load case"), the static 10."""
    from flexshaft.thesis import strength

    factors = {None: 10.0, 0: 5.0, 1: 3.0, 2: 7.0, 3: 2.0}
    monkeypatch.setattr(strength, "static_response", lambda model, load: None)
    monkeypatch.setattr(strength, "external_static_load", lambda model: 0.0)
    monkeypatch.setattr(strength, "torque_load", lambda model: 0.0)
    monkeypatch.setattr(strength, "design_eccentricity", lambda design: 1e-5)
    monkeypatch.setattr(
        strength,
        "shaft_safety_factor",
        lambda model, q_static, q_imb=None, *args, **kw: SimpleNamespace(
            safety_factor=factors[None if q_imb is None else int(q_imb[0])]
        ),
    )
    q = np.arange(4.0)[None, :].repeat(3, axis=0)  # (ndof, n_cases): column c holds c
    point = SimpleNamespace(model=SimpleNamespace(design=None, speed=300.0))
    assert strength.strength_outputs(point, imbalance=q) == {"safety_factor_static": 10.0, "safety_factor": 2.0}


def test_gain_study_hands_its_imbalance_response_to_the_strength_check(monkeypatch):
    from flexshaft.thesis import gain

    q = np.arange(12.0).reshape(3, 4, 1) + 1.0  # (ndof, n_cases, one speed)
    seen = {}

    def strength(point, imbalance):
        seen["imbalance"] = imbalance
        return {"safety_factor_static": 3.0, "safety_factor": 2.0}

    monkeypatch.setattr(gain, "imbalance_response", lambda model, speeds, loads: q)
    monkeypatch.setattr(gain, "imbalance_loads", lambda model: None)
    monkeypatch.setattr(gain, "actuator_response", lambda model, qc, speeds: ({"a": [float(qc[0, 0])]}, None))
    monkeypatch.setattr(gain, "strength_outputs", strength)
    point = SimpleNamespace(model=SimpleNamespace(speed=300.0, shaft=SimpleNamespace(laminate=object())))
    out = gain._actuator_outputs(point)
    np.testing.assert_array_equal(seen["imbalance"], q[:, :, 0])
    assert out["actuator_displacement"] == 4.0  # the largest of the cases' 1, 2, 3, 4

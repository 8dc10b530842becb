"""The chapter-3 studies as :func:`~flexshaft.thesis.design_studies.plan_design_studies` sets
them up, each task run on the reduced baseline mesh at a few grid points (tens of milliseconds
each): what the tasks compute, against the physics and the documented rules.

References (derived here or quoted):

* **Whirl onset of an undamped support = the synchronous critical speed.** With the design's
  gains (K_p = 1e7 N/m, K_d = 0) the bearings add no damping; the forward whirl mode keeps the
  shaft's own loss, hysteretic and rotating with it (the map's default damping model), and
  the fixed-frame loss of the tailboom (the baseline's boom_aluminium has loss factor 0.02).
  docs/model.md (whirl stability, *Jeffcott rotor*): the forward roots solve
  ``m s² + c_e s + k(1 + iησ)`` with real parts −(ηω_n + c_e/m)/2 below ω_d and
  +(ηω_n − c_e/m)/2 above it, and "with ηω_n > c_e/m the onset is ω_d itself", the forward
  whirl frequency (a jump of the real part, not a zero crossing). With ηω_n < c_e/m both real
  parts stay negative and there is no onset at all, so the finite onset asserted first also
  shows the rotating loss outweighs the fixed-frame one here. With gyroscopic stiffening ω_d
  depends on Ω and the onset is where Ω = ω_d(Ω): the synchronous critical speed, where the
  spin-up curve peaks. So the stability map's onset at (1e7, 0) must equal the spin-up task's
  refined peak speed at the same gains, an independent analysis (a forced-response scan, no
  eigenvalues). Tolerance 1 %: the onset is solved between the speed samples by regula falsi
  and "does not depend on the speed grid" (docs/model.md); a resonance this lightly damped (a
  0.3 m sampled peak from a few-micron imbalance orbit scale) peaks within O(η²) of ω_d, and
  the spin-up peak is refined on a fine grid; measured 0.003 % apart. A map that tracks too
  few modes (the boom's two lowest, 4.9 Hz) finds no onset at all.
* **The tuned gains respect the actuator gap.** docs/studies.md: "The tuned gains are the
  map's smallest peak deflection (within ``actuator_gap`` if given)". With a gap of 0.1 mm,
  smaller than the actuator orbit of the unconstrained best pair (checked here, so the gap
  binds), every actuator's sampled peak orbit at the chosen pair must be within the gap (the
  rule is stated on the map's samples).
* **The forced-response study compares two walls.** docs/studies.md lists the datasets of
  ``DesignStudies``: "`forced_response` (2 walls × speed)". Two walls whatever the
  wall-thickness grid: the grid here has three walls, so a forced response run on the grid
  has three. The two are the thesis's: figure 3.5, "Maximum shaft response with 1mm and 4mm
  wall" (the thesis text, /work/shared/seed, its list of figures and page 51).
* **A metal shaft still has its wall study.** docs/studies.md: ``wall_thickness_study`` "gives
  NaN safety factors for a non-laminated shaft" (its natural frequency and spin-up peak apply
  to any shaft), and a study is None only when it "does not apply to the design" (the
  ``DesignStudies`` docstring, src/flexshaft/thesis/design_studies.py); so on an aluminium
  shaft the wall study is kept with finite natural frequencies and NaN safety factors,
  no best wall is named and no study is reported skipped.
* **Study 1 is the design's own strength check.** docs/thesis-reproduction.md (*Loads
  flexshaft adds beyond the thesis*): flexshaft's strength check adds two loads (the spinning
  wall's centrifugal hoop stress and the laminate's cool-down thermal residual stress);
  "`shaft_safety_factor(..., speed=0.0, thermal_residual=False)` and
  `ply_angle_study(..., added_loads=False)` leave both out". The two switches name the same
  load set, so the study's default (added_loads=True) is :func:`~flexshaft.analyses.
  shaft_strength.shaft_safety_factor` with its defaults. So the design studies' R at α = 30°
  must be ``shaft_safety_factor`` of (30/−30/−30/30), no imbalance, under the static external
  loads and torque, with its default (full) load set. At 30° the matrix-dominated σ2 governs
  and the cool-down residual σ2 (α_T > α_L) takes a large share of Y_t: the thesis load set
  gives a safety factor over twice as large (checked, so the test tells the two apart). Same
  arithmetic on the same model, operations possibly ordered differently: rel 1e-9.
* **The operating speed is in rad/s** (``DesignStudies.operating_speed  # rad/s``): the
  baseline's 4800 rpm is 4800 · 2π / 60 = 502.6548... rad/s (one multiplication: 1e-12).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import flexshaft.thesis.design_studies as studies
from flexshaft.analyses.response import static_response
from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load, torque_load
from flexshaft.design import baseline_design, with_overrides
from flexshaft.parallel.tasks import start_tasks
from flexshaft.sweep.study import SweepError
from flexshaft.thesis.ply_angle import one_angle_layup

COARSE = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}

#: The report's grids cut to a few points each (the rules above do not depend on the sizes).
FEW = {
    "angles": np.array([30.0]),
    "walls": np.array([2.0, 3.0, 5.0]) * 1e-3,
    "map_kp": np.logspace(5, 8, 4),
    "map_kd": np.concatenate([[0.0], np.logspace(1, 4.5, 3)]),
    "map_speeds": 40,
    "forced_speeds": 20,
    "stab_kp": np.array([1e7]),
    "stab_kd": np.array([0.0]),
    "stab_speeds": 16,
}


@pytest.fixture(scope="module")
def coarse():
    return with_overrides(baseline_design(), COARSE)


@pytest.fixture
def few(monkeypatch):
    monkeypatch.setitem(studies.STUDY_GRIDS, "few", {**studies.STUDY_GRIDS["report"], **FEW})
    return "few"


def _task(tasks, key):
    (found,) = [t for t in tasks if t.key == key]
    return found


def _run(task):
    return task.function(*task.args)


def test_whirl_onset_at_undamped_supports_is_the_synchronous_critical_speed(coarse, few):
    res, tasks = studies.plan_design_studies(coarse, few)
    spinup = _run(_task(tasks, "spinup"))
    assert spinup["gains_before"] == (1e7, 0.0)  # the design's gains: the map's only point
    (row,) = _run(_task(tasks, "stability:0"))["stability_rows"]
    onset = float(row.onset_speed[0, 0])
    assert math.isfinite(onset), "no whirl onset found below 1.5 x the operating speed"
    assert onset == pytest.approx(spinup["peak_speed_before"], rel=0.01)


def test_tuned_gains_keep_the_actuator_orbit_within_the_gap(coarse, few):
    gap = 1e-4
    free = _run(_task(studies.plan_design_studies(coarse, few)[1], "spinup"))
    res, tasks = studies.plan_design_studies(coarse, few, actuator_gap=gap)
    held = _run(_task(tasks, "spinup"))
    orbit = held["spinup_map"]["actuator_displacement_peak"]  # over (kp, kd, actuator)
    assert np.max(orbit.sel(kp=free["gains_after"][0], kd=free["gains_after"][1])) > gap  # the gap binds
    assert np.max(orbit.sel(kp=held["gains_after"][0], kd=held["gains_after"][1])) <= gap
    assert res.actuator_gap == gap


def test_forced_response_compares_two_walls(coarse, few):
    _, tasks = studies.plan_design_studies(coarse, few)
    ds = _run(_task(tasks, "forced_response"))["forced_response"]
    assert len(FEW["walls"]) != 2  # the grid's wall count differs from the documented 2
    assert ds.sizes["wall_thickness"] == 2
    assert list(ds["wall_thickness"].values) == pytest.approx([1e-3, 4e-3], rel=1e-12)  # thesis fig. 3.5
    assert ds.sizes["speed"] == FEW["forced_speeds"]


def test_a_metal_shaft_keeps_its_wall_study(coarse, few):
    metal = with_overrides(coarse, {"shaft.material": "al6061_t6", "shaft.layup": None})
    res, tasks = studies.plan_design_studies(metal, few)
    run = start_tasks([_task(tasks, "wall")], None, errors=(SweepError, ValueError))
    done = studies.finish_design_studies(res, run)
    assert not any("skipped" in note and "wall" in note for note in done.notes), done.notes
    assert done.wall is not None
    wall = done.wall  # plain labelled arrays, as the workers send them
    assert np.all(np.isnan(np.asarray(wall["safety_factor"])))
    assert np.all(np.isfinite(np.asarray(wall["natural_frequency_1"]))) and np.all(
        np.asarray(wall["natural_frequency_1"]) > 0
    )
    assert done.best_wall is None and done.best_wall_safety_factor is None


def test_operating_speed_is_in_rad_per_s(coarse, few):
    res, _ = studies.plan_design_studies(coarse, few)
    assert res.operating_speed == pytest.approx(4800.0 * 2.0 * math.pi / 60.0, rel=1e-12)


def test_ply_angle_study_is_the_strength_check_with_its_added_loads(coarse, few):
    _, tasks = studies.plan_design_studies(coarse, few)
    study = _run(_task(tasks, "ply_angle"))
    model = build_model(with_overrides(coarse, {**one_angle_layup(30.0), "loads.eccentricity": 0.0}))
    q = static_response(model, external_static_load(model) + torque_load(model))
    full = shaft_safety_factor(model, q).safety_factor
    thesis_loads = shaft_safety_factor(model, q, speed=0.0, thermal_residual=False).safety_factor
    assert thesis_loads > 2.0 * full  # the added loads matter at 30 deg
    assert study["optimal_angle"] == 30.0
    assert study["optimal_angle_safety_factor"] == pytest.approx(full, rel=1e-9)

"""The chapter-3 studies' headline and plan on hand-built inputs
(:mod:`flexshaft.thesis.design_studies`): what ``design_studies.json`` tells a user.

* **The gains.** The headline gives the design's and the tuned (K_p, K_d) under their own
  names: docs/thesis-reproduction.md (study 9) quotes the tuned pair K_p 1.26e6 N/m, K_d
  2370 N s/m beside the Table 3.1 pair K_p 1e7 N/m, K_d 0; a hand-built result with
  ``gains_before = (1e7, 300)`` and ``gains_after = (1.26e6, 2370)`` (300 only so that a swap
  shows) must give exactly those numbers under ``kp_N_per_m`` and ``kd_N_s_per_m``.
* **The quietest wall.** :func:`flexshaft.thesis.wall.quietest_spinup_wall` gives (wall,
  peak): of a hand-built wall study over 2, 3, 4 mm with spin-up peaks 5, 1, 3 mm the
  quietest is 3 mm with a 1 mm peak.
* **The thesis's numbers.** docs/thesis-reproduction.md: the Table 3.1 layup (55/−55/0/0)s,
  i.e. the pair (55°, 0°), and a spin-up peak cut "from 38 to 4 mm" (fig. 3.17): 0.038 m
  and 0.004 m; docs/studies.md (study 6): "38 → 4 mm".
* **A 0° pair names its plies once.** (0/−0/55/−55)s is (0/0/55/−55)s: a 0° ply is its own
  mirror, so the name of the pair (0°, 55°) is ``(0/0/55/-55)s`` (the pair (55°, 0°):
  tests/test_design_studies_picks_reference.py).
* **The K_d = 0 column of the spin-up map.** The baseline's Table 3.1 gains have K_d = 0
  (docs/thesis-reproduction.md, the baseline row): the map over (K_p, K_d) contains the
  design's own undamped column at both resolutions.
* **A study's time is the sum of its tasks.** The stability map runs one task per K_p row;
  two rows of 1.5 s and 2.0 s are 3.5 s of ``stability`` and of ``elapsed``.
* **No actuator, no gain studies.** The gain studies (4 and 6) and the stability map are
  studies of the active bearings' PD gains, which a design without actuators does not have:
  the Jeffcott rotor (isotropic steel, one contact damper) plans the wall and forced-response
  studies only (the planned task keys are asserted).

Hand-built inputs and one 8-element model: about 0.1 s of CPU.

Written for the mutations h50b-ds-* of scripts/mutations.toml.
"""

from __future__ import annotations

import tomllib

import flexshaft.thesis.design_studies as studies
from flexshaft.analyses.labelled import LabelledArrays
from flexshaft.design import baseline_design, design_from_dict
from flexshaft.parallel.tasks import Task, TaskOutcome
from flexshaft.validation.runner import design_text


def _result(**fields):
    return studies.DesignStudies(design_name="hand", resolution="report", operating_speed=500.0, **fields)


def test_the_headline_gives_each_gain_under_its_name():
    out = studies.headline(_result(gains_before=(1.0e7, 300.0), gains_after=(1.26e6, 2370.0)))
    assert out["gains_before"] == {"kp_N_per_m": 1.0e7, "kd_N_s_per_m": 300.0}
    assert out["gains_after"] == {"kp_N_per_m": 1.26e6, "kd_N_s_per_m": 2370.0}


def test_the_quietest_wall_and_its_peak():
    wall = LabelledArrays(
        {"spinup_peak_deflection": ("wall_thickness", [5e-3, 1e-3, 3e-3])}, {"wall_thickness": [2e-3, 3e-3, 4e-3]}
    )
    out = studies.headline(_result(wall=wall))
    assert out["quietest_spinup_wall_m"] == 3e-3
    assert out["quietest_spinup_peak_m"] == 1e-3


def test_the_thesis_headline_numbers():
    thesis = studies.headline(_result())["thesis"]
    assert thesis["best_two_angle_deg"] == [55.0, 0.0]
    assert studies.two_angle_name(thesis["best_two_angle_deg"]) == "(55/-55/0/0)s"
    assert thesis["tuned_peak_before_m"] == 0.038
    assert thesis["tuned_peak_after_m"] == 0.004


def test_a_zero_degree_pair_first_is_named_once_per_ply():
    assert studies.two_angle_name((0.0, 55.0)) == "(0/0/55/-55)s"


def test_the_spin_up_map_holds_the_baselines_undamped_gains():
    kds = {b.kd for b in baseline_design().bearings if b.kind == "active"}
    assert kds == {0.0}
    for grid in studies.STUDY_GRIDS.values():
        assert 0.0 in grid["map_kd"] and 0.0 in grid["stab_kd"]


class _Run:
    def __init__(self, seconds):
        self.tasks = [Task(f"stability:{i}", "stability margin map", print) for i in range(len(seconds))]
        self._outcomes = {t.key: TaskOutcome(t.key, {}, s) for t, s in zip(self.tasks, seconds)}

    def results(self, progress=None):
        return self._outcomes


def test_a_study_split_in_tasks_is_timed_by_their_sum():
    done = studies.finish_design_studies(_result(), _Run([1.5, 2.0]))
    assert done.timings == {"stability": 3.5}
    assert done.elapsed == 3.5


def test_a_design_without_actuators_plans_no_gain_study():
    design = design_from_dict(tomllib.loads(design_text("jeffcott_internal_damping.toml")))
    res, tasks = studies.plan_design_studies(design)
    assert sorted(t.key for t in tasks) == ["forced_response", "wall"]
    assert any("need PD active bearings" in note for note in res.notes)

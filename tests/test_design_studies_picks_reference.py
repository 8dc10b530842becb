"""What the chapter-3 studies' headline picks out of a two-angle map, and the speeds the
stability margin map covers (:mod:`flexshaft.thesis.design_studies`), on hand-built inputs.

* **The best ply pair is named larger angle first.** The two-angle map is symmetric in α ↔ β
  ((α/−α/β/−β)s and (β/−β/α/−α)s hold the same plies: :mod:`flexshaft.thesis.two_angles`), so
  its best value appears twice; docs/studies.md (study 2) names the best pair with the larger
  angle first, as the thesis's headline (55°, 0°) does. A hand-built symmetric map over 0°,
  30°, 55° whose largest value 2.0 sits at (55, 0) and (0, 55) must give the pair (55.0, 0.0)
  and the factor 2.0.
* **The stability map reaches the speed the onset requirement asks about.** The whirl-onset
  requirement asks for no onset below (1 + min_onset_margin) × Ω_op (default margin 0.15); a
  map of onset speed against the gains that stops at Ω_op cannot show an onset between Ω_op
  and that speed. Each row task's speeds must run from rest to at least 1.15 Ω_op.

The studies themselves are replaced by recorders (no sweep is run, no model built): exact
values. CPU: milliseconds.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

import flexshaft as fs
import flexshaft.thesis.design_studies as studies


def test_the_best_pair_of_a_symmetric_map_is_named_larger_angle_first(monkeypatch):
    angles = np.array([0.0, 30.0, 55.0])
    sf = np.array([[1.0, 1.2, 2.0], [1.2, 1.5, 1.8], [2.0, 1.8, 1.1]])
    assert np.array_equal(sf, sf.T)

    class Map(dict):
        alpha = SimpleNamespace(values=angles)
        beta = SimpleNamespace(values=angles)

    def fake_study(alpha, beta, design=None, **run):
        return Map(safety_factor=SimpleNamespace(values=sf))

    monkeypatch.setattr(studies, "two_angle_study", fake_study)
    found = studies._two_angle_task(None, angles, {})
    assert found["best_two_angle"] == (55.0, 0.0)
    assert found["best_two_angle_safety_factor"] == 2.0
    assert studies.two_angle_name(found["best_two_angle"]) == "(55/-55/0/0)s"


def test_the_stability_map_runs_from_rest_past_the_required_onset_speed(monkeypatch):
    design = fs.baseline_design()
    seen = []

    def record(design, kps, kds, speeds, n_modes):
        seen.append(np.asarray(speeds))
        return "row"

    monkeypatch.setattr(studies, "gain_stability_map", record)
    grid = studies.STUDY_GRIDS["report"]
    assert studies._stability_row_task(design, grid, 1e6) == {"stability_rows": ["row"]}
    (speeds,) = seen
    required = (1.0 + design.requirements.min_onset_margin) * design.operating.speed_rad_s
    assert speeds[0] == 0.0 and speeds.size == grid["stab_speeds"]
    assert speeds[-1] >= required


def test_the_optimal_ply_angle_reports_its_own_safety_factor(monkeypatch):
    """A hand-built ply-angle curve over 10°, 30°, 55°, 70° with safety factors 1.1, 1.6, 2.4,
    1.9: the optimum is 55° and the factor reported with it is that angle's, 2.4 (not the
    sweep's first, 1.1)."""
    angles = np.array([10.0, 30.0, 55.0, 70.0])
    sf = np.array([1.1, 1.6, 2.4, 1.9])

    class Curve(dict):
        alpha = SimpleNamespace(values=angles)

    def fake_study(alpha, design=None, **run):
        return Curve(safety_factor=SimpleNamespace(values=sf))

    monkeypatch.setattr(studies, "ply_angle_study", fake_study)
    found = studies._ply_angle_task(None, angles, {})
    assert found["optimal_angle"] == 55.0
    assert found["optimal_angle_safety_factor"] == 2.4

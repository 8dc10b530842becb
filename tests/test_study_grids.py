"""The thesis studies' definitions: their default grids, laminates, load sets and selections,
against what their docstrings and the thesis (../shared/seed, M.S. thesis chapter 3) state.

The studies themselves are not run: ``run_sweep`` is replaced by a stub that returns the
:class:`~flexshaft.sweep.study.Study` it is given, so each test reads the grid and the
overrides a study would sweep (no model is built; a few milliseconds each). References:

* the thesis, §3.2: "for analyzing ply orientation and wall thickness variables, some of the
  operations are considered without the effect of the dynamic loads (i.e. no unbalance load)"
  (studies 1 and 2 run with ``loads.eccentricity = 0``); study 1's laminate (α/−α/−α/α),
  study 2's (α/−α/β/−β)s, figure 3.3's optimum named (55°/−55°/0°/0°)s;
* the docstrings' grids: study 1 every 5° from 5° (below 90°), study 2 every 15° from 0° to
  90°, study 3 ten walls from 1.5 to 6 mm, study 4 thirteen K_p from 1e5 to 1e8 N/m (four per
  decade), study 6 K_d 0 and 29 values from 10 to 10^4.5 N s/m;
* study 4 sets K_p on both active bearings of the baseline (its bearings 1 and 2).
"""

from __future__ import annotations

import numpy as np

from flexshaft.design import baseline_design
from flexshaft.thesis import gain, ply_angle, spinup_maps, two_angles, wall
from flexshaft.thesis.two_angles import best_pair
from flexshaft.thesis.wall import quietest_spinup_wall
from flexshaft.thesis.whirl import THESIS_SHAFTS


def _study_of(monkeypatch, module, call):
    """The Study that ``call()`` hands to ``module.run_sweep``."""
    seen = []
    monkeypatch.setattr(module, "run_sweep", lambda study, **run: seen.append(study) or study)
    call()
    (study,) = seen
    return study


def test_ply_angle_study_default_grid_laminate_and_loads(monkeypatch):
    """Every 5° from 5° to 85° (17 angles), each as (α/−α/−α/α) in degrees, without imbalance."""
    study = _study_of(monkeypatch, ply_angle, lambda: ply_angle.ply_angle_study())
    (alpha,) = study.variables
    assert alpha.values == tuple(5.0 * k for k in range(1, 18))
    assert alpha.design_overrides(30.0) == {"shaft.layup": "(30/-30/-30/30)"}
    assert alpha.design_overrides(55.0) == {"shaft.layup": "(55/-55/-55/55)"}
    assert dict(study.fixed) == {"loads.eccentricity": 0.0}


def test_two_angle_study_default_grid_laminate_and_loads(monkeypatch):
    """Every 15° from 0° to 90° on both axes (7 × 7), each point (α/−α/β/−β)s, no imbalance."""
    study = _study_of(monkeypatch, two_angles, lambda: two_angles.two_angle_study())
    grid = tuple(15.0 * k for k in range(7))
    assert [v.values for v in study.variables] == [grid, grid]
    assert dict(study.fixed) == {"loads.eccentricity": 0.0, "loads.balance_grade": None}
    assert two_angles.two_angle_layup((55.0, 10.0)) == {"shaft.layup": "(55/-55/10/-10)s"}
    assert two_angles.two_angle_layup((30.0, 45.0)) == {"shaft.layup": "(30/-30/45/-45)s"}


def test_two_angle_points_solve_their_own_pair(monkeypatch):
    """A point (α, β) is the laminate of both its angles: the pair handed to the strength is
    (larger, smaller) of (α, β), never one angle twice."""
    pairs = []
    monkeypatch.setattr(two_angles, "_pair_strength", lambda key, high, low: pairs.append((high, low)) or ())

    class _Point:
        design = baseline_design()

    for alpha, beta in ((55.0, 10.0), (10.0, 55.0), (30.0, 30.0)):
        _Point.axes = {"alpha": alpha, "beta": beta}
        two_angles._two_angle_strength(_Point)
    assert pairs == [(55.0, 10.0), (55.0, 10.0), (30.0, 30.0)]


def test_best_pair_names_the_larger_angle_first_of_a_tie():
    """A symmetric map has its best plies twice, (α, β) and (β, α); the study names the laminate
    with the larger angle first (docs/studies.md: the thesis's (55/−55/0/0)s, not (0/0/55/−55)s).
    A hand-made map with its maximum R = 9 at (0, 55) and (55, 0)."""
    angles = np.array([0.0, 30.0, 55.0])
    sf = np.array([[1.0, 2.0, 9.0], [2.0, 3.0, 4.0], [9.0, 4.0, 5.0]])
    assert best_pair(sf, angles, angles) == (2, 0)
    assert best_pair(sf.T, angles, angles) == (2, 0)


def test_wall_study_default_grid(monkeypatch):
    """Ten walls from 1.5 to 6 mm in metres (0.5 mm apart)."""
    study = _study_of(monkeypatch, wall, lambda: wall.wall_thickness_study())
    (walls,) = study.variables
    assert walls.path == "shaft.wall_thickness" and walls.units == "m"
    np.testing.assert_allclose(walls.values, 1.5e-3 + 0.5e-3 * np.arange(10), rtol=1e-12)


def test_quietest_spinup_wall_is_the_smallest_peak():
    """The wall of the smallest spin-up peak of a hand-made table (NaN walls skipped); None when
    no wall has a peak (no actuators)."""

    class _Column:
        def __init__(self, values):
            self.values = np.asarray(values, dtype=float)

    class _Table:
        def __init__(self, walls, peaks):
            self.wall_thickness = _Column(walls)
            self.peaks = _Column(peaks)

        def __getitem__(self, name):
            assert name == "spinup_peak_deflection"
            return self.peaks

    table = _Table([1e-3, 2e-3, 3e-3, 4e-3], [5e-3, np.nan, 1e-3, 2e-3])
    assert quietest_spinup_wall(table) == (3e-3, 1e-3)
    assert quietest_spinup_wall(_Table([1e-3, 2e-3], [np.nan, np.nan])) is None


def test_gain_study_default_grid_sets_both_actuators(monkeypatch):
    """Thirteen K_p from 1e5 to 1e8 N/m (four per decade), each on both active bearings."""
    study = _study_of(monkeypatch, gain, lambda: gain.proportional_gain_study())
    (kp,) = study.variables
    np.testing.assert_allclose(kp.values, 10.0 ** (5 + 0.25 * np.arange(13)), rtol=1e-12)
    active = [f"bearings[{i}].kp" for i, b in enumerate(baseline_design().bearings) if b.kind == "active"]
    assert kp.design_overrides(2e6) == dict.fromkeys(active, 2e6)
    assert len(active) == 2


def test_spinup_gain_map_default_grid(monkeypatch):
    """K_p: 30 from 1e5 to 1e8 N/m; K_d: 0 and 29 from 10 to 10^4.5 N s/m (30 values)."""
    seen = {}

    class _Map:
        def to_dataset(self):
            return seen

    def spinup_map(model, kp, kd, speeds):
        seen.update(kp=np.asarray(kp), kd=np.asarray(kd))
        return _Map()

    monkeypatch.setattr(spinup_maps, "spinup_map", spinup_map)
    monkeypatch.setattr(spinup_maps, "build_model", lambda design: None)
    monkeypatch.setattr(spinup_maps, "spinup_speeds", lambda model, n: None)
    spinup_maps.spinup_gain_map(design=baseline_design())
    np.testing.assert_allclose(seen["kp"], np.logspace(5, 8, 30), rtol=1e-12)
    assert seen["kd"].size == 30 and seen["kd"][0] == 0.0
    np.testing.assert_allclose(np.log10(seen["kd"][1:]), 1 + 3.5 * np.arange(29) / 28, rtol=1e-12)


def test_thesis_whirl_shafts_are_figures_4_2_to_4_4():
    """Thesis figures 4.2-4.4: an aluminium shaft, a (45/−45)s and a (45/−45/0/0)s FMC shaft."""
    layups = [overrides.get("shaft.layup") for _, overrides in THESIS_SHAFTS]
    assert layups == [None, "(45/-45)s", "(45/-45/0/0)s"]
    assert THESIS_SHAFTS[0][1]["shaft.material"] == "al6061_t6"

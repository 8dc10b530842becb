"""The default search of ``flexshaft optimize`` (:func:`flexshaft.optimize.default_variables`):
bounds in the design file's units, from its docstring and the thesis.

* ply angles in degrees (the layup template reads degrees): a in [30°, 75°], b in [0°, 30°],
  around the thesis's optimum (55°/−55°/0°/0°)s (§3.2, figure 3.3);
* the wall from 1 mm to 4 mm in metres (the thesis's figure 3.5 walls, its design point 3 mm);
* K_p shared, log scale, from 1e5 to 1e7 N/m: the search coordinate is log10 K_p, and decoding
  a bound's coordinate gives the bound back (10^5, 10^7);
* each active bearing's station within ±1 m of its own and at least 0.3 m from its neighbours.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.design import baseline_design, with_overrides
from flexshaft.optimize import default_variables


@pytest.fixture(scope="module")
def search():
    """The baseline with its first actuator moved to 1.2 m, 0.41 m from the forward hanger at
    0.79 m: its lower bound is set by the 0.3 m clearance (1.09 m), not by the ±1 m (0.2 m)."""
    design = with_overrides(baseline_design(), {"bearings[1].x": 1.2})
    variables, template = default_variables(design)
    return design, {v.name: v for v in variables}, template


def test_ply_angles_in_degrees_around_the_thesis_optimum(search):
    _, v, template = search
    assert template == "({a}/{-a}/{b}/{-b})s"
    assert (v["ply_angle_a"].lower, v["ply_angle_a"].upper, v["ply_angle_a"].units) == (30.0, 75.0, "degree")
    assert (v["ply_angle_b"].lower, v["ply_angle_b"].upper) == (0.0, 30.0)
    assert v["ply_angle_a"].lower < 55.0 < v["ply_angle_a"].upper  # (55/-55/0/0)s inside


def test_wall_from_1_to_4_mm_in_metres(search):
    _, v, _ = search
    assert (v["wall_thickness"].lower, v["wall_thickness"].upper, v["wall_thickness"].units) == (1e-3, 4e-3, "m")


def test_proportional_gain_is_searched_on_log10_between_its_bounds(search):
    """Coordinates 5 and 7 decode to 1e5 and 1e7 N/m (4 significant digits: exact), and 6.3 to
    10^6.3 = 1.995e6 N/m; a value encodes to its log10."""
    _, v, _ = search
    kp = v["kp"]
    assert kp.log and (kp.lower, kp.upper) == (1e5, 1e7)
    assert kp.search_bounds == pytest.approx((5.0, 7.0), abs=1e-15)
    assert kp.decode(5.0) == 1e5 and kp.decode(7.0) == 1e7
    assert kp.decode(6.3) == pytest.approx(1.995e6, rel=1e-12)
    assert kp.encode(2e6) == pytest.approx(math.log10(2e6), rel=1e-15)
    assert kp.paths == ("bearings[1].kp", "bearings[2].kp")


def test_actuator_stations_keep_their_neighbours_clearance(search):
    """amb_1 at 1.2 m: [max(0.79 + 0.3, 1.2 − 1), min(1.2 + 1, 5.63 − 0.3)] = [1.09, 2.2] m;
    amb_2 at 5.63 m: [4.63, 6.63] m (8.05 − 0.3 = 7.75 does not bind)."""
    design, v, _ = search
    assert [b.x for b in design.bearings] == [0.79, 1.2, 5.63, 8.05]
    assert (v["amb_1_x"].lower, v["amb_1_x"].upper) == pytest.approx((1.09, 2.2), abs=1e-12)
    assert (v["amb_2_x"].lower, v["amb_2_x"].upper) == pytest.approx((4.63, 6.63), abs=1e-12)

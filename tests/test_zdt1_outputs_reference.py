"""The ZDT1 verification problem's output function, against its closed form evaluated by hand.

Reference: ZDT1 (Zitzler, Deb & Thiele 2000) as restated in the docstring of
:mod:`flexshaft.optimize.reference`: with the variables normalised to u in [0, 1] (the wall from
1 mm to 4 mm, the two active bearings' K_d from 0 to 2000 N s/m, log10 K_p of the first from 5 to
7, n the count of 0° plies per half of the symmetric layup), g = 1 + 3 (u2 + u3 + u4) + (n − 3)²,
f1 = u1, f2 = g (1 − √(f1/g)) = g − √(f1 g), margin_lower = u1 − 0.1, margin_probe = 1 or NaN
(not evaluated) where u3 > 0.9. The values below are worked out here from that statement.

This is a cheap self-check of the verification problem, not of a product path. The optimizer runs
of tests/test_optimize.py catch some mapping errors (u3 read from the first bearing breaks the
not-evaluated probe that test_nsga2_approaches_the_known_zdt1_front_and_resumes checks), but they
judge the designs on and near the front; the gap this file closes is mainly the K_p log mapping
off the front, where g and f2 depend on it.

Tolerance: each output is a handful of additions, one log10 and one square root of O(1) numbers;
rel 1e-12 is a thousand ulps, far above rounding and far below any mapping error (≥ 1e-2 here).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from flexshaft.design import baseline_design, with_overrides
from flexshaft.optimize.reference import zdt1_outputs


def _outputs(wall: float, kd1: float, kd2: float, kp1: float, n: int) -> dict[str, float]:
    design = with_overrides(
        baseline_design(),
        {
            "shaft.wall_thickness": wall,
            "bearings[1].kd": kd1,
            "bearings[2].kd": kd2,
            "bearings[1].kp": kp1,
            "shaft.layup": f"(55/-55/0_{n})s",
        },
    )
    return zdt1_outputs(SimpleNamespace(design=design))


def test_zdt1_outputs_off_the_front_follow_the_closed_form():
    """Wall 2.5 mm, K_d 500 and 1000 N s/m, K_p 1e6 N/m, n = 2:
    u = (0.5, 0.25, 0.5, 0.5) (log10 1e6 = 6 is halfway from 5 to 7, whereas a linear map of K_p
    would give 9e5/9.9e6 = 0.0909), g = 1 + 3·1.25 + 1 = 5.75, f2 = 5.75 − √(0.5·5.75)."""
    out = _outputs(0.0025, 500.0, 1000.0, 1e6, 2)
    assert out["f1"] == pytest.approx(0.5, rel=1e-12)
    assert out["f2"] == pytest.approx(5.75 - math.sqrt(2.875), rel=1e-12)
    assert out["margin_lower"] == pytest.approx(0.4, rel=1e-12)
    assert out["margin_probe"] == 1.0


@pytest.mark.parametrize(("kp1", "u4"), [(1e5, 0.0), (1e7, 1.0), (10**5.5, 0.25)])
def test_zdt1_stiffness_is_mapped_by_its_logarithm(kp1, u4):
    """K_p enters through u4 = (log10 K_p − 5)/2 (docstring): 1e5 → 0, 1e7 → 1, 10^5.5 → 0.25.
    On the front's other coordinates (u1 = 0.1 at wall 1.3 mm, u2 = u3 = 0, n = 3):
    g = 1 + 3 u4 and f2 = g − √(0.1 g)."""
    out = _outputs(0.0013, 0.0, 0.0, kp1, 3)
    g = 1.0 + 3.0 * u4
    assert out["f1"] == pytest.approx(0.1, rel=1e-12)
    assert out["f2"] == pytest.approx(g - math.sqrt(0.1 * g), rel=1e-12)


def test_zdt1_lower_bounds_and_the_not_evaluated_probe():
    """Every variable at its lower bound (wall 1 mm, K_d 0, K_p 1e5, n = 1): u = 0, g = 1 + (1 − 3)²
    = 5, f1 = 0, f2 = 5, margin_lower = −0.1 (violated). With the second K_d at 1900 N s/m
    (u3 = 0.95 > 0.9) the probe is not evaluated (NaN) and g = 5 + 3·0.95 = 7.85; the first K_d
    at 1900 N s/m alone (u2 = 0.95) leaves the probe evaluated."""
    low = _outputs(0.001, 0.0, 0.0, 1e5, 1)
    assert low["f1"] == pytest.approx(0.0, abs=1e-15)
    assert low["f2"] == pytest.approx(5.0, rel=1e-12)
    assert low["margin_lower"] == pytest.approx(-0.1, rel=1e-12)
    probe = _outputs(0.001, 0.0, 1900.0, 1e5, 1)
    assert math.isnan(probe["margin_probe"])
    assert probe["f2"] == pytest.approx(7.85, rel=1e-12)
    first = _outputs(0.001, 1900.0, 0.0, 1e5, 1)
    assert first["margin_probe"] == 1.0
    assert first["f2"] == pytest.approx(7.85, rel=1e-12)

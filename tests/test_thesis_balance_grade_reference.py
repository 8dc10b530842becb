"""The thesis strength studies' imbalance from a balance grade (ISO 21940-11) as from an eccentricity.

A design may give its imbalance as ``[loads] balance_grade`` G instead of an ``eccentricity``
(which is then 0); ISO 21940-11 §5.3 gives the permissible eccentricity e_per = G/Ω_max, Ω_max the
highest service speed (here the operating speed: the baseline has no ``speed_range``). So a
design with G = e Ω_op (G in mm/s: 1e3 e Ω_op) carries the same rotating force e m Ω² as the
design with eccentricity e, and every "safety factor with the imbalance" of the thesis studies
(3: wall, 4: proportional gain) must be the same for both. Studies 1 and 2 run without imbalance
(thesis §3.2): a balance grade must not bring one back.

Baseline design at a coarse mesh (18 shaft, 12 boom elements) and the 1.7 mm wall (the
operating speed near a shaft mode, thesis figure 3.5: the imbalance lowers the safety factor
visibly); both designs build the same matrices, so they agree to round-off (1e-12 relative).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.design import baseline_design, with_overrides
from flexshaft.sweep.study import Point
from flexshaft.thesis.strength import strength_outputs
from flexshaft.thesis.two_angles import two_angle_study

COARSE = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12, "shaft.wall_thickness": 0.0017}


@pytest.fixture(scope="module")
def pair():
    """(design with eccentricity e, the same design with balance grade G = 1e3 e Ω_op [mm/s])."""
    base = with_overrides(baseline_design(), COARSE)
    assert base.operating.speed_range is None  # Ω_max = Ω_op
    e = base.loads.eccentricity
    assert e > 0.0
    grade = 1e3 * e * base.operating.speed_rad_s
    graded = with_overrides(base, {"loads.eccentricity": 0.0, "loads.balance_grade": grade})
    return base, graded


def test_balance_grade_imbalance_enters_the_strength_study(pair):
    """safety_factor with G = e Ω_op equals the one with e (ISO 21940-11 e_per = G/Ω_max) to
    1e-12, and is below the static factor (the imbalance is there)."""
    with_e, with_grade = (strength_outputs(Point(0, {}, {}, d)) for d in pair)
    assert with_grade["safety_factor_static"] == pytest.approx(with_e["safety_factor_static"], rel=1e-12)
    assert with_grade["safety_factor"] == pytest.approx(with_e["safety_factor"], rel=1e-12)
    assert with_grade["safety_factor"] < with_grade["safety_factor_static"] * (1 - 1e-4)


def test_two_angle_study_has_no_imbalance_with_a_balance_grade(pair):
    """Study 2 runs without imbalance (thesis §3.2): with a balance grade too, its safety
    factor is the static one, which the grade does not change (the same static loads)."""
    _, graded = pair
    ds = two_angle_study(np.array([45.0]), np.array([45.0]), design=graded, progress=False, as_arrays=True)
    sf, static = float(ds["safety_factor"].values[0, 0]), float(ds["safety_factor_static"].values[0, 0])
    assert sf == static
    reference = strength_outputs(Point(0, {}, {}, with_overrides(pair[0], {"shaft.layup": "(45/-45/45/-45)s"})))
    assert static == pytest.approx(reference["safety_factor_static"], rel=1e-12)

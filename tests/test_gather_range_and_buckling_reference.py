"""The evidence of a point hands the operating speed range to the separation check, and the buckling
location reports the governing (weaker-sense) critical torque.

References (documented rules, hand computations):

* docs/requirements.md, the `separation` row: the actual margin of a lateral critical is measured
  "from the lowest speed of `[operating] speed_range` for a critical below the operating speed,
  from its highest (the maximum continuous speed) for one above"; its § on the separation rule
  quotes the tuned design's forward-overhang critical at 6000 rpm, 19 % above the maximum
  continuous speed 5040 rpm, where API 684 asks 22.4 % (its AF 5.2 is in the table at the top of
  that page; the AF 5.19 used here is tests/test_separation_speed_range_reference.py's).
* docs/requirements.md, the `buckling` row: "T_cr / T, weaker torque sense".

No analysis runs: the point's analyses are stand-ins whose answers are written by hand.
"""

from __future__ import annotations

import math
import re
from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.analyses.criticals import LateralCritical
from flexshaft.design.loads import Operating
from flexshaft.design.requirements import Requirements
from flexshaft.verdict import gather
from flexshaft.verdict.checks import evaluate

RPM = 2.0 * math.pi / 60.0  # [rad/s] per rpm

#: Ω_op = 4800 rpm with speed_range [0.9, 1.05]: N_min = 4320 rpm, N_max = 5040 rpm (the
#: design's own Operating computes the limits from the fractions).
OPERATING_POINT = Operating(speed_rpm=4800.0, power=0.0, speed_range=(0.9, 1.05))
LIMITS = (4320.0 * RPM, 5040.0 * RPM)


def _point() -> NS:
    """A point with two lateral criticals and no other result (every other check not evaluated)."""
    criticals = (
        LateralCritical(3000.0 * RPM, 5.19, {"station": 1.0}),
        LateralCritical(6000.0 * RPM, 5.19, {"station": 2.0}),
    )
    return criticals_only_point(criticals, OPERATING_POINT)


def criticals_only_point(criticals, operating: Operating, note: str = "") -> NS:
    """A stand-in point whose only result is a critical-speed search to 8000 rpm with these
    ``criticals`` and ``note`` at ``operating`` (every other check not evaluated)."""
    return NS(
        strength_static=None,
        strength_total=None,
        metal_strength=None,
        coupling_misalignment=None,
        buckling=None,
        criticals=NS(criticals=criticals, search_top=8000.0 * RPM, note=note),
        thermal=None,
        design=NS(thermal=NS(allowable_temperature_c=100.0), operating=operating),
        spinup=NS(speeds=np.array([0.0]), shaft_peak=np.zeros(1), up_to=lambda speed: np.array([], int)),
        torsional_separation=None,
        torsional_modes=None,
        bearing_loops=None,
        operating_speed=operating.speed_rad_s,
        model=NS(actuators=[]),
    )


def _required_above(af: float) -> float:
    """API 684 (docs/requirements.md): min(26, 10 + 17(1 − 1/(AF − 1.5))) % above the range."""
    return min(26.0, 10.0 + 17.0 * (1.0 - 1.0 / (af - 1.5))) / 100.0


def test_the_evidence_measures_separation_from_the_ends_of_the_speed_range(monkeypatch):
    """The thesis' critical at 6000 rpm (AF 5.19) lies 6000/5040 − 1 = 19.05 % above the maximum
    continuous speed: below the 22.39 % API 684 asks, a failure (it would pass with 25 % measured
    from the operating speed 4800 rpm). The critical at 3000 rpm below the range is measured from
    N_min = 4320 rpm: (4320 − 3000)/4320 = 30.56 %. The margins are ratios of binary-exact rpm
    values times one common factor: a few ulps, hence rel 1e-12."""
    monkeypatch.setattr(gather, "_whirl", lambda p: {})  # no stability result: the onset is not judged here
    evidence = gather.gather_evidence(_point())
    assert evidence.operating_range == pytest.approx(LIMITS, rel=1e-15)
    check = evaluate(evidence, Requirements()).check("separation")
    below, above = check.findings
    assert below.value == pytest.approx((4320.0 - 3000.0) / 4320.0, rel=1e-12)
    assert below.location["reference_speed"] == pytest.approx(LIMITS[0], rel=1e-15)
    assert above.value == pytest.approx(6000.0 / 5040.0 - 1.0, rel=1e-12)
    assert above.limit == pytest.approx(_required_above(5.19), rel=1e-12)
    assert above.location["reference_speed"] == pytest.approx(LIMITS[1], rel=1e-15)
    assert check.status == "fail" and check.margin == pytest.approx(6000.0 / 5040.0 - 1.0 - _required_above(5.19))


@pytest.mark.parametrize(("positive", "negative"), [(1000.0, 1500.0), (1800.0, 1200.0)])
def test_the_buckling_location_reports_the_weaker_senses_critical_torque(positive, negative):
    """T_cr of the two torque senses, applied torque T = 250 N m, no torque factor: the factor is
    min(T_cr)/T, and the location's T_cr is that weaker sense's (docs/requirements.md: "T_cr / T,
    weaker torque sense"), the smaller of the two written here (whole newton metres; the factor is
    then T_cr/T)."""
    weaker = min(positive, negative)
    result = NS(torque_positive=positive, torque_negative=negative, n_positive=3, n_negative=4, theory="Donnell")
    p = NS(buckling=NS(result=result, safety_factor=weaker / 250.0, torque=250.0), torque_factor=1.0)
    out = gather._buckling(p, {})
    found = re.search(r"T_cr = (\d+) N m", out["buckling_location"]["detail"])
    assert found is not None
    assert float(found.group(1)) == weaker
    sense = "positive" if positive < negative else "negative"
    assert out["buckling_location"]["case"].startswith(f"{sense} torque")

"""Reference: API's separation margin over an operating speed range (review, sixteenth session).

API 684 / 617 measure a critical speed below the operating range from the minimum operating
speed and one above it from the maximum continuous speed (docs/requirements.md). flexshaft took
both from the nominal operating speed: the tuned design's forward-overhang critical at 6000 rpm
passed with 25 % (API asks 22.4 % at its AF 5.2) although the design runs continuously up to
1.05 × 4800 = 5040 rpm, 19 % below it.

References, typed by hand:

* margin above the range = (N_c − N_max)/N_max, below = (N_min − N_c)/N_min, 0 inside it;
* the required margin: min(26, 10 + 17 (1 − 1/(AF − 1.5))) % above, min(16, 17 (1 − 1/(AF − 1.5)))
  % below, 0 for AF < 2.5 (the rule docs/requirements.md states, as ROSS implements it);
* the scan must reach 26 % over N_max, the largest margin API asks above the range.

Every comparison is of a few floating-point operations on the same inputs: rel 1e-12.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.criticals import LateralCritical
from flexshaft.analyses.separation import api684_separation
from flexshaft.design.requirements import Requirements
from flexshaft.resolution import REPORT, SCREENING
from flexshaft.verdict import checks
from flexshaft.verdict.evidence import Evidence

RPM = 2.0 * np.pi / 60.0
OMEGA = 4800.0 * RPM
RANGE = (0.95 * OMEGA, 1.05 * OMEGA)


def _af_above(af: float) -> float:
    return min(26.0, 10.0 + 17.0 * (1.0 - 1.0 / (af - 1.5))) / 100.0


def _af_below(af: float) -> float:
    return min(16.0, 17.0 * (1.0 - 1.0 / (af - 1.5))) / 100.0


@pytest.mark.parametrize(
    ("critical_rpm", "af", "margin", "required", "reference_rpm"),
    [
        (6000.0, 5.19, (6000.0 - 5040.0) / 5040.0, _af_above(5.19), 5040.0),  # the tuned design's, fails
        (6758.0, 5.81, (6758.0 - 5040.0) / 5040.0, _af_above(5.81), 5040.0),  # after the re-tune, passes
        (3600.0, 8.8, (4560.0 - 3600.0) / 4560.0, _af_below(8.8), 4560.0),  # below: from the minimum speed
        (4700.0, 1.8, 0.0, 0.0, 4560.0),  # inside the range (below N_op): no separation, none needed at AF < 2.5
        (4900.0, 3.0, 0.0, _af_above(3.0), 5040.0),  # inside (above N_op), AF 3: fails
    ],
)
def test_the_margin_is_measured_from_the_ends_of_the_range(critical_rpm, af, margin, required, reference_rpm):
    sep = api684_separation(critical_rpm * RPM, af, OMEGA, RANGE)
    assert sep.margin == pytest.approx(margin, rel=1e-12, abs=1e-15)
    assert sep.required_margin == pytest.approx(required, rel=1e-12, abs=1e-15)
    assert sep.reference_speed == pytest.approx(reference_rpm * RPM, rel=1e-12)
    assert sep.passed == (margin >= required)


def test_without_a_range_the_margin_is_from_the_operating_speed():
    """|N_c − N_op|/N_op on both sides, as before (one operating speed)."""
    above = api684_separation(6000.0 * RPM, 5.19, OMEGA)
    below = api684_separation(3600.0 * RPM, 8.8, OMEGA)
    assert above.margin == pytest.approx(1200.0 / 4800.0, rel=1e-12)
    assert below.margin == pytest.approx(1200.0 / 4800.0, rel=1e-12)
    assert above.reference_speed == below.reference_speed == pytest.approx(OMEGA, rel=1e-15)


@pytest.mark.parametrize("bad", [(1.1 * OMEGA, 1.2 * OMEGA), (0.8 * OMEGA, 0.9 * OMEGA), (0.0, OMEGA), (np.nan, OMEGA)])
def test_a_range_that_does_not_hold_the_operating_speed_is_refused(bad):
    with pytest.raises(ValueError, match="speed_range must hold the operating speed"):
        api684_separation(6000.0 * RPM, 5.0, OMEGA, bad)


def test_the_check_reads_the_range_of_the_evidence():
    """The verdict's separation check on a critical at 6000 rpm, AF 5.19: passes with one
    operating speed (25 % ≥ 22.4 %), fails over 0.95-1.05 (19.0 %), and names the speed the
    margin is measured from."""
    critical = (LateralCritical(6000.0 * RPM, 5.19, {"station": 0.0}),)
    one = checks.separation(Evidence(OMEGA, critical_speeds=critical), Requirements())
    ranged = checks.separation(Evidence(OMEGA, RANGE, critical_speeds=critical), Requirements())
    assert one.status == "pass" and one.value == pytest.approx(0.25, rel=1e-12)
    assert ranged.status == "fail" and ranged.value == pytest.approx(960.0 / 5040.0, rel=1e-12)
    assert ranged.limit == pytest.approx(_af_above(5.19), rel=1e-12)
    assert ranged.location["reference_speed"] == pytest.approx(RANGE[1], rel=1e-12)


@pytest.mark.parametrize("resolution", [SCREENING, REPORT])
def test_the_scan_reaches_26_percent_over_the_highest_speed(resolution):
    """The scan's top (and so the critical-speed search) is scan_top × the highest operating
    speed: 1.30 × 1.05 × Ω ≥ 1.26 × 1.05 × Ω, API's largest margin above the range; one
    operating speed keeps 1.30 × Ω."""
    ranged = resolution.spin_speeds(OMEGA, 1.05)
    assert ranged[-1] == pytest.approx(1.30 * 1.05 * OMEGA, rel=1e-12) and ranged[-1] >= 1.26 * RANGE[1]
    assert resolution.spin_speeds(OMEGA)[-1] == pytest.approx(1.30 * OMEGA, rel=1e-12)
    assert ranged.size == resolution.spinup_speeds

"""The operating point's validation in rad/s whichever unit the speed is given in, and the
speed range's ends, worked by hand.

References (documented rules, and two rules derived here, worked by hand):

* **Torque cap in rad/s.** docs/limits.md: "Torque: P/Ω at most 1e9 N m". At 1 rev/min,
  Ω = 2π/60 = 0.10472 rad/s, so the cap is P <= 1e9 × 0.10472 = 1.0472e8 W: P = 2e8 W
  (T = 1.91e9 N m) is refused, P = 1e8 W (T = 9.55e8 N m) allowed. A cap computed with the
  rev/min number would allow 1e9 W, so 2e8 W sits between the right and the slipped cap.
* **At rest in rad/s.** With Ω = 0 a positive power gives T = P/Ω infinite: refused as a
  validation error whether the speed is given as ``speed = 0`` [rad/s] or ``speed_rpm = 0``.
* **The range brackets the operating speed** (rule derived here, not quoted: no hand-written
  doc states lowest <= 1 <= highest; it follows from docs/requirements.md, where the separation
  margins are measured from N_min, the lowest end of ``[operating] speed_range``, for a critical
  below the range and from N_max, the highest, for one above, and from docs/transient.md, where
  a balance grade is converted at the highest speed: a range that does not hold the operating
  speed would check margins and the balance grade away from it). A range [0.90, 0.95] lies
  wholly below the operating speed and is refused, as is [1.05, 1.10] above it; [0.95, 1.05]
  is accepted with limits 0.95 Ω and 1.05 Ω.
* **The lowest end is above 0** (derived here from what the analyses need). A range from
  standstill, [0, 1.05], would be accepted as a design and then crash the analyses that need a
  speed above 0: ``torsional_separation`` raises ValueError ("speed_range must be
  0 < lowest"), and the tail-rotor torque-oscillation response refuses a speed of 0 (both
  measured on tuned.toml with speed_range = [0.0, 1.05] and the lower bound dropped). So it is
  refused at validation; [0.01, 1.05] is accepted.

Pure schema validation (no model is built): a few ms.
"""

from __future__ import annotations

import math

import pytest
from pydantic import ValidationError

from flexshaft.design.loads import Operating

ONE_RPM = 2.0 * math.pi / 60.0  # [rad/s]


def test_the_torque_cap_is_in_rad_s_when_the_speed_is_given_in_rev_min():
    with pytest.raises(ValidationError, match="power"):  # cap 1e9 x ONE_RPM = 1.0472e8 W
        Operating(speed_rpm=1.0, power=2e8)
    # rel 1e-14: Ω may be formed as π/30 or 2π/60, equal within a few ulp (~1e-16 each), then
    # one division; a unit slip would be off by 60/(2π) = 9.55.
    assert Operating(speed_rpm=1.0, power=1e8).torque == pytest.approx(1e8 / ONE_RPM, rel=1e-14)


@pytest.mark.parametrize("speed", [{"speed": 0.0}, {"speed_rpm": 0.0}], ids=["rad-s", "rev-min"])
def test_power_at_rest_is_refused_whichever_unit_gives_the_speed(speed):
    with pytest.raises(ValidationError, match="power"):
        Operating(**speed, power=1.0)
    assert Operating(**speed, power=0.0).torque == 0.0


@pytest.mark.parametrize("speed_range", [(0.90, 0.95), (1.05, 1.10)])
def test_a_range_beside_the_operating_speed_is_refused(speed_range):
    with pytest.raises(ValidationError, match="speed_range"):
        Operating(speed=100.0, power=0.0, speed_range=speed_range)


def test_a_bracketing_range_gives_its_ends_in_rad_s():
    low, high = Operating(speed=100.0, power=0.0, speed_range=(0.95, 1.05)).speed_limits
    # rel 1e-15: 0.95 x 100 is one rounded product of a stored 0.95, exact to 1 ulp (2.2e-16).
    assert (low, high) == (pytest.approx(95.0, rel=1e-15), pytest.approx(105.0, rel=1e-15))


def test_a_range_from_standstill_is_refused():
    with pytest.raises(ValidationError, match="speed_range"):
        Operating(speed=100.0, power=0.0, speed_range=(0.0, 1.05))
    assert Operating(speed=100.0, power=0.0, speed_range=(0.01, 1.05)).speed_limits[0] == pytest.approx(1.0)

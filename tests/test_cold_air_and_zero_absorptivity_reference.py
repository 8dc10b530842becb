"""Air below the c_p table (a cold envelope point) and a skin that absorbs no sun (hunt h46c).

* Cold air. :func:`~flexshaft.thermal.air.air_properties` interpolates c_p in Incropera &
  DeWitt's 250-400 K rows and holds the 250 K row below them. At −40 °C (233.15 K, the usual
  cold-day point) Çengel & Ghajar, *Heat and Mass Transfer*, Table A-15 (air at 1 atm) gives
  c_p = 1002 J/(kg K), and 1006 J/(kg K) at −10 and 0 °C: c_p varies by 0.4 % over that range, so
  the held value must lie within 0.5 % of 1002 (a value taken from the table's hot end,
  1014 J/(kg K) at 400 K, is 1.2 % off).
* Zero solar absorptivity. ``solar_absorptivity`` replaces ε for the sun only when given
  (:class:`~flexshaft.thermal.environment.ThermalEnvironment`): α_s = 0 is a given value (a
  skin that absorbs no sun), not "not given". With no absorbed sun the parked skin's balance
  (thesis eq. 2.55) reads εσ(T⁴ − T_sky⁴) + h(T − T_amb) = 0: both loss terms cannot be
  positive, so T lies between T_sky = 285 K and T_amb = 298.75 K, far below the sun-soaked
  89 °C of α_s = ε.

Microseconds (two energy balances).
"""

from __future__ import annotations

import pytest

from flexshaft.thermal.air import air_properties
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.tailboom import tailboom_temperature


def test_cold_air_specific_heat_against_cengel_table_a15():
    air = air_properties(233.15)  # -40 °C
    assert air.specific_heat == pytest.approx(1002.0, rel=5e-3)


def test_a_given_zero_solar_absorptivity_absorbs_no_sun():
    env = ThermalEnvironment(solar_absorptivity=0.0)
    assert env.absorptivity == 0.0
    assert env.emissivity == 0.97  # the infrared emissivity is kept
    parked = tailboom_temperature("parked", 0.3, env, "hilpert").temperature
    assert env.sky_temperature <= parked <= env.ambient_temperature

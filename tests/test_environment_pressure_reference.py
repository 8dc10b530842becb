"""The thermal environment's air pressure is the standard sea-level 101325 Pa (hunt h41a).

Reference: U.S. Standard Atmosphere, 1976 (NOAA/NASA/USAF), sea level: p₀ = 101325 Pa,
T₀ = 288.15 K, ρ₀ = 1.2250 kg/m³. The pressure is not a ``[thermal]`` field: every design's
environment (:func:`~flexshaft.thermal.options.environment_from`) takes the dataclass default,
which sets the air density of every film (:func:`~flexshaft.thermal.air.air_properties`,
ρ = p/(R T)). At T₀ the density must be the table's ρ₀; the gas constant R = 287.05 J/(kg K)
rounds the standard's 287.053 (1e-5 relative), so 2e-4 relative is asserted. A pressure of 1 bar
(100000 Pa, the IUPAC STP) gives 1.2090 kg/m³, 1.3 % low.

A few microseconds. Written for h41a-env-pressure-one-bar of scripts/mutations.toml.
"""

from __future__ import annotations

import pytest

from flexshaft.design.thermal_schema import Thermal
from flexshaft.thermal.air import air_properties
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.options import environment_from


@pytest.mark.parametrize("env", [ThermalEnvironment(), environment_from(Thermal())], ids=["default", "design"])
def test_the_film_air_has_the_standard_sea_level_density(env):
    assert env.air_pressure == 101325.0
    assert air_properties(288.15, env.air_pressure).density == pytest.approx(1.2250, rel=2e-4)

"""A parked boom sits in still air; a sun below the horizon is refused.

* Air speed. Hovering, the boom sits in the main rotor's downwash, the momentum-theory induced
  velocity V = √(W / (2 ρ π R²)) (thesis eq. 2.56); with m = 6838 kg (thesis Table 2.1),
  R = 7.315 m and ρ = 1.225 kg/m³ (the defaults table of docs/thermal.md, ``rotor_radius`` and
  ``air_density``) and g = 9.80665 m/s², that is 12.76 m/s (docs/thermal.md, "Hover"), written
  out below. Parked, the rotor is stopped and the boom loses heat by free convection
  (Churchill-Chu) in still air: its air speed is zero.
* Sun position. The absorbed solar flux is α G with G = S_c f cos θ_s (thesis eq. 2.58,
  docs/thermal.md). For |θ_s| > 90° the sun is below the horizon and cos θ_s < 0 would turn the
  sun into a heat sink (physics: G ≥ 0 for any sun). API contract:
  :class:`~flexshaft.thermal.environment.ThermalEnvironment` takes the zenith in [−π/2, π/2]
  (as the design schema takes ±90°, design/thermal_schema.py ``Zenith``). So a zenith of 2 rad,
  −2 rad or π is refused, or, if accepted, must still give G ≥ 0 (G = 1353 cos 2 < 0 would be
  a sun that cools: the physics catch), and every accepted zenith gives G ≥ 0.

The downwash is a square root of a quotient, exact to a few ulps: rel = 1e-12.

Milliseconds (two energy balances).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.tailboom import tailboom_temperatures


def test_hover_boom_in_the_downwash_parked_boom_in_still_air():
    booms = tailboom_temperatures(0.3)
    V = math.sqrt(6838.0 * 9.80665 / (2.0 * 1.225 * math.pi * 7.315**2))
    assert V == pytest.approx(12.76, abs=0.01)
    assert booms["hover"].velocity == pytest.approx(V, rel=1e-12)
    assert booms["parked"].velocity == 0.0


@pytest.mark.parametrize("zenith", [2.0, -2.0, math.pi])
def test_a_sun_below_the_horizon_is_refused_or_never_cools(zenith):
    """|θ_s| > π/2: refused (the API contract), and in no case a negative G = S_c f cos θ_s."""
    try:
        environment = ThermalEnvironment(solar_zenith=zenith)
    except ValueError:
        return  # refused: the contract
    assert environment.solar_irradiation >= 0.0, environment.solar_irradiation


@pytest.mark.parametrize("zenith", [0.0, 1.0, -1.5, math.pi / 2])
def test_an_accepted_sun_never_cools(zenith):
    """Every zenith in [−π/2, π/2] gives G = S_c f cos θ_s ≥ 0."""
    assert ThermalEnvironment(solar_zenith=zenith).solar_irradiation >= 0.0

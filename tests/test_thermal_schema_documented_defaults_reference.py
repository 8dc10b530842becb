"""A design file without a ``[thermal]`` table gets the thermal environment docs/thermal.md documents.

References (the hand-written table of docs/thermal.md, "The `[thermal]` table of the design
file", and thesis eq. 2.58 as that table quotes it):

* ``solar_constant``, ``solar_fraction``, ``solar_zenith_deg``: "1353 W/m², 1, 0°", the S_c, f,
  θ_s of G = S_c f cos θ_s (eq. 2.58): G = 1353 · 1 · cos 0 = 1353 W/m²;
* ``ambient_temperature_c``: 25.6 °C, i.e. 25.6 + 273.15 = 298.75 K (the Celsius scale's
  definition); the sky 285 K (thesis Table 2.1);
* ``boom_convection`` ``"hilpert"``, ``shaft_convection`` ``"becker"``;
* ``fibre_conductivity``, ``transverse_conductivity``: 5.0, 0.5 W/(m K);
* ``matrix_modulus_decay``, ``matrix_loss_growth``: 40 K, 60 K in the law E_T, G_LT ∝
  exp(−ΔT/θ_E) and η_T, η_LT ∝ exp(+ΔT/θ_η), capped at 1 (docs/thermal.md, "Lamina
  properties over temperature"). At
  ΔT = 60 K above the 20 °C reference a transverse modulus of 1 GPa becomes e^(−1.5) GPa and a
  loss factor 0.01 becomes 0.01 e = 0.027 (below the documented cap of 1);
* docs/limits.md: "temperatures (−273.15, 400] °C": a −20 °C night sky is a valid input
  (253.15 K) and absolute zero itself is refused.

Tolerances: G is one product and the kelvin values one addition of typed numbers (1e-12
relative, 1e-9 K absolute); the law's factors are one exp each, 1e-12 relative.

Written for the mutations h64f-thermal-* of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import pytest
from boomed_rotor import shaft_and_boom

from flexshaft.design import DesignError, loads_design
from flexshaft.thermal.options import thermal_options

DESIGN = f"""
name = "no thermal table"
{shaft_and_boom(2.5)}[[bearings]]
name = "aft"
kind = "contact"
x = 1.9
stiffness = {{ v = 1e7, w = 1e7 }}
[operating]
speed_rpm = 3000.0
power = 0.0
"""

REFERENCE = {  # lamina values at the law's reference temperature (any positive numbers)
    "E_L": 100e9,
    "E_T": 1e9,
    "G_LT": 0.5e9,
    "loss_E_L": 0.002,
    "loss_E_T": 0.01,
    "loss_G_LT": 0.02,
}


@pytest.fixture(scope="module")
def options():
    return thermal_options(loads_design(DESIGN).thermal)


def test_default_sun_air_and_sky(options) -> None:
    env = options.environment
    assert env.solar_irradiation == pytest.approx(1353.0 * 1.0 * math.cos(0.0), rel=1e-12)
    assert env.ambient_temperature == pytest.approx(25.6 + 273.15, abs=1e-9)
    assert env.sky_temperature == pytest.approx(285.0, abs=1e-9)


def test_default_correlations_and_ply_conductivities(options) -> None:
    assert (options.boom_convection, options.shaft_convection) == ("hilpert", "becker")
    assert (options.fibre_conductivity, options.transverse_conductivity) == (5.0, 0.5)


def test_default_matrix_law_at_sixty_kelvin_above_reference(options) -> None:
    law = options.matrix_law
    assert law.reference_temperature == pytest.approx(20.0 + 273.15, abs=1e-9)
    hot = law.properties(REFERENCE, 20.0 + 273.15 + 60.0)
    assert hot["E_T"] == pytest.approx(1e9 * math.exp(-60.0 / 40.0), rel=1e-12)
    assert hot["G_LT"] == pytest.approx(0.5e9 * math.exp(-60.0 / 40.0), rel=1e-12)
    assert hot["loss_E_T"] == pytest.approx(0.01 * math.e, rel=1e-12)
    assert hot["loss_G_LT"] == pytest.approx(0.02 * math.e, rel=1e-12)
    assert hot["E_L"] == REFERENCE["E_L"]


def test_a_night_sky_below_freezing_is_valid_and_absolute_zero_is_not() -> None:
    cold = thermal_options(loads_design(DESIGN + "[thermal]\nsky_temperature_c = -20.0\n").thermal)
    assert cold.environment.sky_temperature == pytest.approx(253.15, abs=1e-9)
    with pytest.raises(DesignError, match="sky_temperature_c"):
        loads_design(DESIGN + "[thermal]\nsky_temperature_c = -273.15\n")

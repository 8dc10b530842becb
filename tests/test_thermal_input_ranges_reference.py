"""The ``[thermal]`` quantities are refused just beyond the ranges docs/limits.md documents.

Reference, docs/limits.md (hand-written), "Also bounded: ... the ambient air −73 to 176 °C (the
air properties are evaluated from 200 to 600 K, at the tailboom's film temperatures up to the
ambient + 150 K: 400 °C, the former maximum, failed inside the thermal analysis), and the
`[thermal]` quantities (... conductivities 1e-3–2000 W/(m K), the matrix law's temperature
scales 5 K to 1e6 K so that exp(±ΔT/θ) stays below 1e59 over the allowed temperatures)";
docs/thermal.md repeats "allowed −73 to 176 °C" for ``ambient_temperature_c``.

The limits follow from closed forms derived here:

* the ambient: the hottest film temperature is T_amb + 150 K; at 176 °C it is 176 + 273.15 +
  150 = 599.15 K, inside the 600 K the air properties reach, and at 177 °C it is 600.15 K,
  outside: 177 °C must be refused at the design's validation, not inside the analysis;
* the temperature scales: temperatures lie in (−273.15, 400] °C (docs/limits.md), so |ΔT| is at
  most 400 − (−273.15) = 673.15 K; exp(673.15/5) = e^134.63 ≈ 2.9e58 < 1e59, while at 4.9 K
  exp(673.15/4.9) = e^137.38 ≈ 4.6e59 > 1e59: 5 K is the smallest scale (to 0.1 K) that keeps
  the documented bound, and 4.9 K must be refused;
* the conductivities: 1e-3 W/(m K) is accepted and 9e-4 (10 % below) refused.

Each value is a typed decimal compared with a typed bound, and the exponentials sit a factor 3
and more from 1e59, so no tolerance enters.

Written for the mutations h92b-ambient-ceiling-former-400, h92b-matrix-scale-floor-half-kelvin
and h92b-conductivity-floor-zero of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import pytest
from boomed_rotor import shaft_and_boom

from flexshaft.design import DesignError, loads_design
from flexshaft.thermal.air import AIR_TEMPERATURE_RANGE

DESIGN = f"""
name = "thermal ranges"
{shaft_and_boom(2.5)}[[bearings]]
name = "aft"
kind = "contact"
x = 1.9
stiffness = {{ v = 1e7, w = 1e7 }}
[operating]
speed_rpm = 3000.0
power = 0.0
"""


def _thermal(field: str, value: float):
    return loads_design(f"{DESIGN}[thermal]\n{field} = {value!r}\n").thermal


@pytest.mark.parametrize(
    ("field", "inside", "outside"),
    [
        ("ambient_temperature_c", 176.0, 177.0),
        ("ambient_temperature_c", -73.0, -74.0),
        ("matrix_modulus_decay", 5.0, 4.9),
        ("matrix_loss_growth", 5.0, 4.9),
        ("fibre_conductivity", 1e-3, 9e-4),
        ("transverse_conductivity", 1e-3, 9e-4),
    ],
)
def test_a_thermal_quantity_is_accepted_at_its_documented_limit_and_refused_beyond(field, inside, outside):
    """The limit itself loads and keeps its value; the value just beyond it is refused, naming the
    field (docs/limits.md, quoted in the module docstring)."""
    assert getattr(_thermal(field, inside), field) == inside
    with pytest.raises(DesignError, match=rf"thermal\.{field}: "):
        _thermal(field, outside)


def test_the_limits_are_where_the_closed_forms_put_them():
    """The documented reasons of the limits, derived in the module docstring: the film
    temperature T_amb + 150 K against the air properties' 600 K, and the largest matrix-law factor
    exp(673.15 K/θ) against 1e59."""
    span = 400.0 - (-273.15)  # K, the allowed temperatures (docs/limits.md)
    top = AIR_TEMPERATURE_RANGE[1]  # the air properties' range, docs/limits.md's 600 K
    assert top == 600.0
    assert 176.0 + 273.15 + 150.0 <= top < 177.0 + 273.15 + 150.0
    assert math.exp(span / 5.0) < 1e59 < math.exp(span / 4.9)

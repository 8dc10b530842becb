"""The design schema's lower bounds at values a real design uses, from their stated ranges.

* **Wall thickness** (:data:`flexshaft.design.quantities.WallThickness`, "from 10 µm (a tenth
  of one ply) to 1 m"): a 0.5 mm wall, four 0.125 mm prepreg plies, is a real thin tube and is
  accepted; its bore is D − 2t by hand. 5 µm (below the floor) is refused.
* **Stress-free temperature** (:data:`flexshaft.design.materials.Celsius`, "above absolute
  zero and at most 400 °C"): −40 °C (a ply relaxed in the cold) is accepted and is
  233.15 K (T[K] = T[°C] + 273.15, the definition of the Celsius scale); −273.15 °C, absolute
  zero itself, is refused and −273 °C accepted.
* **Gains** (:data:`flexshaft.design.quantities.ProportionalGain`, "from 0"): k_p = 0 with
  k_d > 0 is a pure damper bearing, accepted: C(s) = k_d s, i.e. ((k_d, 0), (1,)) highest power
  first (the ActiveBearing docstring's PD law).

Schema objects only, no model: a few ms. Exact comparisons except the Kelvin sum (1e-12).
"""

from __future__ import annotations

import pytest
from test_schema_bounds_reference import PLY

from flexshaft.design.bearings import ActiveBearing
from flexshaft.design.components import Shaft
from flexshaft.design.materials import Lamina

SHAFT = {"x_start": 0.0, "x_end": 1.0, "outer_diameter": 0.05, "material": "ply", "layup": "(45/-45)s"}


def test_a_half_millimetre_wall_is_a_shaft():
    shaft = Shaft(**SHAFT, wall_thickness=0.5e-3)
    assert shaft.inner_diameter == pytest.approx(0.05 - 1.0e-3, rel=1e-12)
    with pytest.raises(ValueError, match="wall_thickness"):
        Shaft(**SHAFT, wall_thickness=5.0e-6)


def test_a_stress_free_temperature_below_zero_celsius_is_above_absolute_zero():
    assert Lamina(**PLY, stress_free_temperature_c=-40.0).stress_free_temperature == pytest.approx(233.15, rel=1e-12)
    Lamina(**PLY, stress_free_temperature_c=-273.0)
    with pytest.raises(ValueError, match="stress_free_temperature_c"):
        Lamina(**PLY, stress_free_temperature_c=-273.15)


def test_a_pure_damper_bearing_has_no_proportional_gain():
    bearing = ActiveBearing(name="damper", kind="active", x=0.5, kp=0.0, kd=300.0)
    assert bearing.transfer_function() == ((300.0, 0.0), (1.0,))

"""The magnet's saturation flux density against its documented range and the saturation force.

* **Range** (docs/limits.md, the table of quantity ranges: "``FluxDensity`` |
  ``saturation_flux_density`` | up to 10 T | iron-cobalt saturates at 2.4 T"). The 2.4 T of
  iron-cobalt is the why of the row, not its bound: a B_sat of 5 T or 10 T (an idealised or
  superconducting magnet) is accepted, the next double above 10 T and B_sat = 0 are refused
  (the row reads "up to", and ``Current``, ``CoilTurns``, ``PoleArea`` of the row above are
  "above 0"; a zero saturation flux density would give a magnet with no force).
* **What an accepted B_sat gives** (docs/magnetic-bearings.md, "Magnet physics": the largest
  net force of one axis is ``f_sat = B_sat² A_a cos α / μ0``, "about 40 N/cm² of pole face at
  1 T"; ``Actuator.saturation_force`` "is this f_sat when saturation_flux_density and
  pole_area are given"). At 10 T, A_a = 6 cm² and the default α = 22.5° (same document's key
  table) the hand value is f_sat = 100 · 6e-4 · cos(π/8)/(4π·1e-7) ≈ 4.41e4 N, and f_sat scales
  as B_sat² (100 times the 1 T force). The product's ``magnetic.saturation_force`` is called
  with the validated keys as the model build does (assembly/build.py); a handful of float
  operations on both sides: relative 1e-9 (the docs name μ0 without a value: the exact 4π·1e-7 and
  the SI 2019 value differ by 5.5e-10; rounding is ~1e-16 per operation).

Written for the mutation h73b-flux-density-max-at-iron-cobalt of scripts/mutations.toml.
Only the pydantic model is built (no model is assembled).
"""

from __future__ import annotations

import math

import pydantic
import pytest

from flexshaft.design.bearings import ActiveBearing
from flexshaft.elements import magnetic

POLE_AREA = 6.0e-4  # A_a [m²], 6 cm² per pole face
MU_0 = 4.0e-7 * math.pi  # vacuum permeability [H/m] (the pre-2019 SI value)


def active(b_sat: float) -> ActiveBearing:
    """An ideal-law active bearing (kp only, k_s and k_i given by default) with a B_sat."""
    return ActiveBearing(kind="active", name="amb", x=0.5, kp=1.0e6, pole_area=POLE_AREA, saturation_flux_density=b_sat)


@pytest.mark.parametrize("b_sat", [1.0, 2.4, 5.0, 10.0])
def test_a_saturation_flux_density_up_to_ten_tesla_is_accepted(b_sat):
    bearing = active(b_sat)
    assert bearing.saturation_flux_density == b_sat
    assert bearing.pole_angle == 22.5  # documented default: an 8-pole stator


@pytest.mark.parametrize("b_sat", [math.nextafter(10.0, math.inf), 0.0, -1.2])
def test_a_saturation_flux_density_outside_the_range_is_refused(b_sat):
    with pytest.raises(pydantic.ValidationError):
        active(b_sat)


def test_the_ten_tesla_magnet_gives_the_documented_saturation_force():
    bearing = active(10.0)
    assert bearing.saturation_flux_density is not None and bearing.pole_area is not None
    force = magnetic.saturation_force(bearing.saturation_flux_density, bearing.pole_area, bearing.pole_angle_rad)
    expected = 10.0**2 * POLE_AREA * math.cos(math.pi / 8.0) / MU_0
    assert force == pytest.approx(expected, rel=1e-9)
    assert 4.40e4 < force < 4.42e4  # the hand value, 4.411e4 N
    # f_sat ∝ B_sat²: 100 times the 1 T force of the same pole face
    one_tesla = active(1.0)
    assert one_tesla.pole_area is not None
    base = magnetic.saturation_force(1.0, one_tesla.pole_area, one_tesla.pole_angle_rad)
    assert force == pytest.approx(100.0 * base, rel=1e-9)

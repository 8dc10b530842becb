"""The physical ranges of :mod:`flexshaft.design.quantities` at their edges.

References: a mass, a moment of inertia and a density cannot be negative, and a zero density
makes the mass matrix singular (docs/limits.md, the `Density` row); the bounds are those of the
table in docs/limits.md. The eccentricity's upper bound is 10 mm; a balance quality grade G40
(ISO 1940-1: G = e Ω in mm/s) at 5000 rpm allows e = 40 / (5000 · 2π/60) mm = 76.4 µm, well
inside it, and 50 mm (a bound typed in millimetres instead of metres) must be refused.
"""

from __future__ import annotations

import math

import pytest
from pydantic import TypeAdapter, ValidationError

from flexshaft.design.quantities import Density, Eccentricity, Inertia, Mass, Modulus, Power


def _accepts(kind, value) -> bool:
    try:
        TypeAdapter(kind).validate_python(value)
    except ValidationError:
        return False
    return True


def test_masses_inertias_and_densities_are_not_negative():
    assert _accepts(Mass, 0.0) and not _accepts(Mass, -1.0)
    assert _accepts(Inertia, 0.0) and not _accepts(Inertia, -1e-3)
    assert not _accepts(Density, -1.0)


def test_the_transmitted_power_is_not_negative():
    """The tail rotor absorbs power (P ≥ 0, docs/limits.md): a negative power would reverse the
    steady torque P/Ω the strength and buckling checks carry."""
    assert _accepts(Power, 0.0) and _accepts(Power, 5e5)
    assert not _accepts(Power, -1.0)


def test_zero_density_is_refused_but_the_massless_idealisation_is_not():
    assert not _accepts(Density, 0.0)
    assert _accepts(Density, 1e-6)


def test_eccentricity_is_in_metres_up_to_ten_millimetres():
    g40_at_5000_rpm = 40e-3 / (5000.0 * 2.0 * math.pi / 60.0)  # [m], ISO 1940-1 G = e Ω
    assert g40_at_5000_rpm == pytest.approx(76.4e-6, rel=1e-3)
    assert _accepts(Eccentricity, g40_at_5000_rpm)
    assert _accepts(Eccentricity, 10e-3)
    assert not _accepts(Eccentricity, 50e-3)


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
def test_non_finite_numbers_are_refused(value):
    for kind in (Mass, Density, Modulus, Eccentricity):
        assert not _accepts(kind, value)

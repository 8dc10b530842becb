"""Edges of the design quantities a requirement or an idealisation rests on.

Reference: the range table of docs/limits.md (one row per quantity type) and the module
docstring of :mod:`flexshaft.design.quantities`, which promise

* ``Modulus`` "1 kPa to 1e16 Pa": the rigid-member idealisation (5e4 × steel) is accepted,
  though real materials stop at 1.2e12 Pa (diamond); a modulus above 1e16 is refused.
* ``SafetyFactor`` "above 0, up to 100": a required safety factor of 0 would pass every strength
  and buckling check whatever the load (the check is value ≥ limit), so 0 is refused and the
  smallest positive value is accepted.
* ``Deflection`` "above 0, up to 10 m": a deflection limit of 0 m fails every spin-up (any
  orbit exceeds it) and its relative margin (limit − value)/limit divides by zero.
* ``ForceCapacity`` "above 0, up to 1e9 N": an actuator that can carry no force is refused.

Each check validates one number against the annotated type (pydantic), exact: no tolerance.
Written for the mutations h39b-q-rigid-modulus-refused, h39b-q-zero-safety-factor,
h39b-q-zero-deflection-limit and h39b-q-zero-force-capacity of scripts/mutations.toml.
"""

from __future__ import annotations

import math

from pydantic import TypeAdapter, ValidationError

from flexshaft.design.quantities import Deflection, ForceCapacity, Modulus, SafetyFactor


def _accepts(kind, value: float) -> bool:
    try:
        TypeAdapter(kind).validate_python(value)
    except ValidationError:
        return False
    return True


def test_the_rigid_member_idealisation_is_a_modulus():
    assert _accepts(Modulus, 1.2e12)  # diamond
    assert _accepts(Modulus, 1e16)  # the rigid member's cap, 5e4 × 200 GPa = 1e16 (docs/limits.md)
    assert not _accepts(Modulus, math.nextafter(1e16, math.inf))


def test_a_required_safety_factor_is_positive():
    assert not _accepts(SafetyFactor, 0.0)
    assert _accepts(SafetyFactor, math.nextafter(0.0, 1.0)) and _accepts(SafetyFactor, 100.0)


def test_a_deflection_limit_is_positive():
    assert not _accepts(Deflection, 0.0)
    assert _accepts(Deflection, 1e-6) and _accepts(Deflection, 10.0)


def test_an_actuator_force_capacity_is_positive():
    assert not _accepts(ForceCapacity, 0.0)
    assert _accepts(ForceCapacity, 1.0) and _accepts(ForceCapacity, 1e9)

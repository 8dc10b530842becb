"""A contact bearing's stiffness and damping bounds (docs/limits.md, section 1).

docs/limits.md's table: ``Stiffness`` (contact-bearing stiffness) "0 to 1e12 N/m (N m/rad)",
"1e12 is rigid for any shaft"; ``Damping`` (contact-bearing damping) "0 to 1e9 N s/m". The two
ranges differ by a factor 1000, so a near-rigid support of 1e10 N/m (between them) and one of
exactly 1e12 N/m must be accepted as stiffness, while 1e10 N s/m of damping is refused; a
stiffness just above 1e12 (1.000001e12) is refused. The values stored are the values written
(no arithmetic: exact comparison). Schema objects only, no model: a millisecond.
"""

from __future__ import annotations

import pydantic
import pytest

from flexshaft.design.bearings import ContactBearing


def _hanger(**tables: dict[str, float]) -> ContactBearing:
    return ContactBearing.model_validate({"kind": "contact", "name": "h", "x": 1.0, **tables})


def _upper_bounds(error: pydantic.ValidationError) -> list[tuple[tuple[object, ...], float]]:
    """(field location, upper bound) of each refusal; every refusal must be an upper bound."""
    assert all(e["type"] == "less_than_equal" for e in error.errors())
    return [(tuple(e["loc"]), float(e["ctx"]["le"])) for e in error.errors()]


def test_a_near_rigid_support_is_accepted_up_to_1e12() -> None:
    for k in (1.0e10, 1.0e12):
        bearing = _hanger(stiffness={"v": k, "w": k, "beta": k})
        assert (bearing.stiffness_of("v"), bearing.stiffness_of("w"), bearing.stiffness_of("beta")) == (k, k, k)
    with pytest.raises(pydantic.ValidationError) as refused:
        _hanger(stiffness={"v": 1.000001e12})
    assert _upper_bounds(refused.value) == [(("stiffness", "v"), 1.0e12)]


def test_damping_keeps_its_own_smaller_bound_1e9() -> None:
    assert _hanger(stiffness={"v": 1.0e10}, damping={"v": 1.0e9}).damping_of("v") == 1.0e9
    with pytest.raises(pydantic.ValidationError) as refused:
        _hanger(stiffness={"v": 1.0e10}, damping={"v": 1.0e10})
    assert _upper_bounds(refused.value) == [(("damping", "v"), 1.0e9)]

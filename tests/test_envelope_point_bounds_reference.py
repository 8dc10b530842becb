"""The operating envelope's points and the shared design-field types at the edges that
docs/design-reference.md states (design/envelope.py, design/fields.py), on hand-typed values.

References (the rows of docs/design-reference.md, quoted):

* ``[[envelope.points]]`` temperatures: "(-273.15, 400]" -- absolute zero (0 K, where the
  radiation and air laws divide by T) is refused, 400 °C accepted;
* ``solar_fraction``: "[0, 1]" -- 1 (the whole sun) accepted;
* ``load_scale``: "[0, 100] ... (0: no manoeuvre or point loads)" -- 0 and 100 accepted,
  just above 100 refused;
* ``material_temperature_c``: "required with material_temperature = "given", refused otherwise";
* ``points``: "1 to 20 tables", unique names; an unknown name is not a point (KeyError), and
  a design without ``[envelope]`` still finds each of the three default points by name, the
  cold day at -40 °C with the shaft at the ambient;
* a point's known material temperature is checked against each lamina's temperature_table,
  "outside the table nothing is extrapolated" (docs/design-reference.md): a temperature equal
  to the table's first or last row lies inside it (closed interval), 0.01 °C beyond either
  does not;
* ``shaft_elements``: "[1, 2000]"; a controller's ``numerator``/``denominator``: "1 to 21
  items"; a bearing's ``stiffness``: "keys u, v, w, beta, gamma" (no twist, theta);
  ``fixed_start``: "each one of u, v, w, theta, beta, gamma".

Exact comparisons: every value is a bound typed from the table. CPU about 5 ms.
"""

from __future__ import annotations

from types import SimpleNamespace

import pydantic
import pytest

from flexshaft.design.envelope import Envelope, EnvelopePoint, check_envelope_temperatures, envelope_point
from flexshaft.design.fields import BearingDirection, Coefficients, DofName, ElementCount, Problems

ABSOLUTE_ZERO_C = -273.15


def _refused(**values) -> bool:
    try:
        EnvelopePoint(name="p", **values)
    except pydantic.ValidationError:
        return True
    return False


@pytest.mark.parametrize("key", ["ambient_temperature_c", "sky_temperature_c"])
def test_point_temperatures_are_above_absolute_zero_and_at_most_400_c(key):
    assert _refused(**{key: ABSOLUTE_ZERO_C})
    assert not _refused(**{key: -273.0})
    assert not _refused(**{key: 400.0})
    assert _refused(**{key: 400.01})


def test_the_whole_sun_and_no_sun_are_fractions():
    assert not _refused(solar_fraction=1.0) and not _refused(solar_fraction=0.0)
    assert _refused(solar_fraction=1.0001)


def test_a_load_scale_from_zero_to_one_hundred():
    assert EnvelopePoint(name="p", load_scale=0.0).load_scale == 0.0
    assert EnvelopePoint(name="p", load_scale=100.0).load_scale == 100.0
    assert _refused(load_scale=100.01) and _refused(load_scale=-1e-9)


def test_a_material_temperature_only_with_the_given_source():
    given = EnvelopePoint(name="p", material_temperature="given", material_temperature_c=50.0)
    assert given.material_temperature_c == 50.0
    for source in ("ambient", "shaft_air", "parked"):
        assert _refused(material_temperature=source, material_temperature_c=50.0)
    assert _refused(material_temperature="given")


def test_points_are_found_by_their_unique_name():
    envelope = Envelope(points=(EnvelopePoint(name="hot", ambient_temperature_c=45.0), EnvelopePoint(name="cold")))
    assert envelope.point("hot").ambient_temperature_c == 45.0
    with pytest.raises(KeyError):
        envelope.point("missing")
    with pytest.raises(pydantic.ValidationError):
        Envelope(points=(EnvelopePoint(name="a"), EnvelopePoint(name="a", load_scale=2.0)))


def test_a_design_without_an_envelope_finds_every_default_point():
    design = SimpleNamespace(envelope=None)
    cold = envelope_point(design, "cold_day")
    assert cold.ambient_temperature_c == -40.0 and cold.material_temperature == "ambient"
    assert envelope_point(design, "standard_day").ambient_temperature_c == 15.0
    assert envelope_point(design, "hot_soak_start").material_temperature == "parked"
    with pytest.raises(KeyError):
        envelope_point(design, "missing")


@pytest.mark.parametrize(("value", "inside"), [(-40.0, True), (80.0, True), (-40.01, False), (80.01, False)])
def test_a_table_is_a_closed_interval_of_temperatures(value, inside):
    """A table of rows -40 ... 80 °C; the point puts the shaft at the ambient ``value``."""
    table = SimpleNamespace(temperature_c=(-40.0, 20.0, 80.0))
    envelope = Envelope(points=(EnvelopePoint(name="p", ambient_temperature_c=value),))
    problems = Problems()
    check_envelope_temperatures(problems, envelope, 25.0, {"epoxy": table})
    assert (problems.items == []) is inside
    if not inside:
        assert problems.items[0][0] == ("envelope", "points", 0, "ambient_temperature_c")


def test_element_counts_from_one_and_laws_of_up_to_21_coefficients():
    count = pydantic.TypeAdapter(ElementCount)
    assert count.validate_python(1) == 1 and count.validate_python(2000) == 2000
    with pytest.raises(pydantic.ValidationError):
        count.validate_python(0)
    coefficients = pydantic.TypeAdapter(Coefficients)
    assert len(coefficients.validate_python((1.0,) * 21)) == 21
    with pytest.raises(pydantic.ValidationError):
        coefficients.validate_python((1.0,) * 22)


def test_a_bearing_holds_no_twist_and_an_end_may_fix_any_of_six_dofs():
    directions = pydantic.TypeAdapter(BearingDirection)
    for name in ("u", "v", "w", "beta", "gamma"):
        assert directions.validate_python(name) == name
    with pytest.raises(pydantic.ValidationError):
        directions.validate_python("theta")
    dofs = pydantic.TypeAdapter(DofName)
    for name in ("u", "v", "w", "theta", "beta", "gamma"):
        assert dofs.validate_python(name) == name

"""What :func:`flexshaft.thermal.envelope.point_conditions` reports at an envelope point, checked
against the documented rules (docs/thermal.md, "The operating envelope") and hand conversions.

References:

* Units: ``PointConditions.ambient_temperature`` is in kelvin and ``ambient_temperature_c`` in
  degrees Celsius (the terminal's envelope rows and results.json print the latter); °C = K - 273.15
  by definition of the Celsius scale. A point with ``ambient_temperature_c = -40`` and
  ``material_temperature = "ambient"`` therefore has 233.15 K and -40 °C for both.
* docs/thermal.md: "``point_conditions`` evaluates ... every lamina at T_m (table or law)". The
  order of ``[materials]`` is not part of that rule: a lamina listed after an isotropic metal is
  at T_m too. The tuned file's lamina table has a row at 80 °C (tuned.toml:
  G_LT = 22.313 MPa, loss_G_LT = 0.326194; "linear in T on the logarithm between rows", so at a
  row the row's value), which is the reference for a point given at 80 °C.
* docs/thermal.md / tuned.toml: tables "are never extrapolated"; a point whose known material
  temperature lies outside is refused, and the refusal names THAT point's index
  (``envelope.points[k]``), the path the user has to edit.
"""

from __future__ import annotations

import pytest

from flexshaft.design import DesignError, tuned_design, with_overrides
from flexshaft.design.envelope import EnvelopePoint
from flexshaft.design.io import design_from_dict
from flexshaft.thermal.envelope import point_conditions

# °C <-> K offsets and the table row values are exact decimal data; the only rounding is the
# K <-> °C round trip and the table's log-linear interpolation at a row (exp(log(x)) ~ 1e-16
# relative): 1e-9 is far above both and far below any unit slip (273.15) or row mix-up (>60 %).
TOL = 1e-9


def test_cold_day_ambient_is_reported_in_celsius():
    """-40 °C ambient: 233.15 K in kelvin, -40 °C in the Celsius property (hand conversion)."""
    point = EnvelopePoint(name="cold", ambient_temperature_c=-40.0, material_temperature="ambient")
    conditions = point_conditions(tuned_design(), point)
    assert conditions.ambient_temperature == pytest.approx(233.15, abs=TOL)
    assert conditions.ambient_temperature_c == pytest.approx(-40.0, abs=TOL)
    assert conditions.material_temperature_c == pytest.approx(-40.0, abs=TOL)


def test_a_lamina_listed_after_a_metal_is_at_the_point_temperature():
    """[materials] with the isotropic al6061_t6 first: the lamina is still taken at T_m = 80 °C,
    where the tuned table's row gives G_LT = 22.313 MPa and loss_G_LT = 0.326194."""
    data = tuned_design().model_dump()
    materials = data["materials"]
    data["materials"] = {"al6061_t6": materials.pop("al6061_t6"), **materials}
    design = design_from_dict(data, "<metal first>")
    names = list(design.materials)
    assert names.index("al6061_t6") < names.index("t700_adiprene")
    point = EnvelopePoint(name="warm", material_temperature="given", material_temperature_c=80.0)
    conditions = point_conditions(design, point)
    assert conditions.material_temperature == pytest.approx(80.0 + 273.15, abs=TOL)
    assert "t700_adiprene" in conditions.materials
    lamina = conditions.materials["t700_adiprene"]
    assert lamina.G_LT == pytest.approx(22.313e6, rel=TOL)
    assert lamina.loss_G_LT == pytest.approx(0.326194, rel=TOL)
    assert "al6061_t6" not in conditions.materials  # isotropic metals do not vary (docs/thermal.md)


@pytest.mark.parametrize("index", [1, 3])
def test_a_point_outside_the_table_is_refused_at_its_own_index(index):
    """A point at -70 °C ambient (10 K below the table's -60 °C) at envelope.points[index] is
    refused with that index in the path; points[0] (cold_day, -40 °C) is inside the table."""
    override = {
        f"envelope.points[{index}].material_temperature": "ambient",
        f"envelope.points[{index}].ambient_temperature_c": -70.0,
    }
    with pytest.raises(DesignError) as info:
        with_overrides(tuned_design(), override)
    text = str(info.value)
    assert f"envelope.points[{index}].ambient_temperature_c: puts the shaft at -70" in text
    assert "envelope.points[0]" not in text

"""An envelope point whose shaft sits at the point's own ambient must be checked against the
lamina's temperature table at THAT ambient, not the design's ``[thermal]`` one.

Reference: the point's definition (docs/thermal.md, design/envelope.py): with
``material_temperature = "ambient"`` the shaft's material temperature is the point's
``ambient_temperature_c`` (the design's only when the point omits it), and a lamina's table is
never extrapolated. The tuned design's lamina table spans -60 to 120 °C (tuned.toml) and its
``[thermal]`` ambient is 25.6 °C, inside it: a cold day at -70 °C puts the shaft 10 K below the
table and must be refused before any analysis; at -50 °C it is inside and accepted.
"""

from __future__ import annotations

import pytest

from flexshaft.design import DesignError, tuned_design, with_overrides


@pytest.mark.parametrize(("ambient", "refused"), [(-70.0, True), (-50.0, False)])
def test_a_cold_point_is_checked_at_its_own_ambient(ambient, refused):
    design = tuned_design()
    table = design.materials["t700_adiprene"].temperature_table
    assert (table.temperature_c[0], table.temperature_c[-1]) == (-60.0, 120.0)
    assert table.temperature_c[0] <= design.thermal.ambient_temperature_c <= table.temperature_c[-1]
    override = {
        "envelope.points[0].material_temperature": "ambient",
        "envelope.points[0].ambient_temperature_c": ambient,
    }
    if refused:
        with pytest.raises(DesignError, match=r"envelope\.points\[0\]\.ambient_temperature_c: puts the shaft at -70"):
            with_overrides(design, override)
    else:
        assert with_overrides(design, override).envelope.points[0].ambient_temperature_c == ambient

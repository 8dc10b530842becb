"""A lamina the matrix law takes out of the schema's bounds at an envelope point is refused naming
the point's material temperature in the unit the point gives it (°C).

Documented rule: docs/thermal.md, a lamina the law takes out of the schema's bounds at an envelope
point's material temperature is "refused with the fields that set them", and the law's refusal
gives "the temperature, each field with the value it would take and its bound" (the envelope
module's refusal text); docs/thermal.md's ``material_temperature_c`` is "the
material temperature with ``"given"`` [°C]". Reference, derived here: without a temperature table
the baseline lamina follows the ``[thermal]`` exponential law, whose loss factors reach the schema's
bound (< 1) by 150 °C (the test asserts the refusal), and the message must read
"at 150 °C" (150 + 273.15 = 423.15 K printed as "423.1 °C" would send the user 273 K away). This is
a user-facing message, so the check is on its text.
"""

from __future__ import annotations

import pytest

from flexshaft.design import baseline_design, with_overrides
from flexshaft.design.envelope import EnvelopePoint
from flexshaft.thermal.envelope import point_conditions


def test_a_law_refusal_names_the_points_temperature_in_celsius():
    design = with_overrides(baseline_design(), {"materials.t700_adiprene.temperature_table": None})
    point = EnvelopePoint(name="hot_test", material_temperature="given", material_temperature_c=150.0)
    with pytest.raises(ValueError) as info:
        point_conditions(design, point)
    message = str(info.value)
    assert "'hot_test'" in message and "'t700_adiprene'" in message
    assert "at 150 °C" in message
    assert "423.1 °C" not in message

"""The compare report shows every compared length in millimetres, as the report's module and the
README's ``flexshaft compare`` section promise (SI converted to rpm, mm, °C, degrees, %).

References (derived, by hand): mm = m · 1e3, shown to 3 significant digits (the report's length
format). The first test takes hand-chosen values; the second the embedded comparison's own metrics
in metres (the spin-up peak orbit and the static deflection the verdict checks), converted here.
"""

from __future__ import annotations

import math

from flexshaft.report.compare import format_metric


def test_a_length_in_metres_is_shown_in_millimetres():
    """0.25 mm spin-up orbit (2.5e-4 m) and 12.3 mm static deflection (0.0123 m), by m · 1e3."""
    assert format_metric("spinup_peak", "m", 2.5e-4) == "0.25 mm"
    assert format_metric("static_deflection", "m", 0.0123) == "12.3 mm"
    assert format_metric("spinup_peak", "m", 2.5e-4, lower_bound=True) == "> 0.25 mm"


def test_embedded_comparison_lengths_read_back_as_millimetres(embedded_comparison):
    """Each metre-valued metric of the embedded comparison (both designs) is printed as "<x> mm"
    with x = value · 1e3 to the 3 significant digits shown: |x − 1e3·value| ≤ 0.5 units of the third
    digit (rel 5e-3, the rounding of the displayed number, nothing tighter is printed)."""
    lengths = [m for m in embedded_comparison.metrics() if m.unit == "m"]
    assert {m.key for m in lengths} >= {"spinup_peak", "static_deflection"}
    checked = 0
    for m in lengths:
        for value in m.values:
            if value is None or not math.isfinite(value) or value == 0.0:
                continue
            text = format_metric(m.key, m.unit, value)
            assert text.endswith(" mm"), (m.key, text)
            shown = float(text.removesuffix(" mm"))
            assert math.isclose(shown, value * 1e3, rel_tol=5e-3), (m.key, value, text)
            checked += 1
    assert checked >= 2

"""Fractions in percent and margins with their sign, as the verdict tables display them.

References:

* percent: 1 % = 0.01 (ISO 80000-1:2009, the percent sign as the number 0.01), so a fraction
  f displays as 100 f %; a separation of 0.25 is 25.0 %, of 0.032 is 3.2 %. A difference of
  two fractions is a margin in percentage points, 100 Δf pts.
* API contract (docstring of :func:`flexshaft.units.format_quantity`; no docs page states it):
  "a value (or a signed margin)": a margin carries its sign, '+' when positive, so a table cell
  of a margin never reads like a value; a value carries none. The display units are the ones
  that docstring lists (speeds in rpm = 60 Ω/(2π), lengths in mm, forces in N, angles in
  degrees, gains in dB, ratios plain).

Exact strings: every number here is exactly representable to the printed digits after one
multiplication (100 × 0.25, 60/(2π) × 2π·80 = 4800 to far below the 0.5 rpm rounding), so the
formatted text is the same on any machine.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.units import format_quantity


def test_fraction_value_is_percent():
    """0.25 → 25.0 % and 0.032 → 3.2 % (100 f %); a margin of 0.05 → +5.0 pts."""
    assert format_quantity("fraction", 0.25) == "25.0 %"
    assert format_quantity("fraction", 0.032) == "3.2 %"
    assert format_quantity("fraction", 0.05, margin=True) == "+5.0 pts"


@pytest.mark.parametrize(
    ("kind", "margin", "text"),
    [
        ("speed", 2.0 * math.pi * 80.0, "+4800 rpm"),  # 80 rev/s = 4800 rev/min
        ("length", 2.5e-3, "+2.5 mm"),
        ("force", 125.0, "+125 N"),
        ("angle", math.pi / 4.0, "+45°"),
        ("decibel", 6.0, "+6 dB"),
        ("ratio", 0.75, "+0.75"),
    ],
)
def test_positive_margin_carries_its_plus_sign_and_a_value_none(kind, margin, text):
    """A positive margin shows '+', the same number as a value shows no sign."""
    assert format_quantity(kind, margin, margin=True) == text
    assert format_quantity(kind, margin) == text[1:]

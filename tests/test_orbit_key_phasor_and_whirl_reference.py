"""What an orbit panel (plot/response.py, ``orbit_figure``) marks on a hand-built orbit.

References, derived here:

* v = a cos φ, w = b sin φ is the complex pair (v, w) = (a, −i b), since Re(−i b e^{iφ}) =
  b sin φ. With w horizontal and v vertical (API contract: the docstring of ``orbit_figure``,
  "Lateral w is horizontal, vertical v up"), the key phasor
  φ = 0 is the point (w, v) = (0, a): the dot sits there, on the ellipse, for any a ≠ b.
* The whirl runs the way φ grows: the tangent (dw/dφ, dv/dφ) = (b cos φ, −a sin φ). The
  arrow from the point at φ_j to the one at φ_{j+1} must point along it (positive dot
  product); for a, b > 0 it starts at the top moving to +w, clockwise in this view, which is
  forward whirl of a shaft spinning about +x looking aft (API contract: the same docstring;
  independently, docs/model.md writes the orbit r = v + i w and the imbalance load turns +v
  toward +w, so forward whirl is clockwise with w to the right and v up).
* The share of the gap an orbit uses is its major semi-axis over the radial clearance, a
  length ratio that does not depend on the unit the panel draws in: a circular orbit of
  radius 20 μm in a 0.25 mm gap uses 100 · 0.020 / 0.25 = 8 %.

Agg, no file; CPU milliseconds.
"""

from __future__ import annotations

import re

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from flexshaft.plot.response import orbit_figure  # noqa: E402


def _panel(fig):
    return fig.axes[0]


def test_key_phasor_dot_sits_on_the_top_of_the_orbit():
    """v = 0.3 mm cos φ, w = 0.1 mm sin φ: the φ = 0 dot at (w, v) = (0, 0.3) mm.

    The dot's coordinates are 0.3e-3 m · 1000 (a product of exact-ish floats and one cos/sin
    of 0): 1e-12 mm absorbs their round-off, far below the 0.2 mm a swapped dot would move.
    """
    a, b = 0.3e-3, 0.1e-3
    fig = orbit_figure({"P": (a, -1j * b)})
    dots = [ln for ln in _panel(fig).get_lines() if ln.get_marker() == "o"]
    assert len(dots) == 1
    np.testing.assert_allclose(dots[0].get_xdata(), [0.0], atol=1e-12)
    np.testing.assert_allclose(dots[0].get_ydata(), [0.3], atol=1e-12)


def test_whirl_arrow_points_the_way_phi_grows():
    """The arrow (tail → head) has a positive component along the tangent (b cos φ, −a sin φ)
    at its tail, and heads to +w when started in the upper-right quadrant (clockwise).

    The sign test needs no tolerance: the step between two of the 121 ellipse points is
    ~2π/120 of the orbit size, many orders above round-off.
    """
    a, b = 0.3e-3, 0.1e-3
    fig = orbit_figure({"P": (a, -1j * b)})
    arrows = [t for t in _panel(fig).texts if getattr(t, "arrow_patch", None) is not None]
    assert len(arrows) == 1
    head = np.array(arrows[0].xy, dtype=float)
    tail = np.array(arrows[0].xyann, dtype=float)
    a_mm, b_mm = a * 1e3, b * 1e3
    # the tail's phase from its position on v = a cos φ, w = b sin φ
    phi = np.arctan2(tail[0] / b_mm, tail[1] / a_mm)
    tangent = np.array([b_mm * np.cos(phi), -a_mm * np.sin(phi)])
    assert float(np.dot(head - tail, tangent)) > 0.0
    assert tail[0] > 0.0 and tail[1] > 0.0  # upper right: φ in (0, π/2)
    assert head[0] > tail[0]  # clockwise from the top: towards +w


def test_gap_share_does_not_depend_on_the_drawing_unit():
    """A 20 μm circular orbit (drawn in μm) in a 0.25 mm gap: the note says 8 % of the gap.

    The note writes 3 significant digits; 8 is exact, so equality of the parsed number to
    8 within 0.5 % (the last written digit) is the test; the unit slip would write 8000.
    """
    r = 20e-6
    fig = orbit_figure({"P": (r, -1j * r)}, gaps=0.25e-3)
    notes = [t.get_text() for t in _panel(fig).texts if "% of gap" in t.get_text()]
    assert len(notes) == 1
    assert "μm" in notes[0]  # the panel draws in micrometres: the case the share must survive
    share = float(re.search(r"([0-9.eE+-]+) % of gap", notes[0]).group(1))
    assert abs(share - 100 * 0.020 / 0.25) <= 0.005 * 8.0

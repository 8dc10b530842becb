"""The circle geometry behind the loops' dip search (:mod:`flexshaft.analyses.loop_dips`),
each piece against a closed form.

References, derived here:

* **Angle about a centre.** ``_turn(c, a, b)`` is the counter-clockwise angle from ``a − c`` to
  ``b − c`` in [0, 2π): about 0, from 1 to −i is 3π/2 and from 1 to i is π/2 (a full turn is
  2π, not π).
* **Möbius map through three points.** A Möbius map f(x) = (p x + q)/(r x + s) is fixed by three
  points (the invariance of the cross-ratio under Möbius maps; f is built directly from p, q,
  r, s, not from a cross-ratio): the map through f at x = 0.1, 0.4, 0.9 must give f itself at
  any fourth x, to round-off.
* **A lightly damped mode's circle** (``dip_crossovers``' docstring): L = A + B/(1 − i(x_r − x)/ζ) with
  x = ln ω. With y = (x − x_r)/ζ, 1/(1 + iy) = (1 − iy)/(1 + y²): a circle of centre 1/2 and
  radius 1/2, Im = −y/(1 + y²), lowest (−1/2) at y = 1. For real B > 0 the circle's lowest point
  is A + B/2 − iB/2, reached at x = x_r + ζ, radius B/2.
* **A dip above the peak.** L = c + (b/2)(1 + iu)/(1 − iu), u = (ω_r² − ω²)/(2ζω_rω) (a
  resonance H = 2iζω_rω/(ω_r² − ω² + 2iζω_rω) = 1/(1 − iu) on the circle of centre 1/2 and
  radius 1/2, its point at angle 2 atan u about the centre), with c = −1.5 + 0.499i,
  |b| = 2r = 1 and arg b = arg(−1 − c) = −44.94°: at u = 0 (ω = ω_r) L is the circle's point
  nearest −1, the sensitivity peak. Im L = c_i + r sin θ < 0 for sin θ < −0.998, θ = arg b +
  2 atan u: u between tan((−π − asin(−0.998) − arg b)/2) = −0.4524 and tan((asin(−0.998) −
  arg b)/2) = −0.3782, ω = −ζω_r u + √((ζω_r u)² + ω_r²), i.e. 0.378 to 0.452 ζω_r *above* the
  peak, both crossings at Re L ≈ −1.5 (negative: phase crossovers). On a grid of step 0.1 ζω_r
  with points at 0.36 and 0.46 ζω_r past ω_r, every grid point has Im L > 0: the dip hides in
  that one interval, four intervals above the first grid point past the peak, within 3 half widths of it (the peak's
  |S| halves its square 20° of circle away, about 0.17 ζω_r). The search must hold that
  interval and, run on L, return the two crossings.
* **Which arc may dip.** On the circle of centre −0.5 + 0.4i and radius 0.5 (it dips 0.1 below
  the real axis, crossing it at Re L = −0.8 and −0.2), the points at −50° and −130° (Im L =
  +0.017) bound two arcs: the lower one, through the lowest point (−90°), crosses the axis
  twice; the upper one (through +90°) never does. ``may_dip(la, lb, third)`` tests the arc *without*
  the third point: True with the third on the upper arc, False with it on the lower one.

Tolerances: exact geometry evaluated in double precision with O(1) numbers, so 1e-12; the
dip's crossings are bracketed to 1e-8 ω and refined by the Illinois method: 1e-8 relative.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses import loop_dips


def test_turn_is_counter_clockwise_over_a_full_circle():
    assert loop_dips._turn(0j, 1 + 0j, -1j) == pytest.approx(1.5 * np.pi, abs=1e-12)
    assert loop_dips._turn(0j, 1 + 0j, 1j) == pytest.approx(0.5 * np.pi, abs=1e-12)
    assert loop_dips._turn(2 + 1j, 3 + 1j, 2 + 0j) == pytest.approx(1.5 * np.pi, abs=1e-12)


def test_mobius_through_three_points_is_the_map():
    p, q, r, s = 1.3 - 0.2j, 0.4 + 0.7j, 0.5 + 1.1j, -0.9 + 0.3j

    def f(x):
        return (p * x + q) / (r * x + s)

    points = [(x, f(x)) for x in (0.1, 0.4, 0.9)]
    for x in (0.0, 0.25, 0.6, 1.7):
        assert abs(loop_dips._mobius(points, x) - f(x)) < 1e-12


def test_predicted_extreme_of_a_mode_circle():
    A, B, x_r, zeta = -0.8 + 0.3j, 0.6, np.log(300.0), 0.02

    def L(x):
        return A + B / (1.0 - 1j * (x_r - x) / zeta)

    points = [(x, L(x)) for x in (x_r - 0.03, x_r + 0.005, x_r + 0.06)]
    x, extreme, radius = loop_dips._predicted_extreme(points, 1.0)
    assert x == pytest.approx(x_r + zeta, abs=1e-12)
    assert abs(extreme - (A + B / 2 - 0.5j * B)) < 1e-12
    assert radius == pytest.approx(B / 2, rel=1e-12)


def test_may_dip_reads_the_arc_without_the_third_point():
    centre, radius = -0.5 + 0.4j, 0.5

    def at(deg):
        return centre + radius * np.exp(1j * np.radians(deg))

    la, lb = at(-50.0), at(-130.0)
    assert la.imag > 0 and lb.imag > 0
    assert loop_dips.may_dip(la, lb, at(90.0))
    assert loop_dips.may_dip(lb, la, at(60.0))
    assert not loop_dips.may_dip(la, lb, at(-95.0))


def test_a_dip_above_the_peak_is_searched_and_found():
    zeta, wr = 1e-3, 2 * np.pi * 100.0
    c, r = -1.5 + 0.499j, 0.5
    b = 2 * r * np.exp(1j * np.angle(-1 - c))

    def loop(w):
        u = (wr * wr - w * w) / (2 * zeta * wr * w)
        return c + (b / 2) * (1 + 1j * u) / (1 - 1j * u)

    w = wr + zeta * wr * (0.1 * np.arange(-30, 31) + 0.06)
    L = loop(w)
    assert np.all(L.imag > 0)
    edge = np.arcsin(-c.imag / r)
    u = np.tan((np.array([-np.pi - edge, edge]) - np.angle(b)) / 2)
    crossings = -zeta * wr * u + np.sqrt((zeta * wr * u) ** 2 + wr * wr)
    assert (crossings - wr) / (zeta * wr) == pytest.approx([0.4525, 0.3783], abs=1e-4)
    (task,) = loop_dips.dip_searches(w, L, np.array([wr]), np.array([loop(wr)]))
    assert w[task.lo] < crossings.min() and crossings.max() < w[task.hi]
    steps = task.start()
    value = next(steps)
    try:
        while True:
            value = steps.send(complex(loop(value)))
    except StopIteration as done:
        found = sorted(point[0] for point in done.value)
    assert found == pytest.approx(sorted(crossings), rel=1e-8)

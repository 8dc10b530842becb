r"""A resonance circle that only just dips across the real axis between two grid points
(``hidden_crossovers`` of flexshaft.analyses.loop_margins, ``may_dip`` and ``dip_crossovers`` of
flexshaft.analyses.loop_dips, and the margins made of them), against the crossings of the circle solved by hand.

The loop, built by formula: L(ω) = a + iε + b H(ω), H = 2iζω_rω/(ω_r² − ω² + 2iζω_rω) a
resonance of ζ = 1e-3 at ω_r = 2π·100 rad/s. With u = (ω_r² − ω²)/(2ζω_rω), H = i/(u + i)
= q(1 + iu), q = 1/(1 + u²): H runs over the circle of diameter [0, 1] exactly, so L over the
circle of centre c = a + iε + b/2 and radius |b|/2, and

    Im L = ε + q(b_i + b_r u),   Re L = a + q(b_r − b_i u).

Im L = 0 where ε(1 + u²) + b_i + b_r u = 0, i.e. ε u² + b_r u + (ε + b_i) = 0; ω from u is the
positive root of ω² + 2ζω_r u ω − ω_r² = 0, ω = −ζω_r u + √((ζω_r u)² + ω_r²). The point of the
circle nearest −1 is p = c + r(−1 − c)/|−1 − c| (|S|max = 1/(|−1 − c| − r)); its u is
Im H/Re H there, H = (p − a − iε)/b.

With a = −0.3, b = −0.3 − 0.4i, ε = 0.448: c = −0.45 + 0.248i, r = 0.25, the circle reaches
0.002 (0.8 % of r) below the axis: 0.448u² − 0.3u + 0.048 = 0, u = (0.3 ± √0.003984)/0.896 =
0.40527, 0.26438, Re L = −0.41844, −0.48156 (both phase crossovers), the upper gain margin
20 log₁₀(1/0.48156) = 6.347 dB. Both lie 1.4e-4 apart in ω inside one interval of a 200-point
logarithmic grid (4.7 % steps) and Im p = +0.145: neither the grid nor L at the refined peak
lies across the axis (what hidden_crossovers needed alone). With ε = 0.46 the circle stops
0.01 above the axis (the discriminant 0.09 − 4·0.46·0.06 < 0: no crossing); mirrored,
a = +0.3, b = +0.3 + 0.4i, ε = 0.048, c = 0.45 + 0.248i, it dips across at Re L > 0
(0.048u² + 0.3u + 0.448 = 0): no phase crossover.

Tolerances: the crossings are refined by regula falsi to a bracket of 1e-8 ω (the point
returned lies in it), so the frequencies to 1e-8 relative (2e-8 with the conversions). The gain
margin is |L| there: |dL/d ln ω| = |b| |dH/du| |du/d ln ω| ≤ 0.5 · 1 · (ω_r² + ω²)/(2ζω_rω)
≈ 500 near ω_r, so |L| to 5e-6 and the margin to 20/ln 10 · 5e-6/0.48 ≈ 1e-4 dB.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from flexshaft.analyses.local_projection import lockstep
from flexshaft.analyses.loop_dips import dip_crossovers, may_dip
from flexshaft.analyses.loop_margins import hidden_crossovers, loop_margins

ZETA, WR = 1e-3, 2 * np.pi * 100.0
GRID = np.geomspace(2 * np.pi * 1.0, 2 * np.pi * 1e4, 200)


def _loop(a, eps, b):
    def loop(w):
        h = 2j * ZETA * WR * w / (WR * WR - w * w + 2j * ZETA * WR * w)
        return a + 1j * eps + b * h

    return loop


def _omega(u):
    u = np.asarray(u, dtype=float)
    return -ZETA * WR * u + np.sqrt((ZETA * WR * u) ** 2 + WR * WR)


def _crossings(a, eps, b):
    """u, ω and L at the circle's crossings of the real axis (closed form, module docstring)."""
    u = np.roots([eps, b.real, eps + b.imag])
    u = np.sort(u[np.isreal(u)].real)
    q = 1 / (1 + u * u)
    return u, _omega(u), a + q * (b.real - b.imag * u)


def _nearest(a, eps, b):
    """ω and |S| of the circle's point nearest −1 (the sensitivity peak)."""
    c, r = a + 1j * eps + b / 2, abs(b) / 2
    p = c + r * (-1 - c) / abs(-1 - c)
    h = (p - a - 1j * eps) / b
    return float(_omega(h.imag / h.real)), 1 / (abs(-1 - c) - r), p


@pytest.mark.parametrize("mirrored", [False, True], ids=["above", "below"])
def test_a_shallow_dip_between_two_grid_points_sets_the_upper_gain_margin(mirrored):
    """Mirrored: conj L, the same circle reflected in the real axis (Im L < 0 at the grid,
    the same crossings and margins)."""
    a, eps, b = -0.3, 0.448, -0.3 - 0.4j
    loop = _loop(a, eps, b)
    if mirrored:
        loop = (lambda f: lambda w: np.conj(f(w)))(loop)
    u, w, real = _crossings(a, eps, b)
    assert u == pytest.approx([0.26437619, 0.40526667], abs=1e-8)
    assert real == pytest.approx([-0.48155947, -0.41844053], abs=1e-8)
    gm = 20 * np.log10(1 / abs(real).max())
    assert gm == pytest.approx(6.3470, abs=1e-4)
    k = np.searchsorted(GRID, w[0])
    assert GRID[k - 1] < w.min() and w.max() < GRID[k]  # one grid interval holds both
    assert np.all((-1) ** mirrored * loop(GRID).imag > 0)
    w_peak, peak, p = _nearest(a, eps, b)
    assert p.imag > 0.1  # the peak's L lies on the grid's side of the axis
    # the coarse grid, and one with points at the peak's top and half width (loop_grid's)
    for grid in (GRID, np.sort(np.append(GRID, w_peak * np.array([1 - ZETA / 2, 1, 1 + ZETA / 2])))):
        m = loop_margins(loop, grid)
        assert m.phase_crossovers == pytest.approx(w[::-1] / (2 * np.pi), rel=2e-8)
        assert abs(m.gain_margin_upper_db - gm) < 1e-4
        assert m.gain_margin_frequency == pytest.approx(w[0] / (2 * np.pi), rel=2e-8)
        assert m.gain_margin_lower_db == -np.inf and m.phase_margin_deg == np.inf  # |L| <= 0.75
        assert m.peak_sensitivity == pytest.approx(peak, rel=1e-6)


def test_a_circle_that_stops_short_of_the_axis_has_no_crossover():
    a, eps, b = -0.3, 0.46, -0.3 - 0.4j
    loop = _loop(a, eps, b)
    assert _crossings(a, eps, b)[0].size == 0
    w_peak, peak, _ = _nearest(a, eps, b)
    # the circle through three grid values cannot exclude a dip 4 % of r away (DIP_SLACK),
    # but the Möbius map through them, exact here up to the cube of ln(ω/ω_r), checked at a
    # fourth grid point does: no search
    k = np.searchsorted(GRID, w_peak)
    part = GRID[k - 1], GRID[k], complex(loop(GRID[k - 1])), complex(loop(GRID[k]))
    assert may_dip(part[2], part[3], complex(loop(GRID[k + 1])))
    tasks = hidden_crossovers(GRID, loop(GRID), np.array([w_peak]), loop(np.array([w_peak])))
    assert [t for t in tasks if t.kind == "dip"] == []
    # the search itself, asked, stops on the refitted extreme after one evaluation
    calls = []
    search = dip_crossovers(*part, GRID[k + 1], complex(loop(GRID[k + 1])))
    assert lockstep([search], lambda x, _: calls.append(x) or loop(x)) == [[]]
    assert len(calls) == 1
    m = loop_margins(loop, GRID)
    assert m.phase_crossovers == () and m.gain_margin_upper_db == np.inf
    assert m.peak_sensitivity == pytest.approx(peak, rel=1e-6)


def test_a_dip_across_the_positive_real_axis_is_no_phase_crossover():
    a, eps, b = 0.3, 0.048, 0.3 + 0.4j
    loop = _loop(a, eps, b)
    u, w, real = _crossings(a, eps, b)
    assert u.size == 2 and np.all(real > 0)
    k = np.searchsorted(GRID, w[0])
    assert GRID[k - 1] < w.min() and w.max() < GRID[k]
    # the search itself finds the two crossings (closed form) ...
    part = GRID[k - 1], GRID[k], complex(loop(GRID[k - 1])), complex(loop(GRID[k]))
    found = lockstep([dip_crossovers(*part, GRID[k + 1], complex(loop(GRID[k + 1])))], lambda x, _: loop(x))[0]
    assert [x for x, _ in found] == pytest.approx(sorted(w), rel=2e-8)
    assert [v.real for _, v in found] == pytest.approx(list(real[np.argsort(w)]), abs=1e-5)
    # ... but the circle test spends none on them (its crossings lie at Re L > 0)
    assert not may_dip(part[2], part[3], complex(loop(GRID[k + 1])))
    w_peak, _, _ = _nearest(a, eps, b)
    tasks = hidden_crossovers(GRID, loop(GRID), np.array([w_peak]), loop(np.array([w_peak])))
    assert [t for t in tasks if t.kind == "dip"] == []
    m = loop_margins(loop, GRID)
    assert m.phase_crossovers == () and m.gain_margin_upper_db == np.inf


def test_a_loop_constant_between_grid_points_has_no_circle_and_no_crossover():
    """L ≡ −0.5 + 0.1i: every grid point is a flat maximum of |S| = 1/|0.5 + 0.1i|, refined,
    and no three values of L make a circle; Im L > 0 everywhere, so no phase crossover."""
    m = loop_margins(lambda w: np.full(np.shape(w), -0.5 + 0.1j), np.geomspace(1.0, 1e3, 40))
    assert m.phase_crossovers == () and m.gain_margin_upper_db == np.inf
    assert m.peak_sensitivity == pytest.approx(1 / abs(0.5 + 0.1j), rel=1e-15)


def test_a_part_whose_arc_holds_both_extreme_points_is_searched_to_its_dip():
    """Im L = ε + q(b_i + b_r u) is extreme where b_r u² + 2b_i u − b_r = 0: with b = −0.3 − 0.4i,
    0.3u² + 0.8u − 0.3 = 0, u = 1/3 (the dip, between the crossings at u = 0.264 and 0.405)
    and u = −3 (the top). A part from u = 1 to u = −10 (ω rising, ln ω nearly linear in u)
    holds both, its arc more than half the circle, the dip in its first 6 % (a search for one
    extremum of Im L, whose first two points at 38 % and 62 % lie beyond the top, goes the
    wrong way); the search finds the two crossings of the closed form."""
    a, eps, b = -0.3, 0.448, -0.3 - 0.4j
    loop = _loop(a, eps, b)
    assert np.roots([0.3, 0.8, -0.3]) == pytest.approx([-3.0, 1 / 3])
    _, w, real = _crossings(a, eps, b)
    lo, hi, beside = _omega([1.0, -10.0, 3.0])
    ends = loop(np.array([lo, hi]))
    assert ends.imag.min() > 0 and lo < w.min() and w.max() < hi
    search = dip_crossovers(lo, hi, ends[0], ends[1], beside, complex(loop(beside)))
    found = lockstep([search], lambda x, _: loop(x))[0]
    assert [x for x, _ in found] == pytest.approx(sorted(w), rel=2e-8)
    assert [v.real for _, v in found] == pytest.approx(list(real[np.argsort(w)]), abs=1e-5)


def test_a_dip_several_grid_intervals_from_the_refined_peak_is_searched():
    """The peak lies at ω/ω_r − 1 = +0.257ζ, the dip at −0.264ζ…−0.405ζ (closed forms above);
    a grid with the peak and three points each side between it and the dip (as a loop grid's
    samples about a pole) puts the dip four intervals below the peak: beyond a reach counted
    in grid intervals, within one of three half widths of the peak (about ζω_r each)."""
    a, eps, b = -0.3, 0.448, -0.3 - 0.4j
    loop = _loop(a, eps, b)
    _, w, real = _crossings(a, eps, b)
    w_peak, peak, _ = _nearest(a, eps, b)
    assert (w_peak / WR - 1) / ZETA == pytest.approx(0.2573, abs=1e-4) and w_peak > w.max()
    steps = np.array([-0.75, -0.5, -0.25, 0.0, 0.25, 0.5, 0.75])
    grid = np.sort(np.append(GRID, w_peak + (w.max() - w_peak) * steps))
    k = np.searchsorted(grid, w_peak)
    assert grid[k - 4] < w.min() and w.max() < grid[k - 3]  # four intervals below the peak's point
    m = loop_margins(loop, grid)
    assert m.phase_crossovers == pytest.approx(w[::-1] / (2 * np.pi), rel=2e-8)
    assert abs(m.gain_margin_upper_db - 20 * np.log10(1 / abs(real).max())) < 1e-4


def _dense_upper_margin(loop, centre):
    """The smallest upper gain margin by an independent route: Im L sampled on 200001 points
    over the grid's range and 200001 within ±2 % of ``centre``, each change of sign solved by
    scipy's brentq to 1e-13 rad/s."""
    ws = np.unique(np.concatenate([np.geomspace(GRID[0], GRID[-1], 200001), np.geomspace(0.98, 1.02, 200001) * centre]))
    im = loop(ws).imag
    changes = np.flatnonzero(im[:-1] * im[1:] < 0)
    roots = [brentq(lambda x: loop(np.array([x]))[0].imag, ws[k], ws[k + 1], xtol=1e-13) for k in changes]
    values = loop(np.array(roots))
    margins = 20 * np.log10(1 / np.abs(values[(values.real < 0) & (np.abs(values) < 1)]))
    return margins.min()


@pytest.mark.parametrize(
    "eps, slope, second, sep, samples",
    [
        (0.44451486, -0.04744716, -0.06396522 + 0.01817943j, 0.02397604, 0),
        (0.44614186, 0.27027822, 0.01367210 - 0.00457096j, 0.00928426, 2),
    ],
    ids=["second-mode", "slope-and-samples"],
)
def test_a_shallow_dip_on_a_background_the_circle_does_not_fit(eps, slope, second, sep, samples):
    """The shallow dip with a background: i·slope·ln(ω/ω_r) and a second mode of ζ = 1e-3 at
    ω_r(1 + sep), so that three grid values fix no exact circle (the search takes more than
    one point; the check at a fourth grid point sees the map's error); with, in the second
    case, points at the peak and ±ζ of it (a loop grid's samples). The margin against a dense
    sampling solved by brentq (:func:`_dense_upper_margin`); 1e-4 dB as above."""
    base = _loop(-0.3, eps, -0.3 - 0.4j)

    def loop(w):
        h2 = 2j * ZETA * WR * (1 + sep) * w / ((WR * (1 + sep)) ** 2 - w * w + 2j * ZETA * WR * (1 + sep) * w)
        return base(w) + 1j * slope * np.log(w / WR) + second * h2

    grid = GRID
    if samples:
        fine = np.geomspace(0.99 * WR, 1.01 * WR, 200001)
        top = fine[np.argmax(1 / np.abs(1 + loop(fine)))]
        grid = np.sort(np.append(GRID, top * (1 + ZETA * np.array([-1.0, 0.0, 1.0]))))
    true = _dense_upper_margin(loop, WR)
    assert 5.5 < true < 6.5  # a dip, with Re L < 0, below 6.5 dB
    assert abs(loop_margins(loop, grid).gain_margin_upper_db - true) < 1e-4


def test_a_clean_circle_whose_dip_lies_beyond_the_peaks_band_is_found():
    """A single mode's clean circle (ζ = 0.02, no background) of radius r = 0.3 and centre
    c = −0.85 + 0.294i, entered at θ = 2.793 (b = 2r e^{iθ}, a + iε = c − b/2): it dips 0.006
    (2 % of r) across the axis at u = 1.1604 and 1.7838 (the closed form of the module
    docstring with this ζ), Re L = −0.90970 and −0.79030: an upper gain margin of
    20 log₁₀(1/0.90970) = 0.8220 dB, at 97.706 and 96.496 Hz. The grid is the coarse one plus
    the three samples loop_grid places at a closed-loop pole (its frequency and ± half its decay
    rate; the pole from (1 + a + iε)(s² + 2ζω_r s + ω_r²) + 2bζω_r s = 0), at 98.17-98.34 Hz:
    the sensitivity peak (|S| = 33.3 at 98.25 Hz) lies more than three of its half widths
    above the dip, whose grid interval (93.29-97.71 Hz) only the extra interval beyond that band
    reaches. (An independent review found it read as no crossover when the band stopped at the
    intervals touching it.) Tolerance: |dL/d ln ω| ≤ |b|/(2ζ) = 15 here, so the refined
    crossings' 1e-8 brackets put |L| within 1.5e-7 and the margin within 2e-6 dB; 1e-4 dB
    asserted, the frequencies to 2e-8 relative."""
    zeta, r, theta, c = 0.02, 0.3, 2.793, -0.85 + 0.294j
    b = 2 * r * np.exp(1j * theta)
    a_eps = c - b / 2

    def loop(w):
        return a_eps + b * 2j * zeta * WR * w / (WR * WR - w * w + 2j * zeta * WR * w)

    u = np.roots([a_eps.imag, b.real, a_eps.imag + b.imag])
    u = np.sort(u[np.isreal(u)].real)
    real = a_eps.real + (b.real - b.imag * u) / (1 + u * u)
    w = -zeta * WR * u + np.sqrt((zeta * WR * u) ** 2 + WR * WR)
    assert u == pytest.approx([1.16044545, 1.78384719], abs=1e-7)
    assert real == pytest.approx([-0.90969925, -0.79030075], abs=1e-7)
    gm = 20 * np.log10(1 / abs(real[0]))
    s = np.roots([1, 2 * zeta * WR * (1 + b / (1 + a_eps)), WR * WR])
    s = s[np.argmax(s.imag)]
    grid = np.unique(np.append(GRID, s.imag - s.real * np.array([-0.5, 0.0, 0.5])))
    k = np.searchsorted(grid, w[0])
    assert grid[k - 1] < w.min() and w.max() < grid[k]  # one grid interval holds both crossings
    m = loop_margins(loop, grid)
    assert m.peak_sensitivity > 30 and m.peak_frequency > 98.2  # the peak, far above the dip
    assert abs(m.gain_margin_upper_db - gm) < 1e-4
    assert m.phase_crossovers == pytest.approx(np.sort(w) / (2 * np.pi), rel=2e-8)

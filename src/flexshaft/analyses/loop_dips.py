r"""Pairs of phase or gain crossovers a loop's grid hides near a lightly damped peak: a dip of
Im L across the negative real axis between two grid points whose Im L agree in sign, or a bump
of |L| across 1 between two whose ln|L| do, found without evaluating the loop where it cannot
be (:func:`dip_searches`, used by :func:`flexshaft.analyses.loop_margins.hidden_crossovers`).

Gain crossovers are searched as dips too, of u = i(S − 1/2) = i(1/(1 + L) − 1/2)
(:func:`gain_image`): |L| = 1 is |1 − S| = |S|, Re S = 1/2, so Im u changes sign exactly where
|L| crosses 1 (Im u > 0 where |L| < 1); u is a Möbius map of L, so a lightly damped mode's u
traces a circle, the image of ln ω under a Möbius map, as its L does, and the same tests and
search apply (without the test of Re L, which only phase crossovers need). It finds the pair of
tests/test_loop_hidden_gain_pair_reference.py: a delayed integrator and a mode whose |L| exceeds
1 only over 99.92-100.08 Hz, one grid interval, while the |S| peak lies at 100.155 Hz where
|L| = 0.958 (so the split at the peak shows no change of sign): the grid read a phase margin of
27.8° at 78 Hz, the search finds the pair's 6.0° at 100.08 Hz.

A resonance circle whose centre lies above the negative real axis and whose radius only just
reaches below it has its point nearest −1 above the axis, and its dip below the axis may be
narrower than the grid around the peak (a test loop of a 6.35 dB upper margin, its Im L below
zero over a fraction of the peak's half width, read no crossover even with the pole samples of
:mod:`flexshaft.analyses.loop_grid`): its upper gain margin was missed, read as no crossover
(optimistic).

In the grid intervals within :data:`DIP_WIDTHS` half widths of each refined peak (from |S| at
the peak and beside it) and one interval more each side, split at the peaks, every part whose
ends agree in the sign of Im L is tested (:func:`may_dip`) on the circle through L at its ends
and at its neighbour toward the peak (a single lightly damped mode's L traces a circle: three
points fix it): its arc between the ends must hold the circle's extreme point toward the other
sign, within :data:`DIP_SLACK` of its radius of the axis, and cross (or near) the axis at Re L <
0. The same three points fix the Möbius map ln ω ↦ L of such a mode; checked at the grid point
on the part's other side, the part is dropped when the extreme stays on its side by more than
:data:`DIP_FOURTH_SAFETY` times that map's error there (no evaluation). A part left is searched
(:func:`dip_crossovers`): L is evaluated where the map predicts the extreme, the map refitted,
and the search stops once the refitted extreme stays on its side by more than
:data:`DIP_CONFIRM` times the previous map's error (one or two solves on a clean circle), or
splits the part at the first point across the axis and refines both crossings. On the baseline
design's loops at its envelope points (tests/test_bearing_loops_accuracy.py) 392 parts are
searched, none crossing: 339 solves on the projected route the assessment takes, 14 % of its
2420 (2081 without the searches), 678 of 8649 with every solve full; on the tuned design's, 2
searches, each finding a pair, 20 of 1497 (counted by an independent review). The gain searches
(counted when they were added, bearing_loops' banded solves at the three envelope points)
add at most a few searches and 4 to 8 solves on the tuned design's loops (0.3 % of 1351 to
1682); on the baseline's, tens of searches a point finding 15 to 32 pairs of gain crossovers that
were missed before (the count depends on the call: 17 to 22 searches and 15 to 19 pairs a point
by an independent review's count of the second round's gain tasks; 54 searches and 39 pairs in
all through ``assess(baseline, SCREENING)``; none setting its phase margin; at the cold point a
20 000-point grid finds them too, and 7 to 10 more pairs a loop beside close mode pairs, none
setting the phase margin either), 437 to 664 solves (18 to 28 % over 2364 to 2404; bearing_loops
12 to 17 % more CPU on the baseline). Its limits,
measured by that review against a 200 001-point scan on random single-mode loops (200 a family,
on the coarse 200-point grid with loop_grid's three samples at each closed-loop pole): a dip
beyond the band (clean circles: none of 200 after the band gained its extra interval each side;
on a background slope 1 to 3 of 200, the background distorting the half width); one the fits'
error hides, the maps fitted to L at points up to a grid interval apart, where a varying
background or a second mode moves them (two modes within 10 % of each other, both poles sampled:
2 to 4 of 200); with one sample a pole (as on a screening grid) more escape (11 of 200 on a
background slope, 16 to 22 with two modes), the peak's refinement then sometimes ending below
the grid's top. The gain searches share these limits (measured only on the test loop above and
the embedded designs' loops, not on random loops).
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence

import numpy as np

from flexshaft.analyses.local_projection import GOLDEN, Refinement, RefinementTask, illinois_root

__all__ = [
    "DIP_CONFIRM",
    "DIP_FOURTH_SAFETY",
    "DIP_SLACK",
    "DIP_WIDTHS",
    "dip_crossovers",
    "dip_searches",
    "gain_image",
    "may_dip",
]

#: How near the real axis, and Re L = 0, the circle through L at a part's ends and beside them
#: must come, in its radius, for a dip across the axis to be searched (:func:`may_dip`).
DIP_SLACK = 0.05
#: Half widths of a refined sensitivity peak each side of it searched for a dip (the grid
#: intervals that reach into that band and one more each side; :func:`dip_searches`).
DIP_WIDTHS = 3.0
#: How many times the error of the circle's fit the refitted extreme must stay on its side of
#: the axis for a dip's search to stop without a crossing (:func:`dip_crossovers`).
DIP_CONFIRM = 1.0
#: The same for a part to be dropped unsearched, on the error of the map at the grid point on
#: the part's other side (an extrapolation, which can fit there and not at the extreme: at 4
#: times, random loops on a background slope missed dips the search finds; :func:`dip_searches`).
DIP_FOURTH_SAFETY = 10.0


def dip_searches(w: np.ndarray, L: np.ndarray, peaks: np.ndarray, at_peaks: np.ndarray) -> list[RefinementTask]:
    """The searches for a dip of Im L across the negative real axis (:func:`dip_crossovers`)
    in the parts, between the grid ``w`` and the ``peaks`` [rad/s], of the grid intervals
    within :data:`DIP_WIDTHS` half widths of a peak (:func:`_half_width`) and one more each
    side where Im L keeps its sign, the circle through L at the part's ends and its neighbour
    toward the peak may dip (:func:`may_dip`) and the Möbius map through them, checked at the
    grid point on the other side, does not clear the axis (:func:`_clear_of_axis`); and the
    same searches for a pair of gain crossovers (|L| = 1, task role ``"gain"``) on
    u = i(S − 1/2) (:func:`gain_image`, module docstring), without the test of Re L."""
    near = _near_peaks(w, L, peaks, at_peaks)
    return _searches(w, L, peaks, at_peaks, near, "phase") + _searches(w, L, peaks, at_peaks, near, "gain")


def gain_image(L: np.ndarray) -> np.ndarray:
    """u = i(S − 1/2), S = 1/(1 + L): Im u = Re S − 1/2 is zero where |L| = 1 (|1 − S| = |S|),
    positive where |L| < 1, and u is a Möbius map of L (module docstring)."""
    with np.errstate(all="ignore"):
        return 1j * (1.0 / (1.0 + np.asarray(L, dtype=complex)) - 0.5)


def _near_peaks(w: np.ndarray, L: np.ndarray, peaks: np.ndarray, at_peaks: np.ndarray) -> np.ndarray:
    """The grid points within :data:`DIP_WIDTHS` half widths of a peak and one interval more
    each side (a mask of ``w``): where :func:`dip_searches` looks, for either role."""
    near = np.zeros(w.size, dtype=bool)
    for p, lp in zip(peaks, at_peaks):
        band = DIP_WIDTHS * _half_width(w, L, float(p), complex(lp))
        low = int(np.searchsorted(w, p - band, side="right")) - 1  # a grid point beyond the band
        high = int(np.searchsorted(w, p + band))
        near[max(low - 1, 0) : high + 2] = True  # and one interval more each side
    return near


def _searches(
    w: np.ndarray, L: np.ndarray, peaks: np.ndarray, at_peaks: np.ndarray, near: np.ndarray, role: str
) -> list[RefinementTask]:
    """:func:`dip_searches` for the crossings of Im V = 0 of V = L (``role`` ``"phase"``) or
    V = :func:`gain_image` of L (``"gain"``), on the grid points ``near`` the peaks."""
    phase = role == "phase"
    V = L if phase else gain_image(L)
    V_at_peaks = at_peaks if phase else gain_image(at_peaks)
    tasks: list[RefinementTask] = []
    runs = np.split(np.flatnonzero(near), np.flatnonzero(np.diff(np.flatnonzero(near)) > 1) + 1)
    for run in runs:
        if run.size == 0:
            continue
        points = [(float(w[n]), complex(V[n])) for n in run]
        points += [
            (float(p), complex(v)) for p, v in zip(peaks, V_at_peaks) if w[run[0]] < p < w[run[-1]] and p not in w
        ]
        points.sort(key=lambda point: point[0])
        if len(points) < 3:
            continue  # no third point to fit a circle through
        for k, ((a, la), (b, lb)) in enumerate(zip(points[:-1], points[1:])):
            if la.imag == 0 or np.sign(la.imag) != np.sign(lb.imag):
                continue  # a crossing the grid or a peak brackets
            toward = k == 0 or (k + 2 < len(points) and bool(np.any((b <= peaks) & (peaks <= points[-1][0]))))
            third = points[k + 2][1] if toward else points[k - 1][1]  # the neighbour toward a peak
            c = points[k + 2][0] if toward else points[k - 1][0]
            if may_dip(la, lb, third, phase):
                fit = [(float(np.log(a)), la), (float(np.log(b)), lb), (float(np.log(c)), third)]
                fourth = k - 1 if toward else k + 2  # the neighbour on the other side
                n = run[0] - 1 if fourth < 0 else run[-1] + 1  # beyond the run: the grid's
                extra = points[fourth] if 0 <= fourth < len(points) else None
                if extra is None and 0 <= n < w.size:
                    extra = (float(w[n]), complex(V[n]))
                if extra is not None and _clear_of_axis(fit, extra):
                    continue
                j = int(np.searchsorted(w, a, side="right")) - 1
                dip = functools.partial(dip_crossovers, a, b, la, lb, c, third)
                if not phase:
                    dip = functools.partial(_on_gain_image, dip)
                tasks.append(RefinementTask("dip", j, j + 1, dip, role))
    return tasks


def _on_gain_image(search: Callable[[], Refinement]) -> Refinement:
    """A :func:`dip_crossovers` ``search`` on u = :func:`gain_image` of L: each L the caller
    sends is mapped to u, and the crossings found are returned with L (as evaluated)."""
    steps = search()
    seen: dict[float, complex] = {}
    try:
        x = next(steps)
        while True:
            value = yield x
            seen[x] = complex(value)
            x = steps.send(complex(gain_image(np.asarray(value))))
    except StopIteration as stop:
        return [(x, seen[x]) for x, _ in stop.value]


def _half_width(w: np.ndarray, L: np.ndarray, p: float, lp: complex) -> float:
    """The half width [rad/s] of a sensitivity peak at ``p`` (L there ``lp``) from |S| there and
    at the grid points beside it, as a resonance's |S|p/√(1 + ((ω − p)/h)²) would give it (the
    wider of the two; the peak's grid interval where |S| is not lower beside it)."""
    top = abs(1.0 / (1.0 + lp))
    i = int(np.searchsorted(w, p))
    widths = [abs(w[0] - p) + abs(w[-1] - p)]
    for n in (i - 1, i) if 0 < i < w.size else ():
        ratio = top * abs(1.0 + L[n])
        widths.append(abs(w[n] - p) / np.sqrt(ratio**2 - 1.0) if ratio > 1.0 else abs(w[n] - p))
    return float(max(widths[1:], default=widths[0]))


def _mobius(points: Sequence[tuple[float, complex]], x: float) -> complex:
    """L at ``x`` by the Möbius map x ↦ L through three ``points`` (x, L) (cross-ratio)."""
    (x1, l1), (x2, l2), (x3, l3) = points
    z = (x - x1) * (x2 - x3) / ((x - x3) * (x2 - x1))
    m = (l2 - l1) / (l2 - l3)
    return complex((l1 - z * m * l3) / (1.0 - z * m))


def _clear_of_axis(fit: Sequence[tuple[float, complex]], fourth: tuple[float, complex]) -> bool:
    """Whether the circle of the Möbius map through ``fit`` (x = ln ω, L: a part's ends first,
    Im L of one sign there) keeps its extreme point on that side by more than
    :data:`DIP_FOURTH_SAFETY` times the error of the map's Im L at a ``fourth`` point (ω, L) of
    the grid (no evaluation)."""
    side = float(np.sign(fit[0][1].imag))
    predicted = _predicted_extreme(fit, side)
    with np.errstate(all="ignore"):
        error = abs(_mobius(fit, float(np.log(fourth[0]))).imag - fourth[1].imag)
    return predicted is not None and bool(side * predicted[1].imag > DIP_FOURTH_SAFETY * error)


def may_dip(la: complex, lb: complex, third: complex, phase: bool = True) -> bool:
    """Whether L can cross the negative real axis twice between two frequencies where it is
    ``la`` and ``lb`` (Im L of one sign), by the circle a lightly damped mode's L traces through
    them and L at a third frequency beside them (``third``, outside the part): its arc from
    ``la`` to ``lb`` (the one without ``third``) must hold the circle's extreme point toward the
    other sign, within :data:`DIP_SLACK` of its radius of the axis, and its leftmost crossing of
    the axis (or that extreme point) within as much of Re L = 0 (module docstring); without
    that last test when not ``phase`` (the values are then :func:`gain_image`'s)."""
    circle = _circle(la, lb, third)
    if circle is None:
        return False  # on one line: Im L between la and lb is monotonic
    centre, radius = circle
    side = np.sign(la.imag)
    if side * centre.imag - radius > DIP_SLACK * radius:
        return False  # the circle stays on the side of the ends
    leftmost = centre.real - np.sqrt(max(radius**2 - centre.imag**2, 0.0))
    if phase and leftmost > DIP_SLACK * radius:
        return False  # it would cross the real axis at Re L > 0 only: no phase crossover
    turn = functools.partial(_turn, centre)
    extreme = centre - 1j * side * radius
    if turn(la, third) < turn(la, lb):  # the arc from la to lb without third runs clockwise
        return turn(lb, extreme) <= turn(lb, la)
    return turn(la, extreme) <= turn(la, lb)


def _turn(centre: complex, start: complex, end: complex) -> float:
    """The counter-clockwise angle about ``centre`` from ``start`` to ``end`` in [0, 2π)."""
    return float(np.angle((end - centre) / (start - centre)) % (2.0 * np.pi))


def _circle(l1: complex, l2: complex, l3: complex) -> tuple[complex, float] | None:
    """Centre and radius of the circle through three values of L (None when on one line, or
    when the first two are equal)."""
    ratio = (l3 - l1) / (l2 - l1) if l2 != l1 else np.nan
    if not (np.isfinite(ratio) and ratio.imag != 0):
        return None
    centre = l1 + (l2 - l1) * (ratio - abs(ratio) ** 2) / (2j * ratio.imag)
    return centre, float(abs(l1 - centre))


def _predicted_extreme(points: Sequence[tuple[float, complex]], side: float) -> tuple[float, complex, float] | None:
    """From L at three ``points`` (x = ln ω, L): the x where the Möbius map x ↦ L through them
    (a lightly damped mode's L about its resonance, x = ln ω, up to the cube of x − ln ω_r)
    reaches its circle's extreme point toward −``side``, that point and the circle's radius;
    None when the points lie on one line or the prediction is not finite."""
    (x1, l1), (x2, l2), (x3, l3) = points
    circle = _circle(l1, l2, l3)
    if circle is None:
        return None
    centre, radius = circle
    extreme = centre - side * radius * 1j
    with np.errstate(all="ignore"):  # cross-ratio: L1 -> 0, L2 -> 1, L3 -> inf and the same in x
        z = ((extreme - l1) * (l2 - l3) / ((extreme - l3) * (l2 - l1))).real
        k = (x2 - x1) / (x2 - x3)
        x = (x1 - z * k * x3) / (1.0 - z * k)
    return (float(x), extreme, radius) if np.isfinite(x) else None


def dip_crossovers(a: float, b: float, la: complex, lb: complex, c: float, lc: complex) -> Refinement:
    """The two crossings of the real axis of a dip of L between ``a`` and ``b`` [rad/s] (where
    L is ``la``, ``lb``, Im L of one sign; ``c``, ``lc`` a third frequency beside the part and
    L there). The circle of a lightly damped mode is the image of the frequency axis under a
    Möbius map in x = ln ω (L = A + B/(1 − i(x_r − x)/ζ) near the resonance, module
    docstring), which three points fix: L is evaluated where the map through the three points
    nearest the lowest Im L found (toward the other sign) reaches its circle's extreme point
    toward the other sign (:func:`_predicted_extreme`), or, where that lies outside their
    bracket, at the golden section of the bracket's larger half. At the first point across
    the axis the part is split and both crossings are refined (:func:`illinois_root`, 1e-8 ω
    relative). The search stops without a crossing when the extreme of the map refitted
    through the new point and its neighbours (or, outside the bracket, the lowest point) stays
    on its side by more than :data:`DIP_CONFIRM` times the error of the previous map's Im L at
    the new point, or when the bracket is 1e-8 in ln ω wide (a dip narrower is not resolved).
    On a single mode's circle the first point lands on the extreme and the refit confirms it
    (one evaluation); where the map fits badly (another mode, a varying background) the
    golden steps narrow the bracket until it fits. Returns the crossings' (ω, L(iω)), none
    when no point crosses; a point exactly on the axis is returned alone (a circle touching
    it). Every crossing returned is bracketed by a change of sign of the loop's own Im L: none
    is spurious; a dip the search steps past (two extrema of Im L in a bracket the map does not
    follow) can be missed."""
    side = float(np.sign(la.imag))
    known = sorted([(float(np.log(a)), la), (float(np.log(b)), lb)], key=lambda point: point[0])
    fit = [known[0], known[1], (float(np.log(c)), lc)]
    lo, best, hi = known[0], known[0] if side * la.imag <= side * lb.imag else known[1], known[1]
    while hi[0] - lo[0] > 1e-8:
        predicted = _predicted_extreme(fit, side)
        if predicted is not None and lo[0] < predicted[0] < hi[0] and predicted[0] != best[0]:
            x = predicted[0]
        elif best[0] - lo[0] >= hi[0] - best[0]:  # the golden section of the larger half
            x = best[0] - (1.0 - GOLDEN) * (best[0] - lo[0])
        else:
            x = best[0] + (1.0 - GOLDEN) * (hi[0] - best[0])
        with np.errstate(all="ignore"):
            model = _mobius(fit, x)
        lx = yield float(np.exp(x))
        if side * lx.imag <= 0:
            return (yield from _split(known, x, lx))
        known.append((x, lx))
        known.sort(key=lambda point: point[0])
        i = min(range(len(known)), key=lambda n: side * known[n][1].imag)
        best = known[i]
        i = min(max(i, 1), len(known) - 2)
        lo, hi = known[i - 1], known[i + 1]
        fit = [lo, known[i], hi]
        refit = _predicted_extreme(fit, side)
        if refit is not None and lo[0] < refit[0] < hi[0]:
            margin = side * refit[1].imag
        else:  # on the refitted circle Im L is monotonic about the bracket: its lowest point is known
            margin = side * best[1].imag
        if margin > DIP_CONFIRM * abs(lx.imag - model.imag):
            return []
        if best is not known[i]:  # the lowest point is an end: bracket it with its neighbour
            lo, hi = (known[0], known[1]) if best is known[0] else (known[-2], known[-1])
    return []


def _split(known: list[tuple[float, complex]], x: float, lx: complex) -> Refinement:
    """The two crossings each side of a point ``x`` (ln ω, L there ``lx``) across the axis,
    bracketed by the nearest ``known`` points (ln ω, L; on the other side)."""
    m = float(np.exp(x))
    if lx.imag == 0:
        return [(m, lx)]
    below = max((point for point in known if point[0] < x), key=lambda point: point[0])
    above = min((point for point in known if point[0] > x), key=lambda point: point[0])
    low, high = float(np.exp(below[0])), float(np.exp(above[0]))
    first = yield from illinois_root(_imag, low, m, below[1], lx, 1e-8 * low)
    second = yield from illinois_root(_imag, m, high, lx, above[1], 1e-8 * m)
    return [first, second]


def _imag(value: complex) -> float:
    return value.imag

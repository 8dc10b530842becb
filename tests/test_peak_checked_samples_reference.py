"""Which samples of a projected orbit are checked by full solves: extrema, their neighbours, ends.

:func:`flexshaft.analyses.peak_projection._checked_samples` chooses the samples whose full
solves make a peak's numbers trustworthy (the module docstring's rule): both ends of the round;
every local maximum and minimum with its two neighbours (the three samples of the parabolic
vertex, a flanking minimum that decides whether two bumps are one); and, around each maximum,
the two samples on either side of its half-power level max/√2
(tests/test_peak_half_power_samples_reference.py checks those on one peak).

Reference curve: the driving-point receptance of a two-degree-of-freedom chain (ground–k₁–m₁–k₂–
m₂, light viscous damping c at each mass), |H₁₁(ω)| = |k₂ − m₂ω² + icω| / |det(K − ω²M + iωC)|,
m₁, m₂ = 1, 0.5 kg, k₁, k₂ = 1e4, 3e3 N/m, c = 2 N s/m, sampled at ω = 40, 41, ..., 160 rad/s
(sample j at 40 + j). Physical anchors, by hand: the undamped resonances are the roots of
det(K − λM) = (13000 − λ)(3000 − λ/2) − 3000² = 0, i.e. λ² − 19000λ + 6e7 = 0, λ = 4000 and
15000, ω = 63.25 and 122.47 rad/s (ζ ≤ c/(2m₂ω₁) = 0.032: the peaks move by O(ζ²)ω, far
less than the grid's 1 rad/s); the anti-resonance ω = √(k₂/m₂) = 77.46 rad/s lies between them
(the numerator's zero: the second mass, held by k₂ alone, then cancels the force on the first).
Its sampled minimum is sample 38
(ω = 78), not 37: |numerator| is 158 at 77 and 162 at 78, but |det| grows from 8.84e6 to
9.38e6, so |H| = 1.79e-5 and 1.72e-5 (and 2.01e-5 at 79). So samples 0 and 120 (the ends) and
37, 38, 39 (the minimum and its neighbours) must be checked. The full expected set is built here
by scanning the sampled curve with plain loops (strict neighbours' comparisons; the curve has no
ties), so the rule is checked sample by sample, exactly.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.peak_projection import _checked_samples


def _receptance(w: np.ndarray) -> np.ndarray:
    m1, m2, k1, k2, c = 1.0, 0.5, 1.0e4, 3.0e3, 2.0
    out = []
    for x in w:
        Z = np.array([[k1 + k2 - m1 * x * x + 1j * c * x, -k2], [-k2, k2 - m2 * x * x + 1j * c * x]])
        out.append(abs((k2 - m2 * x * x + 1j * c * x) / np.linalg.det(Z)))
    return np.array(out)


def _expected(values: np.ndarray) -> set[int]:
    n = values.size
    out = {0, n - 1}
    maxima = [k for k in range(1, n - 1) if values[k] > values[k - 1] and values[k] > values[k + 1]]
    minima = [k for k in range(1, n - 1) if values[k] < values[k - 1] and values[k] < values[k + 1]]
    for k in maxima + minima:
        out |= {k - 1, k, k + 1}
    for k in maxima:
        level = values[k] / np.sqrt(2.0)
        left = [j for j in range(k) if values[j] < level]
        if left:
            out |= {left[-1], left[-1] + 1}
        right = [j for j in range(k + 1, n) if values[j] < level]
        if right:
            out |= {right[0] - 1, right[0]}
    return out


def test_extrema_their_neighbours_ends_and_half_power_brackets_are_checked():
    w = np.linspace(40.0, 160.0, 121)
    values = _receptance(w)
    minima = [k for k in range(1, w.size - 1) if values[k] < values[k - 1] and values[k] < values[k + 1]]
    maxima = [k for k in range(1, w.size - 1) if values[k] > values[k - 1] and values[k] > values[k + 1]]
    assert len(maxima) == 2 and len(minima) == 1  # two resonances, the anti-resonance between
    assert abs(w[minima[0]] - np.sqrt(3.0e3 / 0.5)) <= 1.0  # √(k₂/m₂) = 77.5 rad/s, on a 1 rad/s grid
    # the undamped resonances, roots of λ² − 19000 λ + 6e7 = 0: λ = 4000, 15000 (rad/s)²
    assert abs(w[maxima[0]] - np.sqrt(4000.0)) <= 1.0 and abs(w[maxima[1]] - np.sqrt(15000.0)) <= 1.0
    checked = set(_checked_samples(values).tolist())
    assert {0, 120, 37, 38, 39} <= checked  # the ends; the minimum (ω = 78) and its neighbours, by hand
    assert checked == _expected(values)

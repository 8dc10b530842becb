"""The sensitivity peak of a loop whose |S| is largest at the low end of its grid is reported there
(mutation hunt h95c).

Reference, derived here: a PD law on a single mass with a negative magnet stiffness,

    L(s) = (k_p + k_d s) / (m s² − k_s),   S = 1/(1 + L) = (m s² − k_s) / (m s² + k_d s + k_p − k_s),

so on s = iω, with x = ω² and ε = k_p − k_s > 0,

    |S(iω)|² = (m x + k_s)² / ((ε − m x)² + k_d² x).

At ω → 0 it is (k_s/ε)², and for k_d² > 2 m ε + 2 m ε²/k_s its slope in x is negative there (the
derivative of the quotient at x = 0 is (2 k_s m ε² − k_s²(k_d² − 2 m ε))/ε⁴): with m = 1 kg,
k_s = 1e4 N/m, k_p = 1.5e4 N/m, k_d = 1000 N s/m (k_d² = 1e6 > 1.5e4) |S| falls from 2 to a
minimum of about 0.2 near 16 Hz and then rises back towards 1 from below,
and |S|² < 4 at every ω > 0 ((x + k_s)² < 4(ε − x)² + 4 k_d² x ⟺ 3x² + 3.94e6 x > 0 with
m = 1): it never climbs back to its value at ω → 0. On a grid from 0.1 Hz the largest |S| is at the
grid's first point (checked below on the closed form, not on the code): there is no interior
maximum to refine. Rule (docs/magnetic-bearings.md): the loops are evaluated "on a logarithmic grid
over 0.1 Hz-2 kHz by default ...; peaks and crossovers refined on the loop function", so the peak
reported is the grid's largest |S| and its frequency is where |S| takes it; the supremum |S(0)| = 2
lies off the grid, at ω → 0, and is not asked for. |L|, by contrast, peaks inside the grid
(|L(0)| = k_p/k_s = 1.5, rising while k_d² k_s > 2 k_p² m): a peak placed by the wrong curve is seen
(it would report 15.4 Hz, where |S| ≈ 0.2).

Tolerances: the closed form and the code both evaluate one rational function of ω at the grid's
first point; |1 + L| = 0.5 there against |L| = 1.5, a cancellation of a factor 3, so 1e-12
relative is ~1e3 ulp of headroom; the frequency is a grid value passed through, divided by 2π.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.loop_margins import loop_margins

M, KS, KP, KD = 1.0, 1e4, 1.5e4, 1e3


def loop(w: np.ndarray) -> np.ndarray:
    s = 1j * np.asarray(w)
    return (KP + KD * s) / (M * s**2 - KS)


def closed_form_s(w: np.ndarray) -> np.ndarray:
    """|S(iω)| from the expression in the module docstring (real arithmetic)."""
    x = np.asarray(w) ** 2
    eps = KP - KS
    return (M * x + KS) / np.sqrt((eps - M * x) ** 2 + KD**2 * x)


def test_a_sensitivity_peak_at_the_low_end_of_the_grid_is_reported_there():
    w = 2 * np.pi * np.logspace(-1, 3.3, 400)
    s_ref = closed_form_s(w)
    l_ref = np.abs(KP + 1j * KD * w) / (M * w**2 + KS)
    assert int(np.argmax(s_ref)) == 0  # the premise: |S| is largest at the grid's first point
    assert s_ref[1:].max() < s_ref[0] * (1 - 1e-6)  # not a near tie
    assert int(np.argmax(l_ref)) > 10  # and |L| is largest well inside the grid
    result = loop_margins(loop, w)
    assert abs(result.peak_sensitivity - s_ref[0]) <= 1e-12 * s_ref[0]
    # The reported frequency is where |S| takes the reported peak, below the grid's second point.
    at_peak = closed_form_s(2 * np.pi * np.array([result.peak_frequency]))[0]
    assert abs(at_peak - result.peak_sensitivity) <= 1e-12 * s_ref[0]
    assert result.peak_frequency < w[1] / (2 * np.pi)
    assert result.zone == "A"  # 1.98 < 3 (docs/magnetic-bearings.md: zone A below 3)

"""Sensitivity peak, gain and phase margins of two loops with closed-form answers, derived here.

**PD law on a mass with a negative-stiffness magnet** (the magnetic bearing's loop, docstring of
:mod:`flexshaft.analyses.loop_margins`): m ẍ − k_s x = f, f = −(k_p + k_d s) x, so

    L(s) = (k_p + k_d s)/(m s² − k_s),  L(0) = −k_p/k_s < 0.

For ω > 0 the denominator −mω² − k_s is negative real, so Im L = −k_d ω/(mω² + k_s) < 0: the only
phase crossover is ω = 0, with |L(0)| = k_p/k_s > 1, a lower gain margin 20 log10(k_s/k_p) dB
and no upper one (+inf). The gain crossover |k_p + i k_d ω| = mω² + k_s is the positive root
x = ω² of m² x² + (2 m k_s − k_d²) x + k_s² − k_p² = 0, where arg L = atan(k_d ω/k_p) − 180°:
phase margin 180° − |arg L| = atan(k_d ω_gc/k_p). With x = ω², a = k_p − k_s,

    |S|² = |1/(1 + L)|² = (m x + k_s)² / ((a − m x)² + k_d² x),

whose maximum over x solves 2m[(a − m x)² + k_d² x] + (m x + k_s)(2m(a − m x) − k_d²) = 0 (the
derivative's numerator divided by m x + k_s > 0), a quadratic solved here. With m = 1 kg,
k_s = 1e4 N/m, k_p = 2e4 N/m, k_d = 10 N s/m the closed loop has ω_n = 100 rad/s, ζ = 0.05: a
peak |S| ≈ 20 that a 60-point grid (17 % steps) samples well below its top, so the refined
peak is what is checked.

**Third-order lag** L(s) = K/(s + a)³ with K = 4a³: L(0) = 4 > 0 (no crossover at 0); phase
−3 atan(ω/a) reaches −180° at ω_pc = a tan 60° = √3 a, where |L| = K/(4a²)^{3/2} = ½: upper
gain margin 20 log10 2 = 6.02 dB, no lower one; |L| = 1 at ω_gc = a √(K^{2/3}/a² − 1), phase
margin 180° − 3 atan(ω_gc/a).

Frequencies are reported in Hz (ω/2π, :class:`LoopMargins`). Tolerances: the refinements stop at
1e-6 (golden section, in ln ω) and 1e-8 (regula falsi, relative ω): frequencies to 1e-5
relative, values at a maximum (second order) and at a refined root to 1e-6; the closed forms
are a quadratic's roots in double precision. ISO 14839-3 zone A is *below* 3 (the module's
docstring): a peak of exactly 3 is zone B. Written for the h26a-loop-* mutations of
scripts/mutations.toml; about 10 ms.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.loop_margins import loop_margins, sensitivity_zone

M, KS, KP, KD = 1.0, 1.0e4, 2.0e4, 10.0
GRID = np.geomspace(1.0, 1.0e4, 60)


def pd_on_magnet(w):
    s = 1j * np.asarray(w)
    return (KP + KD * s) / (M * s**2 - KS)


def test_pd_loop_on_an_unstable_magnet_margins_and_peak():
    result = loop_margins(pd_on_magnet, GRID, static_gain=-KP / KS)
    # the only phase crossover: ω = 0, |L| = k_p/k_s
    assert result.phase_crossovers == (0.0,)
    assert result.gain_margin_lower_db == pytest.approx(20.0 * math.log10(KS / KP), rel=1e-12)
    assert result.gain_margin_upper_db == math.inf
    assert result.gain_margin_db == pytest.approx(20.0 * math.log10(KS / KP), rel=1e-12)
    assert result.gain_margin_frequency == 0.0
    # gain crossover and phase margin
    x = np.roots([M * M, 2 * M * KS - KD * KD, KS * KS - KP * KP])
    w_gc = math.sqrt(float(x[x.real > 0].real[0]))
    assert result.gain_crossovers == pytest.approx((w_gc / (2 * math.pi),), rel=1e-5)
    assert result.phase_margin_frequency == pytest.approx(w_gc / (2 * math.pi), rel=1e-5)
    assert result.phase_margin_deg == pytest.approx(math.degrees(math.atan(KD * w_gc / KP)), rel=1e-6)
    # sensitivity peak
    a = KP - KS
    quadratic = 2 * M * np.poly1d([M * M, -2 * a * M + KD * KD, a * a]) + np.poly1d([M, KS]) * np.poly1d(
        [-2 * M * M, 2 * M * a - KD * KD]
    )
    xs = [r.real for r in quadratic.roots if abs(r.imag) < 1e-9 * abs(r) and r.real > 0]
    peak_x = max(xs, key=lambda x: (M * x + KS) ** 2 / ((a - M * x) ** 2 + KD * KD * x))
    peak = (M * peak_x + KS) / math.sqrt((a - M * peak_x) ** 2 + KD * KD * peak_x)
    grid_peak = float(np.abs(1.0 / (1.0 + pd_on_magnet(GRID))).max())
    assert grid_peak < 0.9 * peak  # the grid alone misses the top: the refinement is checked
    assert result.peak_sensitivity == pytest.approx(peak, rel=1e-6)
    assert result.peak_sensitivity_db == pytest.approx(20.0 * math.log10(peak), rel=1e-6)
    assert result.peak_frequency == pytest.approx(math.sqrt(peak_x) / (2 * math.pi), rel=1e-5)


A = 300.0  # rad/s
K = 4.0 * A**3


def third_order_lag(w):
    return K / (1j * np.asarray(w) + A) ** 3


def test_third_order_lag_upper_gain_margin_at_its_phase_crossover():
    result = loop_margins(third_order_lag, np.geomspace(10.0, 1.0e5, 80), static_gain=K / A**3)
    w_pc = math.sqrt(3.0) * A
    assert result.phase_crossovers == pytest.approx((w_pc / (2 * math.pi),), rel=1e-5)
    assert result.gain_margin_upper_db == pytest.approx(20.0 * math.log10(2.0), rel=1e-6)
    assert result.gain_margin_lower_db == -math.inf
    assert result.gain_margin_db == pytest.approx(20.0 * math.log10(2.0), rel=1e-6)
    assert result.gain_margin_frequency == pytest.approx(w_pc / (2 * math.pi), rel=1e-5)
    w_gc = A * math.sqrt(K ** (2.0 / 3.0) / A**2 - 1.0)
    assert result.phase_margin_frequency == pytest.approx(w_gc / (2 * math.pi), rel=1e-5)
    assert result.phase_margin_deg == pytest.approx(180.0 - 3.0 * math.degrees(math.atan(w_gc / A)), rel=1e-6)


def test_iso_zone_a_is_below_three():
    assert sensitivity_zone(2.999) == "A"
    assert sensitivity_zone(3.0) == "B"
    assert sensitivity_zone(4.0) == "C"
    assert sensitivity_zone(5.0) == "D"

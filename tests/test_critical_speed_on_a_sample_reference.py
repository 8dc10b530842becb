"""A Campbell curve that meets an excitation line exactly at a sample speed is a critical speed.

Reference (derived here): a whirl frequency ω₀ independent of the spin (the Jeffcott rotor of
tests/test_campbell_criticals.py: a disk without polar inertia) meets the excitation line
ω = kΩ at Ω = ω₀/k, whatever the speed grid. On a grid that holds ω₀/k itself the curve minus
the line, g = ω₀ − kΩ, is exactly 0 at that sample and changes sign across it, but not within
either neighbouring interval: the crossing must still be found, once, at Ω = ω₀/k (it used to
be missed). A curve that touches the line at a sample (g = +, 0, +: ω = Ω there) is a resonance
at that speed too. A divergent root (Im s = 0) meets ω = kΩ only at rest, where it is no
resonance: no critical speed.

Exact numbers (ω₀ = 120 rad/s, grid steps of 20 rad/s): every value is exact in binary floating
point, so the asserted crossings are exact (rel 1e-15 allowed for the interpolation's rounding).
Pure array arithmetic: well under 0.01 s.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.campbell import critical_speeds

OMEGA_0 = 120.0  # rad/s


def _labels(n_speeds: int, n_modes: int = 1):
    return np.full((n_speeds, n_modes), "forward"), np.full((n_speeds, n_modes), "lateral")


@pytest.mark.parametrize("start", [0.0, 10.0])  # grid through the crossings, or between them
def test_a_constant_frequency_is_critical_at_omega_0_over_k_on_any_grid(start):
    speeds = np.arange(start, 200.0, 20.0)
    eigenvalues = np.full((speeds.size, 1), -1.0 + 1j * OMEGA_0)
    whirl, kind = _labels(speeds.size)
    found = critical_speeds(speeds, eigenvalues, whirl, kind, harmonics=(1.0, 2.0))
    assert [(c.harmonic, c.mode, c.whirl) for c in found] == [(2.0, 0, "forward"), (1.0, 0, "forward")]
    assert [c.speed for c in found] == pytest.approx([OMEGA_0 / 2, OMEGA_0], rel=1e-15)


def test_a_curve_touching_the_line_at_a_sample_is_critical_there():
    speeds = np.array([80.0, 100.0, 120.0, 140.0, 160.0])
    frequencies = speeds + (speeds - OMEGA_0) ** 2 / 40.0  # above ω = Ω except at Ω = ω₀
    whirl, kind = _labels(speeds.size)
    found = critical_speeds(speeds, (1j * frequencies)[:, None], whirl, kind)
    assert [c.speed for c in found] == [OMEGA_0]


def test_a_divergent_root_has_no_critical_speed_at_rest():
    speeds = np.array([0.0, 50.0, 100.0])
    eigenvalues = np.array([[5.0 + 0j], [5.0 + 0j], [5.0 + 0j]])  # real s > 0 at every speed
    whirl, kind = _labels(speeds.size)
    assert critical_speeds(speeds, eigenvalues, whirl, kind) == ()

"""Crossings of a Campbell curve with fractional excitation lines ω = kΩ (k = 0.5, 1.5, 2).

Reference (closed form, derived here): a lateral curve whose damped frequency rises linearly
with the spin, Im s = ω₀ + aΩ (a forward whirl stiffened by gyroscopic coupling, to first
order), meets the line ω = kΩ where ω₀ + aΩ = kΩ, at Ω* = ω₀/(k − a) (k > a). Between two
samples the distance g(Ω) = Im s − kΩ is linear in Ω, so the linear interpolation of
:func:`~flexshaft.analyses.campbell.critical_speeds` is exact and the crossing is Ω* to
round-off; the excitation order it reports is k itself (half-order and 1.5-order lines are the
sub-synchronous ½× and 3/2× rub orders a designer draws on a Campbell diagram).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.campbell import critical_speeds

W0, SLOPE = 200.0, 0.2  # ω₀ [rad/s], dω/dΩ [-]


def test_fractional_orders_cross_at_omega0_over_k_minus_a():
    """Ω* = ω₀/(k − a) for k = 0.5, 1.5, 2 (a = 0.2): 3.33 ω₀, 0.769 ω₀, 0.556 ω₀, none on a
    sample of the 0.5 ω₀ grid, each reported with its own order k. Tolerance 1e-12 relative:
    the interpolation is exact for a linear g; its round-off is a few ulps of ω₀ (the samples
    and g are O(ω₀) numbers), well below 1e-12."""
    speeds = np.linspace(0.0, 5.0 * W0, 11)
    eigenvalues = (-0.01 * W0 + 1j * (W0 + SLOPE * speeds))[:, None]  # (speeds, 1 mode)
    whirl = np.full(eigenvalues.shape, "forward")
    kind = np.full(eigenvalues.shape, "lateral")
    found = critical_speeds(speeds, eigenvalues, whirl, kind, harmonics=(0.5, 1.5, 2.0))
    expected = sorted((W0 / (k - SLOPE), k) for k in (0.5, 1.5, 2.0))
    assert [c.harmonic for c in found] == [k for _, k in expected]
    assert [c.speed for c in found] == pytest.approx([s for s, _ in expected], rel=1e-12)
    assert all(c.mode == 0 and c.whirl == "forward" for c in found)

"""A seeded critical speed is kept only at a maximum of the envelope, never on its flank
(mutation hunt 23c).

:func:`flexshaft.analyses.criticals._envelope_peak` decides whether a peak refined from a
synchronous root's seed is a maximum of the envelope (the largest orbit over the shaft and
the load cases): full solves a 20th of its half-power bandwidth N/AF to either side must not
be above it (a quarter before hunt h94b).

Reference (derived): the Jeffcott-like rotor of tests/rotors.py with a dashpot c_e = 2ζ m ω_n
at the disk (no loss) under a forward imbalance u at the disk has the circular orbit

    |r(Ω)| = u Ω² / |k − m Ω² + iΩ c_e|,

whose square's reciprocal, (k/Ω² − m)² + (c_e/Ω)², decreases, then increases in 1/Ω²: one
maximum, at Ω_p = ω_n/√(1 − 2ζ²). So |r| rises strictly below Ω_p and falls strictly above it:
a candidate at 0.9 ω_n or 1.1 ω_n (AF = 1/(2ζ) = 25, its neighbours ±0.2 % of the speed away,
all on one side of Ω_p) is a flank, the one at Ω_p the peak. No tolerance: the decision is a
comparison of orbits that differ by 0.5 % or more (1.8-2 % on the flanks, 0.5 % at the peak,
from the formula), far above the solve's round-off.
CPU: 9 banded solves on 8 elements, about 0.02 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.criticals import LateralCritical, _envelope_peak

ZETA = 0.02


@pytest.mark.parametrize(("ratio", "peak"), [(0.9, False), (1.0 / np.sqrt(1 - 2 * ZETA**2), True), (1.1, False)])
def test_only_the_envelope_maximum_is_a_peak(ratio, peak):
    model = jeffcott(0.0, 2 * ZETA * M_DISK * WN)
    v, w = disk_dofs(model)
    loads = np.zeros((model.dofs.size, 1), complex)
    loads[v, 0], loads[w, 0] = 1e-4, -1e-4j  # forward imbalance u = 1e-4 kg m
    critical = LateralCritical(ratio * WN, 1.0 / (2 * ZETA), {})
    assert _envelope_peak(model, loads, critical) is peak

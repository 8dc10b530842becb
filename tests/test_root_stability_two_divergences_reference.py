"""Two divergent roots of different rates: the every-root check's least-damped root is the faster.

Reference (derived). The Jeffcott rotor of tests/rotors.py (a 20 kg disk on a near-massless
pinned-pinned tube, k = 48EI/L³) with, at the disk, an open-loop magnet (K_p = 0, negative
stiffness k_s = 3k in both planes) and a contact bearing of stiffness k_c = k in w only, as in
tests/test_single_divergence_reference.py but with a softer w bearing. No damping, no loss, no
polar inertia, so each plane is one mass:

* v: m s² + (k − k_s) = 0, s = √(2k/m): a divergence;
* w: m s² + (k − k_s + k_c) = 0, s = √(k/m): a slower one.

A divergence grows as e^{st}: the faster, s = √(2k/m), is the least stable root (ζ = −1 for
both). Tolerance 1e-4 relative: the tube's mass (7e-6 of the disk's) leaves ~1e-6 on these
roots (tests/test_single_divergence_reference.py). Four tube elements: about 0.05 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.root_stability import root_stability

FAST, SLOW = np.sqrt(2 * K_SHAFT / M_DISK), np.sqrt(K_SHAFT / M_DISK)


def test_the_least_damped_of_two_divergences_is_the_faster():
    magnet = f'kind = "active"\nkp = 0.0\nks = {3 * K_SHAFT}\nki = 100.0'
    w_only = f'\n[[bearings]]\nname = "c"\nx = 0.5\nkind = "contact"\nstiffness = {{ w = {K_SHAFT} }}'
    result = root_stability(model_with(magnet + w_only + "\ndamping = {}"), [0.0, 100.0])
    assert result.least_damped == pytest.approx([FAST, FAST], rel=1e-4)
    for speed in (0.0, 100.0):
        rates = sorted(r.root.real for r in result.unstable if r.speed == speed and r.kind == "divergence")
        assert rates == pytest.approx([SLOW, FAST], rel=1e-4)

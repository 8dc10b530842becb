"""Two divergent roots of different rates: the whirl stability reports the faster (mutation hunt
h37c).

Reference (derived), the rotor of tests/test_root_stability_two_divergences_reference.py: the
Jeffcott rotor of tests/rotors.py (a 20 kg disk on a near-massless pinned-pinned tube,
k = 48EI/L³) with, at the disk, an open-loop magnet (K_p = 0, negative stiffness k_s = 3k in both
planes; its ``ki`` = 100 N/A is the current gain, no integrator: no controller states) and a
contact bearing of stiffness k_c = k in w only. No damping, no loss, no polar
inertia, so each plane is one mass:

* v: m s² + (k − k_s) = 0, s = √(2k/m): a divergence;
* w: m s² + (k − k_s + k_c) = 0, s = √(k/m): a slower one.

A divergence grows as e^{st}; :class:`StabilityResult`'s ``divergence`` is "the largest real
root" at each speed (the growth that decides), so √(2k/m) at rest and at 100 rad/s (no
gyroscopic term couples the planes). The onset is a divergence at the first speed. Tolerance
1e-4 relative: the tube's mass (7e-6 of the disk's) leaves ~1e-6 on these roots.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.stability import stability

FAST = np.sqrt(2 * K_SHAFT / M_DISK)


def test_the_reported_divergence_is_the_faster_of_two():
    magnet = f'kind = "active"\nkp = 0.0\nks = {3 * K_SHAFT}\nki = 100.0'
    w_only = f'\n[[bearings]]\nname = "c"\nx = 0.5\nkind = "contact"\nstiffness = {{ w = {K_SHAFT} }}'
    result = stability(model_with(magnet + w_only + "\ndamping = {}"), [0.0, 100.0], n_modes=2)
    assert result.divergence == pytest.approx([FAST, FAST], rel=1e-4)
    assert result.onset_kind == "divergence" and result.onset_speed == 0.0

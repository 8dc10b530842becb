"""The two planes of a Jeffcott rotor on an anisotropic bearing, and the modes nearest a
frequency.

Reference (derived here): the Jeffcott rotor of tests/jeffcott_bearing.py (disk mass m on a
near-massless tube of stiffness k) with an undamped contact bearing at the disk, stiffness k_v
in v and k_w in w. At rest the planes decouple into single masses:
ω_v = √((k + k_v)/m) and ω_w = √((k + k_w)/m), two planar modes, the v plane first for
k_v < k_w. ``Modes.nearest(f, n)`` returns the indices of the n modes nearest f (its
docstring): with two modes, both for any f; with one, the plane whose frequency is nearer f.
The order of the returned indices is not a documented result and is not asserted.

Tolerance: the tube's mass (3.5e-6 of the disk's) shifts the frequencies by ~1e-6 relative;
1e-4 asserted, far below the 8 % separation of the planes.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.modal import modes

KV, KW = 4.0e5, 8.0e5  # N/m


def test_anisotropic_planes_and_the_nearest_modes():
    m = modes(model_with(f'kind = "contact"\nstiffness = {{ v = {KV}, w = {KW} }}\ndamping = {{}}'), 0.0, n_modes=2)
    wv, ww = np.sqrt((K_SHAFT + KV) / M_DISK), np.sqrt((K_SHAFT + KW) / M_DISK)
    assert 2 * np.pi * m.frequencies == pytest.approx([wv, ww], rel=1e-4)
    assert list(m.whirl) == ["planar", "planar"]
    fw = ww / (2 * np.pi)
    assert sorted(m.nearest(10 * fw, 2)) == [0, 1]
    assert list(m.nearest(0.0, 1)) == [0] and list(m.nearest(10 * fw, 1)) == [1]

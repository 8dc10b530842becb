"""A single divergent root of the Jeffcott rotor (one plane diverges, the other vibrates), derived here.

The Jeffcott rotor of tests/rotors.py (a 20 kg disk on a near-massless pinned-pinned tube, k =
48EI/L³) with, at the disk, an open-loop magnet (K_p = 0, negative stiffness k_s = 3k, acting in
both planes) and a contact bearing of stiffness k_c = 3k in w only. No damping, no loss, no polar
inertia (no gyroscopic coupling), so each plane is one mass:

* v: m s² + (k − k_s) = 0, s = ±√((k_s − k)/m) = ±√(2k/m): one divergence (real s > 0, ζ = −1);
* w: m s² + (k − k_s + k_c) = 0, s = ±i√(k/m) = ±iω_n: a neutral vibration.

So the two lowest damped modes are exactly one divergence (returned first, Im s = 0) and the
w vibration at ω_n, at every speed; and the every-root check's least-damped root is the
divergence, ζ = −1 (a real root s > 0 grows without oscillating).

Tolerance 1e-4 relative: the tube's mass (3.5e-6 of the disk's: 0.1 kg/m³ × π(D_o² − D_i²)/4
× 1 m = 7.1e-5 kg) leaves ~1e-6 on these roots (asserted at 1e-4 in
tests/test_jeffcott_modes_closed_form.py for the same rotor). Four tube elements
(tests/jeffcott_bearing.py): the planes' equations are exact at any mesh. About 0.05 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK, WN

from flexshaft.analyses.modal import modes
from flexshaft.analyses.root_stability import root_stability

RATE = np.sqrt(2 * K_SHAFT / M_DISK)  # √((k_s − k)/m)


@pytest.fixture(scope="module")
def model():
    magnet = f'kind = "active"\nkp = 0.0\nks = {3 * K_SHAFT}\nki = 100.0'
    w_only = f'\n[[bearings]]\nname = "c"\nx = 0.5\nkind = "contact"\nstiffness = {{ w = {3 * K_SHAFT} }}'
    w_only += "\ndamping = {}"
    return model_with(magnet + w_only)


@pytest.mark.parametrize("speed", [0.0, 100.0])
def test_the_lowest_modes_are_the_one_divergence_then_the_w_vibration(model, speed):
    m = modes(model, speed, n_modes=2)
    assert list(m.divergent) == [True, False]
    assert m.eigenvalues[0] == pytest.approx(RATE, rel=1e-4)
    assert m.eigenvalues[0].imag == 0.0
    assert m.eigenvalues[1] == pytest.approx(1j * WN, rel=1e-4)
    assert m.damping_ratios[0] == pytest.approx(-1.0, rel=1e-12)


def test_the_every_root_check_reports_the_divergence_as_least_damped_at_zeta_minus_one(model):
    result = root_stability(model, [0.0, 100.0])
    assert result.least_damped == pytest.approx([RATE, RATE], rel=1e-4)
    assert list(result.least_damping_ratio) == [-1.0, -1.0]
    divergences = [r for r in result.unstable if r.kind == "divergence"]
    assert [r.speed for r in divergences] == [0.0, 100.0]
    assert [r.root for r in divergences] == pytest.approx([RATE, RATE], rel=1e-4)
    assert all(r.damping_ratio == -1.0 for r in divergences)
    assert result.onset_speed == 0.0

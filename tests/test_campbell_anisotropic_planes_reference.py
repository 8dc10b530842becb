"""The Campbell diagram of a disk on two uncoupled bending planes: its modes numbered by damped
frequency, and ``damped=False`` without the dampers (mutation hunt h35a).

The rotor: tests/jeffcott_bearing.py's (a 20 kg disk at midspan of a near-massless
pinned-pinned tube, k = 48EI/L³, a point mass: no gyroscopic coupling) with a contact bearing at
the disk, stiff and damped in v (k_v = 2e6 N/m, c_v = 2·0.7·√((k + k_v) m): ζ = 0.7), softer and
undamped in w (k_w = 4e5 N/m). The planes stay uncoupled at every speed, each the disk's
m s² + c s + k_plane = 0 (derived):

    v: ω_n = √((k + k_v)/m) = 437.4 rad/s, s = −ζω_n + iω_n√(1 − ζ²) = −306.2 + 312.3i;
    w: s = i√((k + k_w)/m) = 333.6i.

By damped frequency Im s the v plane's mode comes first (312 < 334 rad/s), by |s| the w
plane's (334 < 437): ``track_modes`` numbers the first speed's modes by damped frequency, as
``modes()`` numbers them ("column k is mode k + 1 of its tables"). With ``damped=False`` the
dampers go (``campbell``'s docstring: ``damped`` includes the bearing dampers), so the v plane's
root is iω_n = 437.4i with Re s = 0.

Tolerance 1e-5 relative (the tube's 3.5e-6 share of the disk's mass; measured 1e-6). Three speeds,
two modes: about 0.03 s of CPU.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.modal import modes

KV, KW, ZETA = 2.0e6, 4.0e5, 0.7
CV = 2 * ZETA * np.sqrt((K_SHAFT + KV) * M_DISK)
SPEEDS = [0.0, 50.0, 100.0]
WV, WW = np.sqrt((K_SHAFT + KV) / M_DISK), np.sqrt((K_SHAFT + KW) / M_DISK)


@pytest.fixture(scope="module")
def model():
    return model_with(f'kind = "contact"\nstiffness = {{ v = {KV}, w = {KW} }}\ndamping = {{ v = {CV}, w = 0.0 }}')


def test_modes_are_numbered_by_damped_frequency(model):
    sv = complex(-ZETA * WV, WV * np.sqrt(1 - ZETA**2))
    assert sv.imag < WW < abs(sv)  # the orders by Im s and by |s| differ
    c = campbell(model, SPEEDS, n_modes=2)
    assert c.eigenvalues[:, 0] == pytest.approx(np.full(3, sv), rel=1e-5)
    assert c.eigenvalues[:, 1].imag == pytest.approx(np.full(3, WW), rel=1e-5)
    assert np.abs(c.eigenvalues[:, 1].real).max() <= 1e-9 * WW
    assert modes(model, 0.0, n_modes=2).eigenvalues == pytest.approx([sv, 1j * WW], rel=1e-5, abs=1e-9 * WW)


def test_the_undamped_diagram_has_no_dampers(model):
    c = campbell(model, SPEEDS, n_modes=2, damped=False)
    assert c.eigenvalues.imag == pytest.approx(np.tile([WW, WV], (3, 1)), rel=1e-5)
    assert np.abs(c.eigenvalues.real).max() <= 1e-9 * WV

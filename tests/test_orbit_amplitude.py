"""The orbit amplitude the requirements use: the largest excursion of an elliptical orbit.

References (derived here):

* an orbit (v, w) = (Re(a e^{iφ}), Re(b e^{iφ})) is an ellipse; its major semi-axis is the
  largest √(v² + w²) over φ, found here by brute force on 20 000 phases (the maximum of a
  smooth periodic function sampled that finely is within 1.3e-8 relative of the true one);
* a circular orbit (b = −ia, forward) has radius |a|; a planar one (b = 0) has |a|;
* the synchronous response of the Jeffcott rotor (tests/rotors.py) to an imbalance U at the
  disk is a forward circle of radius U Ω² / |k − mΩ² + icΩ|.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.reactions import worst_case_orbits
from flexshaft.analyses.response import imbalance_response, orbit_amplitude


def brute_force(a: complex, b: complex) -> float:
    phi = np.linspace(0.0, 2 * np.pi, 20000, endpoint=False)
    e = np.exp(1j * phi)
    return float(np.sqrt((a * e).real ** 2 + (b * e).real ** 2).max())


def test_major_semi_axis_of_random_ellipses():
    rng = np.random.default_rng(23)
    a = rng.normal(size=40) + 1j * rng.normal(size=40)
    b = rng.normal(size=40) + 1j * rng.normal(size=40)
    got = orbit_amplitude(a, b)
    assert got == pytest.approx([brute_force(x, y) for x, y in zip(a, b)], rel=1e-7)


def test_circles_and_lines():
    a = 0.3 - 0.4j
    assert orbit_amplitude(a, -1j * a) == pytest.approx(0.5, rel=1e-14)  # forward circle
    assert orbit_amplitude(a, 1j * a) == pytest.approx(0.5, rel=1e-14)  # backward circle
    assert orbit_amplitude(a, 0.0) == pytest.approx(0.5, rel=1e-14)  # planar along y
    assert orbit_amplitude(0.0, a) == pytest.approx(0.5, rel=1e-14)  # planar along z


def test_jeffcott_imbalance_orbit_is_the_closed_form_circle():
    c = 0.05 * 2 * np.sqrt(K_SHAFT * M_DISK)
    model = jeffcott(0.0, c)
    v, w = disk_dofs(model)
    U = 1e-4  # kg m
    Q1 = np.zeros(model.dofs.size, complex)
    Q1[v], Q1[w] = U, -1j * U  # forward rotating load U Ω² e^{iΩt}
    speeds = np.array([0.5, 0.95, 1.0, 1.3]) * WN
    q = np.asarray(imbalance_response(model, speeds, Q1))
    q = q.reshape(model.dofs.size, -1)
    expected = U * speeds**2 / np.abs(K_SHAFT - M_DISK * speeds**2 + 1j * c * speeds)
    # tube mass 7e-6 of the disk: ~1e-5 at resonance (ζ = 0.05 amplifies it 10x); 1e-4 asserted
    assert orbit_amplitude(q[v], q[w]) == pytest.approx(expected, rel=1e-4)
    amp, _ = worst_case_orbits(model, q[:, None, :])
    node = model.dofs.node_at("shaft", 0.5)
    assert amp[node, 0] == pytest.approx(expected, rel=1e-4)

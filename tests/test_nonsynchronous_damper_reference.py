"""Non-synchronous harmonic response of the damped Jeffcott rotor (the banded solver), derived here.

The Jeffcott rotor of tests/rotors.py (a 20 kg disk on a near-massless pinned-pinned tube,
k = 48EI/L³) with an external dashpot c at the disk (ζ = c/(2√(km)) = 0.2), no material loss and
no polar inertia (no gyroscopic term): each plane is one mass, so a force F e^{iωt} in v at the
disk gives

    v = F / (k − m ω² + i ω c),    w = 0,

at any spin speed Ω: the dashpot's force is i ω c v at the excitation frequency ω, whatever the
spin (a load at ω ≠ Ω: a base excitation, a magnet's test signal, a receptance). Checked at
ω = 0.5 ω_n and 1.3 ω_n with Ω = 0.3 ω_n and at rest (the damping term is 20 % and 40 % of the
dynamic stiffness there: the same damper at Ω instead of ω changes |v| by 3-40 %).

Tolerance 1e-4 relative: the tube's mass (7e-6 of the disk's) changes the disk's effective mass by
about that fraction, amplified by k/|k − mω² + iωc| ≤ 1.6 at these frequencies; its polar
inertia couples w to v by less than that (w below 1e-6 of v asserted). Eight elements:
the stiffness condenses exactly onto the disk at any mesh. About 0.02 s of CPU.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.response import frequency_response

ZETA = 0.2
C = 2 * ZETA * np.sqrt(K_SHAFT * M_DISK)


@pytest.mark.parametrize("speed", [0.0, 0.3 * WN])
def test_disk_response_to_a_nonsynchronous_force_is_the_damped_oscillators(speed):
    model = jeffcott(0.0, C)
    v, w = disk_dofs(model)
    loads = np.zeros(model.dofs.size, complex)
    loads[v] = 1.0
    omegas = np.array([0.5, 1.3]) * WN
    q = np.asarray(frequency_response(model, loads, omegas, speed=speed))
    expected = 1.0 / (K_SHAFT - M_DISK * omegas**2 + 1j * omegas * C)
    assert q[v] == pytest.approx(expected, rel=1e-4)
    assert np.all(np.abs(q[w]) <= 1e-6 * np.abs(expected))  # the tube's own gyroscopic coupling

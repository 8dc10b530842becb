"""Loss of the stationary-frame strains (matrix F) is met at the excitation frequency ω.

docs/model.md, "One damping physics": the loss matrix ``F`` holds the tailboom's and "the
shaft's axial and torsional strains", and the loss is ``L(ω, Ω) = i sgn(ω) F + …`` — its
weight depends on ω alone, never on the whirl sign σ = sgn(ω − Ω) that the shaft's lateral
loss uses. Physically (derived here): an axial strain of the axisymmetric shaft is the same
in the fixed and in the rotating frame, so spinning the shaft does not change the frequency at
which its material is cycled.

Reference (derived here): the Jeffcott-like rotor of tests/rotors.py has its axial motion held
at x = 0 and free at x = L, so axially the midspan disk (mass m) sits on the first half of the
tube alone, a spring k_a = E A/(L/2), A = π(D_o² − D_i²)/4; the second half carries no axial
load. With the hysteretic loss η the axial receptance at the disk is

    u/f = 1 / (k_a (1 + iη) − m ω²)     at every spin speed Ω,

including ω < Ω (where the lateral loss changes sign) and ω = Ω (where the lateral forward
loss vanishes). A wrong weight sgn(ω − Ω) on F flips Im(u/f) below the spin speed (a passive
axial spring would then feed energy in) and drops it on the synchronous line.

Tolerance: the tube's own axial mass (3.5e-6 of the disk's) shifts m ω² by that fraction,
amplified by 1/|1 − ω²/ω_a² + iη| ≈ 5 at ω = 0.9 ω_a: about 2e-5 relative (measured 1.0e-5),
so 1e-4 is asserted; the wrong weights change u/f by 2η/0.19 ≈ 20 % and η/0.19 ≈ 10 %.
"""

import numpy as np
import pytest
from rotors import DI, DO, M_DISK, E, L, jeffcott

from flexshaft.analyses import frequency_response

ETA = 0.02
K_AXIAL = E * np.pi * (DO**2 - DI**2) / 4 / (L / 2)
W_AXIAL = np.sqrt(K_AXIAL / M_DISK)


@pytest.mark.parametrize("speed_ratio", [0.0, 0.9, 1.5])
def test_axial_receptance_of_the_spinning_shaft_is_independent_of_the_spin(speed_ratio):
    """Excitation at ω = 0.9 ω_a; spin at rest, synchronous with ω, and above ω (σ = −1)."""
    model = jeffcott(ETA, 0.0)
    u = model.dofs.shaft(model.dofs.node_at("shaft", L / 2), "u")
    Q = np.zeros(model.dofs.size)
    Q[u] = 1.0
    omega = 0.9 * W_AXIAL
    got = frequency_response(model, Q, omega, speed=speed_ratio * W_AXIAL)[u]
    expected = 1.0 / (K_AXIAL * (1 + 1j * ETA) - M_DISK * omega**2)
    assert got == pytest.approx(expected, rel=1e-4)
    assert got.imag < 0  # a passive hysteretic spring absorbs power at every spin speed

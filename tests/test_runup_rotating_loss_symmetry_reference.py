"""The run-up's rotating-frame loss damps through a symmetric matrix between modes of different
frequencies (flexshaft.analyses.envelope.EnvelopeSystem.matrix).

Reference, derived here (Rayleigh's dissipation function): the velocity forces of a linear
system split into a dissipative part −C v with C = Cᵀ (the forces of the dissipation function
½ vᵀ C v, whose power −vᵀ C v is the energy lost) and a workless gyroscopic part −Ω G v with
G = −Gᵀ. The shaft's hysteretic loss η K_lat, made viscous at each mode's reference frequency
ω_j + Ω (the module docstring), enters the modal velocity block as
D^{-1/2} Φᵀ K_lat Φ D^{-1/2}, D = diag(ω_j + Ω): a congruence of a symmetric matrix, symmetric
whatever the frequencies. So the velocity block of J(Ω) less its gyroscopic part Ω G̃ and the
frame rotation −iΩ I must be real and symmetric. Scaling a coupling term L_ij by the row's
mode alone, L_ij/(ω_i + Ω), breaks this as soon as two coupled modes differ in frequency, and
gives the loss a spurious workless (gyroscopic-like) part that shifts the whirl.

Rotor: the Jeffcott tube of tests/rotors.py made a real steel tube (7800 kg/m³, so its second
bending mode, 3404 rad/s, joins the disk's 393 rad/s), with η = 0.05 rotating-frame loss and a
3e6 N/m support at 0.3 L; then Φᵀ K_lat Φ couples the two frequencies (|L_14| ≈ 0.02 |L_44|:
K_lat is the shaft's alone, Φ diagonalises shaft plus support). Tolerance 1e-10 relative to
the block's largest entry: the block is built by elementwise products of exactly symmetric
factors and a projection Φᵀ K Φ symmetric to round-off (measured 4e-15); a row-scaled loss is
asymmetric by 0.1 to 0.17 here. Well under 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import jeffcott_text

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.envelope import EnvelopeSystem
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


@pytest.fixture(scope="module")
def system():
    text = (
        jeffcott_text(0.05, 0.0)
        .replace("density = 0.1", "density = 7800.0")
        .replace("x = 0.5\nstiffness = {}", "x = 0.3\nstiffness = { v = 3e6, w = 3e6 }")
    )
    assert "x = 0.3" in text and "density = 7800.0" in text
    model = build_model(loads_design(text))
    red = reduce(model, 4)
    omega = np.sqrt(red.w2)
    assert omega.max() > 5 * omega.min()  # the premise: two bending frequencies, far apart
    coupled = np.abs(red.L - np.diag(np.diag(red.L)))
    assert coupled.max() > 1e-3 * np.abs(red.L).max()  # the premise: the loss couples them
    return EnvelopeSystem(model, red, np.zeros(model.dofs.size), 300.0)


@pytest.mark.parametrize("speed", [0.0, 100.0, 300.0])
def test_the_dissipative_velocity_block_is_real_and_symmetric(system, speed):
    nb = system.nb
    block = system.matrix(speed)[nb : 2 * nb, nb : 2 * nb] + 1j * speed * np.eye(nb) - speed * system.gyroscopic
    scale = np.abs(block).max()
    assert np.abs(block.imag).max() <= 1e-10 * scale
    assert np.abs(block.real - block.real.T).max() <= 1e-10 * scale

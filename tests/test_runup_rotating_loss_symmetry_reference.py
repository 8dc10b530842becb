"""The run-up's rotating-frame loss damps through a symmetric matrix between modes of different
frequencies, and its circulatory stiffness is skew (flexshaft.analyses.envelope.EnvelopeSystem.matrix).

Reference, derived here (Rayleigh's dissipation function): the velocity forces of a passive
rotor without actuators or bearing damping (this one) split into a dissipative part −C v with
C = Cᵀ (the forces of the dissipation function ½ vᵀ C v, whose power −vᵀ C v is the energy
lost) and a workless gyroscopic part −Ω G v with G = −Gᵀ. The shaft's hysteretic loss η K_lat,
made viscous at each mode's reference frequency ω_j + Ω (docs/transient.md, "The causal loss
model": "scaled symmetrically in modal coordinates, D = W^{-1/2} K̃'' W^{-1/2}", W = ω_j + Ω
for the rotating-frame loss), enters the modal velocity block as
D^{-1/2} Φᵀ K_lat Φ D^{-1/2}, D = diag(ω_j + Ω): a congruence of a symmetric matrix, symmetric
whatever the frequencies. So the velocity block of J(Ω) less its gyroscopic part Ω G̃ and the
frame rotation −iΩ I must be real and symmetric. Scaling a coupling term L_ij by the row's
mode alone, L_ij/(ω_i + Ω), breaks this as soon as two coupled modes differ in frequency, and
gives the loss a spurious workless (gyroscopic-like) part. The effect on the response is small
(measured by the review on this rotor: its eigenvalues shift by about 1e-4 rad/s at 100 and
300 rad/s; on the baseline design with 12 modes the steady envelope changes by 3e-7 to 1.4e-6
relative and the eigenvalues by 7e-7 of |Re λ|), so the symmetry is what catches it.

The same loss seen from the fixed frame (docs/transient.md's table: D (ẏ + Ω S̃ y), Zorzi &
Nelson's rotating damping) adds the circulatory stiffness Ω D S̃ on the modal displacements,
derived here to be skew for an isotropic rotor: the viscous force of the spinning material is
−C_i times its velocity seen in the rotating frame, ẏ + Ω S y (S the −90° rotation of each
node's lateral pair, Sᵀ = −S); its displacement part −Ω C_i S is skew when C_i commutes with S,
(C_i S)ᵀ = Sᵀ C_i = −S C_i = −C_i S, which is what isotropy means (the same stiffness in both
lateral planes; this rotor's supports are v = w). Projection on the real modes (Φᵀ C_i S Φ) and
the symmetric scaling W^{-1/2} · W^{-1/2} (an elementwise product with the symmetric
d_i d_j) keep it skew; the row-scaled loss multiplies it by d_i² and does not. So
(J(Ω) − J(0))[nb:2nb, :nb], the speed-dependent part of the displacement columns of the
acceleration rows (state [y, v, controller]; the frame rotation −iΩ sits on the diagonal, the
gyroscopic term in the velocity block), is −Ω (d_i d_j) S̃_ij and must be skew-symmetric.

Rotor: the Jeffcott tube of tests/rotors.py made a real steel tube (7800 kg/m³, so its second
bending mode, 3404 rad/s, joins the disk's 393 rad/s), with η = 0.05 rotating-frame loss and a
3e6 N/m support at 0.3 L; then Φᵀ K_lat Φ couples the two frequencies (|L_14| ≈ 0.02 |L_44|:
K_lat is the shaft's alone, Φ diagonalises shaft plus support). Tolerance 1e-10 relative to
the block's largest entry: the blocks are built by elementwise products of exactly symmetric
factors and a projection Φᵀ K Φ (or Φᵀ K S Φ) symmetric (or skew) to round-off (measured 4e-15
and 4.5e-15); a row-scaled loss is asymmetric by 0.1 to 0.17 in the velocity block and not
skew by 0.098 to 0.14 in the displacement block. About 0.15 s (the fixture's setup, 0.13 s).
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
    """The velocity block of J(Ω) with Ω G̃ and −iΩ I taken out is the (negated) dissipative
    matrix: real and symmetric to round-off (1e-10 of its largest entry), at rest and at 100
    and 300 rad/s (Rayleigh's dissipation function, the module docstring)."""
    nb = system.nb
    block = system.matrix(speed)[nb : 2 * nb, nb : 2 * nb] + 1j * speed * np.eye(nb) - speed * system.gyroscopic
    scale = np.abs(block).max()
    assert np.abs(block.imag).max() <= 1e-10 * scale
    assert np.abs(block.real - block.real.T).max() <= 1e-10 * scale


@pytest.mark.parametrize("speed", [100.0, 300.0])
def test_the_circulatory_displacement_block_is_skew(system, speed):
    """The rotating loss's circulatory stiffness, (J(Ω) − J(0))[nb:2nb, :nb] = −Ω (d_i d_j) S̃_ij,
    is skew-symmetric for this isotropic rotor (derived in the module docstring):
    |D + Dᵀ| ≤ 1e-10 max|D|, and not zero (the premise: the loss acts)."""
    nb = system.nb
    block = (system.matrix(speed) - system.matrix(0.0))[nb : 2 * nb, :nb]
    scale = np.abs(block).max()
    assert scale > 0.0
    assert np.abs(block + block.T).max() <= 1e-10 * scale

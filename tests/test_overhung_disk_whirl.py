"""Gyroscopic whirl of an overhung disk on a massless cantilever shaft: forward and backward
frequencies against the closed form, with the whirl direction read from the mode shapes.

Reference (derived here; the classical overhung rotor, e.g. Genta, Dynamics of Rotating
Systems, ch. 4): a shaft clamped at x = 0 carries a rigid disk (m, I_d, I_p) at x = L. The tip
stiffness of the massless Euler-Bernoulli cantilever on (deflection, slope) is
EI/L³ [[12, −6L], [−6L, 4L²]]. Spinning at Ω > 0, the disk's gyroscopic moment acts on a
circular whirl of frequency ω > 0 as an extra tilt stiffness +I_p Ω ω when the whirl turns with
the spin (forward) and −I_p Ω ω against it (backward), so the whirl frequencies are the positive
roots of

    (k11 − m ω²)(k22 − I_d ω² ± I_p Ω ω) − k12² = 0      (+ forward, − backward).

The forward frequencies rise with Ω and the backward ones fall. The direction of each computed
mode is read here from the tip's complex amplitudes (V, W): a forward whirl e^{iωt} has
W = −iV (v = cos ωt, w = sin ωt turns from y to z, the sense of the spin about +x), so its
forward part (V + iW)/2 dominates its backward part (V − iW)/2.

The tube's mass is 1e-6 of the disk's (density 0.1 kg/m³, as tests/rotors.py): the frequencies
agree to a few 1e-6; 5e-5 is asserted. The gyroscopic split at Ω = 1000 rad/s is 30 %, so a sign
error or a disk scattered onto the wrong rotations cannot pass.
"""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.design import loads_design

E, G = 210e9, 80e9
DO, DI, L = 0.05, 0.04, 0.5
MASS, I_D, I_P = 20.0, 0.4, 0.8
EI = E * np.pi * (DO**4 - DI**4) / 64


def design_text(speed_rpm: float) -> str:
    return f"""
name = "overhung disk"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G}
density = 0.1
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "steel"
fixed_start = ["u", "v", "w", "theta", "beta", "gamma"]
[[bearings]]
name = "unloaded"
kind = "contact"
x = 0.0
stiffness = {{}}
[[disks]]
name = "disk"
x = {L}
mass = {MASS}
diametral_inertia = {I_D}
polar_inertia = {I_P}
[operating]
speed_rpm = {speed_rpm}
power = 0.0
[mesh]
shaft_elements = 4
"""


def closed_form(speed: float, sense: int) -> np.ndarray:
    """Positive roots ω of (k11 − mω²)(k22 − I_d ω² + sense I_p Ω ω) − k12² = 0 (sense ±1)."""
    k11, k12, k22 = 12 * EI / L**3, -6 * EI / L**2, 4 * EI / L
    a = np.polynomial.Polynomial([k11, 0.0, -MASS])
    b = np.polynomial.Polynomial([k22, sense * I_P * speed, -I_D])
    roots = (a * b - k12**2).roots()
    roots = roots[np.abs(roots.imag) < 1e-9 * np.abs(roots)].real
    return np.sort(roots[roots > 0])


def whirl_of_modes(speed: float):
    """(frequencies [rad/s], forward flags) of the four lowest lateral modes at ``speed``."""
    model = fs.build_model(loads_design(design_text(speed * 60 / (2 * np.pi))))
    m = fs.modes(model, speed=speed, n_modes=8, damped=False)
    lateral = np.flatnonzero(m.kind == "lateral")[:4]  # the disk's torsion (269 rad/s) is not a whirl
    tip = model.dofs.node_at("shaft", L)
    V, W = m.shapes[model.dofs.shaft(tip, "v"), lateral], m.shapes[model.dofs.shaft(tip, "w"), lateral]
    forward = np.abs(V + 1j * W) > np.abs(V - 1j * W)
    return np.abs(m.eigenvalues[lateral].imag), forward


@pytest.mark.parametrize("speed", [0.0, 400.0, 1000.0])
def test_forward_and_backward_whirl_of_the_overhung_disk(speed):
    freqs, forward = whirl_of_modes(speed)
    fwd_ref, bwd_ref = closed_form(speed, +1), closed_form(speed, -1)
    if speed == 0.0:  # planar pairs: compare the frequencies only
        assert np.sort(freqs) == pytest.approx(np.repeat(fwd_ref, 2), rel=5e-5)
        return
    assert forward.sum() == 2, (freqs, forward)
    assert np.sort(freqs[forward]) == pytest.approx(fwd_ref, rel=5e-5)
    assert np.sort(freqs[~forward]) == pytest.approx(bwd_ref, rel=5e-5)


def test_forward_whirl_rises_and_backward_falls_with_speed():
    f0 = closed_form(0.0, +1)
    fwd, bwd = closed_form(1000.0, +1), closed_form(1000.0, -1)
    assert np.all(fwd > f0) and np.all(bwd < f0)
    # the split is large here, so the test above discriminates the sense
    assert fwd[1] / bwd[1] > 1.3

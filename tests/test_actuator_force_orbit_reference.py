"""Force amplitude of a non-collocated magnetic bearing at a whirl frequency: the major semi-axis
of its force orbit from the linearised magnet (derived here).

The Jeffcott rotor of tests/jeffcott_bearing.py with its active bearing's magnet at the disk and
its sensor 0.125 m further on. The linearised magnet (its
definition in docs/magnetic-bearings.md: f = k_s x + k_i i) with the ideal PD law i = −(k_p + k_d s) d_s pulls the shaft
with f = k_s d_a − k_i (k_p + k_d s) d_s at s = iω, so the bearing carries, per axis (v, w),

    F = k_i (k_p + i ω k_d) d_s − k_s d_a            (complex amplitudes at the magnet, sensor).

The carried force turns on the orbit (Re(F_v e^{iφ}), Re(F_w e^{iφ})); its amplitude is the
largest |·| over φ, here by brute force over 20 001 phases and by the ellipse's major semi-axis
√((|F_v|² + |F_w|² + |F_v² + F_w²|)/2). For a circular (forward) orbit, F_w = −i F_v, that is
|F_v|, not √(|F_v|² + |F_w|²) = √2 |F_v|. The motion taken is the rotor's unbalance response at
200 rad/s (circular: the rotor is axisymmetric) and the same with its w components scaled by
0.3 (an ellipse).

Tolerance: the closed form against the product, a few operations, relative 1e-12; the
phase sampling finds the maximum of a smooth function of φ to a relative (π/20 000)²/2 ≈ 1e-8.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import KD, KI, KP, KS, imbalance_vector, model_with

from flexshaft.analyses.reactions import actuator_response
from flexshaft.analyses.response import imbalance_response

OMEGA = 200.0  # rad/s


@pytest.fixture(scope="module")
def motions():
    model = model_with(f'kind = "active"\nkp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}\nsensor_offset = 0.125')
    q = np.asarray(imbalance_response(model, [OMEGA], imbalance_vector(model)))[:, 0]
    elliptic = q.copy()
    elliptic[model.dofs.shaft(np.arange(model.dofs.n_shaft_nodes), "w")] *= 0.3
    return model, q, elliptic


def _carried(model, q) -> np.ndarray:
    a = model.actuators[0]
    d_a, d_s = a.lateral_rows @ q, a.sensing_rows @ q
    return KI * (KP + 1j * OMEGA * KD) * d_s - KS * d_a


def _brute_force_amplitude(f: np.ndarray) -> float:
    phi = np.linspace(0.0, 2 * np.pi, 20001)
    turning = np.exp(1j * phi)
    return float(np.hypot((f[0] * turning).real, (f[1] * turning).real).max())


@pytest.mark.parametrize("shape", ["circular", "elliptic"])
def test_the_force_amplitude_is_the_major_semi_axis_of_the_force_orbit(motions, shape):
    model, circular, elliptic = motions
    q = circular if shape == "circular" else elliptic
    f = _carried(model, q)
    major = np.sqrt((abs(f[0]) ** 2 + abs(f[1]) ** 2 + abs(f[0] ** 2 + f[1] ** 2)) / 2)
    assert _brute_force_amplitude(f) == pytest.approx(major, rel=1e-8)
    if shape == "circular":
        assert abs(f[1]) == pytest.approx(abs(f[0]), rel=1e-9) and major == pytest.approx(abs(f[0]), rel=1e-9)
    _, force = actuator_response(model, q[:, None], np.array([OMEGA]))
    assert force[model.actuators[0].name] == pytest.approx([major], rel=1e-12)

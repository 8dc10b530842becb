"""A growing whirl mode has a negative damping ratio and a negative log decrement.

Reference (derived here): the Jeffcott rotor of tests/rotors.py (disk mass m, shaft stiffness k,
external dashpot c_e at the disk, rotating hysteretic loss factor η of the shaft). In the
stationary complex coordinate r = v + i w a whirl r = e^{st}, s = σ + iω, obeys
m s² + c_e s + k (1 + i η sgn(ω − Ω)) = 0. Above the critical speed (Ω = 1.2 ω_n) both whirls,
forward (ω = +ω_d) and backward (ω = −ω_d), have ω < Ω, so both are roots of the one quadratic
m s² + c_e s + k (1 − i η) = 0: the root with Im s > 0 is the forward whirl, the conjugate of the
root with Im s < 0 the backward one. With c_e = η k/(2 ω_n) the forward whirl grows
(σ ≈ +η ω_n/4) and the backward decays (σ ≈ −3η ω_n/4). ζ = −Re s/|s| and the logarithmic
decrement δ = 2πζ/√(1 − ζ²) (docs/requirements.md: "a damping ratio is checked as
δ = 2πζ/√(1 − ζ²)"), which keeps the sign of ζ: δ < 0 is a growing amplitude ratio
x_{n+1}/x_n = e^{−δ} > 1.

Tolerance: the tube's mass is 3.5e-6 of the disk's and the eigenvalues are refined to 1e-10;
the eigenvalues agree to 8.6e-7 relative (about ½ · 17/35 of the mass ratio), 1e-5 asserted
(12 times that); the measured agreement in δ is ~1e-6 relative, 1e-4 asserted (well above the
tube's mass and far below the sign change the test is about).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.modal import modes

ETA = 0.02


def _decrement(s: complex) -> float:
    zeta = -s.real / abs(s)
    return 2 * np.pi * zeta / np.sqrt(1 - zeta**2)


def test_the_growing_forward_whirl_has_a_negative_log_decrement():
    c_e = 0.5 * ETA * K_SHAFT / WN
    m = modes(jeffcott(ETA, c_e), 1.2 * WN, n_modes=2)
    roots = np.roots([M_DISK, c_e, K_SHAFT * (1 - 1j * ETA)])
    forward = roots[roots.imag > 0][0]
    backward = np.conj(roots[roots.imag < 0][0])
    assert forward.real > 0 > backward.real  # the closed form: forward grows, backward decays
    whirl = list(m.whirl)
    assert sorted(whirl) == ["backward", "forward"]
    f, b = whirl.index("forward"), whirl.index("backward")
    assert m.eigenvalues[f] == pytest.approx(forward, rel=1e-5)
    assert m.eigenvalues[b] == pytest.approx(backward, rel=1e-5)
    assert m.log_decrements[f] == pytest.approx(_decrement(forward), rel=1e-4)
    assert m.log_decrements[b] == pytest.approx(_decrement(backward), rel=1e-4)
    assert m.log_decrements[f] < 0 < m.log_decrements[b]
    rows = {r["whirl"]: r for r in m.table()}
    assert rows["forward"]["log_decrement"] == pytest.approx(_decrement(forward), rel=1e-4)
    assert rows["forward"]["damping_ratio"] == pytest.approx(-forward.real / abs(forward), rel=1e-4)

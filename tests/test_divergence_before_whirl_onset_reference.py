"""A divergence at rest is the onset even when a whirl mode turns unstable later
(mutation hunt 23c).

The rotor (derived here): the near-massless pinned-pinned tube of tests/rotors.py (L = 1 m,
EI from its diameters) with two 20 kg disks at L/4 and 3L/4 and a magnetic bearing at the first
disk whose negative stiffness k_s = 5e6 N/m exceeds its control stiffness k_i k_p = 5e5 N/m
(PD law, k_d = 1 A s/m: a damping k_i k_d = 100 N s/m). The tube's flexibility at the disks
(simply supported beam, unit load at a, deflection at x ≤ a: b x (L² − b² − x²)/(6 L EI),
b = L − a) is L³/(768 EI) [[9, 7], [7, 9]], whose inverse is 24 EI/L³ [[9, −7], [−7, 9]]. The
disks then obey

    M q̈ + C q̇ + K q = 0,   M = m I,   C = diag(k_i k_d, 0),
    K = 24 EI/L³ [[9, −7], [−7, 9]] + diag(k_i k_p − k_s, 0),

per lateral direction. det K < 0 (k_i k_p − k_s = −4.5e6 < −(256/3) EI/L³ = −3.2e6), so one
root is real and positive, s ≈ 199.4 1/s: a divergence at every speed (the loss-free state
matrix barely depends on the spin: the disks have no polar inertia, the tube almost none).
The other mode whirls at ω ≈ 798 rad/s; the tube's rotating hysteretic loss (η = 0.05,
about η ω/2 = 20 1/s of growth rate against the magnet's 0.8 1/s of damping) drives it
unstable once the spin exceeds it, so at 1200 rad/s it grows while at rest it decays.

The onset is the first instability: the divergence, at the first speed analysed (0 rad/s),
not the whirl onset near 800 rad/s. Tolerance on the divergence rate 1e-5 relative: the tube
carries 3.5e-6 of the disks' mass (measured 8e-7).
CPU: a three-speed stability run on 8 elements, about 0.05 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import DI, DO, M_DISK, E, jeffcott_text

from flexshaft.analyses.stability import stability
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KI, KP, KD, KS = 100.0, 5.0e3, 1.0, 5.0e6
SPEEDS = [0.0, 600.0, 1200.0]


def _model():
    text = jeffcott_text(0.05, 0.0)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    one = '[[disks]]\nname = "disk"\nx = 0.5\nmass = 20.0'
    assert one in tail
    two = '[[disks]]\nname = "d1"\nx = 0.25\nmass = 20.0\n[[disks]]\nname = "d2"\nx = 0.75\nmass = 20.0'
    bearing = f'[[bearings]]\nname = "b"\nx = 0.25\nkind = "active"\nkp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}\n'
    return build_model(loads_design(head + bearing + tail.replace(one, two)))


def _divergence_rate() -> float:
    EI = E * np.pi * (DO**4 - DI**4) / 64
    K = 24 * EI * np.array([[9.0, -7.0], [-7.0, 9.0]]) + np.diag([KI * KP - KS, 0.0])
    assert np.linalg.det(K) < 0
    C = np.diag([KI * KD, 0.0])
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-K / M_DISK, -C / M_DISK]])
    s = np.linalg.eigvals(A)
    return float(s[np.abs(s.imag) == 0].real.max())


def test_the_divergence_at_rest_is_the_onset_before_the_whirl_instability():
    result = stability(_model(), SPEEDS, n_modes=2)
    rate = _divergence_rate()
    assert rate == pytest.approx(199.43, rel=1e-4)
    np.testing.assert_allclose(result.divergence, rate, rtol=1e-5)
    # the whirl mode: stable at rest, unstable at 1200 rad/s (the loss above its frequency)
    growth = result.eigenvalues.real.max(axis=1)
    assert growth[0] < 0 < growth[-1]
    assert result.onset_kind == "divergence"
    assert result.onset_speed == 0.0 and result.unstable_mode is None

"""The whirl-stability's divergence with the viscous method at speed: the circulatory term of the
spinning shaft moves the real root (mutation hunt h43b).

The Jeffcott rotor of tests/rotors.py (a 20 kg disk on a near-massless pinned-pinned tube,
k = 48EI/L³, loss factor η = 0.1) with, at the disk, an open-loop magnet (K_p = 0, k_s = 3k, both
planes) and a contact bearing 3k in w only, as tests/test_single_divergence_reference.py. The
viscous method (thesis chapter 4; Zorzi & Nelson 1977) models the shaft's loss as the
rotating-frame damping c = ηk/ω_ref, in the fixed frame c in both planes plus the circulatory
stiffness ±Ωc coupling them. The disk's characteristic equation is then (derived)

    (m s² + c s + k − k_s) (m s² + c s + k − k_s + k_w) + (Ωc)² = 0,

the skew coupling giving +(Ωc)² for either sign. Its one real root s > 0 is the divergence
rate: 412.455 1/s at rest, 409.208 1/s at Ω = 3ω_n (ω_ref = ω_n given), 0.8 % apart; the
quartic is solved here by numpy.roots. Tolerance 1e-4 relative, as the single-divergence test on
this rotor: the tube's mass (3.5e-6 of the disk's: 0.1 kg/m³ × π(D_o² − D_i²)/4 × 1 m =
7.1e-5 kg) leaves ~1e-6 (measured 8e-7).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.stability import stability
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA = 0.1
KS, KW = 3 * K_SHAFT, 3 * K_SHAFT


def _model():
    text = jeffcott_text(ETA, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    bearings = (
        f'[[bearings]]\nname = "b"\nx = 0.5\nkind = "active"\nkp = 0.0\nks = {KS}\nki = 100.0\n\n'
        f'[[bearings]]\nname = "c"\nx = 0.5\nkind = "contact"\nstiffness = {{ w = {KW} }}\ndamping = {{}}\n\n'
    )
    return build_model(loads_design(head + bearings + tail))


def _rate(speed: float) -> float:
    c = ETA * K_SHAFT / WN
    kv = K_SHAFT - KS
    quartic = np.polyadd(np.polymul([M_DISK, c, kv], [M_DISK, c, kv + KW]), [(speed * c) ** 2])
    roots = np.roots(quartic)
    real = roots[(np.abs(roots.imag) < 1e-9 * np.abs(roots)) & (roots.real > 0)].real
    assert real.size == 1
    return float(real[0])


def test_the_viscous_divergence_rate_at_speed_carries_the_circulatory_term():
    speeds = np.array([0.0, 3.0]) * WN
    result = stability(_model(), speeds, n_modes=2, damping_model="viscous", reference_frequency=WN)
    expected = [_rate(s) for s in speeds]
    assert expected[1] < expected[0] * (1 - 5e-3)  # the premise: the term moves the root
    assert result.divergence == pytest.approx(expected, rel=1e-4)
    assert result.onset_kind == "divergence" and result.onset_speed == 0.0

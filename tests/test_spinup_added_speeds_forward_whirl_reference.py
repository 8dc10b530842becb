"""A speed added to a spin-up scan is solved under the same forward-turning imbalance as the scan,
on a Jeffcott rotor whose rotating loss tells forward from backward whirl (derived here).

The Jeffcott rotor of tests/rotors.py (a 20 kg disk at the middle of a near-massless
pinned-pinned tube, k = 48EI/L³) with a shaft loss factor η = 0.1 acting in the rotating frame
(``internal_damping = "rotating"``) and an external dashpot c_e = 2ζ√(km), ζ = 0.02, at the
disk. The design's imbalance, eccentricity e = 1e-5 m, the whole shaft as its one bay (a lone
damper makes no bearing span; "mid_bay"), is the force
e M Ω² at the disk (M the rotating mass: the disk and the tube, 0.1 kg/m³ × π(D_o² − D_i²)/4 × L)
turning with the shaft (docs: ``Q_v = F, Q_w = −iF``). In complex coordinates r = v + iw the
forward synchronous whirl does not cycle the material (it turns at ω − Ω = 0 in the rotating
frame; tests/test_damping.py, the rotating model), so the disk describes the circle

    r(Ω) = e M Ω² / |k − mΩ² + i c_e Ω|,

whereas a backward-turning force of the same size would meet k(1 + iη) (cycled at 2Ω): at
Ω = 0.995 ω_n that orbit is 3.4 times smaller. The tube deflects as a midspan-loaded beam, so
the largest shaft orbit is the disk's.

:func:`with_speeds` adds Ω = 0.995 ω_n, between two samples of a projected scan, as an assessment
adds a refined critical speed; the added sample must be r(Ω).

Tolerance 1e-3 relative: the tube's mass (3.5e-6 of the disk's) and its mesh (the stiffness
condenses exactly onto the disk) change the response by ~1e-5, which the resonance amplifies at
most 1/(2ζ) = 25 times (tests/test_damping.py holds 1e-3 at 0.99 ω_n on this rotor). Under
0.1 s of CPU (a 54-DOF model, a dozen solves).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import DI, DO, K_SHAFT, M_DISK, WN, L, jeffcott_text

from flexshaft.analyses.spinup_response import spinup_response, with_speeds
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA, ZETA, ECC = 0.1, 0.02, 1e-5
C_E = 2 * ZETA * np.sqrt(K_SHAFT * M_DISK)
M_ROTATING = M_DISK + 0.1 * np.pi * (DO**2 - DI**2) / 4 * L


def test_added_speed_sees_the_forward_imbalance():
    text = jeffcott_text(ETA, C_E).replace("speed_rpm = 0.0", f"speed_rpm = {1.5 * WN * 30 / np.pi}")
    model = build_model(loads_design(f'{text}[loads]\neccentricity = {ECC}\nimbalance_placement = "mid_bay"\n'))
    scan = spinup_response(model, np.linspace(0.2, 1.2, 41) * model.speed)
    assert scan.basis is not None  # a projected scan (41 speeds: 0.995 ω_n between 0.975 and 1.0125 ω_n)
    speed = 0.995 * WN
    assert not np.isin(speed, scan.speeds)
    added = with_speeds(model, scan, [speed])
    k = int(np.flatnonzero(added.speeds == speed)[0])
    forward = ECC * M_ROTATING * speed**2 / abs(K_SHAFT - M_DISK * speed**2 + 1j * C_E * speed)
    backward = ECC * M_ROTATING * speed**2 / abs(K_SHAFT * (1 + 1j * ETA) - M_DISK * speed**2 + 1j * C_E * speed)
    assert forward > 3 * backward  # the test tells the two whirl directions apart
    assert added.shaft_peak[k] == pytest.approx(forward, rel=1e-3)

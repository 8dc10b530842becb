"""A long dwell of a damped rotor is integrated, not refused, and settles on the Jeffcott response.

A run that holds one speed is refused before integrating only when a free whirl would grow more
than MAX_GROWTH-fold there (``∫ max(0, growth rate) dt``, :mod:`flexshaft.analyses.transient`): a
decaying whirl is no growth, however long the dwell. The rotor of tests/rotors.py (a 20 kg disk
at the middle of a pinned-pinned tube of 7e-6 of its mass, k = 48 E I / L³) with an external
dashpot c_e at the disk and no loss: in complex coordinates r = v + i w it obeys
m r̈ + c_e ṙ + k r = U (Ω² − iΩ̇) e^{iφ} (Jeffcott; e.g. Friswell et al., Dynamics of Rotating
Machines, §3.6). Both whirls decay at c_e/(2m) = 15 1/s here, so over the 1 s dwell a free whirl
shrinks e^{-15}-fold (a rate counted by its size would be refused as e^{15} > MAX_GROWTH = e^{6.9}).

Started from rest at Ω = 100 rad/s, the transient has died out by the end (e^{-15} = 3e-7), and
the disk's orbit radius is the steady forward circular whirl

    |r| = U Ω² / |k − m Ω² + i c_e Ω|   (closed form).

Tolerance 1e-4: the tube's mass (7e-6 of the disk's) and the neglected decay (3e-7) are far
below it; rtol = 1e-7 holds the integration error near 1e-7. At t = 0 the run is at rest: its
orbit there is only the static correction of the modes left out of the two-mode basis (below
1e-9 of the steady orbit: the tube is light and stiff). CPU: one two-mode run of 21 output samples, about 0.05 s.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, L, jeffcott_text

from flexshaft.analyses.transient import SpeedProfile, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

U = 1e-4  # kg m
SPEED = 100.0  # rad/s, a third of the critical sqrt(k/m) = 302 rad/s
C_E = 600.0  # N s/m: decay c_e/(2m) = 15 1/s
DWELL = 1.0  # s


def test_a_long_dwell_of_a_damped_rotor_settles_on_the_steady_jeffcott_orbit():
    model = build_model(loads_design(jeffcott_text(0.0, C_E)))
    dm = model.dofs
    node = dm.node_at("shaft", L / 2)
    q1 = np.zeros(dm.size, complex)
    q1[dm.shaft(node, "v")], q1[dm.shaft(node, "w")] = U, -1j * U  # forward rotating imbalance at the disk
    assert C_E / (2 * M_DISK) * DWELL > math.log(1e3)  # a decay counted as growth would be refused
    run = transient_response(
        model,
        SpeedProfile.table([0.0, DWELL], [SPEED, SPEED]),
        loads_per_speed_squared=q1,
        basis_size=2,
        rtol=1e-7,
        output_step=0.05,
        initial="rest",
    )
    orbit = run.shaft_orbit[node]
    steady = U * SPEED**2 / abs(K_SHAFT - M_DISK * SPEED**2 + 1j * C_E * SPEED)
    assert orbit[0] <= 1e-9 * steady  # rest, but for the quasi-static part of the modes left out
    assert orbit[-1] == pytest.approx(steady, rel=1e-4)

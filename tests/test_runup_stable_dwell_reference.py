"""A long dwell of a damped rotor is integrated, not refused, and settles on the Jeffcott response.

A run that holds one speed is refused before integrating only when a free whirl would grow more
than MAX_GROWTH-fold there (``∫ max(0, growth rate) dt``, :mod:`flexshaft.analyses.transient`): a
decaying whirl is no growth, however long the dwell. The rotor of tests/rotors.py (a 20 kg disk
at the middle of a pinned-pinned tube, k = 48 E I / L³) with an external dashpot c_e at the disk
and no loss: in complex coordinates r = v + i w it obeys
m r̈ + c_e ṙ + k r = U (Ω² − iΩ̇) e^{iφ} (Jeffcott; e.g. Friswell et al., Dynamics of Rotating
Machines, §3.6). Both whirls decay at c_e/(2m) = 15 1/s here, so over a dwell of 1 s or more a
free whirl shrinks at least e^{-15}-fold (a rate counted by its size would be refused, as
e^{15} > MAX_GROWTH).

Started from rest at a constant Ω (so φ = Ω t), the transient has died out by the end and the
disk's whirl is the steady forward circular one (forward: from +y towards +z, docs/model.md),

    r = v + i w = U Ω² e^{iΩt} / (k − m Ω² + i c_e Ω)   (closed form),

asserted as a complex number at the last sample (a backward part, a wrong phase or a wrong
radius all miss it) and through the orbit envelope, its radius. Two cases: Ω = 100 rad/s, a
third of the critical sqrt(k/m) = 302 rad/s, for 1 s; and Ω = 280 rad/s for 1.5 s, near the
critical, where c_e Ω is 0.66 of |k − mΩ²| and a 7 % error in c_e moves |r| by 2 % (by 1e-4
only at 100 rad/s).

m is the disk's mass plus the tube's Rayleigh mass at midspan, 17/35 ρ A L (the kinetic energy
of the static deflection shape of a pinned-pinned beam under a midspan load, y ∝ 3ξ − 4ξ³ on
ξ = x/L ≤ 1/2: ∫ y² / y(1/2)² dx = 17/35 L); the tube is 3.5e-6 of the disk's mass, so without
it the reference errs by 2e-7 at 100 rad/s and 9e-6 at 280 rad/s. Tolerance 1e-6 (relative):
the integrator's rtol 1e-7, the transient left at the end (e^{-15} = 3e-7 of the start's at
100 rad/s, e^{-22.5} = 2e-10 at 280 rad/s), and the static correction of the modes left out of
the two-mode basis (below 1e-9). Measured: 3.0e-7 and 2.2e-8. At t = 0 the run is at rest:
its orbit there is only that static correction.
CPU: two two-mode runs of 21 and 31 output samples, about 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import DI, DO, K_SHAFT, M_DISK, L, jeffcott_text

from flexshaft.analyses.envelope import MAX_GROWTH
from flexshaft.analyses.transient import SpeedProfile, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

U = 1e-4  # kg m
C_E = 600.0  # N s/m: decay c_e/(2m) = 15 1/s
DENSITY = 0.1  # kg/m³, the tube's in jeffcott_text
M_EFFECTIVE = M_DISK + 17 / 35 * DENSITY * np.pi * (DO**2 - DI**2) / 4 * L


@pytest.mark.parametrize(("speed", "dwell"), [(100.0, 1.0), (280.0, 1.5)])
def test_a_long_dwell_of_a_damped_rotor_settles_on_the_steady_jeffcott_orbit(speed, dwell):
    text = jeffcott_text(0.0, C_E)
    assert f"density = {DENSITY}" in text
    model = build_model(loads_design(text))
    dm = model.dofs
    node = dm.node_at("shaft", L / 2)
    q1 = np.zeros(dm.size, complex)
    q1[dm.shaft(node, "v")], q1[dm.shaft(node, "w")] = U, -1j * U  # forward rotating imbalance at the disk
    assert C_E / (2 * M_DISK) * dwell > np.log(MAX_GROWTH)  # a decay counted as growth would be refused
    run = transient_response(
        model,
        SpeedProfile.table([0.0, dwell], [speed, speed]),
        loads_per_speed_squared=q1,
        basis_size=2,
        rtol=1e-7,
        output_step=0.05,
        initial="rest",
    )
    steady = U * speed**2 / (K_SHAFT - M_EFFECTIVE * speed**2 + 1j * C_E * speed)
    pos = np.full(dm.size, -1)
    pos[dm.free] = np.arange(dm.free.size)
    v, w = run.displacement(pos[[dm.shaft(node, "v"), dm.shaft(node, "w")]])
    r = (v[-1] + 1j * w[-1]) * np.exp(-1j * speed * run.time[-1])  # the whirl in the frame of φ = Ω t
    assert abs(r - steady) <= 1e-6 * abs(steady), r / steady
    orbit = run.shaft_orbit[node]
    assert orbit[0] <= 1e-9 * abs(steady)  # rest, but for the quasi-static part of the modes left out
    assert orbit[-1] == pytest.approx(abs(steady), rel=1e-6)

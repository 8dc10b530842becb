"""Which mode decides that a critical speed is an undamped resonance (AF infinite), against
the rigid rotor's closed forms (derived here).

A rigid tube (E = 2.1e15 Pa: its bending modes lie above 2e5 rad/s) of mass m_t and length
1 m with a 20 kg disk of diametral inertia 240 kg m² (no polar inertia: no gyroscopic term) at
its middle, on two springs k_b = 1e6 N/m at ±a = ±0.4 m from the middle, and a dashpot c at
the middle. The structure is symmetric about the middle, so the lateral modes separate:

* translation: ω_t = √(2k_b/M), M = m_t + 20 kg, damped by the dashpot, ζ = c/(2√(2k_b M));
* rocking (conical): ω_c = √(2k_b a²/I), I = 240 + m_t L²/12 + ρ I_A L (the tube's rotatory
  inertia), whose node is the middle: the dashpot does nothing to it, ζ = 0 exactly.

So at the speed ω_c the synchronous lateral mode is the undamped rocking one; at ω_t it is the
damped translation. ω_t ≈ 6 ω_c on purpose: a lookup that compared Im s in Hz with a speed in
rad/s would take the translation for the rocking mode.

Tolerances: the frequencies hold to the tube's flexibility (~1e-6 relative); 1e-4 asserted.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.criticals import _undamped_at
from flexshaft.analyses.modal import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KB, C, A_HALF, M_DISK, I_DISK, RHO = 1.0e6, 2000.0, 0.4, 20.0, 240.0, 7800.0
DO, DI = 0.1, 0.08
M_TUBE = RHO * math.pi / 4 * (DO**2 - DI**2)
I_TOTAL = I_DISK + M_TUBE / 12 + RHO * math.pi / 64 * (DO**4 - DI**4)
W_ROCK = math.sqrt(2 * KB * A_HALF**2 / I_TOTAL)
W_TRANS = math.sqrt(2 * KB / (M_TUBE + M_DISK))
ZETA_TRANS = C / (2 * math.sqrt(2 * KB * (M_TUBE + M_DISK)))

TEXT = f"""
name = "rigid rotor, dashpot at its middle"
[materials.stiff]
kind = "isotropic"
E = 2.1e15
G = 8e14
density = {RHO}
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "stiff"
fixed_start = ["u", "theta"]
[[bearings]]
name = "left"
kind = "contact"
x = {0.5 - A_HALF}
stiffness = {{ v = {KB}, w = {KB} }}
[[bearings]]
name = "right"
kind = "contact"
x = {0.5 + A_HALF}
stiffness = {{ v = {KB}, w = {KB} }}
[[bearings]]
name = "dashpot"
kind = "contact"
x = 0.5
stiffness = {{}}
damping = {{ v = {C}, w = {C} }}
[[disks]]
name = "disk"
x = 0.5
mass = {M_DISK}
diametral_inertia = {I_DISK}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 10
"""


def test_the_synchronous_mode_decides_an_undamped_resonance():
    model = build_model(loads_design(TEXT))
    m = modes(model, 0.0, n_modes=4)
    # the premise: the two pairs where the closed forms put them
    assert m.undamped_frequencies * 2 * np.pi == pytest.approx([W_ROCK] * 2 + [W_TRANS] * 2, rel=1e-4)
    assert np.abs(m.damping_ratios[:2]).max() < 1e-9
    assert m.damping_ratios[2:] == pytest.approx([ZETA_TRANS] * 2, rel=1e-4)
    assert W_TRANS / W_ROCK == pytest.approx(6.0, rel=0.01)
    assert _undamped_at(model, W_ROCK)
    assert not _undamped_at(model, W_TRANS)

"""The whirl-damping check holds every lateral mode below the onset requirement's speed, not only
the resolution's count of the lowest ones.

Was: the check held the ``modes`` lowest lateral modes at the operating speed (10 at every
resolution), which on the tuned design stop at 48.6 Hz of its 80 Hz: the forward whirl modes
between, slower than the spin, where the rotating damping destabilises them, were not held.
Now it holds, besides the count, every lateral mode below (1 + ``min_onset_margin``) × the
operating speed (:func:`flexshaft.verdict.point_tasks.required_onset_speed`).

Reference (closed form): a uniform steel tube pinned at both ends, no disk, no material loss, with
one isotropic dashpot at midspan (c = 250 N s/m). Its bending modes are ω_k = (kπ/L)² √(EI/ρA)
(Euler-Bernoulli; ω₁ = 331 rad/s, ω₂ = 4 ω₁), each a pair of whirls. The second pair's shape is
antisymmetric about midspan, where the dashpot sits, so the dashpot does no work on it: its
damping, so its log decrement, is exactly zero (the mesh is symmetric about the dashpot's node,
and the gyroscopic coupling is conservative). The first pair has ζ ≈ c/(2 ω₁ ρAL/2) ≈ 0.05
(δ ≈ 0.32, a pass). Spun at Ω = ω₂/1.1, the scope 1.15 Ω reaches past ω₂; with ``modes = 2`` the
count alone holds the first pair and passes, the check must hold the second and fail at δ = 0.
Tolerances: δ within 1e-4 of zero (the eigenvalues' 1e-6 relative accuracy makes at most
2π × 1e-6 of δ); the mode's frequency within 2 % of ω₂ (the tube's rotary inertia and the
gyroscopic split of the pair at this speed, about 1 %: enough to tell it from ω₁ = ω₂/4).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.design import loads_design
from flexshaft.units import rad_s_to_rpm

L, DO, DI = 1.5, 0.05, 0.03
E, G, RHO = 2.1e11, 8.1e10, 7850.0
AREA, INERTIA = np.pi * (DO**2 - DI**2) / 4, np.pi * (DO**4 - DI**4) / 64
OMEGA_1 = (np.pi / L) ** 2 * np.sqrt(E * INERTIA / (RHO * AREA))
OMEGA_2 = 4 * OMEGA_1
SPEED = OMEGA_2 / 1.1

TEXT = f"""
name = "Pinned-pinned tube with a dashpot at midspan"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G}
density = {RHO}
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "damper"
kind = "contact"
x = {L / 2}
stiffness = {{}}
damping = {{ v = 250.0, w = 250.0 }}
[operating]
speed_rpm = {rad_s_to_rpm(SPEED)}
power = 0.0
[mesh]
shaft_elements = 20
"""


def test_a_mode_below_the_onset_speed_is_held_beyond_the_count():
    design = loads_design(TEXT)
    assert design.requirements.min_onset_margin == 0.15 and OMEGA_2 < 1.15 * SPEED  # the case
    resolution = dataclasses.replace(fs.SCREENING, name="two modes", modes=2)
    check = fs.assess(design, resolution).verdict.check("whirl_damping")
    assert check.value == pytest.approx(0.0, abs=1e-4)
    assert not check.passed  # the first pair alone (about 0.32) passed
    assert check.location["frequency"] == pytest.approx(OMEGA_2, rel=2e-2)
    assert f"every one below {1.15 * SPEED / (2 * np.pi):.3g} Hz" in check.note

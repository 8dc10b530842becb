"""The whirl-damping check holds every lateral mode below the onset requirement's speed, not only
the resolution's count of the lowest ones.

Was: the check held the ``modes`` lowest lateral modes at the operating speed (10 at every
resolution), which on the tuned design stop at 48.6 Hz of its 80 Hz: the forward whirl modes
between, slower than the spin, where the rotating damping destabilises them, were not held.
Now it holds, besides the count, every lateral mode below (1 + ``min_onset_margin``) × the
operating speed (:func:`flexshaft.verdict.point_tasks.required_onset_speed`).

Reference (closed form): the pinned-pinned steel tube of tests/rotors.py at steel's density,
without its disk, with its dashpot at midspan (c = 250 N s/m) and no material loss. Its bending
modes are ω_k = (kπ/L)² √(EI/ρA) (Euler-Bernoulli; ω₁ = 817 rad/s, ω₂ = 4 ω₁), each a pair of
whirls. The second pair's shape is antisymmetric about midspan, where the dashpot sits, so the
dashpot does no work on it: its damping, so its log decrement, is exactly zero (the mesh is
symmetric about the dashpot's node, and the gyroscopic coupling is conservative). The first
pair has ζ ≈ c/(2 ω₁ ρAL/2) ≈ 0.055 (δ ≈ 0.35, a pass). Spun at Ω = ω₂/1.1, the scope 1.15 Ω
reaches past ω₂; with ``modes = 2`` the count alone holds the first pair and passes, the check
must hold the second and fail at δ = 0. Tolerances: δ within 1e-4 of zero (the eigenvalues'
1e-6 relative accuracy makes at most 2π × 1e-6 of δ); the mode's frequency within 2 % of ω₂
(the tube's rotary inertia, (2π r_g/L)² ≈ 1 %, and the gyroscopic split of the pair at this
speed: measured 1.4 % below; enough to tell it from ω₁ = ω₂/4).
"""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest
from rotors import DI, DO, E, L, jeffcott_text

import flexshaft as fs
from flexshaft.design import loads_design
from flexshaft.units import rad_s_to_rpm

RHO = 7850.0
AREA, INERTIA = np.pi * (DO**2 - DI**2) / 4, np.pi * (DO**4 - DI**4) / 64
OMEGA_1 = (np.pi / L) ** 2 * np.sqrt(E * INERTIA / (RHO * AREA))
OMEGA_2 = 4 * OMEGA_1
SPEED = OMEGA_2 / 1.1

# the Jeffcott rotor's file at steel's density, its disk dropped, spun at SPEED
TEXT = re.sub(
    r"\[\[disks\]\]\n(?:[^\[\n][^\n]*\n)*",
    "",
    jeffcott_text(0.0, 250.0, elements=20)
    .replace("density = 0.1", f"density = {RHO}")
    .replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(SPEED)}"),
)


def test_a_mode_below_the_onset_speed_is_held_beyond_the_count():
    design = loads_design(TEXT)
    assert "[[disks]]" not in TEXT and not design.disks  # the case: the tube alone,
    assert design.requirements.min_onset_margin == 0.15 and OMEGA_2 < 1.15 * SPEED  # its ω₂ in the scope
    resolution = dataclasses.replace(fs.SCREENING, name="two modes", modes=2)
    check = fs.assess(design, resolution).verdict.check("whirl_damping")
    assert check.value == pytest.approx(0.0, abs=1e-4)
    assert not check.passed  # the first pair alone (about 0.32) passed
    assert check.location["frequency"] == pytest.approx(OMEGA_2, rel=2e-2)
    assert f"every one below {1.15 * SPEED / (2 * np.pi):.3g} Hz" in check.note

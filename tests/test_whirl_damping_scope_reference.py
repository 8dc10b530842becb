"""The whirl-damping check states where its scope ends: the frequency of the highest lateral
whirl mode computed at the operating speed (the resolution's ``modes`` lowest ones).

Reference (closed form): the Jeffcott rotor of tests/rotors.py, its disk on a near-massless tube
(7e-6 of the disk's mass) with a light dashpot (ζ = 0.01) and no polar inertia: its two lowest
lateral modes are the disk's pair at ω_d = ω_n √(1 − ζ²), ω_n = √(k/m), whatever the speed (no
gyroscopic coupling); the tube's own modes lie decades above. With ``modes = 2`` the check holds
that pair and says so: "to ω_d/2π Hz" (three significant figures, far above the tube's 7e-6
share).
"""

from __future__ import annotations

import dataclasses

import numpy as np
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

import flexshaft as fs
from flexshaft.design import loads_design
from flexshaft.units import rad_s_to_rpm


def test_the_note_names_the_top_of_the_modes_held():
    zeta = 0.01
    text = jeffcott_text(0.0, 2 * zeta * np.sqrt(K_SHAFT * M_DISK))
    design = loads_design(text.replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(0.5 * WN)}"))
    resolution = dataclasses.replace(fs.SCREENING, name="two modes", modes=2)
    check = fs.assess(design, resolution).verdict.check("whirl_damping")
    top = WN * np.sqrt(1 - zeta**2) / (2 * np.pi)
    assert f"to {top:.3g} Hz" in check.note
    assert "none above is held" in check.note

"""A two-bladed tail rotor excites the driveline at 2/rev too (documented rule, closed form derived here).

docs/model.md (lines 350-353, hand-written) lists the excitations: "shaft 1/rev, tail rotor
1/rev and N/rev, main rotor 1…N/rev at `main_rotor_speed_rpm`, each a fixed multiple of Ω", with
"the gear ratio n = shaft speed / rotor speed" (line 331), so the tail rotor turns at Ω/n. For
N = 2 blades behind a gearbox of ratio n = 2.5 the excitation ratios to the shaft speed are
therefore exactly 1 (shaft 1/rev), 1/n = 0.4 and N/n = 0.8 (tail rotor 1/rev and 2/rev); no main
rotor is given.

The separation check is then set on a mode placed inside the 2/rev band. A near-massless steel
tube (k = G J_p/L = 1.350e5 N m/rad) between a disk J₁ = 0.3 kg m² and the tail rotor's reflected
inertia J₂ = J_tr/n² = 0.64 kg m² has the two-inertia frequency ω = √(k (J₁ + J₂)/(J₁ J₂)) =
813 rad/s, f = 129.4 Hz (as in tests/test_torsional.py, to 3e-7). Over shaft speeds
[900, 1100] rad/s the 2/rev band is 0.8 × [900, 1100]/2π = [114.6, 140.1] Hz, which holds f with
8 % to spare above and 13 % below (far beyond the 3e-7 of the closed form), so the mode's nearest
excitation is the tail rotor's 2/rev at margin 0, inside the band. The shaft's 1/rev band
[143.2, 175.1] Hz lies above it (margin 1 − 129.4/143.2 = 0.096) and the tail rotor's 1/rev
[57.3, 70.0] Hz below it.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import DO, G_STEEL, LENGTH, WALL, shaft_text

from flexshaft.analyses.torsional import torsional_excitations, torsional_modes, torsional_separation
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

J1, J_TR, N_GEAR = 0.3, 4.0, 2.5

TEXT = shaft_text(
    f'[[disks]]\nname = "hub"\nx = 0.0\nmass = 1.0\npolar_inertia = {J1}\n'
    f"[tail_rotor]\nblades = 2\npolar_inertia = {J_TR}\ngearbox_ratio = {N_GEAR}\n",
    '["u", "v", "w"]',
    elements=4,
    rpm=9550.0,
)


def test_a_two_bladed_tail_rotor_adds_its_2_per_rev():
    design = loads_design(TEXT)
    ratios = {e.name: e.ratio for e in torsional_excitations(design)}
    assert set(ratios) == {"shaft 1/rev", "tail rotor 1/rev", "tail rotor 2/rev"}
    assert ratios["shaft 1/rev"] == 1.0
    assert ratios["tail rotor 1/rev"] == pytest.approx(1 / N_GEAR, rel=1e-15)
    assert ratios["tail rotor 2/rev"] == pytest.approx(2 / N_GEAR, rel=1e-15)


def test_a_mode_inside_the_2_per_rev_band_has_no_margin():
    model = build_model(loads_design(TEXT))
    j_polar = np.pi * (DO**4 - (DO - 2 * WALL) ** 4) / 32
    k, j2 = G_STEEL * j_polar / LENGTH, J_TR / N_GEAR**2
    expected = np.sqrt(k * (J1 + j2) / (J1 * j2)) / (2 * np.pi)
    modes = torsional_modes(model)
    assert modes.natural_frequencies[1] == pytest.approx(expected, rel=3e-7)
    (first, *_) = torsional_separation(model, modes, speed_range=(900.0, 1100.0))
    assert first.natural_frequency == pytest.approx(expected, rel=3e-7)
    assert first.excitation == "tail rotor 2/rev" and first.order == 2
    assert first.margin == 0.0 and first.within_range and not first.passed
    band = tuple(2 / N_GEAR * w / (2 * np.pi) for w in (900.0, 1100.0))
    assert first.band == pytest.approx(band, rel=1e-14)

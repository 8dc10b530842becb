"""The whirl-stability map over the actuator gains when a magnetic bearing's negative stiffness
exceeds its control stiffness: an onset at 0 rad/s is an onset, not a stable point.

The rotor of tests/rotors.py (a 20 kg disk at mid-span of a near-massless pinned-pinned tube,
shaft stiffness k = 48EI/L³, viscous internal damping c_i = ηk/ω_ref) with two active bearings
at the disk, each of negative stiffness k_s and PD law C(s) = K_p + K_d s (k_i = 1 N/A). In
r = v + iw the disk obeys (derived here, as in tests/test_gain_stability_map_reference.py with
the magnet's −k_s added)

    m s² + (c_i + 2K_d) s + k + 2(K_p − k_s) − iΩ c_i = 0.

At rest (Ω = 0) the net stiffness k_net = k + 2(K_p − k_s) < 0 gives a real root
s = (−c + √(c² − 4m k_net))/(2m) > 0: an aperiodic instability (Earnshaw's theorem for the
uncontrolled magnet), which the stability analysis counts as an onset at the first divergent
speed (docs/magnetic-bearings.md: the stability analysis "counts the first divergent speed as
the onset"). On a grid starting at 0 rad/s the map's onset must be
0 rad/s exactly (the grid's first speed, no interpolation), where a stable point reads NaN.
With K_p above k_s − k/2 the same rotor is stable at rest and whirls from
Ω = ω(1 + 2K_d/c_i), ω² = k_net/m (the internal-damping threshold; tolerance 2e-5 as in the
reference file above: the tube's mass, 3.5e-6 of the disk's, is left out).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, L, jeffcott_text

from flexshaft.design import loads_design
from flexshaft.thesis.whirl import gain_stability_map

ETA = 0.02
C_I = ETA * K_SHAFT / WN
KS = K_SHAFT  # each magnet's negative stiffness [N/m]: k + 2(K_p − k_s) < 0 for K_p < k_s − k/2


def test_divergent_point_has_onset_zero_and_stable_point_the_whirl_threshold():
    amb = "\n".join(
        f'[[bearings]]\nname = "amb_{k}"\nkind = "active"\nx = {L / 2}\nkp = 1.0\nks = {KS!r}\n' for k in ("a", "b")
    )
    text = jeffcott_text(ETA, 0.0).replace("speed_rpm = 0.0", f"speed_rpm = {float(WN * 30 / np.pi)!r}")
    kp_low = 0.1 * K_SHAFT  # k_net = k + 2(0.1k − k) = −0.8k < 0: divergent
    kp_high = 1.5 * K_SHAFT  # k_net = k + 2(1.5k − k) = 2k: stable at rest
    speeds = np.linspace(0.0, 4.0, 21) * WN
    design = loads_design(text + amb)
    # the divergent rotor keeps one oscillatory mode at rest (its disk's are real roots): 1 tracked
    low = gain_stability_map(
        design, [kp_low], [0.0], speeds, damping_model="viscous", n_modes=1, reference_frequency=WN
    )
    smap = gain_stability_map(
        design, [kp_high], [0.0], speeds, damping_model="viscous", n_modes=2, reference_frequency=WN
    )
    assert low.onset_speed[0, 0] == 0.0
    omega = np.sqrt((K_SHAFT + 2 * (kp_high - KS)) / M_DISK)  # = √2 ω_n, inside the grid
    assert smap.onset_speed[0, 0] == pytest.approx(omega, rel=2e-5)

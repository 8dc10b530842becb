"""The whirl-stability map over the actuator gains (thesis chapter 4,
:func:`flexshaft.thesis.whirl.gain_stability_map`) against the Jeffcott rotor's characteristic
equation.

The rotor of tests/rotors.py (a 20 kg disk at mid-span of a near-massless pinned-pinned tube,
shaft stiffness k = 48EI/L³, viscous internal damping c_i = ηk/ω_ref, no external dashpot)
with two active bearings at the disk, current gain k_i [N/A] and law C(s) = K_p + K_d s (or
with a derivative filter K_d s/(1 + s/ω_d)): each adds the force k_i C(s) r, so in
r = v + iw the disk obeys

    m s² + c_i s + k + 2k_i C(s) − iΩ c_i = 0      (× (1 + s/ω_d) with the filter: a cubic).

For the ideal PD law the onset (Re s = 0, s = iω) is in closed form: ω² = (k + 2k_i K_p)/m and
Ω_onset = ω (1 + 2k_i K_d/c_i) (the classical threshold of internal damping,
tests/test_stability.py); with the filter it is the Ω where the largest real part of the cubic's
roots crosses zero (Brent's method on the polynomial's roots). The map's margin at the
operating speed is the smallest damping ratio −Re s/|s| of the roots there.

The bearings carry a design K_d of 500 N s/m: each map point's K_d is the bearings' whole
derivative gain (the function builds the shared basis at K_d = 0), so the onset above uses the
map's K_d alone; a basis keeping the design's K_d would add 500 N s/m to every point.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, L, jeffcott_text
from scipy.optimize import brentq

from flexshaft.design import loads_design
from flexshaft.thesis.whirl import gain_stability_map

ETA, KP, KD = 0.02, 2e5, 40.0
C_I = ETA * K_SHAFT / WN  # ω_ref = ω_n of the shaft alone
OPERATING = 0.8 * WN  # [rad/s], on the map's speed grid below


def _rotor_with_two_ambs(extra: str = ""):
    amb = "\n".join(
        f'[[bearings]]\nname = "amb_{k}"\nkind = "active"\nx = {L / 2}\nkp = 1.0\nkd = 500.0\n{extra}'
        for k in ("a", "b")
    )
    text = jeffcott_text(ETA, 0.0).replace("speed_rpm = 0.0", f"speed_rpm = {float(OPERATING * 30 / np.pi)!r}")
    return loads_design(text + amb)


def _roots(speed, ki, kd, wd):
    """Roots of the disk's characteristic polynomial at spin ``speed`` (module docstring)."""
    rotor = np.array([M_DISK, C_I, K_SHAFT - 1j * speed * C_I])
    if wd is None:
        return np.roots(rotor + [0.0, 2 * ki * kd, 2 * ki * KP])
    law = np.array([0.0, 0.0, 2 * ki * (KP / wd + kd), 2 * ki * KP])  # 2k_i C(s)(1 + s/ω_d)
    return np.roots(np.polymul(rotor, [1 / wd, 1.0]) + law)


@pytest.mark.parametrize(
    "ki, wd, extra",
    [(1.0, None, ""), (2.0, None, "ki = 2.0\n"), (1.0, 2 * np.pi * 100.0, "derivative_cutoff = 100.0\n")],
    ids=["thesis PD", "current gain 2 N/A", "derivative filter at 100 Hz"],
)
def test_onset_and_margin_over_kd_follow_the_characteristic_equation(ki, wd, extra):
    """K_d = 0 and 40 N s/m on both bearings (the ideal law's onset 334 → 554 rad/s at k_i = 1).
    Re s is nearly linear in Ω here, so the linear interpolation of the onset on the grid of 26
    speeds adds no visible error. Both the onset and the margin at the operating speed (a grid
    speed) to 2e-5: the reference leaves out the tube's mass, 7e-6 of the disk's (measured
    9e-7 on the onset, 3e-6 on the margin). With k_i = 2 N/A the force law is k_i C(s) (was: the
    map added K_d without k_i: 602 instead of 842 rad/s); the filter at 100 Hz (ω_d = 628 rad/s,
    near the onset) puts K_d in the law's states (each point's own model): 507 instead of the
    ideal law's 554 rad/s."""
    speeds = np.linspace(0.5, 3.0, 26) * WN
    assert np.min(np.abs(speeds - OPERATING)) < 1e-9 * WN
    smap = gain_stability_map(
        _rotor_with_two_ambs(extra), [KP], [0.0, KD], speeds, damping_model="viscous", n_modes=2, reference_frequency=WN
    )
    for j, kd in enumerate((0.0, KD)):
        onset = brentq(lambda speed, kd=kd: _roots(speed, ki, kd, wd).real.max(), 0.5 * WN, 3.0 * WN, xtol=1e-9 * WN)
        if wd is None:
            assert onset == pytest.approx(np.sqrt((K_SHAFT + 2 * ki * KP) / M_DISK) * (1 + 2 * ki * kd / C_I), rel=1e-9)
        assert smap.onset_speed[0, j] == pytest.approx(onset, rel=2e-5)
        roots = _roots(OPERATING, ki, kd, wd)
        assert smap.margin_at_operating[0, j] == pytest.approx(np.min(-roots.real / np.abs(roots)), rel=2e-5)
    assert smap.max_speed == speeds[-1]

"""The spin-up map of a Jeffcott rotor on an ideal PD bearing uses the speeds and the imbalance
its caller gives, derived here.

The Jeffcott rotor of tests/jeffcott_bearing.py (a 20 kg disk on a near-massless pinned-pinned
tube, k = 48EI/L³) with an ideal magnetic bearing at the disk (k_s = 0, k_i = 1, no lag,
collocated, law G(iΩ) = k_p + iΩ k_d). In complex coordinates the disk obeys
m r̈ + k_d ṙ + (k + k_p) r = U Ω² e^{iΩt} for an imbalance U [kg m] at the disk: a forward circle
of radius

    r(Ω) = U Ω² / |k + k_p − mΩ² + iΩ k_d|,

which is also the bearing's relative orbit (it sits at the disk), carrying the force
|k_p + iΩ k_d| r. The tube deflects as a midspan-loaded beam, so the shaft's largest orbit is
the disk's.

:func:`spinup_map` is called without a precomputed receptance, with its own ``speeds`` (150 to
380 rad/s, reaching beyond the design's operating speed of 250 rad/s) and its own
``loads_per_speed_squared`` (3U at the disk, three times the design's own imbalance U there). Its docstring: "speeds:
Spin speeds [rad/s]; default spinup_speeds" and "loads_per_speed_squared: Imbalance Q₁ [N s²];
default from the design". Each gain pair's peak is then the largest r(Ω) over those speeds with
3U, at the speed where r is largest (the resonances of the two k_p, √((k + k_p)/m) ≈ 302 and
314 rad/s, lie above the operating speed: a map over the default speeds would peak at its
last one, 250 rad/s).

Tolerance 1e-3 relative, that of tests/test_spinup_pd_bearing_reference.py at the same model:
the tube's mass (3.5e-6 of the disk's) and its mesh change the disk's response by less than 1e-4
away from the resonance, and the speeds stay 5 % or more from the damped peaks so that the
relative error is not amplified. Under 0.05 s of CPU (one tiny model, six banded solves).
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import U, imbalance_vector
from rotors import K_SHAFT, M_DISK, jeffcott_text

from flexshaft.analyses.spinup import spinup_map
from flexshaft.assembly import build_model
from flexshaft.assembly.balance import rotating_mass
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import loads_design

OPERATING = 250.0  # rad/s
PD = 'kind = "active"\nkp = 5000.0\nkd = 100.0'


def pd_model():
    """tests/jeffcott_bearing.py's model_with(PD), spinning at OPERATING."""
    text = jeffcott_text(0.0, 0.0, elements=4).replace("speed_rpm = 0.0", f"speed_rpm = {OPERATING * 30 / np.pi}")
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    design = f'{head}[[bearings]]\nname = "b"\nx = 0.5\n{PD}\n{tail}'
    # the design's own imbalance: U at the disk (mid-bay of the whole shaft, the rotor's rotating mass)
    ecc = U / rotating_mass(build_model(loads_design(design)))
    return build_model(loads_design(f'{design}[loads]\neccentricity = {ecc!r}\nimbalance_placement = "mid_bay"\n'))


def orbit(speeds, kp, kd, scale):
    return scale * U * speeds**2 / np.abs(K_SHAFT + kp - M_DISK * speeds**2 + 1j * speeds * kd)


def test_map_reads_the_given_speeds_and_imbalance():
    model = pd_model()
    assert model.speed == pytest.approx(OPERATING)
    speeds = np.array([150.0, 220.0, 260.0, 285.0, 330.0, 380.0])  # 5 % or more from 302 and 314 rad/s
    load = imbalance_vector(model, 3.0)
    # the design's own imbalance is U at the disk, a third of the one given here
    np.testing.assert_allclose(imbalance_loads(model)[:, 0], imbalance_vector(model, 1.0), rtol=1e-12, atol=1e-18)
    kp, kd = np.array([2.0e3, 1.5e5]), np.array([60.0, 300.0])
    smap = spinup_map(model, kp, kd, speeds, load)
    for i, p in enumerate(kp):
        for j, d in enumerate(kd):
            r = orbit(speeds, p, d, 3.0)
            k = int(np.argmax(r))  # the largest sample beats the next by 1.23x or more: no tie
            assert speeds[k] > OPERATING  # beyond the default spin-up's last speed
            assert smap.shaft_peak[i, j] == pytest.approx(r[k], rel=1e-3)
            assert smap.shaft_peak_speed[i, j] == speeds[k]
            assert smap.actuator_displacement_peak[i, j, 0] == pytest.approx(r[k], rel=1e-3)
            force = np.abs(p + 1j * speeds * d) * r
            assert smap.actuator_force_peak[i, j, 0] == pytest.approx(force.max(), rel=1e-3)
    assert smap.speeds == pytest.approx(speeds, rel=1e-15)

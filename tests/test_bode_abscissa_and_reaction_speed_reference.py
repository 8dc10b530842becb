"""The imbalance Bode plot's axes and a bearing reaction's speed, against the Jeffcott rotor
with one contact bearing at its disk (tests/jeffcott_bearing.py; closed forms derived here).

The disk (mass m) sits on the pinned-pinned tube (k = 48EI/L³) and the bearing (k_b, c_v, c_w)
in parallel; each plane is a single degree of freedom, so under the imbalance U Ω² (Q_v = U,
Q_w = −iU) the disk's v amplitude is A_v(Ω) = U Ω² / (k + k_b + iΩc_v − mΩ²), and the
bearing, whose far side is the ground, carries Z_b(Ω) A with Z_b = k_b + iΩc.

* The Bode plot of an imbalance response is drawn against the spin speed in rpm
  (Ω · 60/(2π)), its amplitude panel in mm (the plot's documented axes,
  flexshaft.plot.response.bode_figure): the abscissa of each curve is the speeds in rpm
  exactly (an affine map of the inputs: 1e-12 relative), the ordinate 1000|A_v| (1e-3: the
  tube's mass, 3.5e-6 of the disk's (tests/rotors.py), is the model's only departure from the closed form, at
  speeds a factor 1.4 and more from the resonance).
* The orbit plot of a harmonic (non-synchronous) response picks the excitation frequency f [Hz]
  nearest the requested ``speed_rpm`` as f · 60 (rpm = rev/min); a 1000 N load on v at the
  disk, frequencies 5, 10, 20 and 40 Hz at rest, 1200 rpm asked: the 20 Hz orbit, a line of
  half-length |A_v| = 1000 N / |k + k_b + iωc_v − mω²| (the plotted ellipse samples the phase
  every 3°: its largest |v| is within 1 − cos 1.5° = 3.4e-4 of |A_v|, and the model within
  1e-3 of the closed form: 2e-3). The 40 Hz orbit is twice as large.
* A bearing reaction computed at a speed Ω records that Ω (BearingReaction.speed, "the
  imbalance speed"), and its force is Z_b(Ω) times its relative motion, in each plane: that
  is 1e-12 relative algebra on the stored numbers (one complex product).
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from jeffcott_bearing import CONTACT, CV, CW, KB, U, disk, imbalance_vector, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.reactions import bearing_reactions
from flexshaft.analyses.response import frequency_response, imbalance_response, static_response

WB = np.sqrt((K_SHAFT + KB) / M_DISK)  # the disk-on-bearing natural frequency [rad/s]


def test_imbalance_bode_is_drawn_in_rpm_and_mm():
    import matplotlib.pyplot as plt

    model = model_with(CONTACT)
    speeds = WB * np.array([0.2, 0.4, 0.6, 1.4, 1.8])
    q = imbalance_response(model, speeds, imbalance_vector(model))
    fig = q.plot_bode(station=0.5, direction="v")
    try:
        amplitude_line = fig.axes[0].get_lines()[0]
        rpm = speeds * 60.0 / (2.0 * np.pi)
        assert np.asarray(amplitude_line.get_xdata()) == pytest.approx(rpm, rel=1e-12)
        a_v = U * speeds**2 / (K_SHAFT + KB + 1j * speeds * CV - M_DISK * speeds**2)
        assert np.asarray(amplitude_line.get_ydata()) == pytest.approx(1e3 * np.abs(a_v), rel=1e-3)
    finally:
        plt.close(fig)


def test_reaction_records_its_imbalance_speed_and_force_law():
    model = model_with(CONTACT)
    assert model.speed == 0.0  # the design's operating speed: the reaction's speed must not be it
    v, w = disk(model)
    speed = 0.5 * WB
    q_static = static_response(model, np.zeros(model.dofs.size), speed=0.0)
    q_dyn = np.asarray(imbalance_response(model, [speed], imbalance_vector(model)))[:, 0]
    r = bearing_reactions(model, q_static, q_dyn, speed=speed)["b"]
    assert r.speed == pytest.approx(speed, rel=1e-12)
    # the force is the bearing's law at the recorded speed times the recorded motion
    motion_v, motion_w = r.imbalance_motion[1, 0], r.imbalance_motion[2, 0]
    assert r.imbalance_force[1, 0] == pytest.approx((KB + 1j * r.speed * CV) * motion_v, rel=1e-12)
    assert r.imbalance_force[2, 0] == pytest.approx((KB + 1j * r.speed * CW) * motion_w, rel=1e-12)
    a_v = U * speed**2 / (K_SHAFT + KB + 1j * speed * CV - M_DISK * speed**2)
    assert motion_v == pytest.approx(a_v, rel=1e-3)
    assert q_dyn[v] == pytest.approx(a_v, rel=1e-3)
    assert abs(q_dyn[w]) == pytest.approx(
        abs(U * speed**2 / (K_SHAFT + KB + 1j * speed * CW - M_DISK * speed**2)), rel=1e-3
    )


def test_harmonic_orbit_plot_picks_the_frequency_in_rpm():
    import matplotlib.pyplot as plt

    model = model_with(CONTACT)
    v, _ = disk(model)
    load = np.zeros(model.dofs.size)
    load[v] = 1000.0
    hz = np.array([5.0, 10.0, 20.0, 40.0])
    q = frequency_response(model, load, 2.0 * np.pi * hz, speed=0.0)
    fig = q.plot_orbit(station=0.5, speed_rpm=1200.0)
    try:
        ov = np.asarray(fig.axes[0].get_lines()[0].get_ydata())  # v on the vertical axis [mm]
        omega = 2.0 * np.pi * 20.0
        a_v = 1000.0 / (K_SHAFT + KB + 1j * omega * CV - M_DISK * omega**2)
        assert np.abs(ov).max() == pytest.approx(1e3 * abs(a_v), rel=2e-3)
    finally:
        plt.close(fig)

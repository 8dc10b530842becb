"""The documented defaults of a harmonic response's Bode and orbit plots, and the spin a
non-synchronous response records, against the Jeffcott rotor with one contact bearing at its
disk (tests/jeffcott_bearing.py; closed forms derived here).

The disk (mass m) sits on the pinned-pinned tube (k = 48EI/L³) and the bearing (k_b, c_v, c_w)
in parallel; each plane is a single degree of freedom, so under an imbalance s·U Ω² (Q_v = sU,
Q_w = −isU, imbalance_vector(model, s)) the disk's amplitudes are

    A_v(Ω) = s U Ω² / (k + k_b + iΩc_v − mΩ²),    A_w(Ω) = −i s U Ω² / (k + k_b + iΩc_w − mΩ²),

and the pinned ends do not move. Two load cases, s = 0.5 (case 1) and s = 1 (case 2): the
larger is the second, so a default that picked the first case, or the smaller, shows half.

Documented defaults (HarmonicResponse.plot_bode / plot_orbit docstrings):

* ``station`` defaults to "the node of the largest orbit": the disk (the ends' orbit is 0);
* ``case`` defaults to "the one with the largest response there": s = 1;
* ``plot_orbit``'s ``speed_rpm`` defaults to "the last" analysed speed.

The Bode amplitude panel is 1000 |A_v| [mm] (1e-3: the tube's mass, 3.5e-6 of the disk's
(tests/rotors.py), is the model's only departure from the closed form, at speeds a factor 1.4
and more from the resonance; the same tolerance as
tests/test_bode_abscissa_and_reaction_speed_reference.py). The orbit plot samples the phase every
3°: its largest |v| is within 1 − cos 1.5° = 3.4e-4 of |A_v|, with the model's 1e-3: 2e-3; its
axes are in μm for an orbit below 0.1 mm (flexshaft.plot.response.orbit_figure), as these are
(|A_v| = 7.2 μm at 1.8 ω_b).

``frequency_response(..., speed=Ω)`` computes a non-synchronous response at the spin Ω: it
records Ω as the spin of every frequency (``spin_speeds``, which the dataset's ``spin_speed``
copies), an exact copy of the input (1e-12). Its Bode plot is drawn against the excitation
frequency (plot_bode's docstring) in Hz (bode_figure's documented abscissa, "excitation
frequency [Hz] with ``x_label`` saying so", and the axis label): f = ω/(2π), here 5, 10 and
20 Hz (1e-12: one division of the inputs by 2π). Four solves of a 4-element rotor: well under
0.5 s of CPU.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from jeffcott_bearing import CONTACT, CV, CW, KB, U, disk, imbalance_vector, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.response import frequency_response, imbalance_response

WB = np.sqrt((K_SHAFT + KB) / M_DISK)  # the disk-on-bearing natural frequency [rad/s]
SPEEDS = WB * np.array([0.2, 0.4, 0.6, 1.4, 1.8])


def _a_v(speed, scale=1.0):
    return scale * U * speed**2 / (K_SHAFT + KB + 1j * speed * CV - M_DISK * speed**2)


def _a_w(speed, scale=1.0):
    return -1j * scale * U * speed**2 / (K_SHAFT + KB + 1j * speed * CW - M_DISK * speed**2)


@pytest.fixture(scope="module")
def two_cases():
    model = model_with(CONTACT)
    loads = np.column_stack([imbalance_vector(model, 0.5), imbalance_vector(model, 1.0)])
    return imbalance_response(model, SPEEDS, loads)


def test_bode_defaults_to_the_largest_orbit_station_and_case(two_cases):
    import matplotlib.pyplot as plt

    fig = two_cases.plot_bode(direction="v")
    try:
        line = fig.axes[0].get_lines()[0]
        assert "0.50 m" in line.get_label()
        assert np.asarray(line.get_ydata()) == pytest.approx(1e3 * np.abs(_a_v(SPEEDS)), rel=1e-3)
    finally:
        plt.close(fig)


def test_orbit_defaults_to_the_last_speed_largest_station_and_case(two_cases):
    import matplotlib.pyplot as plt

    fig = two_cases.plot_orbit()
    try:
        line = fig.axes[0].get_lines()[0]
        ov, ow = np.asarray(line.get_ydata()), np.asarray(line.get_xdata())  # v vertical, w horizontal [μm]
        assert "μm" in fig.axes[0].get_ylabel()
        top = SPEEDS[-1]
        assert np.abs(ov).max() == pytest.approx(1e6 * abs(_a_v(top)), rel=2e-3)
        assert np.abs(ow).max() == pytest.approx(1e6 * abs(_a_w(top)), rel=2e-3)
    finally:
        plt.close(fig)


def test_harmonic_response_records_the_spin_it_was_computed_at():
    model = model_with(CONTACT)
    v, _ = disk(model)
    load = np.zeros(model.dofs.size)
    load[v] = 1000.0
    omegas = 2.0 * np.pi * np.array([5.0, 10.0, 20.0])
    spin = 0.3 * WB
    q = frequency_response(model, load, omegas, speed=spin)
    assert np.asarray(q.frequencies) == pytest.approx(omegas, rel=1e-12)
    assert np.asarray(q.spin_speeds) == pytest.approx(np.full(omegas.size, spin), rel=1e-12)
    import matplotlib.pyplot as plt

    fig = q.plot_bode(direction="v")
    try:
        assert "[Hz]" in fig.axes[1].get_xlabel()
        line = fig.axes[0].get_lines()[0]
        assert np.asarray(line.get_xdata()) == pytest.approx([5.0, 10.0, 20.0], rel=1e-12)
    finally:
        plt.close(fig)
    # the response itself: the v plane's single degree of freedom (the spin does not enter it)
    expected = 1000.0 / (K_SHAFT + KB + 1j * omegas * CV - M_DISK * omegas**2)
    assert np.asarray(q)[v] == pytest.approx(expected, rel=1e-3)

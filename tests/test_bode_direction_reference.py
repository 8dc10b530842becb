"""The Bode plot of the lateral direction (``HarmonicResponse.plot_bode(direction="w")``)
against the Jeffcott rotor with one contact bearing at its disk (tests/jeffcott_bearing.py;
closed forms derived here).

The disk (mass m) sits on the pinned-pinned tube (k = 48EI/L³) and the bearing (k_b, c_v, c_w)
in parallel; each plane is a single degree of freedom, so under the imbalance U Ω² (Q_v = U,
Q_w = −iU, imbalance_vector(model)) the disk's amplitudes are

    A_v(Ω) = U Ω² / (k + k_b + iΩc_v − mΩ²),    A_w(Ω) = −i U Ω² / (k + k_b + iΩc_w − mΩ²).

The lateral response lags the vertical one by a quarter turn (the −i of the rotating load) and
its damping is c_w = 6 c_v, so its amplitude and, by about 90°, its phase differ from the
vertical ones: a plot asked for the lateral direction that drew the vertical displacement
fails both. Which displacement is lateral: docs/model.md, "y is vertical (up) and z lateral.
Displacements u, v, w along x, y, z", so direction "w" is the lateral displacement. The
reference is the closed form above: the amplitude panel must be 1000 |A_w| [mm] and the phase
panel arg A_w [°] up to whole turns (the figure unwraps and shifts by multiples of 360°; the
units mm and degrees are bode_figure's code docstring).

Tolerances: the tube's mass, 3.5e-6 of the disk's (tests/rotors.py), is the model's only
departure from the closed form, at speeds a factor 1.4 and more from the resonance: 1e-3 on the
amplitude (as tests/test_bode_orbit_defaults_and_nonsynchronous_spin_reference.py), and a
relative error 1e-3 of a complex number moves its argument by at most 1e-3 rad = 0.06°: 0.2°
on the phase, against the ~90° the vertical phase is off. Five solves of a 4-element rotor:
well under 0.5 s of CPU.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from jeffcott_bearing import CONTACT, CV, CW, KB, U, imbalance_vector, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.response import imbalance_response

WB = np.sqrt((K_SHAFT + KB) / M_DISK)  # the disk-on-bearing natural frequency [rad/s]
SPEEDS = WB * np.array([0.2, 0.4, 0.6, 1.4, 1.8])


def _a(speed, damping, load):
    return load * U * speed**2 / (K_SHAFT + KB + 1j * speed * damping - M_DISK * speed**2)


def _turns_apart(phase_deg, reference_deg):
    """Phase difference folded into [−180°, 180°)."""
    return (np.asarray(phase_deg) - reference_deg + 180.0) % 360.0 - 180.0


@pytest.fixture(scope="module")
def response():
    model = model_with(CONTACT)
    return imbalance_response(model, SPEEDS, imbalance_vector(model))


@pytest.mark.parametrize("direction", ["v", "w"])
def test_bode_draws_the_asked_direction(response, direction):
    import matplotlib.pyplot as plt

    expected = _a(SPEEDS, CV, 1.0) if direction == "v" else _a(SPEEDS, CW, -1j)
    other = _a(SPEEDS, CW, -1j) if direction == "v" else _a(SPEEDS, CV, 1.0)
    # the two directions are distinguishable at these speeds (phase ~90° apart)
    assert np.all(np.abs(_turns_apart(np.degrees(np.angle(other)), np.degrees(np.angle(expected)))) > 45.0)
    fig = response.plot_bode(station=0.5, direction=direction)
    try:
        amp_ax, phase_ax = fig.axes[0], fig.axes[1]
        (amp,) = amp_ax.get_lines()
        (phase,) = phase_ax.get_lines()
        off = _turns_apart(phase.get_ydata(), np.degrees(np.angle(expected)))
        assert np.max(np.abs(off)) < 0.2
        assert np.asarray(amp.get_ydata()) == pytest.approx(1e3 * np.abs(expected), rel=1e-3)
        assert amp.get_label().endswith(f", {direction}")
    finally:
        plt.close(fig)


def test_bode_both_draws_vertical_then_lateral(response):
    import matplotlib.pyplot as plt

    fig = response.plot_bode(station=0.5, direction="both")
    try:
        v, w = fig.axes[0].get_lines()
        assert np.asarray(v.get_ydata()) == pytest.approx(1e3 * np.abs(_a(SPEEDS, CV, 1.0)), rel=1e-3)
        assert np.asarray(w.get_ydata()) == pytest.approx(1e3 * np.abs(_a(SPEEDS, CW, -1j)), rel=1e-3)
    finally:
        plt.close(fig)

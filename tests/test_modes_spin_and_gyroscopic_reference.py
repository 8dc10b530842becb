"""``modes`` at a spin speed: the gyroscopic split of both solvers and the shapes drawn near the spin.

References
----------
* The overhung disk of tests/test_overhung_disk_whirl.py (a rigid disk m, I_d, I_p at the tip of
  a massless clamped cantilever, no damping): its whirl frequencies at spin Ω are the positive
  roots of ``(k11 − m ω²)(k22 − I_d ω² ± I_p Ω ω) − k12² = 0`` (+ forward, − backward; Genta,
  *Dynamics of Rotating Systems*, ch. 4; typed there as ``closed_form``). Without any loss the
  damped (``damped=True``) and the gyroscopic-only (``damped=False``) solves at Ω must both give
  the two forward and two backward roots at that Ω (a solve at rest gives the unsplit pairs,
  30 % away at Ω = 1000 rad/s). Frequencies to 5e-5 as in that test (the tube's mass is 1e-6 of
  the disk's).
* The shapes figure draws the modes nearest the spin frequency f = Ω/2π [Hz] = rpm/60. On the
  Jeffcott rotor of tests/rotors.py with a heavy dashpot (ζ = 0.95: damped frequency
  ω_n√(1 − ζ²) = 0.312 ω_n, 15.0 Hz) and a disk polar inertia J giving a torsional mode
  ω_t = √(G J_p/(L/2)/J) = 0.6 ω_n (28.9 Hz; the tube held in twist at x = 0, free at L), spun at
  Ω = 0.3 ω_n (14.4 Hz): the nearest mode is a lateral one of the pair. (Ω read as a frequency
  in Hz, 90.6, would pick the torsional mode.) Frequencies 1e-4 relative (the tube's mass).
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from rotors import WN  # noqa: E402
from test_campbell_core_reference import heavily_damped_with_torsion_text  # noqa: E402
from test_overhung_disk_whirl import closed_form, design_text  # noqa: E402

import flexshaft as fs  # noqa: E402
from flexshaft.design import loads_design  # noqa: E402

SPEED = 1000.0  # rad/s


@pytest.mark.parametrize("damped", [False, True])
def test_modes_at_speed_carry_the_gyroscopic_split(damped):
    model = fs.build_model(loads_design(design_text(SPEED * 60 / (2 * np.pi))))
    found = fs.modes(model, speed=SPEED, n_modes=6, damped=damped, basis_size=24)
    w = found.eigenvalues.imag
    for sense in (+1, -1):
        for root in closed_form(SPEED, sense):
            assert np.min(np.abs(w - root)) <= 5e-5 * root, (sense, root, w)


def test_shapes_figure_draws_the_mode_nearest_the_spin_frequency():
    zeta, w_t = 0.95, 0.6 * WN
    text = heavily_damped_with_torsion_text(zeta)
    speed = 0.3 * WN
    found = fs.modes(fs.build_model(loads_design(text)), speed=speed, n_modes=4)
    f_lateral, f_torsion = WN * np.sqrt(1 - zeta**2) / (2 * np.pi), w_t / (2 * np.pi)
    lateral = np.flatnonzero(found.kind == "lateral")
    (torsional,) = np.flatnonzero(found.kind == "torsional")
    assert found.frequencies[lateral[:2]] == pytest.approx([f_lateral] * 2, rel=1e-4)
    assert found.frequencies[torsional] == pytest.approx(f_torsion, rel=1e-4)
    fig = found.plot_shapes(n=1)
    try:
        titles = [ax.get_title() for ax in fig.axes if ax.get_visible()]
        assert len(titles) == 1
        assert titles[0].startswith(f"mode {lateral[0] + 1}: ")
        assert f"{speed / (2 * np.pi):.1f} Hz" in fig.texts[0].get_text()
    finally:
        plt.close(fig)

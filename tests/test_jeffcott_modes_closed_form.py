"""Damped and undamped frequencies, the rpm column, divergence and (in)stability of the
Jeffcott rotor's modes, against the single-DOF oscillator (derived here).

The Jeffcott rotor of tests/rotors.py (a 20 kg disk at the middle of a near-massless
pinned-pinned tube, k = 48EI/L³) with one bearing at the disk; each plane is a single mass:

* a dashpot c = 2ζ√(km) (ζ = 0.2): s = −ζω_n ± iω_n√(1 − ζ²), so the damped frequency
  ω_d/2π is 2 % below the undamped ω_n/2π = |s|/2π (a difference 2000x the tube-mass error
  of ~1e-5 asserted at 1e-4), and a frequency f [Hz] is 60 f rpm;
* an open-loop magnet (K_p = 0) with negative stiffness k_s = 3k: m s² + (k − k_s) = 0 has the
  real roots s = ±√((k_s − k)/m); the positive one is a divergence (ζ = −1, frequency 0) at
  every speed (no gyroscopic term: no polar inertia), so the stability margin is −1 throughout;
* the viscous stability method's reference frequency is the first shaft bending mode at rest:
  with a tailboom that no bearing ties to the shaft (its first mode, a 50 kg tip mass on a
  2 m aluminium cantilever, near 57 rad/s, lies below), still the Jeffcott ω_n = √(k/m);
* without any damping or loss the rotor is conservative (its energy is constant): every mode
  is neutrally stable at every speed, s = ±iω_n, never unstable.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.modal import modes
from flexshaft.analyses.stability import onset_speed, stability
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ZETA = 0.2


def test_damped_and_undamped_frequencies_of_the_damped_jeffcott_rotor():
    c = ZETA * 2 * np.sqrt(K_SHAFT * M_DISK)
    model = model_with(f'kind = "contact"\nstiffness = {{}}\ndamping = {{ v = {c}, w = {c} }}')
    m = modes(model, 0.0, n_modes=2)
    wd = WN * np.sqrt(1 - ZETA**2)
    assert m.frequencies == pytest.approx([wd / (2 * np.pi)] * 2, rel=1e-4)
    assert m.undamped_frequencies == pytest.approx([WN / (2 * np.pi)] * 2, rel=1e-4)
    assert m.damping_ratios == pytest.approx([ZETA] * 2, rel=1e-4)
    rows = m.table()
    assert [r["frequency_rpm"] for r in rows] == pytest.approx([60 * wd / (2 * np.pi)] * 2, rel=1e-4)
    assert [r["frequency_Hz"] for r in rows] == pytest.approx([wd / (2 * np.pi)] * 2, rel=1e-4)
    assert not m.divergent.any()


def test_an_open_loop_magnet_diverges():
    model = model_with(f'kind = "active"\nkp = 0.0\nks = {3 * K_SHAFT}\nki = 100.0')
    m = modes(model, 0.0, n_modes=2)
    rate = np.sqrt(2 * K_SHAFT / M_DISK)  # √((k_s − k)/m)
    assert m.eigenvalues.real == pytest.approx([rate, rate], rel=1e-4)
    assert list(m.divergent) == [True, True]
    assert m.damping_ratios == pytest.approx([-1.0, -1.0], rel=1e-12)


def test_a_divergence_takes_the_stability_margin_to_minus_one():
    model = model_with(f'kind = "active"\nkp = 0.0\nks = {3 * K_SHAFT}\nki = 100.0')
    result = stability(model, [0.0, 100.0, 200.0], n_modes=2)
    assert result.divergence == pytest.approx([np.sqrt(2 * K_SHAFT / M_DISK)] * 3, rel=1e-4)
    assert result.divergent and result.onset_kind == "divergence" and result.onset_speed == 0.0
    assert list(result.stability_margin) == [-1.0, -1.0, -1.0]


def test_an_undamped_rotor_is_never_unstable():
    model = model_with('kind = "contact"\nstiffness = {}\ndamping = {}')
    result = stability(model, [0.0, 200.0, 400.0], n_modes=2)
    assert np.abs(result.eigenvalues.imag) == pytest.approx(np.full((3, 2), WN), rel=1e-4)
    assert result.onset_speed is None and result.onset_kind is None
    # the onset rule on exact neutral roots ±iω_n (ζ = 0: not below −tolerance)
    neutral = np.full((3, 2), 1j * WN)
    assert onset_speed([0.0, 200.0, 400.0], neutral) == (None, None, None)


BOOM = """[materials.al]
kind = "isotropic"
E = 7e10
G = 2.7e10
density = 2700.0
[tailboom]
length = 2.0
root_semi_axes = [0.1, 0.1]
tip_semi_axes = [0.1, 0.1]
wall_thickness = 0.002
material = "al"
shaft_clearance = 0.05
[tailboom.end_mass]
mass = 50.0
offset = [0.0, 0.0, 0.0]
inertia = [0.0, 0.0, 0.0]
[[bearings]]"""


def test_viscous_reference_is_the_first_shaft_mode_not_a_lower_boom_mode():
    text = jeffcott_text(0.01, 0.0, elements=4).replace("damping = { v = 0.0, w = 0.0 }", "")
    model = build_model(loads_design(text.replace("[[bearings]]", BOOM).replace("[mesh]", "[mesh]\nboom_elements = 4")))
    boom = modes(model, 0.0, n_modes=4, damped=False)
    assert np.any((boom.component == "boom") & (boom.frequencies < 0.5 * WN / (2 * np.pi)))  # the premise
    result = stability(model, [0.0, 100.0], n_modes=4, damping_model="viscous")
    assert result.reference_frequency == pytest.approx(WN, rel=1e-4)

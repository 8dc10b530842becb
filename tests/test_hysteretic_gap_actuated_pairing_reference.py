"""A mode of a magnetically supported rotor in a gap of the hysteretic problem keeps its eigenvalue.

Reference (the hysteretic problem's definition, :mod:`flexshaft.analyses.hysteretic_roots`, whose
branch weights tests/test_damping.py derives): above the spin the loss weights are W₊ = (i, i, 0),
below it W₋ = (i, 0, 1). A mode whose upper-branch root s₊ lies below the spin and whose
lower-branch root s₋ lies above it (ω₊ < Ω < ω₋, a *gap*) has neither as an eigenvalue; its one
eigenvalue lies on the line, Im s = Ω, a root of (1 − μ) T₋ + μ T₊. Computed here as in
tests/test_hysteretic_gap_pairing_reference.py, independently of the code's eigen-solves, pairing,
regula falsi and Newton polish: s₊ and s₋ by QZ on another linearisation
(tests/test_stability.py :func:`pencil_roots`, which adds a stateless bearing channel's
``(k + s d) coupling`` to the pencil), the gap speed by the fixed point Ω = (ω₊ + ω₋)/2, and the
on-line root by QZ of the blended pencil tracked in μ from s₋ with SciPy's brentq on
μ ↦ Im s(μ) − Ω (μ = 1.35e-4, s = 56.30497 + 2490.42070i rad/s here).

What differs from that test: the rotor carries a magnetic bearing whose channel adds to T(s)
(a non-collocated proportional loop, sensor 0.05 m off the magnet: a stiffness of gain
k_i k_p = 1e5 N/m on the coupling B_aᵀ B_s, no controller states). For such a rotor no bound of the modal overlap
exists (:func:`~flexshaft.analyses.hysteretic_roots.mac_bounds` returns None), so the fast paths
(:func:`consistent_values`, :func:`damped_modes` through ``lowest_roots``) must solve the vectors
of every lower-branch root above the line that the pairing may read; with none of them the
pairing finds no match and the mode has no eigenvalue at that speed.

The rotor: tests/rotors.py's Jeffcott rotor with a steel tube, η = 0.05, a 20 kg disk of polar
inertia 0.2 kg m² and its dashpot (50 N s/m) at x = 0.3 m, the magnet at x = 0.7 m
(k_i = 100 N/A, k_p = 1e3 A/m, k_d = 0, k_s = 0). The disk's gyroscopic moment splits the branch
roots of the mode crossing the spin near 2490 rad/s by 3.46e-7 Ω (ω₊ < ω₋: a gap), 350 times the
synchronous band (1e-9 Ω) within which an on-line root is accepted; the next root of either branch
lies 352 rad/s from the pair's midpoint, far outside the disc |s − (s₊ + s₋)/2| <= |s₊ − s₋|
(113 rad/s) the mode is counted in.

Asserted, for :func:`consistent_values` and :func:`damped_modes`: exactly one eigenvalue in that
disc, with Im s = Ω to the band (1e-9), equal to the QZ on-line root within 1e-7 |s| + 40 · 1e-9 Ω.
The first term is the QZ-against-QR tolerance of tests/test_hysteretic_gap_continuation_reference.py;
the second the code's freedom to stop anywhere in the band |Im s − Ω| <= 1e-9 Ω: along the μ path
the root moves |dRe s/dIm s| = 35.1 in real part per unit of imaginary part (the QZ root
differenced in μ), so a stop at the band's edge moves Re s by up to 35.1 · 1e-9 Ω; 40 covers it.
Measured: 7.0e-7 rad/s against a tolerance of 3.5e-4 rad/s.
CPU: one 8-mode reduction and a few dozen 16 × 16 QZ solves, about 0.2 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import jeffcott_text
from test_hysteretic_gap_pairing_reference import gap, on_line_root

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import branches, consistent_values, damped_modes, mac_bounds
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA, C_E, X_DISK, POLAR = 0.05, 50.0, 0.3, 0.2
MAGNET = (
    '[[bearings]]\nname = "m"\nx = 0.7\nkind = "active"\nsensor_offset = 0.05\n'
    "ki = 100.0\nkp = 1000.0\nkd = 0.0\nks = 0.0\n"
)


def _reduced():
    text = jeffcott_text(ETA, C_E, elements=6).replace("density = 0.1", "density = 7800.0")
    disk = f"x = {X_DISK}\nmass = 20.0\npolar_inertia = {POLAR}\ndiametral_inertia = {POLAR / 2}"
    damper = f"x = {X_DISK}\nstiffness = {{}}"
    text = text.replace("x = 0.5\nmass = 20.0", disk).replace("x = 0.5\nstiffness = {}", damper)
    assert disk in text and damper in text
    head, tail = text.split("[[disks]]")
    model = build_model(loads_design(head + MAGNET + "[[disks]]" + tail))
    assert not model.actuators[0].collocated
    return reduce(model, 8)


def test_an_actuated_mode_in_a_gap_keeps_its_eigenvalue_on_the_line():
    red = _reduced()
    speed, p, q = gap(red)
    # the channel adds to T(s): no overlap bound, every candidate's vector must be solved
    lower = branches(red, speed)[0]
    assert mac_bounds(red, speed, lower.weights, np.array([q]), np.eye(red.size)[:, :1]) is None
    reference = on_line_root(red, speed, p, q)
    tol = 1e-7 * abs(reference) + 40 * 1e-9 * speed
    for name, s in (
        ("consistent_values", consistent_values(red, speed)),
        ("damped_modes", damped_modes(red, speed, 6)[0]),
    ):
        mode = s[np.abs(s - 0.5 * (p + q)) <= abs(p - q)]  # a disc holding both branch roots, and no other
        assert mode.size == 1, (name, mode)
        assert mode[0].imag == pytest.approx(speed, rel=1e-9), name
        assert abs(mode[0] - reference) <= tol, (name, mode[0], reference)

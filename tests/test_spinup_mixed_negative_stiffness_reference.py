"""Spin-up of two collocated bearings at one disk, a magnet with negative stiffness k_s and a
PD bearing without: each bearing's own k_s, against the Jeffcott closed form.

The Jeffcott rotor of tests/jeffcott_bearing.py (disk m = 20 kg on a near-massless tube of
k = 48 E I/L³) with two active bearings at the disk: the magnet of tests/jeffcott_bearing.py,
law ``L₁ = k_i (K_p + iΩK_d) − k_s`` with k_s = 2e5 N/m, and a bearing with k_s = 0 and
k_i = 1, law ``L₂ = K_p2 + iΩK_d2``. The module docstring of :mod:`flexshaft.analyses.spinup`
writes each collocated bearing's feedback as ``D = diag(G − k_s)``, bearing by bearing; both act
on the disk's v and w alike, so in complex coordinates (derived here) the disk obeys

    (k − mΩ² + L₁ + L₂) r = U Ω²   (forward imbalance U (1, −i) per Ω²),

a circular orbit of radius |r|: the shaft peak (the disk deflects most on the pinned-pinned
tube), the relative orbit at both magnets, and forces |L_a| |r|. k_s is 11 % of k, so dropping
it from the magnet (as if no bearing had one because one has none) moves |r| by several per cent.

The same law on both bearings (:func:`spinup_map` applies one (K_p, K_d) to every actuator)
gives ``L_a = k_i,a (K_p + iΩK_d) − k_s,a`` per bearing, the peak over the speeds being that of the
closed form on the same grid.

Speeds 0.3, 0.6 and 1.4 ω_n, away from the resonances. Tolerance: the tube's mass and rotary
inertia, 3.5e-6 of the disk's, move the answers by 5e-6 at most (measured): rtol 1e-4, as
tests/test_actuator_receptance_jeffcott_reference.py. CPU: a few milliseconds.
"""

from __future__ import annotations

import numpy as np
from jeffcott_bearing import KD, KI, KP, KS, U, imbalance_vector
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.spinup import actuator_receptance, spinup_curves, spinup_map
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KP2, KD2 = 3.0e5, 400.0  # N/m, N s/m: the second bearing's PD law (k_i = 1, k_s = 0)


def _model():
    text = jeffcott_text(0.0, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    magnet = f'[[bearings]]\nname = "magnet"\nx = 0.5\nkind = "active"\nkp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}\n'
    pd = '[[bearings]]\nname = "pd"\nx = 0.5\nkind = "active"\nkp = 0.0\nkd = 0.0\nks = 0.0\nki = 1.0\n'
    return build_model(loads_design(head + magnet + pd + tail))


def test_each_collocated_bearing_keeps_its_own_negative_stiffness():
    model = _model()
    assert [a.negative_stiffness for a in model.actuators] == [KS, 0.0]  # the premise
    speeds = np.array([0.3, 0.6, 1.4]) * WN
    rec = actuator_receptance(model, speeds, imbalance_vector(model)[:, None])
    curves = spinup_curves(rec, [(KP, KD), (KP2, KD2)])

    law_1 = KI * (KP + 1j * speeds * KD) - KS
    law_2 = KP2 + 1j * speeds * KD2
    r = np.abs(U * speeds**2 / (K_SHAFT - M_DISK * speeds**2 + law_1 + law_2))
    np.testing.assert_allclose(curves.shaft_peak, r, rtol=1e-4)
    np.testing.assert_allclose(curves.actuator_displacement, [r, r], rtol=1e-4)
    np.testing.assert_allclose(curves.actuator_force, [np.abs(law_1) * r, np.abs(law_2) * r], rtol=1e-4)


def test_the_gain_map_keeps_each_bearing_s_own_negative_stiffness():
    model = _model()
    speeds = np.array([0.3, 0.6, 1.4]) * WN
    kp, kd = np.array([KP, 2 * KP]), np.array([KD])
    smap = spinup_map(model, kp, kd, receptance=actuator_receptance(model, speeds, imbalance_vector(model)[:, None]))
    for i, p in enumerate(kp):
        law_1 = KI * (p + 1j * speeds * KD) - KS
        law_2 = p + 1j * speeds * KD
        r = np.abs(U * speeds**2 / (K_SHAFT - M_DISK * speeds**2 + law_1 + law_2))
        np.testing.assert_allclose(smap.shaft_peak[i, 0], r.max(), rtol=1e-4)
        np.testing.assert_allclose(
            smap.actuator_force_peak[i, 0], [(np.abs(law_1) * r).max(), (np.abs(law_2) * r).max()], rtol=1e-4
        )

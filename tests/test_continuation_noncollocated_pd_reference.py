"""The continuation's batched Newton step with a non-collocated PD magnetic bearing, against the
closed-loop Jeffcott rotor's closed form (hunt h40a).

A PD law without a filter has no controller state; with its sensor away from its magnet it is
not folded into the modal basis either, and :func:`flexshaft.analyses.continuation.newton_many`
adds it to ``T(s)`` as the rank-two term (k + s c) rowsᵀ·sensing. The rotor: the Jeffcott rotor
of tests/jeffcott_bearing.py (disk m at the middle of a pinned steel tube, k = 48EI/L³,
tests/rotors.py) with its magnetic bearing at the disk (k_i, k_p, k_d, k_s) and its sensor
125 mm further along (x_s = 0.625 m):

    f = k_s d − k_i (k_p + k_d s) d_s.

Reference (derived): the tube is nearly massless (3.5e-6 of the disk), so it takes the static
shape of a midspan point load, y(x) = P x (3L² − 4x²)/(48EI) for x ≤ L/2 (Roark, simply
supported beam, centre load), and the sensor (at L − x_s = 0.375 m by symmetry) reads
d_s = ρ d with ρ = x(3L² − 4x²)/L³ = 0.9140625; the disk's rotation is zero by symmetry. The
disk obeys, in either plane,

    m s² + k_i k_d ρ s + (k − k_s + k_i k_p ρ) = 0,

s = −k_i k_d ρ/(2m) ± i √((k − k_s + k_i k_p ρ)/m − (k_i k_d ρ/2m)²) = −4.570 + 322.68i rad/s.
The 4-element mesh's cubic shape functions hold that static shape exactly (one load at a node).
The continuation starts 1 % off the reduced model's two disk roots (a pair: isotropic, no
spin) with the viscous model and with the hysteretic branches, and must come back to it.
Tolerance 5e-6 relative: the tube's mass (not in the closed form) moves the root by 8.6e-7,
about a sixth of that; Newton stops at
1e-10 |s|. A damping term entered with the wrong sign moves Re s to +4.57 (a factor 2 on |Re s|
is 1.4e-2 of |s|). CPU: one small model, a few ms.
"""

from __future__ import annotations

import math

import numpy as np
from jeffcott_bearing import KD, KI, KP, KS, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.continuation import mode_roots, newton_many
from flexshaft.analyses.eigen import candidates, reduce
from flexshaft.analyses.loss import LossCoefficients

X_SENSOR = 0.375  # the sensor's distance from the nearer pin [m] (0.5 + 0.125 on a 1 m span)
RHO = X_SENSOR * (3.0 - 4.0 * X_SENSOR**2)  # y(x)/y(L/2) with L = 1 m


def test_newton_with_a_non_collocated_pd_bearing_gives_the_closed_loop_root():
    c = KI * KD * RHO
    k = K_SHAFT - KS + KI * KP * RHO
    expected = complex(-c / (2 * M_DISK), math.sqrt(k / M_DISK - (c / (2 * M_DISK)) ** 2))
    model = model_with(f'kind = "active"\nkp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}\nsensor_offset = 0.125')
    red = reduce(model, model.dofs.free.size)
    passive = [a for a in red.actuators if a.law is None and a.damping]
    assert passive, "the non-collocated PD law enters T(s) as k + s c"
    s0, Y0 = candidates(red, 0.0)
    start = s0[:2] * (1 + 0.01 - 0.01j)
    s, _, ok = newton_many(red, 0.0, start, Y0[:, :2], viscous=LossCoefficients(0.0, 0.0, 0.0))
    assert np.all(ok)
    np.testing.assert_allclose(s, [expected, expected], rtol=5e-6)
    s, _, found = mode_roots(red, 0.0, start, Y0[:, :2])
    assert np.all(found)
    np.testing.assert_allclose(s, [expected, expected], rtol=5e-6)

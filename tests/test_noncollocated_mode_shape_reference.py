"""Mode shapes of a rigid rotor on two magnetic bearings whose sensors are offset from the magnets.

Reference (derived here, as in tests/test_amb.py's hand-built model of the same rotor): a PD law
without filters acts from the sensing to the actuation rows, so on the rigid body's (y, θ) at the
disk, in one plane,

    (M s² + C s + K) v = 0,   K = Σ_j (k_i K_p b_a,j b_s,jᵀ − k_s b_a,j b_a,jᵀ),   C = Σ_j k_i K_d b_a,j b_s,jᵀ,

with b_a,j = (1, x_j) at the magnet and b_s,j = (1, x_j + e_j) at the sensor (x_j = ∓0.4 m from
the disk, offsets e = (0.06, −0.02) m). K and C are not symmetric: the right eigenvector v (the
mode shape) differs from the left one w (that of Kᵀ, Cᵀ), although both problems have the same
eigenvalues (a matrix and its transpose). So the eigenvalues alone do not tell whether the law's
force is applied at the magnet and its displacement read at the sensor, or the other way round;
the shape does. The magnets' displacements of the mode are d_j = v_y + x_j v_θ, so the ratio
d_2 / d_1 = (v_y + x_2 v_θ) / (v_y + x_1 v_θ) is the hand model's in every plane (at rest the two
planes are uncoupled and alike: any combination of the planes' vectors that the solver returns
for the double root has it in both rows of each magnet).

Tolerance 1e-4 of |d_1| (times max(1, |d_2/d_1|)): the tube (E = 2.1e15 Pa) bends by about
1e-5 of the bearing deflection (tests/test_amb.py's static check of the same rotor; measured
1.0e-5 here), which the rigid-body model leaves out. The transposed channel's shape (the left
vector) has a ratio 0.26 and 0.10 of |d_2/d_1| away from the right one's (asserted > 0.05), three
orders above the tolerance.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as la
from test_amb import HALF_SPAN, I_T, KD, KI, KP, KS, MASS, rotor

from flexshaft.analyses import modes

OFFSETS = (0.06, -0.02)  # m, sensor minus magnet position


def _hand_model():
    """M, C, K of the rigid rotor on (y, θ) at the disk, one plane."""
    K, C = np.zeros((2, 2)), np.zeros((2, 2))
    for j, x in enumerate((-HALF_SPAN, HALF_SPAN)):
        b_a, b_s = np.array([1.0, x]), np.array([1.0, x + OFFSETS[j]])
        K += KI * KP * np.outer(b_a, b_s) - KS * np.outer(b_a, b_a)
        C += KI * KD * np.outer(b_a, b_s)
    return np.diag([MASS, I_T]), C, K


def _magnet_ratio(M, C, K, s):
    """d_2/d_1 of the right null vector of M s² + C s + K at its eigenvalue s."""
    v = la.null_space(M * s * s + C * s + K, rcond=1e-8)[:, 0]
    return (v[0] + HALF_SPAN * v[1]) / (v[0] - HALF_SPAN * v[1])


def test_noncollocated_mode_shapes_are_the_right_eigenvectors():
    model = rotor([f"kp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}\nsensor_offset = {o}" for o in OFFSETS])
    M, C, K = _hand_model()
    first_order = np.block([[np.zeros((2, 2)), np.eye(2)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    hand = la.eigvals(first_order)
    hand = hand[hand.imag > 0]
    result = modes(model, 0.0, 4)
    B1, B2 = (a.lateral_rows.toarray() for a in model.actuators)
    for k, s in enumerate(result.eigenvalues):
        root = hand[np.argmin(np.abs(hand - s))]
        assert abs(root - s) <= 1e-5 * abs(root)  # tests/test_amb.py's bar on the same roots
        right = _magnet_ratio(M, C, K, root)
        left = _magnet_ratio(M.T, C.T, K.T, root)
        assert abs(left - right) > 0.05 * abs(right)  # the check below tells them apart
        d1, d2 = B1 @ result.shapes[:, k], B2 @ result.shapes[:, k]
        assert np.linalg.norm(d2 - right * d1) <= 1e-4 * np.linalg.norm(d1) * max(1.0, abs(right)), k

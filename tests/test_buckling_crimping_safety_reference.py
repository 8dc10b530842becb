"""Torsional buckling safety factor when shear crimping governs (the soft-matrix FMC case).

Reference: the shear-crimping limit of a shear-deformable shell, derived in
tests/test_buckling.py::crimping_closed_form (a wave much shorter than R and than the bending
wavelength stores only transverse shear energy A55 kx^2 + 2 A45 kx ky + A44 ky^2 against the work
2 N_xy kx ky; minimised over kx/ky: N_xy = sqrt(A44 A55) -/+ A45, T = 2 pi R^2 N_xy), with the
ply transverse shear moduli rotated as a vector: Q55 = G13 c^2 + G23 s^2,
Q44 = G13 s^2 + G23 c^2, Q45 = (G13 - G23) c s, shear correction k = 5/6. For G13 = G23 = G
this is T = 2 pi R^2 k G t.

What the user sees is the safety factor T_cr/|T| and the crimping torque of the result: with
crimping below the global helix, both must be the crimping value (the lower sense for an
unbalanced wall), never the global helix's. Tolerance 1e-12: the crimping torque is the
closed form evaluated, not a converged mode (tests/test_buckling.py shows the identity).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from flexshaft.buckling import buckling_safety_factor, torsional_buckling_torque
from flexshaft.laminate import Lamina, Laminate

FMC = Lamina.from_loss_factors(115e9, 0.10e9, 0.035e9, 0.35, 1650.0, 0.003, 0.12, 0.12)
RADIUS, LENGTH, WALL, K = (0.1016 - 3e-3) / 2, 7.26, 3e-3, 5 / 6


def crimping(angles_deg, G_13, G_23):
    a = np.radians(np.asarray(angles_deg, dtype=float))
    c, s, h = np.cos(a), np.sin(a), WALL / a.size
    A55 = K * h * np.sum(G_13 * c**2 + G_23 * s**2)
    A44 = K * h * np.sum(G_13 * s**2 + G_23 * c**2)
    A45 = K * h * np.sum((G_13 - G_23) * c * s)
    scale = 2 * np.pi * RADIUS**2
    return scale * (np.sqrt(A44 * A55) - A45), scale * (np.sqrt(A44 * A55) + A45)


def test_safety_factor_is_the_crimping_torque_over_the_torque():
    G = 0.035e8  # a tenth of the baseline G_LT as transverse shear modulus: crimping governs
    soft = Laminate.from_layup("(55/-55/0/0)s", WALL, replace(FMC, G_13=G, G_23=G))
    result = torsional_buckling_torque(soft, RADIUS, LENGTH)
    closed_form = 2 * np.pi * RADIUS**2 * K * G * WALL
    assert result.global_torque > closed_form  # the helix is stiffer: crimping must set the factor
    torque = np.array([100.0, -250.0])
    np.testing.assert_allclose(buckling_safety_factor(result, torque), closed_form / np.abs(torque), rtol=1e-12)
    assert result.crimping_torque == pytest.approx(closed_form, rel=1e-12)


def test_crimping_torque_of_an_unbalanced_wall_is_the_lower_sense():
    layup, angles = "(55/55/0/0)s", [55, 55, 0, 0, 0, 0, 55, 55]  # A45 != 0 splits the senses
    wall = Laminate.from_layup(layup, WALL, replace(FMC, G_13=0.035e9, G_23=0.02e9))
    result = torsional_buckling_torque(wall, RADIUS, LENGTH)
    low, high = crimping(angles, 0.035e9, 0.02e9)
    assert high / low > 1.25
    assert result.crimping_torque == pytest.approx(low, rel=1e-12)
    # positive sense: kx ky < 0, so N_xy = sqrt(A44 A55) - A45 (the closed form's first value)
    assert (result.crimping_torque_positive, result.crimping_torque_negative) == pytest.approx((low, high), rel=1e-12)

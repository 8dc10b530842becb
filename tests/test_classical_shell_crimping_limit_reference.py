"""The classical (Kirchhoff-Love) shell has no shear-crimping limit: its crimping torque is inf.

Reference (derived here from the closed form documented in docs/model.md): the shear-deformable
shell's short waves tend to the crimping limit T = 2πR²(√(A44 A55) ∓ A45), "the transverse shear
stiffness alone; k G t for isotropic shear moduli". The Kirchhoff-Love shell
(``theory="classical"``, "no transverse shear deformation") is that shell with a rigid
transverse shear: A44 = A55 = k G t → ∞, so its crimping limit is T → ∞ in both senses, and
no finite crimping torque can be reported for it (the ``BucklingResult`` docstring says "inf for
the classical shell"). The test first shows the closed form growing with G_13 = G_23 = G on the
shear shell (T_crimp = 2πR² k G t at two G, 1e-12: the closed form is evaluated, not converged),
then that the classical shell of the same wall reports inf for both senses and for the lower
one, beside a finite critical torque.
"""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from flexshaft.buckling import torsional_buckling_torque
from flexshaft.laminate import Lamina, Laminate

FMC = Lamina.from_loss_factors(115e9, 0.10e9, 0.035e9, 0.35, 1650.0, 0.003, 0.12, 0.12)
RADIUS, LENGTH, WALL, K = (0.1016 - 3e-3) / 2, 2.0, 3e-3, 5 / 6


def _wall(G: float) -> Laminate:
    return Laminate.from_layup("(45/-45)s", WALL, replace(FMC, G_13=G, G_23=G))


def test_crimping_limit_grows_with_the_transverse_shear_modulus():
    """T_crimp = 2πR² k G t (docs/model.md) on the shear shell: doubling G doubles it."""
    for G in (0.02e9, 0.04e9):
        shear = torsional_buckling_torque(_wall(G), RADIUS, LENGTH, theory="shear", n_terms=4, n_max=6)
        closed_form = 2 * math.pi * RADIUS**2 * K * G * WALL
        assert shear.crimping_torque == pytest.approx(closed_form, rel=1e-12)


def test_classical_shell_has_no_crimping_limit():
    """Rigid transverse shear (G → ∞ in the closed form): the crimping torque is inf, both senses."""
    classical = torsional_buckling_torque(_wall(0.035e9), RADIUS, LENGTH, theory="classical", n_terms=4, n_max=6)
    assert classical.crimping_torque_positive == math.inf
    assert classical.crimping_torque_negative == math.inf
    assert classical.crimping_torque == math.inf
    assert math.isfinite(classical.critical_torque) and classical.critical_torque > 0

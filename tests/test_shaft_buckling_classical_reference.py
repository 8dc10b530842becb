"""The shaft buckling check's classical-shell comparison is the classical (Kirchhoff-Love) shell.

References (derived). The classical shell takes the normals as inextensible and orthogonal to
the mid-surface: its transverse shear stiffness is infinite, so it has no shear-crimping limit
(T_crimp = 2π R² k G t of the shear-deformable shell, tests/test_shaft_buckling_reference.py,
grows without bound as G₁₃ = G₂₃ → ∞), and the shear deformation it leaves out can only soften
the shell (a Rayleigh quotient over a larger set of displacement fields, the shear strains no
longer forced to zero, is no larger): T_cr,classical ≥ T_cr,shear in each sense. Its safety
factor is, as the verdict's, T_cr/T in the weaker sense with T = P/Ω (Ω = 2π n/60 rad/s).
The tube is tests/test_shaft_buckling_reference.py's [0] tube (4 elements). Tolerance: round-off
(1e-12) for the safety factor; the inequality holds exactly.
"""

from __future__ import annotations

import math

import pytest
from test_shaft_buckling_reference import POWER, RPM, TUBE

from flexshaft.analyses.shaft_buckling import shaft_buckling
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def test_the_comparison_is_the_classical_shell_and_its_safety_factor_its_own():
    result = shaft_buckling(build_model(loads_design(TUBE)))
    shear, classical = result.result, result.classical
    assert shear.theory == "shear" and classical is not None and classical.theory == "classical"
    assert math.isinf(classical.crimping_torque_positive) and math.isinf(classical.crimping_torque_negative)
    assert classical.torque_positive >= shear.torque_positive
    assert classical.torque_negative >= shear.torque_negative
    torque = POWER / (RPM * 2 * math.pi / 60)
    weaker = min(classical.torque_positive, classical.torque_negative)
    out = result.to_dict()
    assert out["classical_critical_torque_Nm"] == pytest.approx(weaker, rel=1e-12)
    assert out["classical_safety_factor"] == pytest.approx(weaker / torque, rel=1e-12)

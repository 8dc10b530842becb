"""The shaft heat's worst imbalance load case and its heat per unit length (derived here).

References:

* documented rule (docs/thermal.md, "Shaft heat generation"): "with several load cases ("worst") the
  case with the most heat is used": the vibration heat of several cases is the per-element
  heat of ONE case, the one with the largest total, never a mix of cases;
* closed form, derived here: an axial stretch Δu of a bar element of length L, section A and
  complex modulus E(1 + iη) stores the loss stiffness K'' = ηEA/L on (u_a, u_b) with the
  pattern [[1, -1], [-1, 1]], so a harmonic Δu e^{iΩt} dissipates (thesis eq. 2.60)
  P = (Ω/2) ηEA/L |Δu|². On the lossy aluminium tube of tests/test_shaft_heat_whirl_reference.py
  (2 m, 50 x 2 mm, η = 0.02, 3000 rpm, 6 elements of L = 1/3 m):

  - case A, u = a at the node x = 1/3 m only: elements 0 and 1 stretched by a, P_A = [c, c, 0...],
    c = (Ω/2) ηEA/L a², total 2c;
  - case B, u = b at every node x ≥ 1 m: element 2 (2/3..1 m) alone stretched by b,
    P_B = [0, 0, c b²/a², 0...], total c b²/a².

  With b² = 1.5 a² case A is the worst (2c > 1.5c), with b² = 3 a² case B; the heat is then
  exactly that case's row: the element-wise maximum over the cases would put heat in all three
  elements.
* heat per unit length, derived here: element e's heat over its own length, P_e / (x_{e+1} − x_e).

Tolerances: the loss power is a quadratic form of 12-vectors (loss stiffness ~1e6 N/m,
amplitudes 1e-5 m, c ~ 0.02 W); rounding ~1e-15 relative, 1e-12 asserted; the unstretched
elements' heat is a cancellation of K''(u_a − u_b) with u_a = u_b exactly, so zero to ~1e-20 W
(1e-12 c asserted). CPU: one model build, a few milliseconds.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_shaft_heat_whirl_reference import field_vector, lossy_tube

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict
from flexshaft.thermal.heat import HeatSources, heat_sources

E, ETA, DO, T_WALL, RPM = 70e9, 0.02, 0.05, 0.002, 3000.0


@pytest.fixture(scope="module")
def model():
    return build_model(design_from_dict(lossy_tube({"eccentricity": 0.0})))


def stretch_heat(model, du: float) -> float:
    """(Ω/2) ηEA/L du² for one element of the tube (derived in the module docstring)."""
    ends = model.dofs.shaft_element_x
    L = float(ends[0, 1] - ends[0, 0])
    A = math.pi / 4 * (DO**2 - (DO - 2 * T_WALL) ** 2)
    Omega = RPM * math.pi / 30
    return 0.5 * Omega * ETA * E * A / L * du**2


@pytest.mark.parametrize("b2_over_a2, worst", [(1.5, "A"), (3.0, "B")])
@pytest.mark.parametrize("loss_model", ["thesis", "rotating"])
def test_several_load_cases_give_the_heat_of_the_worst_single_case(model, loss_model, b2_over_a2, worst):
    ends = model.dofs.shaft_element_x
    assert ends.shape[0] == 6 and np.allclose(ends[:, 1] - ends[:, 0], 1 / 3, rtol=1e-12)
    a = 1e-5
    b = a * math.sqrt(b2_over_a2)
    node1 = float(ends[0, 1])
    case_a = field_vector(model, {"u": lambda x: np.where(np.isclose(x, node1), a, 0.0)})
    case_b = field_vector(model, {"u": lambda x: np.where(x >= 1.0 - 1e-9, b, 0.0)})
    q_imb = np.column_stack([case_a, case_b])
    q_static = np.zeros(model.dofs.size)
    src = heat_sources(model, loss_model, q_imb, q_static)
    c = stretch_heat(model, a)
    expected = np.zeros(6)
    if worst == "A":
        expected[:2] = c
    else:
        expected[2] = c * b2_over_a2
    # axial motion is cycled at Ω in both loss models (docs/thermal.md), so both give P above
    assert src.vibration == pytest.approx(expected, rel=1e-12, abs=1e-12 * c)
    assert np.all(src.static == 0.0)


def test_heat_per_length_is_each_element_over_its_own_length():
    x = np.array([0.0, 0.5, 2.0, 2.25])
    vibration = np.array([1.0, 3.0, 0.5])
    static = np.array([2.0, 0.0, 0.25])
    src = HeatSources(x, vibration, static, "thesis", 100.0)
    # hand: (1 + 2)/0.5, (3 + 0)/1.5, (0.5 + 0.25)/0.25
    assert src.per_length == pytest.approx([6.0, 2.0, 3.0], rel=1e-15, abs=0)

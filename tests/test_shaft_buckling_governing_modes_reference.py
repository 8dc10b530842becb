"""Each sense of the shaft's buckling reports its own governing mode (global helix or crimping).

A [+45] carbon/epoxy tube (0.2 m long, 101.6 mm, 3 mm) whose ply is given a soft transverse
shear modulus G₁₃ = 0.2 GPa in the fibre-thickness plane buckles in two different ways in
the two senses of the torque. The shear-crimping limit of :mod:`flexshaft.buckling` (derived
here from its documented A-matrix closed form, as in tests/test_buckling_weaker_sense_reference.py):
for plies at +45° (the standard rotation Q̄44, Q̄55 = G₁₃ cos²θ + G₂₃ sin²θ and its mirror,
Q̄45 = (G₁₃ − G₂₃) cos θ sin θ), A44 = A55 = k t (G₁₃ + G₂₃)/2, A45 = k t (G₁₃ − G₂₃)/2, so
T = 2πR²(√(A44 A55) ∓ A45) gives T₊ = 2πR² k t G₂₃ and T₋ = 2πR² k t G₁₃, with
R = (D − t)/2 = 49.3 mm the mid-surface radius, k = 5/6 the lamina's default shear
correction and G₂₃ = E_T/3 = 2.667 GPa the default (ν₂₃ = 0.5,
:mod:`flexshaft.design.materials`): T₊ = 101 808.127 N m and T₋ = 7 635.610 N m.

* Negative sense: the critical torque equals T₋ = 2πR² k t G₁₃, the crimping limit, so the
  mode that governs is "shear crimping" and its wave number is None (the documented meaning of
  None in :meth:`~flexshaft.analyses.shaft_buckling.ShaftBuckling.to_dict`: the crimping
  limit, n → ∞).
* Positive sense: the critical torque is far below its crimping limit T₊ (under a tenth of it,
  where a shorter-wave shear mode would sit near T₊) with a small wave number, the long-wave
  helix: "global helical". These two bounds are qualitative (chosen, not derived: the code
  gives 0.071 T₊ and n = 4); the negative sense alone carries the catch.

So a report that gives one sense the other's governing mode fails one of the two. Tolerance
1e-9 on T₋: a few products and one square-root difference of the closed form (about 1e-15
relative; the two G differ by a factor 13, so the difference loses about one digit).
"""

from __future__ import annotations

import math

import pytest
from test_shaft_buckling_senses_reference import TUBE as SENSES_TUBE

from flexshaft.analyses.shaft_buckling import shaft_buckling
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

L, D, WALL, G13, G23 = 0.2, 0.1016, 0.003, 0.2e9, 8.0e9 / 3

#: tests/test_shaft_buckling_senses_reference.py's one-ply tube (same L, D, wall), its ply at +45°
#: and given the soft G₁₃.
TUBE = (
    SENSES_TUBE.replace('name = "one-ply tube"', 'name = "soft-core one-ply tube"')
    .replace('layup = "ANGLE"', 'layup = "45"')
    .replace("G_LT = 4.0e9\n", f"G_LT = 4.0e9\nG_13 = {G13}\n")
)


@pytest.fixture(scope="module")
def numbers():
    return shaft_buckling(build_model(loads_design(TUBE)), compare_classical=False).to_dict()


def test_the_negative_sense_crimps_and_says_so(numbers):
    crimping = 2 * math.pi * ((D - WALL) / 2) ** 2 * (5 / 6) * WALL  # 2πR² k t, per pascal of G
    assert numbers["crimping_torque_negative_Nm"] == pytest.approx(crimping * G13, rel=1e-9)  # 7 635.610
    assert numbers["critical_torque_negative_Nm"] == pytest.approx(crimping * G13, rel=1e-9)
    assert numbers["wave_number_negative"] is None
    assert numbers["governing_negative"] == "shear crimping"


def test_the_positive_sense_buckles_in_the_long_helix_and_says_so(numbers):
    crimping = 2 * math.pi * ((D - WALL) / 2) ** 2 * (5 / 6) * WALL
    assert numbers["crimping_torque_positive_Nm"] == pytest.approx(crimping * G23, rel=1e-9)  # 101 808.127
    assert numbers["critical_torque_positive_Nm"] < 0.1 * crimping * G23
    assert numbers["wave_number_positive"] is not None and numbers["wave_number_positive"] <= 6
    assert numbers["governing_positive"] == "global helical"

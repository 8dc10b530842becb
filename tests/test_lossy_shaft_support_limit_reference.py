"""The rigid-support limit of a lossy shaft is counted with the storage modulus E, not |E*|.

:mod:`flexshaft.assembly.checks` refuses a support stiffer than RIGID_RATIO = 1e8 times one
shaft element's bending stiffness E I/h³ (docs/limits.md, "Support stiffness against one shaft
element"; which E it does not say). The limit guards the conditioning of the stiffness matrix K,
and a hysteretic material's modulus is E(1 + iη): docs/model.md ("One damping physics") keeps
the loss "besides the storage stiffness" in three real loss matrices, so the real part E builds
K and iηE the separate loss stiffness. So the element stiffness is E I/h³ whatever η. (η = 0.75
is no steel's, but the schema allows it and the rule does not depend on the material.)

Reference values, derived here. The steel tube of tests/test_support_limit_law_reference.py
(E = 210 GPa, D_o = 20 mm, wall 1 mm, 2 m in 2 elements, h = 1 m) has E I/h³ = 567 N/m,
I = π(D_o⁴ − D_i⁴)/64, and the limit 5.67e10 N/m. With η = 0.75 the magnitude
|E*| = E sqrt(1 + 0.75²) = 1.25 E exactly, so a limit counted with |E*| would be 25 % higher.
A hanger at 1.1 limits lies between the two: refused with the storage modulus, allowed with
|E*|; 0.9 limits is allowed by either. 10 % either side, far beyond the round-off (1e-15) of
the few operations each side computes.

The element stiffness itself is compared with E I/h³ at rel 1e-14 (a few roundings of
products and a cube, each 1.1e-16, and the cancellation in D_o⁴ − D_i⁴, which amplifies them
about 2.9×: about 1e-15).

CPU: three model builds of a 2-element tube, about 0.1 s.
"""

from __future__ import annotations

import pytest
from test_magnet_geometry_support_limit import design as tube_text
from test_magnet_geometry_support_limit import element_limit

from flexshaft.assembly import build_model
from flexshaft.assembly.checks import element_stiffness
from flexshaft.design import DesignError, loads_design

TUBE = (0.02, 0.001, 2.0, 2)  # outer diameter, wall, length [m], elements: E I/h³ = 567 N/m
ETA = 0.75  # |1 + i η| = 1.25 exactly
PD = "kp = 1e5\nkd = 0.0"


def lossy_design(hanger_v: float):
    text = tube_text(*TUBE, PD, hanger_v=hanger_v)
    text = text.replace("density = 7800.0\n", f"density = 7800.0\nloss_factor = {ETA!r}\n", 1)
    return loads_design(text)


def test_the_element_stiffness_uses_the_storage_modulus():
    soft = lossy_design(1e5)
    model = build_model(soft)
    assert model.shaft.youngs_modulus.imag == pytest.approx(
        ETA * 210e9, rel=1e-15
    )  # lossy indeed (0.75 × 210e9 is exact in binary: ulps of room)
    reference = element_stiffness(soft, model.shaft)
    assert 1e8 * reference["v"] == pytest.approx(element_limit(*TUBE), rel=1e-14)


def test_a_lossy_shaft_refuses_a_support_between_the_storage_and_magnitude_limits():
    limit = element_limit(*TUBE)  # storage modulus E: 5.67e10 N/m
    build_model(lossy_design(0.9 * limit))
    with pytest.raises(DesignError, match=r"bearings\[0\]\.stiffness\.v"):
        build_model(lossy_design(1.1 * limit))  # under the |E*| limit 1.25 limit, over E's

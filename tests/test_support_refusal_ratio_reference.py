"""The too-stiff refusal states how many shaft elements the support is (hunt h101e).

Reference, derived here from the hand-written rule of docs/limits.md: "A contact stiffness,
`ki·kp` or `ks` above 1e8 times the element's stiffness (E A/h axially, E I/h³ laterally, E I/h
in rotation, with h = shaft length / `mesh.shaft_elements`) is refused". The refusal says
"k is R times the <stiffness> of one shaft element (k_e)": R is the support stiffness in units of
one element's, R = k / k_e, with k_e the closed form of that rule for the direction.

The steel tube of the sibling tests (E = 210 GPa, D_o = 20 mm, wall 1 mm: I = π(D_o⁴ − D_i⁴)/64
= 2.70e-9 m⁴), 2 m in 4 elements (h = 0.5 m): k_e = E I/h = 1134 N m/rad in rotation and
E I/h³ = 4537 N/m laterally. A support of 1.25 × 1e8 k_e must be stated as R = 1.25e8 times
k_e (an inverted ratio k_e/k would read 8e-9). Both R and k_e are printed to 3 significant
digits, so they are compared to 5e-3 relative (half a unit in the third digit is at most 5e-3
of the leading one); measured: 0 for R (1.25e+08 exactly), 3.9e-3 (rotation, 1.13e+03 printed for
1134) and 5e-4 (lateral) for k_e, the rounding to 3 digits.

CPU: two refused builds of a 4-element tube, well under 0.1 s. Written for
h101e-checks-too-stiff-ratio-inverted of scripts/mutations.toml.
"""

from __future__ import annotations

import re

import pytest

# the 4-element steel tube, its E I and the documented ratio 1e8; the design text of a refused
# support at the hanger
from test_rotational_support_and_pid_law_reference import ELEMENTS, LENGTH, RIGID_RATIO, _ei
from test_support_refusal_units_reference import _text

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, loads_design

#: The refused support in units of the allowed bound (25 % beyond it: the refusal is certain).
BEYOND = 1.25


@pytest.mark.parametrize(("direction", "power_of_h", "what"), [("beta", 1, "E I/h"), ("v", 3, "E I/h³")])
def test_the_refusal_states_the_support_in_units_of_one_element(direction, power_of_h, what):
    """R in "k is R times the ... of one shaft element (k_e)" is k / k_e, k_e = E I/h^p."""
    element = _ei() / (LENGTH / ELEMENTS) ** power_of_h
    stiffness = BEYOND * RIGID_RATIO * element
    others = ", ".join(f"{d} = 1e5" for d in ("v", "w") if d != direction)
    with pytest.raises(DesignError) as refused:
        build_model(loads_design(_text(f"{others}, {direction} = {stiffness!r}")))
    message = str(refused.value)
    stated = re.search(r" is ([0-9.e+-]+) times the (.+?) of one shaft element \(([0-9.e+-]+) ", message)
    assert stated is not None, message
    assert what in stated.group(2)
    assert float(stated.group(1)) == pytest.approx(BEYOND * RIGID_RATIO, rel=5e-3)
    assert float(stated.group(3)) == pytest.approx(element, rel=5e-3)

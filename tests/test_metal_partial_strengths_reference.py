"""A metal that gives only some of its strengths is not strength-checked (documented rule), and
its tube is still checked for buckling (closed form derived here).

Documented rule: :class:`~flexshaft.design.materials.Isotropic` makes each of ``yield_strength``,
``ultimate_strength`` and ``fatigue_strength`` optional; the DE-Goodman line needs S_e and S_ut
and the first-cycle yield check S_y (Shigley eqs. 7-7, 7-16), so with one of them missing
neither safety factor exists. :func:`~flexshaft.analyses.metal_strength.metal_strength`
documents: "Empty (``evaluated`` False) when no isotropic segment gives its strengths", and its
note names the segment and the strength its material leaves out ("(missing: fatigue_strength)";
review r115: the note used to read "gives no yield_strength, ultimate_strength and
fatigue_strength" when only one was missing, as if none were given). A material giving S_y
and S_ut but no S_e (a common case: the endurance limit of the part is not known yet) must
therefore give an empty result with that note, not a failed analysis; the same holds for every single strength left out.

The buckling record does not need the strengths: its critical torque is the tube's, checked
against Timoshenko & Gere (1961) sec. 11.12's long-tube τ_cr = E/(3√2 (1 − ν²)^{3/4}) (t/r)^{3/2}
times the torque arm 2π r² t (r = (D_o − t)/2 the mid-surface; as quoted in
tests/test_metal_buckling_without_strengths_reference.py, which measured +6.5 % for this tube of
r/t = 12, the O(t/r) thickness correction): within 10 %. Its torque is P/Ω by hand (1e-12: one
division).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_metal_buckling_without_strengths_reference import D_O, POWER, RPM, STRENGTHS, WALL, E, G, _tube

from flexshaft.analyses.metal_strength import metal_strength

# The tube of tests/test_metal_buckling_without_strengths_reference.py (same material, mesh and
# operating point), with its strengths given one by one here.
ALL = STRENGTHS


@pytest.mark.parametrize("missing", sorted(ALL))
def test_one_missing_strength_leaves_the_segment_unchecked(missing):
    given = {k: v for k, v in ALL.items() if k != missing}
    model = _tube(given)
    static = np.zeros(model.dofs.size)
    result = metal_strength(model, static)
    assert not result.evaluated
    assert result.x.size == 0
    (note,) = result.notes
    assert f"(missing: {missing})" in note
    (b,) = result.buckling
    torque = POWER / (RPM * 2 * math.pi / 60)
    assert b.torque == pytest.approx(torque, rel=1e-12)
    r, nu = (D_O - WALL) / 2, E / (2 * G) - 1
    tau_long = E / (3 * math.sqrt(2) * (1 - nu**2) ** 0.75) * (WALL / r) ** 1.5
    assert b.critical_torque == pytest.approx(2 * math.pi * r**2 * WALL * tau_long, rel=0.10)

"""The ``[shaft]`` table's ply angles are the layup string's, inner ply first.

docs/design-reference.md (``[shaft] layup``): "Ply angles [deg] from the shaft axis, inner ply
first". :attr:`flexshaft.design.components.Shaft.ply_angles_deg` is the public reading of that
string (the package docstring's example, the optimizer's reference designs); the model's
nominal tube (``model.shaft``: strength and buckling) is built from it, and each segment's
tube from :attr:`Shaft.tubes`. All must list the angles of the string in its order: reversed,
an unsymmetric layup is another laminate (z -> -z: the bending-extension coupling B changes
sign, D is unchanged). By hand, "30/-60/0/90" is the four angles 30, -60, 0, 90
from the inner surface out; "(30/-60)s" is 30, -60, -60, 30 (the ``s`` mirrors the group).
"""

from __future__ import annotations

import copy

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict, embedded_design


def _baseline_with_layup(layup: str):
    data = copy.deepcopy(embedded_design("baseline").model_dump())
    data["shaft"]["layup"] = layup
    return design_from_dict(data)


@pytest.mark.parametrize(
    "layup, angles", [("30/-60/0/90", (30.0, -60.0, 0.0, 90.0)), ("(30/-60)s", (30.0, -60.0, -60.0, 30.0))]
)
def test_the_shaft_lists_its_plies_inner_ply_first(layup, angles):
    design = _baseline_with_layup(layup)
    assert design.shaft.ply_angles_deg == angles
    assert design.shaft.tubes[0].ply_angles_deg == angles


def test_the_model_laminate_carries_the_shafts_angles():
    """Against the angles expanded by hand (not the design's own reading of them)."""
    model = build_model(_baseline_with_layup("30/-60/0/90"))
    by_hand = np.radians([30.0, -60.0, 0.0, 90.0])
    np.testing.assert_array_equal(model.shaft.laminate.angles, by_hand)
    np.testing.assert_array_equal(model.segments[0].properties.laminate.angles, by_hand)

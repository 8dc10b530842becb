"""The optimizer's mass objective (:mod:`flexshaft.optimize.mass`) by hand from the design file.

The tuned driveline (its design file): one FMC tube, density 1650 kg/m³ (thesis Table 3.2),
D_o 0.1016 m, wall 3.75 mm, 8.05 m long: ρ π/4 (D_o² − D_i²) L = 15.3116 kg; two 1.4 kg hangers
and two 7.0 kg actuators (1500 N each: the estimate 7.0 kg/1500 N gives the same 7.0 kg, so an
actuator whose file mass is used cannot be told from one estimated unless its mass differs).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict, tuned_design, with_overrides
from flexshaft.optimize.mass import driveline_mass, driveline_mass_parts

TUBE = 1650.0 * math.pi / 4 * (0.1016**2 - (0.1016 - 2 * 3.75e-3) ** 2) * 8.05  # 15.3116 kg


def test_tuned_driveline_mass_by_hand():
    """Tube + hangers + actuators, to 1e-12 (the same products in another order)."""
    model = build_model(tuned_design())
    assert TUBE == pytest.approx(15.3116, abs=1e-4)
    assert driveline_mass(model) == pytest.approx(TUBE + 2 * 1.4 + 2 * 7.0, rel=1e-12)


def test_an_actuator_mass_given_in_the_file_is_the_one_counted():
    """An actuator of 5.0 kg in the file (1500 N, whose estimate would be 7.0 kg) counts 5.0 kg,
    from the design; its neighbour without a mass is estimated at 7.0 kg."""
    design = with_overrides(tuned_design(), {"bearings[1].mass": 5.0, "bearings[2].mass": 0.0})
    model = build_model(design)
    parts = driveline_mass_parts(model)
    assert parts["amb_1"] == (5.0, "design")
    assert parts["amb_2"] == (pytest.approx(7.0, rel=1e-12), "estimate")
    assert driveline_mass(model) == pytest.approx(TUBE + 2 * 1.4 + 5.0 + 7.0, rel=1e-12)


def test_a_contact_bearing_without_a_role_is_a_hanger_whose_mass_counts():
    """The schema's documented default (docs/design-reference.md, ``role``: "hanger"): a contact
    bearing written without ``role`` supports the shaft and its mass is a driveline part; with
    ``role = "gearbox"`` it ends the driveline and is not counted (optimize/mass.py). Read from
    a design with the role removed explicitly, so the check does not rest on how the embedded
    file happens to be written. Exact sums of the same doubles: 1e-12 relative."""
    data = tuned_design().model_dump(mode="json", exclude_none=True)
    contact = [b for b in data["bearings"] if b["kind"] == "contact"]
    for bearing in contact:
        bearing.pop("role", None)
    model = build_model(design_from_dict(data))
    assert all(b.role == "hanger" for b in model.design.bearings if b.kind == "contact")
    assert driveline_mass(model) == pytest.approx(TUBE + 2 * 1.4 + 2 * 7.0, rel=1e-12)
    data["bearings"][data["bearings"].index(contact[0])]["role"] = "gearbox"
    assert driveline_mass(build_model(design_from_dict(data))) == pytest.approx(TUBE + 1.4 + 2 * 7.0, rel=1e-12)

"""What a hybrid driveline's operating point hands to its metal and coupling checks, against the
design and closed forms.

docs/requirements.md: the ``metal_strength`` check applies "only when the shaft has an isotropic
segment" -- one is enough; a shaft of metal and laminated segments has its metal ones judged
(docs/segmented-driveline.md). The driveline here is the packaged ``current`` design (five
aluminium 6061-T6 tubes joined by four couplings) with its middle tube (tube_3) made of the
tuned design's T700/Adiprene laminate: by construction the metal segments are tube_1, tube_2,
tube_4 and tube_5, and each of their elements carries the mean shear stress of Saint-Venant
torsion of a circular tube (Timoshenko & Goodier, *Theory of Elasticity*, circular shafts)

    τ_m = f · (P/Ω) · (D_o/2) / J,   J = π (D_o⁴ − D_i⁴)/32,

with f the torsional response's peak-over-steady torque factor (checked against the damped
one-DOF closed form in tests/test_torsional.py). The linear twist elements are exact for a
constant torque: rel 1e-6 (the static solve's round-off on the baseline's conditioning, as in
tests/test_point_loads_reference.py).

**Coupling misalignment at speed.** docs/requirements.md: the coupling check holds the static
plus the imbalance response's misalignment. The imbalance response at the operating speed is a
complex vector q (displacement Re(q e^{iΩt})); a coupling's dynamic angle is the largest
amplitude of the relative flange rotation (Δβ, Δγ) = (a, b) over the phase φ = Ωt. By hand,
Re(a e^{iφ})² + Re(b e^{iφ})² = (|a|² + |b|²)/2 + Re((a² + b²) e^{2iφ})/2, whose maximum over
φ gives the ellipse's semi-major axis √((|a|² + |b|² + |a² + b²|)/2); the worst load case
(column of q) is kept. Read off the point's own imbalance response at the flange nodes: rel
1e-12 (the same numbers through two formulas). The couplings of ``current`` bend under the
imbalance, so every angle is above 0.

Coarse meshes (18 shaft, 12 boom elements) and the smallest grids a resolution accepts: the
torque and the segment list do not depend on them (CPU budget, issue 23).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import SMALLEST

from flexshaft.design import embedded_design, tuned_design
from flexshaft.design.io import design_from_dict
from flexshaft.verdict.operating_point import analyse_point


def _hybrid():
    data = embedded_design("current").model_dump()
    tuned = tuned_design()
    data["materials"]["t700_adiprene"] = tuned.materials["t700_adiprene"].model_dump()
    middle = data["shaft"]["segments"][2]
    assert middle["name"] == "tube_3"
    middle["material"], middle["layup"] = "t700_adiprene", tuned.shaft.layup
    data["mesh"]["shaft_elements"], data["mesh"]["boom_elements"] = 18, 12
    return design_from_dict(data, "<hybrid current>")


@pytest.fixture(scope="module")
def point():
    return analyse_point(_hybrid(), SMALLEST, detail=False)


def test_a_hybrid_shafts_metal_segments_are_judged_with_the_peak_torque(point):
    p = point
    metal = p.metal_strength
    assert metal is not None, "a shaft with isotropic segments must have its metal strength evaluated"
    assert set(metal.segment) == {"tube_1", "tube_2", "tube_4", "tube_5"}
    torque = p.torque_factor * p.model.power / p.model.speed
    tubes = {seg.name: seg.properties for seg in p.model.segments}
    for name, tau in zip(metal.segment, metal.tau_mean):
        d_o, d_i = tubes[name].outer_diameter, tubes[name].inner_diameter
        expected = torque * (d_o / 2) / (math.pi * (d_o**4 - d_i**4) / 32)
        np.testing.assert_allclose(tau, expected, rtol=1e-6, err_msg=name)


def test_the_coupling_misalignment_holds_the_imbalance_response(point):
    p = point
    found = p.coupling_misalignment
    assert found is not None and len(found.names) == len(p.model.couplings) == 4
    dm, q = p.model.dofs, np.asarray(p.imbalance_at_speed).reshape(p.model.dofs.size, -1)
    for k, c in enumerate(p.model.couplings):
        a = q[dm.shaft(c.node_b, "beta")] - q[dm.shaft(c.node_a, "beta")]
        b = q[dm.shaft(c.node_b, "gamma")] - q[dm.shaft(c.node_a, "gamma")]
        major = np.sqrt((abs(a) ** 2 + abs(b) ** 2 + abs(a**2 + b**2)) / 2)
        assert found.dynamic_angle[k] == pytest.approx(float(np.max(major)), rel=1e-12), c.name
        assert found.dynamic_angle[k] > 0.0, c.name


def test_the_bearing_reactions_hold_the_imbalance_response(point):
    """A contact bearing is a Kelvin-Voigt spring-dashpot per direction: at the spin speed Ω its
    complex force amplitude is F = (k + iΩc) Δ over the relative motion Δ (shaft minus support),
    with k and c of the design file (the hangers' 3e6 N/m and 1000 N s/m, the damper's 2e4 N/m
    and 150 N s/m). The imbalance bends the shaft at every bearing, so Δ ≠ 0; rel 1e-12."""
    p = point
    omega = p.model.speed
    for bearing in p.design.bearings:
        if bearing.name == "gearbox_input":
            continue
        found = p.bearing_reactions[bearing.name]
        assert found.speed == omega
        for row, axis in ((1, "v"), (2, "w")):
            motion = found.imbalance_motion[row]
            assert np.all(np.abs(motion) > 0), (bearing.name, axis)
            expected = (bearing.stiffness[axis] + 1j * omega * bearing.damping[axis]) * motion
            np.testing.assert_allclose(found.imbalance_force[row], expected, rtol=1e-12, err_msg=bearing.name)

"""The spin-up envelope is the worst imbalance case's: a shaft on three bearings, two equal bays.

Reference: a uniform shaft over three equally spaced rigid supports has, as its first bending
mode, each bay bending as a simply supported span of length ℓ in antiphase with its neighbour,
ω₁ = π²√(EI/ρA)/ℓ² (by antisymmetry the bending moment vanishes at the middle support), and as
its second the symmetric mode (zero slope there: each bay pinned-clamped, ω₂ = (3.927/π)² ω₁).
The ``"worst"`` imbalance placement loads the bays' midpoints in phase (case 0) and in antiphase
(case 1): by the modes' symmetry the antiphase case alone excites mode 1, the in-phase case mode
2. So near ω₁ the worst case is the antiphase one and near ω₂ the in-phase one, and the envelope
at every speed is the orbit of the case with the largest orbit over the shaft: computed here by
brute force from the full responses of both cases. The supports (10⁸ N/m) move ω₁ about 0.4 %
below the pinned value (and ω₂ to 1.54 ω₁); 3 % is asserted for the frequency, the envelope to
1e-12 (the same solves, no arithmetic between).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.response import imbalance_response, orbit_amplitude
from flexshaft.analyses.spinup_response import spinup_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import loads_design

E, RHO, DO, WALL, SPAN = 210e9, 7800.0, 0.05, 0.003, 1.0


def _bearing(name: str, x: float) -> str:
    return (
        f'[[bearings]]\nname = "{name}"\nkind = "contact"\nx = {x}\n'
        "stiffness = { v = 1e8, w = 1e8 }\ndamping = { v = 300.0, w = 300.0 }\n"
    )


TEXT = f"""
name = "two equal bays"
[materials.steel]
kind = "isotropic"
E = {E}
G = 80e9
density = {RHO}
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = {2 * SPAN}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "theta"]
{_bearing("a", 0.0)}{_bearing("b", SPAN)}{_bearing("c", 2 * SPAN)}
[operating]
speed_rpm = 3000.0
power = 0.0
[loads]
imbalance_placement = "worst"
eccentricity = 1e-5
[mesh]
shaft_elements = 8
"""


def test_spinup_envelope_is_the_orbit_of_the_worst_imbalance_case():
    model = build_model(loads_design(TEXT))
    di = DO - 2 * WALL
    w1 = np.pi**2 * np.sqrt(E * np.pi * (DO**4 - di**4) / 64 / (RHO * np.pi * (DO**2 - di**2) / 4)) / SPAN**2
    speeds = np.array([0.5, 0.98, 1.02, 1.3, 1.6]) * w1  # ω₂ = 1.54 ω₁ on these supports
    result = spinup_response(model, speeds, projected=False)
    q = np.asarray(imbalance_response(model, speeds, imbalance_loads(model)))  # (ndof, 2 cases, speeds)
    nodes = np.arange(model.dofs.n_shaft_nodes)
    orbits = orbit_amplitude(q[model.dofs.shaft(nodes, "v")], q[model.dofs.shaft(nodes, "w")])
    worst = np.argmax(orbits.max(axis=0), axis=0)
    assert list(worst[1:3]) == [1, 1] and worst[-1] == 0  # antiphase near ω₁, in phase near ω₂
    np.testing.assert_allclose(result.envelope, orbits[:, worst, np.arange(speeds.size)], rtol=1e-12)
    np.testing.assert_allclose(result.shaft_peak, orbits.max(axis=(0, 1)), rtol=1e-12)
    peak = np.argmax(result.shaft_peak[:3])
    assert speeds[peak] == pytest.approx(w1, rel=0.03)

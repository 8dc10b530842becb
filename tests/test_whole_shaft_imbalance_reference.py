"""The imbalance of a shaft without a bay (fewer than two bearings) acts at the middle of the
whole shaft (flexshaft.assembly.loads.imbalance_loads).

Reference: a bay is the span between consecutive bearings (flexshaft.assembly.balance.
imbalance_bays); with none, the loads module takes the whole shaft as the one bay (documented
in per_bay_imbalance_loads: "Bay b (imbalance_bays, or the whole shaft when there are none)"),
and "mid_bay" puts "a point force at each bay's midpoint" (imbalance_loads's docstring). The
Jeffcott rotor (tests/validation design ``jeffcott_internal_damping.toml``: shaft x = 0 to 1 m,
one damper at 0.5 m, 8 elements) has no bay, so its imbalance force F = e m (per unit Ω²) sits
at x = 0.5 m.

Physically (derived here): with no bay the rotor's static unbalance e m acts at its mass
centre, which for this rotor (10 kg disk at 0.5 m on a uniform tube over 0-1 m) is x = 0.5 m
by symmetry, the shaft's middle too. The two rules agree for this rotor only; the loads
module's rule (the middle of the whole shaft) is what the test holds, the mass centre what
makes it the right answer here.

Derived here: a consistent nodal load vector of a point force F in y at x_F has the resultant
Σ Q_v = F and the moment about z at x = 0, Σ x_i Q_v,i + Σ Q_γ,i = F x_F (the cubic shape
functions reproduce rigid translation and rotation exactly; the same resultants as
tests/test_assembly_load_resultants_reference.py uses). So the centroid Mz / F = 0.5 m, and F
itself is e m with m = 10 kg of disk + ρ A L of tube (ρ = 0.01 kg/m³, A = π/4 (D² − d²)),
rotating_mass's parts (tubes and disks). The w components are −i times the v components
(Q_w = −i F). Sums of nine nodal values of size 1e-3: rel 1e-12 on the resultant, abs 1e-12 m
on the centroid (the first element's midpoint, 0.0625 m, is 0.44 m away).

The Monte-Carlo run-up's per-bay loads (per_bay_imbalance_loads) follow the same rule: with no
bay the one bay is the whole shaft (its docstring, quoted above), and bay b's unbalance U_b at
angle ψ_b sits at x = a_b + position_b (b_b − a_b) with Q_v = U_b e^{iψ_b}, Q_w = −i Q_v (its
docstring). For the Jeffcott shaft (a = 0, b = 1 m) a position of 0.25 puts it at x = 0.25 m,
away from every element midpoint (the first element's, 0.0625 m, is where a first-element bay
would put a mid-bay load; its quarter point 0.03125 m). Same sums, same tolerances as above
(|U| = 2e-3 kg m).

One 8-element model is built per test: a few ms.

Written for the mutations h57b-loads-no-bay-imbalance-first-element and
h82a-loads-per-bay-no-bay-first-element of scripts/mutations.toml.
"""

from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_bays, imbalance_loads, per_bay_imbalance_loads
from flexshaft.design import design_from_dict
from flexshaft.validation.runner import design_text


def test_a_shaft_without_a_bay_carries_its_imbalance_at_mid_shaft():
    model = build_model(design_from_dict(tomllib.loads(design_text("jeffcott_internal_damping.toml"))))
    assert imbalance_bays(model) == []
    e = 1.0e-4
    Q = imbalance_loads(model, "mid_bay", eccentricity=e)[:, 0]
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    x = dm.shaft_x
    v, w, gamma = (Q[dm.shaft(nodes, f)] for f in ("v", "w", "gamma"))
    d_out, d_in = 0.02, 0.02 - 2 * 0.0099999
    mass = 10.0 + 0.01 * math.pi / 4 * (d_out**2 - d_in**2) * 1.0
    force = v.sum()
    assert force.real == pytest.approx(e * mass, rel=1e-12)
    assert abs(force.imag) <= 1e-15
    centroid = ((x * v).sum() + gamma.sum()) / force
    assert abs(centroid - 0.5) <= 1e-12
    np.testing.assert_allclose(w, -1j * v, rtol=0, atol=1e-15)


@pytest.mark.parametrize("position", [0.5, 0.25])
def test_the_run_up_unbalance_of_a_shaft_without_a_bay_spans_the_whole_shaft(position):
    model = build_model(design_from_dict(tomllib.loads(design_text("jeffcott_internal_damping.toml"))))
    assert imbalance_bays(model) == []
    U, psi = 2.0e-3, 0.7
    Q = per_bay_imbalance_loads(model, U, angle=psi, position=position)
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    x = dm.shaft_x
    v, w, gamma = (Q[dm.shaft(nodes, f)] for f in ("v", "w", "gamma"))
    force = v.sum()
    expected = U * np.exp(1j * psi)
    assert abs(force - expected) <= 1e-12 * U
    centroid = ((x * v).sum() + gamma.sum()) / force
    assert abs(centroid - position * 1.0) <= 1e-12
    np.testing.assert_allclose(w, -1j * v, rtol=0, atol=1e-15)

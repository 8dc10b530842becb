"""The imbalance of a shaft without a bay (fewer than two bearings) acts at the middle of the
whole shaft (flexshaft.assembly.loads.imbalance_loads).

Reference: a bay is the span between consecutive bearings (flexshaft.assembly.balance.
imbalance_bays); with none, the loads module takes the whole shaft as the one bay (API
contract, per_bay_imbalance_loads's docstring: "Bay b (imbalance_bays, or the whole shaft when
there are none)"; no hand-written doc states it), and "mid_bay" puts "a point force at each
bay's midpoint" (API contract, imbalance_loads's docstring). The
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
bay the one bay is the whole shaft, and bay b's unbalance U_b at angle ψ_b sits at
x = a_b + position_b (b_b − a_b) with Q_v = U_b e^{iψ_b}, Q_w = −i Q_v (API contract,
per_bay_imbalance_loads's docstring, quoted above; no hand-written doc states it). For the
Jeffcott shaft (a = 0, b = L = 1 m) a position of 0.25 puts it at x = 0.25 m, away from every
element midpoint (the first element's, 0.0625 m, is where a first-element bay would put a
mid-bay load; its quarter point 0.03125 m). Same sums, same tolerances as above
(|U| = 2e-3 kg m). Positions 0.5 and 0.25 sit on nodes (8 elements of 0.125 m), where the
consistent load is the nodal force alone (Q_γ ≡ 0); position 0.3 (x = 0.3 m, 0.4 of the way
into the third element) is off-node, so the end couples Q_γ carry part of the moment and the
centroid tests the "+ Σ Q_γ" of the moment resultant (with "−" it would read 0.288 m).

Also derived here: a zero eccentricity is a perfectly balanced rotor, F = e m Ω² = 0, which
imbalance_loads accepts ("finite and >= 0", its docstring) as a zero load vector, and a design
with neither ``eccentricity`` nor ``balance_grade`` (the schema's default eccentricity 0, the
Jeffcott design has no [loads] table) has a zero unbalance response at every speed.

One 8-element model is built per test: a few ms.

Written for the mutations h57b-loads-no-bay-imbalance-first-element,
h82a-loads-per-bay-no-bay-first-element and h82a-loads-zero-eccentricity-refused of
scripts/mutations.toml.
"""

from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from flexshaft.analyses.response import imbalance_response
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


SHAFT_LENGTH = 1.0  # m, the Jeffcott shaft's x_end − x_start (the one bay's b − a)


def _run_up_unbalance(position: float):
    """The Jeffcott model's per-bay load at ``position`` (U = 2e-3 kg m, ψ = 0.7 rad) and its
    (v, w, γ) rows, after checking the resultant U e^{iψ} and Q_w = −i Q_v."""
    model = build_model(design_from_dict(tomllib.loads(design_text("jeffcott_internal_damping.toml"))))
    assert imbalance_bays(model) == []
    U, psi = 2.0e-3, 0.7
    Q = per_bay_imbalance_loads(model, U, angle=psi, position=position)
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    v, w, gamma = (Q[dm.shaft(nodes, f)] for f in ("v", "w", "gamma"))
    force = v.sum()
    assert abs(force - U * np.exp(1j * psi)) <= 1e-12 * U
    np.testing.assert_allclose(w, -1j * v, rtol=0, atol=1e-15)
    return dm.shaft_x, v, gamma, force


@pytest.mark.parametrize("position", [0.5, 0.25])
def test_the_run_up_unbalance_of_a_shaft_without_a_bay_spans_the_whole_shaft(position):
    """Positions 0.5 and 0.25 of the whole shaft (on nodes): resultant U e^{iψ}, centroid
    x = position L (module docstring)."""
    x, v, gamma, force = _run_up_unbalance(position)
    centroid = ((x * v).sum() + gamma.sum()) / force
    assert abs(centroid - position * SHAFT_LENGTH) <= 1e-12


def test_an_off_node_run_up_unbalance_keeps_its_centroid_through_the_end_couples():
    """Position 0.3 (x = 0.3 m, inside the third element, off every node): the consistent load
    carries end couples (Q_γ not zero, unlike at a node) and the moment resultant
    Σ x_i Q_v,i + Σ Q_γ,i = F x_F still puts the centroid at 0.3 L (module docstring); taking
    the couples with the other sign would put it at 0.288 m, 1.2e-2 off against the 1e-12 m
    tolerance."""
    position = 0.3
    x, v, gamma, force = _run_up_unbalance(position)
    assert np.abs(gamma).max() > 1e-3 * abs(force) * SHAFT_LENGTH  # the couples matter here
    centroid = ((x * v).sum() + gamma.sum()) / force
    assert abs(centroid - position * SHAFT_LENGTH) <= 1e-12


def test_a_zero_eccentricity_gives_a_zero_load_and_a_zero_unbalance_response():
    """e_c = 0 (a perfectly balanced rotor): imbalance_loads returns a zero load vector of the
    model's size (F = e m Ω² = 0; its docstring accepts any finite e_c >= 0), and the Jeffcott
    design, with neither ``eccentricity`` nor ``balance_grade`` (no [loads] table: the schema's
    eccentricity 0), has a zero unbalance response at every speed. A zero right-hand side
    solves to exact zeros on any BLAS kernel; the bound 1e-30 m is far below any response to a
    real unbalance (micrometres here)."""
    model = build_model(design_from_dict(tomllib.loads(design_text("jeffcott_internal_damping.toml"))))
    Q = imbalance_loads(model, "mid_bay", eccentricity=0.0)
    assert Q.shape == (model.dofs.size, 1)
    assert np.all(Q == 0.0)
    default = imbalance_loads(model)
    assert default.shape == (model.dofs.size, 1)
    assert np.all(default == 0.0)
    response = imbalance_response(model, [50.0, 150.0, 400.0], default)
    assert np.all(np.isfinite(response))
    assert np.abs(np.asarray(response)).max() <= 1e-30

"""A harmonic solve at ω ≈ 0 of a shaft whose lateral rigid-body motion is unsupported.

Model (derived here): a steel tube held only axially and in torsion at its start (u, θ fixed),
laterally free, no bearings. Its lateral block carries rigid-body modes (translation and tilt in
two planes) with K t = 0, so at a small excitation frequency ω

    Z = K − ω² M,   σ_min(Z) ≤ ‖Z t‖₂ / ‖t‖₂ = ω² ‖M t‖₂ / ‖t‖₂

for t the rigid translation (v = 1 at every node), while ‖Z‖₂ ≥ max_i |Z_ii|. Z, M and t are
taken on the lateral block alone (the solver's ``coupled`` mask of the loaded row: the block a
lateral load factorises; the uncoupled axial block, never factorised for it, holds the largest
diagonal of the whole Z and would inflate the bound 5×). At ω = 3e-4 rad/s the bound κ₂(Z_lat) ≥
max_i |Z_ii| / σ_min is 1.83/ε (computed below from the assembled matrices; ‖Z_lat‖₂ would give
3.6/ε): the lateral block is singular to working precision. The banded solver's documented rule
(module docstring of flexshaft.analyses.banded): a regular system's refinement corrections
contract by about κ ε per step and must at least halve; those of a system singular to working
precision do not, and SingularSystemError is raised, however many load columns are solved at
once.

The torsional block is regular (θ is held at the start): a torque T at the free end twists it
by θ = T L / (G J), J = π (D_o⁴ − D_i⁴)/32 (linear torsion elements are exact for end loads; the
inertia term ω² ρ J L / (G J / L) is 1e-14 here).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.banded import BandedHarmonicSolver, SingularSystemError
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import loads_design

E, G = 210e9, 80e9
DO, DI, L = 0.05, 0.04, 1.0
OMEGA = 3e-4  # [rad/s]

TEXT = f"""
name = "laterally free tube"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G}
density = 7800.0
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "steel"
fixed_start = ["u", "theta"]
fixed_end = []
[[bearings]]
name = "none"
kind = "contact"
x = {L / 2}
stiffness = {{}}
damping = {{}}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 8
"""


@pytest.fixture(scope="module")
def tube():
    model = build_model(loads_design(TEXT))
    free = list(model.dofs.free)
    end = model.dofs.node_at("shaft", L)
    return (
        model,
        BandedHarmonicSolver(model),
        free.index(model.dofs.shaft(end, "v")),
        free.index(model.dofs.shaft(end, "theta")),
    )


def test_the_lateral_block_is_singular_to_working_precision(tube):
    """The premise, from the assembled matrices restricted to the lateral block that a lateral
    end force loads (the solver's ``coupled`` mask): κ₂(Z_lat) ≥ max|Z_ii| / (ω² ‖M t‖/‖t‖) =
    1.83/ε > 1/ε at ω = 3e-4 rad/s (module docstring), and K t = 0 to round-off of K."""
    model, solver, v, _ = tube
    free = model.dofs.free
    lateral = solver.coupled([v])
    block = np.ix_(lateral, lateral)
    K = restrict(model.K.tocsr(), free).toarray()[block]
    M = restrict(model.M.tocsr(), free).toarray()[block]
    t = np.zeros(free.size)
    t[[list(free).index(model.dofs.shaft(node, "v")) for node in range(model.dofs.n_shaft_nodes)]] = 1.0
    t = t[lateral]
    assert np.linalg.norm(K @ t) <= 1e-12 * np.abs(K).max() * np.linalg.norm(t)
    Z = K - OMEGA**2 * M
    sigma_bound = OMEGA**2 * np.linalg.norm(M @ t) / np.linalg.norm(t)
    assert np.abs(np.diag(Z)).max() / sigma_bound * np.finfo(float).eps > 1.0


def test_torsion_alone_is_regular_and_the_closed_form(tube):
    """θ(L) = T L / (G J) for a unit end torque (module docstring); relative 1e-12: the
    torsion block's κ₂ is 1.1e2 (computed from its 8×8 Z), so κ ε ≈ 2.5e-14 and the LU's
    forward error is below n κ ε ≈ 2e-13 (measured 2e-16); its inertia term is 1e-14."""
    _, solver, _, theta = tube
    rhs = np.zeros(solver.n)
    rhs[theta] = 1.0
    J = np.pi * (DO**4 - DI**4) / 32
    assert solver.solve(OMEGA, rhs, speed=0.0)[theta].real == pytest.approx(L / (G * J), rel=1e-12)


@pytest.mark.parametrize("with_torque", [False, True])
def test_a_load_on_the_free_rigid_body_motion_is_refused(tube, with_torque):
    """A lateral end force at ω = 3e-4 rad/s: SingularSystemError, alone or solved together
    with the torque of the regular torsion block, whose column converges at once; the rule
    is the same for every column (module docstring)."""
    _, solver, v, theta = tube
    rhs = np.zeros((solver.n, 2 if with_torque else 1))
    rhs[v, 0] = 1.0
    if with_torque:
        rhs[theta, 1] = 1.0
    with pytest.raises(SingularSystemError):
        solver.solve(OMEGA, rhs, speed=0.0)

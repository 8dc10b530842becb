"""Forced response, loads, strength chain and Campbell: closed forms and direct-solve checks."""

import numpy as np
import pytest
import scipy.integrate as si

from flexshaft.analyses import BandedHarmonicSolver, imbalance_response, modes, static_response
from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import (
    STANDARD_GRAVITY,
    external_static_load,
    imbalance_loads,
    inertial_load,
    point_load,
    torque_load,
)
from flexshaft.design import baseline_design, loads_design, with_overrides
from flexshaft.elements import ellipse_section

E, G, RHO = 210e9, 80e9, 7850.0
DO, DI, L = 0.10, 0.08, 1.0
K_BRG, C_BRG, M_DISK = 2.0e5, 40.0, 10.0

JEFFCOTT = f"""
name = "Jeffcott-like rotor: heavy midspan disk, near-massless shaft, soft damped bearings"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G}
density = 1e-3
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "a"
kind = "contact"
x = 0.0
stiffness = {{ v = {K_BRG}, w = {K_BRG} }}
damping = {{ v = {C_BRG}, w = {C_BRG} }}
[[bearings]]
name = "b"
kind = "contact"
x = {L}
stiffness = {{ v = {K_BRG}, w = {K_BRG} }}
damping = {{ v = {C_BRG}, w = {C_BRG} }}
[[disks]]
name = "disk"
x = {L / 2}
mass = {M_DISK}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 8
"""


def jeffcott_closed_form(speed, unbalance):
    """Disk amplitude: X = m_u e Ω² / (k_eff(Ω) − mΩ²), k_eff = [1/(2(k + iΩc)) + L³/48EI]⁻¹
    (bearing pair in series with the massless shaft's midspan bending)."""
    I = np.pi * (DO**4 - DI**4) / 64
    bearings = 2 * (K_BRG + 1j * speed * C_BRG)
    k_eff = 1 / (1 / bearings + L**3 / (48 * E * I))
    return unbalance * speed**2 / (k_eff - M_DISK * speed**2)


def test_jeffcott_imbalance_response_matches_closed_form():
    """Amplitude and phase over speed to 1e-5 (the residual shaft mass, density 1e-3 kg/m³,
    is 1e-6 of the disk), the peak at the critical speed and the phase through 90° there."""
    model = build_model(loads_design(JEFFCOTT))
    dm = model.dofs
    node = dm.node_at("shaft", L / 2)
    unbalance = 1e-4  # kg m
    Q = np.zeros(dm.size, dtype=complex)
    Q[dm.shaft(node, "v")] = unbalance
    Q[dm.shaft(node, "w")] = -1j * unbalance  # force turning from +y to +z with the spin
    I = np.pi * (DO**4 - DI**4) / 64
    k_static = 1 / (1 / (2 * K_BRG) + L**3 / (48 * E * I))
    wn = np.sqrt(k_static / M_DISK)
    speeds = np.linspace(0.2 * wn, 2.5 * wn, 2001)
    q = imbalance_response(model, speeds, Q)
    v, w = q[dm.shaft(node, "v")], q[dm.shaft(node, "w")]
    ref = jeffcott_closed_form(speeds, unbalance)
    assert np.allclose(v, ref, rtol=1e-5)
    assert np.allclose(w, -1j * ref, rtol=1e-5)  # circular forward orbit
    peak = speeds[np.argmax(np.abs(v))]
    assert abs(peak / wn - 1) < 0.01  # light damping (ζ ≈ 0.4 %): peak within 1 % of ω_n
    phase = np.degrees(-np.angle(v))  # lag of the response behind the force
    assert phase[speeds < 0.5 * wn].max() < 10 and phase[speeds > 2 * wn].min() > 170
    assert np.interp(wn, speeds, phase) == pytest.approx(90.0, abs=3.0)


def test_campbell_critical_speed_of_jeffcott_rotor():
    # the shaft at density 1 kg/m³ (2.8e-4 of the disk's mass: ω falls by ~7e-5), not 1e-3: the
    # modal basis's round-off is ε (ω_max/ω_n)², 8e-4 at 1e-3 kg/m³ (ω_max = 3.8e8 rad/s), which
    # split the disk's two planes by 1.4e-3 with scipy 1.11's LAPACK; 8e-7 here
    model = build_model(loads_design(JEFFCOTT.replace("density = 1e-3", "density = 1.0")))
    I = np.pi * (DO**4 - DI**4) / 64
    wn = np.sqrt(1 / (1 / (2 * K_BRG) + L**3 / (48 * E * I)) / M_DISK)
    c = campbell(model, np.linspace(0, 2 * wn, 81), n_modes=2)
    crit = [cs.speed for cs in c.critical_speeds]
    # the two whirl directions of the disk's translational mode cross 1x at ω_n (no gyroscopic
    # coupling at a symmetric disk position); damped intersections within 0.1 % (the bearing
    # dampers in series lower it by 3e-4, the shaft's mass by 7e-5)
    assert len(crit) == 2 and np.allclose(crit, wn, rtol=1e-3)


def test_band_ordering_is_no_wider_than_reverse_cuthill_mckee_and_keeps_blocks_apart():
    """Reference: scipy's reverse Cuthill-McKee on the same pattern (the previous ordering), and
    the band of two interleaved chains counted by hand."""
    import scipy.sparse as sp
    from scipy.sparse.csgraph import reverse_cuthill_mckee

    from flexshaft.analyses.banded import band_ordering

    def half_band(pattern, order):
        coo = pattern[order][:, order].tocoo()
        return int(np.abs(coo.row - coo.col).max())

    model = build_model(baseline_design())
    solver = BandedHarmonicSolver(model)
    pattern = sp.csr_matrix(
        (np.ones(solver._rows.size), (solver.perm[solver._rows], solver.perm[solver._cols])), shape=(solver.n, solver.n)
    )
    pattern = pattern + pattern.T
    rcm = half_band(pattern, reverse_cuthill_mckee(pattern.tocsr(), symmetric_mode=True))
    assert rcm == 24 and solver.kl == 19  # 0.40 less band-LU work (∝ kl (kl + ku))
    # the shaft's torsion couples to nothing else: its DOFs form one contiguous run of the ordering
    torsion = model.dofs.shaft(np.arange(model.dofs.n_shaft_nodes), "theta")
    local = np.searchsorted(solver.free, torsion[np.isin(torsion, solver.free)])
    places = np.sort(solver.inverse[local])
    assert np.all(np.diff(places) == 1)
    # two chains of 10 and 5 nodes along the same length, each node coupled to its neighbour and
    # the chains' ends coupled (a ring): chain order gives a half band of 10 (the end link);
    # station order interleaves them (half band 4: A7, A8 and A9 lie between B3 at 0.75 and B4);
    # reverse Cuthill-McKee folds the ring (half band 2); the narrower is taken
    xa, xb = np.linspace(0, 1, 10), np.linspace(0, 1, 5)
    x = np.concatenate([xa, xb])
    links = [(i, i + 1) for i in range(9)] + [(10 + i, 11 + i) for i in range(4)] + [(0, 10), (9, 14)]
    r, c = np.array(links).T
    chains = sp.csr_matrix((np.ones(2 * r.size), (np.r_[r, c], np.r_[c, r])), shape=(15, 15))
    keys = np.column_stack([x, np.r_[np.zeros(10), np.ones(5)]])
    station = np.lexsort(keys.T[::-1])
    assert half_band(chains, np.arange(15)) == 10 and half_band(chains, station) == 4
    assert half_band(chains, band_ordering(chains, keys)) == half_band(chains, band_ordering(chains)) == 2


def test_banded_solver_matches_sparse_direct_solve_on_baseline():
    model = build_model(baseline_design())
    solver = BandedHarmonicSolver(model)
    assert solver.kl == solver.ku == 19  # shaft and boom nodes interleaved by station (see below)
    rng = np.random.default_rng(1)
    rhs = rng.standard_normal(solver.n) + 1j * rng.standard_normal(solver.n)
    # the rotating-frame loss written out here: the shaft's lateral loss K''_lat acts on the
    # forward part P_F = (I + iS)/2 of the response with sgn(ω − Ω) and on the backward part
    # P_B = (I − iS)/2 with +1; the boom's and the shaft's axial/torsional loss with sgn(ω)
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    S = np.zeros((dm.size, dm.size))
    for a, b in (("v", "w"), ("beta", "gamma")):
        S[dm.shaft(nodes, a), dm.shaft(nodes, b)] = 1.0
        S[dm.shaft(nodes, b), dm.shaft(nodes, a)] = -1.0
    lateral = np.zeros(dm.size, bool)
    for f in ("v", "w", "beta", "gamma"):
        lateral[dm.shaft(nodes, f)] = True
    shaft_loss = model.shaft_loss_stiffness.toarray()
    K_lat = np.where(lateral[:, None] & lateral[None, :], shaft_loss, 0.0)
    fixed = model.boom_loss_stiffness.toarray() + shaft_loss - K_lat
    eye = np.eye(dm.size)
    for omega, speed in ((0.0, 0.0), (150.0, 300.0), (model.speed, model.speed), (400.0, 300.0)):
        forward = np.sign(omega - speed) if abs(omega - speed) > 1e-9 * omega else 0.0
        loss = 1j * np.sign(omega) * fixed + 1j * K_lat @ (
            np.sign(omega + speed) * (eye - 1j * S) / 2 + forward * (eye + 1j * S) / 2
        )
        Z = (
            (-(omega**2)) * model.M
            + 1j * omega * (speed * model.G + model.C)
            + model.K
            + model.controller_matrix(1j * omega)
        )
        Z = Z.toarray() + loss
        f = dm.free
        direct = np.linalg.solve(Z[np.ix_(f, f)], rhs)
        assert np.allclose(solver.solve(omega, rhs, speed), direct, rtol=1e-9, atol=1e-12 * np.abs(direct).max())


def test_reduced_campbell_matches_direct_eigenvalues():
    """The modal-basis fast path against the full first-order eigenproblem at three speeds (on the
    baseline meshed with 12 shaft and 8 boom elements: the full problem's two dense complex
    eigen-solves per speed cost as the cube of its size)."""
    design = with_overrides(
        baseline_design(),
        {"bearings[1].kd": 500.0, "bearings[2].kd": 500.0, "mesh.shaft_elements": 12, "mesh.boom_elements": 8},
    )
    model = build_model(design)
    speeds = np.array([0.0, 250.0, model.speed])
    c = campbell(model, speeds, n_modes=10)
    for k, s in enumerate(speeds):
        direct = modes(model, speed=s, n_modes=10, basis_size=model.dofs.free.size).eigenvalues  # full problem
        fast = np.sort_complex(c.eigenvalues[k])
        assert np.allclose(np.sort(fast.imag), np.sort(direct.imag), rtol=1e-5)
        assert np.allclose(np.sort(fast.real), np.sort(direct.real), rtol=1e-3, atol=1e-6 * np.abs(direct).max())


def test_campbell_tracks_forward_and_backward_shaft_modes():
    model = build_model(baseline_design())
    c = campbell(model, np.linspace(0, 1.2 * model.speed, 40), n_modes=8)
    f = c.frequencies
    # tracked curves are continuous: no jump larger than 3 Hz between neighbouring speeds
    assert np.max(np.abs(np.diff(f, axis=0))) < 3.0
    # the first shaft pair splits: one forward (rising), one backward (falling)
    fwd = [m for m in range(8) if np.all(c.whirl[1:, m] == "forward")]
    bwd = [m for m in range(8) if np.all(c.whirl[1:, m] == "backward")]
    assert fwd and bwd
    assert np.all(np.diff(f[:, fwd[0]]) > -1e-9) and np.all(np.diff(f[:, bwd[0]]) < 1e-9)


def test_boom_tip_deflection_under_tip_load_matches_quadrature():
    """Cantilevered tapered boom, no end mass, shaft on soft bearings (1 N/m): tip deflection
    δ = ∫ P(L−x)²/EI_z(x) dx by quadrature; 24 elements give < 1e-4."""
    d = with_overrides(
        baseline_design(),
        {
            "tailboom.end_mass": None,
            "bearings": [
                {"name": "h1", "kind": "contact", "x": 0.79, "stiffness": {"u": 1.0, "v": 1.0, "w": 1.0}},
                {"name": "h2", "kind": "contact", "x": 8.05, "stiffness": {"v": 1.0, "w": 1.0}},
            ],
            "loads.point": [],
            "loads.load_factor": [0.0, 0.0, 0.0],
        },
    )
    model = build_model(d)
    tb = d.tailboom
    P = 1000.0
    q = static_response(model, point_load(model, "boom", (0.0, P, 0.0), x=tb.length))

    def sec(x):
        return ellipse_section(0.5 - 0.25 * x / tb.length, 0.4 - 0.2 * x / tb.length, tb.wall_thickness)

    ref = si.quad(lambda x: P * (tb.length - x) ** 2 / (71e9 * sec(x).I_z), 0, tb.length, epsrel=1e-12)[0]
    assert q[model.dofs.boom(-1, "v")] == pytest.approx(ref, rel=1e-4)


def test_load_factor_and_imbalance_totals():
    """n g on every mass sums to n g × total mass; imbalance forces sum to e_c m_s per Ω²."""
    model = build_model(baseline_design())
    dm = model.dofs
    d = model.design
    Q = inertial_load(model, (0.0, -3.5, 0.0))
    total_v = Q[dm.shaft(np.arange(dm.n_shaft_nodes), "v")].sum() + Q[dm.boom(np.arange(dm.n_boom_nodes), "v")].sum()
    tb = d.tailboom

    def sec(x):
        return ellipse_section(0.5 - 0.25 * x / tb.length, 0.4 - 0.2 * x / tb.length, tb.wall_thickness)

    boom_mass = d.materials[tb.material].density * si.quad(lambda x: sec(x).area, 0, tb.length)[0]
    A = np.pi * (0.1016**2 - (0.1016 - 0.006) ** 2) / 4
    mass = boom_mass + 1650.0 * A * d.shaft.length + 200.0
    assert total_v == pytest.approx(-3.5 * STANDARD_GRAVITY * mass, rel=1e-9)
    Qi = imbalance_loads(model, "mid_bay")[:, 0]
    fy = Qi[dm.shaft(np.arange(dm.n_shaft_nodes), "v")].sum()
    fz = Qi[dm.shaft(np.arange(dm.n_shaft_nodes), "w")].sum()
    assert fy == pytest.approx(d.loads.eccentricity * 1650.0 * A * d.shaft.length, rel=1e-9)
    assert fz == pytest.approx(-1j * fy, rel=1e-9)
    assert imbalance_loads(model, "worst").shape[1] == 4  # 3 bays → 2² phase patterns


def test_pure_torque_safety_factor_of_zero_degree_tube_is_S_J_over_T_r():
    """A [0] laminate under torque T only: τ12 = T r/J at the outer wall, Tsai-Wu pure shear
    gives R = S/τ12 exactly (closed form through static response, strains, CLT, Tsai-Wu). One
    ply has no thermal residual stress; the spin's hoop stress is switched off (speed=0)."""
    d = with_overrides(baseline_design(), {"shaft.layup": "0", "loads.point": [], "loads.load_factor": [0.0, 0.0, 0.0]})
    model = build_model(d)
    T = 400.0
    q = static_response(model, torque_load(model, T))
    res = shaft_safety_factor(model, q, speed=0.0)  # torque only: no centrifugal hoop stress
    Do, Di = 0.1016, 0.1016 - 0.006
    J = np.pi * (Do**4 - Di**4) / 32
    assert res.safety_factor == pytest.approx(20.0e6 * J / (T * Do / 2), rel=1e-9)
    assert res.dominant_stress == "tau12"
    # twist at the aft end: θ = −T ℓ/(G_LT J) over the shaft length (forward end held)
    G_LT = d.materials[d.shaft.material].G_LT
    assert q[model.dofs.shaft(-1, "theta")] == pytest.approx(-T * d.shaft.length / (G_LT * J), rel=1e-9)


def test_baseline_superposed_strength_runs_and_is_finite():
    model = build_model(baseline_design())
    qs = static_response(model, external_static_load(model) + torque_load(model))
    qd = imbalance_response(model, [model.speed], imbalance_loads(model))[:, 0, 0]
    r = shaft_safety_factor(model, qs, qd)
    assert np.isfinite(r.safety_factor) and r.safety_factor > 0
    assert r.along_shaft.min() == pytest.approx(r.safety_factor)
    assert 0.79 <= r.x <= 8.05


def test_bearing_reactions_balance_a_static_load():
    """Steel shaft on two end bearings, midspan force P: each bearing carries P/2 (statics)."""
    from test_model import steel_shaft

    from flexshaft.analyses.reactions import bearing_forces

    model = build_model(steel_shaft(10))
    P = 800.0
    q = static_response(model, point_load(model, "shaft", (0.0, P, 0.0), x=1.0))
    forces = bearing_forces(model, q)
    assert forces["left"][1].real == pytest.approx(P / 2, rel=1e-9)
    assert forces["right"][1].real == pytest.approx(P / 2, rel=1e-9)


def test_banded_solver_without_material_loss_matches_a_direct_solve():
    """A lossless rotor (the Jeffcott case) stores all-zero loss terms, which the solver leaves
    out of its products; reference: scipy's sparse direct solve of the dense-built
    Z = K − ω²M + iω(ΩG + C) (relative 1e-10: two LU factorisations of a well-conditioned
    system away from resonance)."""
    import scipy.sparse.linalg as spla

    model = build_model(loads_design(JEFFCOTT))
    assert model.loss_fixed.count_nonzero() == model.loss_lateral.count_nonzero() == 0
    solver = BandedHarmonicSolver(model)
    rng = np.random.default_rng(3)
    rhs = rng.standard_normal(solver.n) + 1j * rng.standard_normal(solver.n)
    free = model.dofs.free
    omega = speed = 123.4
    Z = (model.K - omega**2 * model.M + 1j * omega * (speed * model.G + model.C)).tocsc()[free][:, free]
    reference = spla.spsolve(Z, rhs)
    np.testing.assert_allclose(
        solver.solve(omega, rhs, speed), reference, rtol=1e-10, atol=1e-10 * np.abs(reference).max()
    )


def test_banded_solvers_sharing_a_sparsity_equal_solvers_set_up_cold():
    """Reference: solvers set up with the band-structure cache emptied before each. Solvers of
    models on one mesh share the ordering and the union pattern (layup, wall and gain sweeps;
    a layup may store fewer entries in one term); their band data and solutions must equal a
    cold set-up's exactly, and a model on another mesh must get its own structure."""
    from flexshaft.analyses import banded

    base = baseline_design()
    variants = [
        base,
        with_overrides(base, {"shaft.layup": "(30/-30)s"}),
        with_overrides(base, {"bearings[1].kp": 2e6}),
        with_overrides(base, {"shaft.wall_thickness": 0.002}),
        with_overrides(base, {"mesh.shaft_elements": 24}),
    ]
    warm = []
    for design in variants:  # the cache fills as a sweep's would
        warm.append(BandedHarmonicSolver(build_model(design)))
    assert all(w._template is warm[0]._template for w in warm[:4])  # one mesh: one structure
    assert warm[4]._template is not warm[0]._template
    for design, solver in zip(variants, warm):
        banded._STRUCTURES.clear()
        cold = BandedHarmonicSolver(build_model(design))
        assert np.array_equal(solver.perm, cold.perm) and (solver.kl, solver.ku) == (cold.kl, cold.ku)
        assert all(np.array_equal(solver.data[k], cold.data[k]) for k in cold.data)
        rhs = np.linspace(1.0, 2.0, cold.n)
        assert np.array_equal(solver.solve(300.0, rhs, 400.0), cold.solve(300.0, rhs, 400.0))

"""Element verification against closed forms (DESIGN.md §6, "elements").

Each test assembles elements by hand with the package's scatter and DOF map and compares with
an independently derived reference. Tolerances are stated where they are used.
"""

import numpy as np
import pytest
import scipy.integrate as si
import scipy.linalg as la

from flexshaft.assembly.dofs import BOOM_FIELDS, DofMap
from flexshaft.assembly.sparse import restrict, scatter
from flexshaft.elements import (
    TubeSection,
    attachment_transform,
    boom_element_matrices,
    disk_matrices,
    ellipse_section,
    end_mass_kinematics,
    end_mass_matrix,
    relative_rows,
    shaft_element_matrices,
)

E, NU, RHO = 210e9, 0.3, 7850.0
G_STEEL = E / (2 * (1 + NU))


def tube_system(n_el, length, section, fixed_fields_start, fixed_fields_end=(), kappa=None, E_=E, dense=True):
    """Uniform tube of n_el elements: returns (M, K, G) restricted to free DOFs, DofMap (the
    matrices as scipy sparse matrices when ``dense`` is False)."""
    x = np.linspace(0, length, n_el + 1)
    dm0 = DofMap(x, np.zeros(0))
    fixed = [dm0.shaft(0, f) for f in fixed_fields_start] + [dm0.shaft(-1, f) for f in fixed_fields_end]
    dm = DofMap(x, np.zeros(0), np.array(sorted(fixed), dtype=int))
    Me, Ke, Ge = shaft_element_matrices(np.diff(x), section, E_, G_STEEL, RHO, kappa)
    d = dm.element_dofs("shaft")
    f = dm.free
    M, K, G = (restrict(scatter(e, d, dm.size), f) for e in (Me, Ke, Ge))
    if not dense:
        return M, K.real, G, dm
    return M.toarray(), K.toarray().real, G.toarray(), dm


SECTION = TubeSection(0.10, 0.09)


def test_element_matrices_symmetry():
    M, K, G = shaft_element_matrices([0.3, 0.7], SECTION, E * (1 + 0.01j), G_STEEL, RHO)
    assert np.allclose(M, np.swapaxes(M, 1, 2), rtol=0, atol=1e-12 * np.abs(M).max())
    assert np.allclose(K, np.swapaxes(K, 1, 2), rtol=0, atol=1e-12 * np.abs(K).max())
    assert np.allclose(G, -np.swapaxes(G, 1, 2), rtol=0, atol=1e-14 * np.abs(G).max())
    # complex modulus scales the bending stiffness: Im K / Re K = loss factor on bending rows
    assert K[0, 1, 1].imag / K[0, 1, 1].real == pytest.approx(0.01, rel=1e-12)
    # rigid-body translation and rotation carry no strain energy
    rigid_v = np.zeros(12)
    rigid_v[[1, 7]] = 1.0
    rigid_rot = np.zeros(12)
    L = 0.3
    rigid_rot[[5, 11]] = 1.0
    rigid_rot[7] = L  # v = x, γ = 1
    assert np.abs(K[0] @ rigid_v).max() < 1e-6 * np.abs(K[0]).max()
    assert np.abs(K[0] @ rigid_rot).max() < 1e-6 * np.abs(K[0]).max()
    # mass of a rigid translation equals ρ A L exactly
    assert rigid_v @ M[0] @ rigid_v == pytest.approx(RHO * SECTION.area * L, rel=1e-12)


def rayleigh_ss_frequencies(k, speed, section, length_unused=None):
    """Spinning simply supported Rayleigh beam, mode sin(kx): forward and backward ω [rad/s].

    Per mode: (ρA + ρI k²) ω² ∓ ρJ k² Ω ω − EI k⁴ = 0 (rotary inertia and gyroscopic
    moment of a spinning tube; Genta, Dynamics of Rotating Systems, §5).
    """
    A, I, J = section.area, section.second_moment, section.polar_moment
    m = RHO * A + RHO * I * k**2
    g = RHO * J * k**2 * speed
    root = np.sqrt(g**2 + 4 * m * E * I * k**4)
    return (g + root) / (2 * m), (-g + root) / (2 * m)


@pytest.mark.parametrize("speed", [0.0, 2000.0])
def test_simply_supported_spinning_tube_matches_rayleigh_closed_form(speed):
    """Pinned-pinned tube, 40 elements: first 3 forward/backward pairs to < 0.01 %."""
    L = 2.0
    M, K, G, dm = tube_system(40, L, SECTION, ("u", "v", "w", "theta"), ("v", "w"))
    n = M.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-la.solve(M, K), -la.solve(M, speed * G)]])
    lam = la.eigvals(A)
    w = np.sort(lam.imag[lam.imag > 1.0])
    for mode in (1, 2, 3):
        fwd, bwd = rayleigh_ss_frequencies(mode * np.pi / L, speed, SECTION)
        # the closest computed root to each closed-form root
        for ref in (fwd, bwd):
            assert np.min(np.abs(w - ref)) / ref < 1e-4
    if speed > 0:
        fwd, bwd = rayleigh_ss_frequencies(np.pi / L, speed, SECTION)
        assert fwd > bwd  # the split grows with speed (gyroscopic stiffening of forward whirl)


def test_cantilever_bending_frequencies_euler_bernoulli():
    """Eq. 3.1 cantilever: ω_n = (β_n L)² √(EI/ρAL⁴). Slender tube so the rotary inertia
    (in the element, absent in the closed form) shifts mode 4 by < 2e-4; tolerance 1e-3."""
    L, sec = 12.0, TubeSection(0.05, 0.04)
    M, K, _, _ = tube_system(60, L, sec, ("u", "v", "w", "theta", "beta", "gamma"))
    w = np.sqrt(la.eigh(K, M, eigvals_only=True))
    bl = np.array([1.875104069, 4.694091133, 7.854757438, 10.99554073])
    ref = bl**2 * np.sqrt(E * sec.second_moment / (RHO * sec.area * L**4))
    lateral = np.array([w[np.argmin(np.abs(w - r))] for r in ref])
    assert np.max(np.abs(lateral / ref - 1)) < 1e-3


def test_axial_and_torsional_rod_frequencies():
    """Fixed-free rod: ω_n = (2n−1)π/(2L)·√(E/ρ) axial and √(G/ρ) torsional. Linear elements
    converge as h²: with 400 elements the error of mode 3 is ≈ (5π/2·/400)²/24 ≈ 1.6e-5."""
    L = 1.0
    # sparse: the dense 2400-DOF matrices cost more than the eigenproblem (CPU budget, issue 23)
    M, K, _, dm = tube_system(400, L, SECTION, ("u", "v", "w", "theta", "beta", "gamma"), dense=False)
    M, K = M.tocsr(), K.tocsr()
    # the axial and twist DOFs are uncoupled from bending (structural zeros, exact): their block
    # alone holds these modes, a 800-DOF problem instead of 2400
    nodes = np.arange(dm.n_shaft_nodes)
    rod = np.isin(dm.free, np.concatenate([dm.shaft(nodes, "u"), dm.shaft(nodes, "theta")]))
    assert not np.any(K[rod][:, ~rod].data) and not np.any(M[rod][:, ~rod].data)
    w = np.sqrt(la.eigh(K[rod][:, rod].toarray(), M[rod][:, rod].toarray(), eigvals_only=True))
    for c in (np.sqrt(E / RHO), np.sqrt(G_STEEL / RHO)):
        for n in (1, 2, 3):
            ref = (2 * n - 1) * np.pi / (2 * L) * c
            assert np.min(np.abs(w - ref)) / ref < 1e-4


def test_timoshenko_simply_supported_converges_to_exact_frequency_equation():
    """Thick tube with shear: per mode sin(kx) the exact Timoshenko equations give
    det([[κGAk² − ρAω², −κGAk], [−κGAk, EIk² + κGA − ρIω²]]) = 0 (lower root).
    The interdependent-interpolation element is exact statically; with its consistent mass the
    frequency error falls as h² (measured ratio 4.0 per halving): check the rate and that
    40 elements are within 3e-4."""
    L, sec, kappa = 0.6, TubeSection(0.10, 0.05), 0.7
    A, I = sec.area, sec.second_moment
    kGA = kappa * G_STEEL * A
    errors = []
    for n_el in (20, 40):
        M, K, _, _ = tube_system(n_el, L, sec, ("u", "v", "w", "theta"), ("v", "w"), kappa=kappa)
        w = np.sqrt(la.eigh(K, M, eigvals_only=True))
        err = []
        for n in (1, 2):
            k = n * np.pi / L
            # quadratic in x = ω²: (ρA·ρI) x² − (ρA(EIk² + kGA) + ρI kGA k²) x + kGA k² EI k² = 0
            a = RHO * A * RHO * I
            b = -(RHO * A * (E * I * k**2 + kGA) + RHO * I * kGA * k**2)
            c = kGA * k**2 * E * I * k**2
            ref = np.sqrt((-b - np.sqrt(b * b - 4 * a * c)) / (2 * a))
            err.append(np.min(np.abs(w - ref)) / ref)
            # shear lowers the frequency well below the Rayleigh-beam value for this thick tube
            assert ref < 0.97 * rayleigh_ss_frequencies(k, 0.0, sec)[0]
        errors.append(err)
    errors = np.array(errors)
    assert np.all(errors[1] < 3e-4)
    assert np.all((errors[0] / errors[1] > 3.5) & (errors[0] / errors[1] < 4.5))


def test_cantilever_static_tip_deflection_exact():
    """Hermite elements are nodally exact for a tip load: δ = PL³/3EI, tip slope PL²/2EI."""
    L, P = 3.0, 1000.0
    M, K, _, dm = tube_system(5, L, SECTION, ("u", "v", "w", "theta", "beta", "gamma"))
    f = np.zeros(dm.size)
    f[dm.shaft(-1, "w")] = P
    q = dm.expand(la.solve(K, f[dm.free]))
    EI = E * SECTION.second_moment
    assert q[dm.shaft(-1, "w")] == pytest.approx(P * L**3 / (3 * EI), rel=1e-10)
    assert q[dm.shaft(-1, "beta")] == pytest.approx(-P * L**2 / (2 * EI), rel=1e-10)  # β = −w'


def test_ellipse_section_circle_and_quadrature():
    """Circle: A = 2πrt, I = πr³t, J = 2πr³t exactly; ellipse vs independent adaptive quadrature."""
    s = ellipse_section(0.3, 0.3, 0.004)
    r, t = 0.3, 0.004
    assert s.area == pytest.approx(2 * np.pi * r * t, rel=1e-12)
    assert s.I_z == pytest.approx(np.pi * r**3 * t, rel=1e-12)
    assert s.I_y == pytest.approx(np.pi * r**3 * t, rel=1e-12)
    assert s.torsion_constant == pytest.approx(2 * np.pi * r**3 * t, rel=1e-12)
    a, b = 0.5, 0.4

    def ds(p):
        return np.hypot(a * np.cos(p), b * np.sin(p))

    Iz = t * si.quad(lambda p: (a * np.sin(p)) ** 2 * ds(p), 0, 2 * np.pi, epsabs=0, epsrel=1e-13)[0]
    P = si.quad(ds, 0, 2 * np.pi, epsabs=0, epsrel=1e-13)[0]
    e = ellipse_section(a, b, t)
    assert e.I_z == pytest.approx(Iz, rel=1e-10)
    assert e.perimeter == pytest.approx(P, rel=1e-10)
    # Roark's thin-ellipse approximation I = π t a²(a + 3b)/4 is within 1 % for b/a = 0.8
    assert e.I_z == pytest.approx(np.pi * t * a**2 * (a + 3 * b) / 4, rel=1e-2)


def _tapered_boom(n_el, L=8.0):
    x = np.linspace(0, L, n_el + 1)

    def sec(xx):
        return ellipse_section(0.5 - 0.25 * xx / L, 0.4 - 0.2 * xx / L, 0.004)

    Me, Ke = boom_element_matrices(x, sec, 71e9, 27e9, 2800.0)
    dm0 = DofMap(np.zeros(0), x)
    dm = DofMap(np.zeros(0), x, np.array([dm0.boom(0, f) for f in BOOM_FIELDS]))
    d = dm.element_dofs("boom")
    return scatter(Me, d, dm.size), scatter(Ke, d, dm.size).real, dm, sec


def _tip_response(n_el, L=8.0, P=5000.0, T=2000.0):
    Mg, Kg, dm, sec = _tapered_boom(n_el, L)
    f = np.zeros(dm.size)
    f[dm.boom(-1, "v")] = P
    f[dm.boom(-1, "theta")] = T
    q = dm.expand(la.solve(Kg.toarray()[np.ix_(dm.free, dm.free)], f[dm.free]))
    return q[dm.boom(-1, "v")], q[dm.boom(-1, "theta")], sec


def test_tapered_cantilever_static_deflection_and_twist_against_quadrature():
    """Tip load P: δ = ∫ P(L−x)²/EI(x) dx; tip torque T: θ = ∫ T/GJ(x) dx (scipy quad).
    Bending (cubic elements, Gauss-integrated EI) is within 1e-5 at 32 elements. Twist uses
    linear elements whose stiffness averages GJ where the exact flexibility averages 1/GJ:
    the error is O(h²), so check < 1e-3 at 32 elements and the ratio ≈ 4 per halving."""
    L, P, T = 8.0, 5000.0, 2000.0
    v16, t16, sec = _tip_response(16)
    v32, t32, _ = _tip_response(32)

    def EIz(x):
        return 71e9 * sec(np.array([x])).I_z[0]

    def GJ(x):
        return 27e9 * sec(np.array([x])).torsion_constant[0]

    delta = si.quad(lambda x: P * (L - x) ** 2 / EIz(x), 0, L, epsrel=1e-12)[0]
    twist = si.quad(lambda x: T / GJ(x), 0, L, epsrel=1e-12)[0]
    assert v32 == pytest.approx(delta, rel=1e-5)
    e16, e32 = abs(t16 / twist - 1), abs(t32 / twist - 1)
    assert e32 < 1e-3
    assert 3.5 < e16 / e32 < 4.5


def test_tapered_boom_mass_integrates_exactly():
    """Rigid vertical translation: Σ mass = ρ ∫ A(x) dx (quadrature)."""
    Mg, _, dm, sec = _tapered_boom(10)
    rigid = np.zeros(dm.size)
    rigid[dm.boom(np.arange(dm.n_boom_nodes), "v")] = 1.0
    mass = rigid @ (Mg @ rigid)
    ref = 2800.0 * si.quad(lambda x: sec(np.array([x])).area[0], 0, 8.0, epsrel=1e-12)[0]
    assert mass == pytest.approx(ref, rel=1e-10)


def test_bearing_at_node_equals_node_spring_and_interior_point_interpolates():
    rows_node = relative_rows(0.0, 0.5)  # shaft point at the element's first node, to ground
    expected = np.zeros((5, 12))
    for r, c in enumerate([0, 1, 2, 4, 5]):
        expected[r, c] = 1.0
    assert np.allclose(rows_node, expected, atol=1e-15)
    # at the far node
    rows_end = relative_rows(1.0, 0.5)
    assert np.allclose(rows_end, np.roll(expected, 6, axis=1), atol=1e-15)
    # mid-element: a rigid lateral translation of the element moves the point by the same amount
    mid = relative_rows(0.37, 0.5)
    q = np.zeros(12)
    q[[1, 7]] = 2e-3
    assert np.allclose(mid @ q, [0, 2e-3, 0, 0, 0])


def test_offset_kinematics_rigid_motion_gives_zero_relative_displacement():
    """Shaft at height h above the boom axis, both rotating rigidly together: no bearing strain."""
    h, eps, x = 0.58, 1e-3, 2.0
    rows = relative_rows(0.25, 0.4, 0.6, 0.5, h)
    # rigid twist about the boom axis by eps: boom θ = eps; the shaft line at height h moves
    # w = h·eps and twists by eps.
    q = np.zeros(22)
    q[[3, 9]] = eps
    q[[2, 8]] = h * eps
    q[12 + 2] = q[12 + 7] = eps  # boom θ at both nodes
    assert np.allclose(rows @ q, 0.0, atol=1e-15)
    # rigid pitch about z by eps through the boom axis: v = x·eps, γ = eps for both members,
    # and the shaft at height h moves axially u = −h·eps.
    xs0, Ls = x - 0.25 * 0.4, 0.4
    xb0, Lb = x - 0.6 * 0.5, 0.5
    q = np.zeros(22)
    q[[0, 6]] = -h * eps
    q[1], q[7] = xs0 * eps, (xs0 + Ls) * eps
    q[[5, 11]] = eps
    q[12 + 0], q[12 + 5] = xb0 * eps, (xb0 + Lb) * eps
    q[12 + 4] = q[12 + 9] = eps
    assert np.allclose(rows @ q, 0.0, atol=1e-15)
    assert attachment_transform(h)[0, 4] == -h


def test_end_mass_matrix_is_m_BtB_and_matches_cross_product_kinematics():
    m, e = 200.0, np.array([0.3, 1.0, -0.2])
    Mend = end_mass_matrix(m, e)
    # independent kinematics: velocity of the mass for unit rates of each DOF via cross products
    cols = []
    for dof in range(5):
        r = np.zeros(3)
        if dof == 0:
            r[1] = 1.0
        elif dof == 1:
            r[2] = 1.0
        else:
            rot = np.zeros(3)
            rot[dof - 2] = 1.0
            r = np.cross(rot, e)
        cols.append(r)
    B = np.array(cols).T
    assert np.allclose(end_mass_kinematics(e), B)
    assert np.allclose(Mend, m * B.T @ B)
    assert np.all(la.eigvalsh(Mend) > -1e-12 * m)
    with_own = end_mass_matrix(m, e, (5.0, 6.0, 7.0))
    assert np.allclose(np.diag(with_own - Mend), [0, 0, 5, 6, 7])


def test_disk_gyroscopic_forward_whirl_rises_with_speed():
    """Rigid disk on tilt springs k: I_d ω² ∓ I_p Ω ω − k = 0 (forward root rises)."""
    Md, Gd = disk_matrices(10.0, 0.2, 0.4)
    k, speed = 1e4, 300.0
    M = Md[4:, 4:]
    G = Gd[4:, 4:]
    K = k * np.eye(2)
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-la.solve(M, K), -la.solve(M, speed * G)]])
    w = np.sort(la.eigvals(A).imag)[2:]
    Id, Ip = 0.2, 0.4
    fwd = (Ip * speed + np.sqrt((Ip * speed) ** 2 + 4 * Id * k)) / (2 * Id)
    bwd = (-Ip * speed + np.sqrt((Ip * speed) ** 2 + 4 * Id * k)) / (2 * Id)
    assert np.allclose(w, [bwd, fwd], rtol=1e-10)


def test_bearing_point_rows_equal_the_element_shape_functions():
    """The bearings' one-point rows are the Euler-Bernoulli shape functions of beam_shape."""
    from flexshaft.elements.bearing import point_rows
    from flexshaft.elements.shape import FIELDS, beam_shape

    for xi, length in ((0.0, 0.3), (0.37, 0.21), (0.5, 2.0), (1.0, 1.7)):
        s = beam_shape(np.array(xi), np.array(length))
        expected = np.stack([s.N[f].reshape(12) for f in FIELDS])
        np.testing.assert_array_equal(point_rows(xi, length), expected)

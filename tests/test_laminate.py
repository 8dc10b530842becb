"""Classical lamination theory against closed forms (DESIGN.md section 6, laminate).

Every reference below is written out here from the engineering constants, independently of the
code path in flexshaft.laminate (which goes through Q, T_eps and a = A^-1).
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from flexshaft.laminate import (
    Lamina,
    Laminate,
    abd_matrices,
    equivalent_density,
    equivalent_moduli,
    hoop_strain_free,
    membrane_strains,
    parse_layup,
    ply_strains,
    ply_stresses,
    reduced_stiffness,
    spin_hoop_resultant,
    thermal_ply_stresses,
    transformed_stiffness,
    transverse_shear_stiffness,
)

# thesis baseline ply (DESIGN.md section 5) and a stiff-matrix carbon/epoxy for contrast
FMC = Lamina.from_loss_factors(115e9, 0.10e9, 0.035e9, 0.35, 1650.0, 0.003, 0.12, 0.12)
CARBON_EPOXY = Lamina(140e9, 10e9, 5e9, 0.3, 1600.0)
TIGHT = 1e-12  # round-off only: a few operations on O(1) relative quantities


def one_ply(angle_deg: float, lamina: Lamina = CARBON_EPOXY) -> Laminate:
    return Laminate.from_layup([angle_deg], 1e-3, lamina)


# ------------------------------------------------------------------------------ parse_layup


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("(55/-55/0/0)s", (55, -55, 0, 0, 0, 0, -55, 55)),
        ("[45/-45]s", (45, -45, -45, 45)),
        ("(±45)s", (45, -45, -45, 45)),
        ("+-45", (45, -45)),
        ("(0/90)2s", (0, 90, 0, 90, 90, 0, 90, 0)),
        ("[0/90]3", (0, 90, 0, 90, 0, 90)),
        ("55/-55/0/0", (55, -55, 0, 0)),
        ("90", (90,)),
        ("-90", (-90,)),
        (" [0/(±30)2]s ", (0, 30, -30, 30, -30, -30, 30, -30, 30, 0)),
        ("22.5/-22.5", (22.5, -22.5)),
        ("[0_2/90]s", (0, 0, 90, 90, 0, 0)),
        (" ( 30 / -30 ) S ", (30, -30, -30, 30)),
        ("[(0/90)2/45]s", (0, 90, 0, 90, 45, 45, 90, 0, 90, 0)),
    ],
)
def test_parse_layup_expands(text, expected):
    assert parse_layup(text) == tuple(float(a) for a in expected)


@pytest.mark.parametrize(
    "text", ["", "(0/90", "(0/90]", "0/", "0 90", "(0/90)0", "(0/90)1.5s", "[0/90]s2", "s", "abc", "95", "-91", "//"]
)
def test_parse_layup_rejects_with_allowed_forms(text):
    with pytest.raises(ValueError, match="allowed"):
        parse_layup(text)


@pytest.mark.parametrize("text", ["0//90", "-90.5", "(0)999s", "±-45", "[0/90)", "0/90s", "nan"])
def test_parse_layup_rejects(text):
    with pytest.raises(ValueError):
        parse_layup(text)


def test_parse_layup_names_out_of_range_angle():
    with pytest.raises(ValueError, match=r"-95 deg is outside \[-90, 90\]"):
        parse_layup("(0/-95)s")


# ------------------------------------------------------------------------------ stiffness


@given(st.floats(-90.0, 90.0))
@settings(max_examples=50, deadline=None)
def test_transformed_stiffness_matches_jones_explicit_formulas(angle_deg):
    """Q_bar against the explicit polynomial forms of Jones (1999) eq. 2.84."""
    Q = reduced_stiffness(CARBON_EPOXY).real
    Q11, Q12, Q22, Q66 = Q[0, 0], Q[0, 1], Q[1, 1], Q[2, 2]
    c, s = np.cos(np.radians(angle_deg)), np.sin(np.radians(angle_deg))
    expected = np.array(
        [
            [
                Q11 * c**4 + 2 * (Q12 + 2 * Q66) * s**2 * c**2 + Q22 * s**4,
                (Q11 + Q22 - 4 * Q66) * s**2 * c**2 + Q12 * (s**4 + c**4),
                (Q11 - Q12 - 2 * Q66) * s * c**3 + (Q12 - Q22 + 2 * Q66) * s**3 * c,
            ],
            [
                0,
                Q11 * s**4 + 2 * (Q12 + 2 * Q66) * s**2 * c**2 + Q22 * c**4,
                (Q11 - Q12 - 2 * Q66) * s**3 * c + (Q12 - Q22 + 2 * Q66) * s * c**3,
            ],
            [0, 0, (Q11 + Q22 - 2 * Q12 - 2 * Q66) * s**2 * c**2 + Q66 * (s**4 + c**4)],
        ]
    )
    expected = np.triu(expected) + np.triu(expected, 1).T
    Q_bar = transformed_stiffness(Q, np.radians([angle_deg]))[0]
    np.testing.assert_allclose(Q_bar.real, expected, rtol=0, atol=TIGHT * Q11)


def test_isotropic_laminate_returns_E_and_G():
    E, G, eta = 68.9e9, 26.0e9, 0.001
    laminate = Laminate.from_layup("(55/-55/0/0)s", 3e-3, Lamina.isotropic(E, G, 2700.0, eta))
    E_x, G_xy = equivalent_moduli(laminate)
    np.testing.assert_allclose(E_x, E * (1 + 1j * eta), rtol=TIGHT)
    np.testing.assert_allclose(G_xy, G * (1 + 1j * eta), rtol=TIGHT)
    assert equivalent_density(laminate) == 2700.0


@pytest.mark.parametrize("lamina", [CARBON_EPOXY, FMC])
def test_unidirectional_plies_return_E_L_and_E_T(lamina):
    """[0] loaded along x with a free hoop is a uniaxial test of E_L; [90] of E_T."""
    assert equivalent_moduli(one_ply(0.0, lamina))[0] == pytest.approx(lamina.E_L, rel=TIGHT)
    assert equivalent_moduli(one_ply(90.0, lamina))[0] == pytest.approx(lamina.E_T, rel=TIGHT)
    assert equivalent_moduli(one_ply(0.0, lamina))[1] == pytest.approx(lamina.G_LT, rel=TIGHT)


@pytest.mark.parametrize("lamina", [CARBON_EPOXY, FMC.storage])
def test_balanced_pm45_shear_and_axial_moduli_closed_form(lamina):
    """[±45]s: pure shear gamma puts eps_1 = gamma/2, eps_2 = -gamma/2 in both plies, so
    tau_xy = (sigma_1 - sigma_2)/2 and G_xy = (Q11 + Q22 - 2 Q12)/4, written with
    engineering constants. Axially (A16 = A26 = 0 by balance): E_x = (A11^2 - A12^2)/(A11 t)
    with A11/t = (Q11 + Q22 + 2 Q12 + 4 Q66)/4 and A12/t = (Q11 + Q22 + 2 Q12 - 4 Q66)/4."""
    E_L, E_T, G, nu = lamina.E_L.real, lamina.E_T.real, lamina.G_LT.real, lamina.nu_LT
    d = 1.0 - nu**2 * E_T / E_L
    Q11, Q22, Q12 = E_L / d, E_T / d, nu * E_T / d
    G_expected = (Q11 + Q22 - 2 * Q12) / 4
    A11 = (Q11 + Q22 + 2 * Q12 + 4 * G) / 4
    A12 = (Q11 + Q22 + 2 * Q12 - 4 * G) / 4
    E_x, G_xy = equivalent_moduli(Laminate.from_layup("[45/-45]s", 2e-3, lamina))
    assert G_xy.real == pytest.approx(G_expected, rel=TIGHT)
    assert E_x.real == pytest.approx((A11**2 - A12**2) / A11, rel=TIGHT)


def test_A_real_symmetric_and_B_zero_for_real_symmetric_laminate():
    laminate = Laminate.from_layup("(55/-55/0/0)s", 3e-3, CARBON_EPOXY)
    A, B, D = abd_matrices(laminate)
    for matrix in (A, D):
        assert np.all(matrix.imag == 0.0)
        np.testing.assert_allclose(matrix, matrix.T, rtol=0, atol=TIGHT * abs(matrix).max())
    assert np.abs(B).max() <= TIGHT * np.abs(A).max() * laminate.thickness
    # an unsymmetric stack has coupling, B11 = (Q11 - Q22) t^2 / 8 for [0/90] of thickness t
    t = 2e-3
    _, B, _ = abd_matrices(Laminate.from_layup("0/90", t, CARBON_EPOXY))
    Q = reduced_stiffness(CARBON_EPOXY).real
    assert B[0, 0].real == pytest.approx((Q[1, 1] - Q[0, 0]) * t**2 / 8, rel=1e-12)


@pytest.mark.parametrize("layup", ["(55/-55/0/0)s", "[45/-45]s", "(30/-30/90)s", "0", "90", "(70/-70)2s"])
def test_complex_moduli_loss_factors_lie_between_lamina_ones(layup):
    """The laminate compliance is a weighted sum of the ply compliances 1/E_L, 1/E_T, 1/G_LT,
    so its loss factor is a weighted mean of 0.003 and 0.12, except that the Poisson term
    -2 nu_LT/E_L enters with a negative weight; near-transverse plies (70 deg) then exceed 0.12
    by ~2e-5 relative. The slack 1e-4 (about nu_LT E_T/E_L = 3e-4) covers that and nothing more."""
    E_x, G_xy = equivalent_moduli(Laminate.from_layup(layup, 3e-3, FMC))
    for modulus in (E_x, G_xy):
        assert modulus.imag > 0.0
        assert 0.003 * (1 - 1e-4) <= modulus.imag / modulus.real <= 0.12 * (1 + 1e-4)


def test_lamina_constructors_and_validation():
    iso = Lamina.isotropic(70e9, 26.9230769e9, 2700.0)
    assert iso.nu_LT == pytest.approx(0.3, rel=1e-8)
    assert FMC.E_T == pytest.approx(0.10e9 * (1 + 0.12j))
    with pytest.raises(ValueError, match="E_T"):
        Lamina(1e9, -1e9, 1e9, 0.3, 1000.0)
    with pytest.raises(ValueError, match="nu_LT"):
        Lamina(1e9, 1e9, 1e9, 1.2, 1000.0)
    with pytest.raises(ValueError, match="thicknesses"):
        Laminate(np.zeros(2), np.array([1e-3, -1e-3]), FMC)
    with pytest.raises(ValueError, match="angles"):
        Laminate(np.array([2.0]), np.array([1e-3]), FMC)


# ------------------------------------------------------------------------------ ply strains, stresses


def test_axial_strain_on_0_and_90_plies():
    laminate = Laminate.from_layup("0/90", 2e-3, CARBON_EPOXY)
    strains = ply_strains(laminate, 1e-3, 0.0, 0.0)
    np.testing.assert_allclose(strains[0], [1e-3, 0.0, 0.0], atol=1e-18)
    np.testing.assert_allclose(strains[1], [0.0, 1e-3, 0.0], atol=1e-18)


def test_pure_shear_rotated_by_pm45_gives_half_gamma_normal_strains():
    gamma = 2e-3
    strains = ply_strains(Laminate.from_layup("45/-45", 2e-3, CARBON_EPOXY), 0.0, 0.0, gamma)
    np.testing.assert_allclose(strains[0], [gamma / 2, -gamma / 2, 0.0], atol=1e-18)
    np.testing.assert_allclose(strains[1], [-gamma / 2, gamma / 2, 0.0], atol=1e-18)


def test_ply_strains_broadcast_over_elements_and_phases():
    laminate = Laminate.from_layup("(55/-55/0/0)s", 3e-3, FMC)
    eps_x = np.linspace(-1e-3, 1e-3, 5)[:, None] * np.ones((1, 7))
    gamma = 1e-3 * np.ones((5, 1))
    eps_y = hoop_strain_free(laminate, eps_x, gamma)
    assert eps_y.shape == (5, 7)
    strains = ply_strains(laminate, eps_x, eps_y, gamma)
    stresses = ply_stresses(laminate, eps_x, eps_y, gamma)
    assert strains.shape == stresses.shape == (5, 7, 8, 3)
    single = ply_strains(laminate, eps_x[3, 2], eps_y[3, 2], gamma[3, 0])
    np.testing.assert_allclose(strains[3, 2], single, rtol=TIGHT)


def test_free_hoop_strain_zeroes_N_y_and_gives_poisson_for_isotropic():
    laminate = Laminate.from_layup("(55/-55/0/0)s", 3e-3, FMC)
    eps_x, gamma = 1e-3, -2e-3
    eps_y = hoop_strain_free(laminate, eps_x, gamma)
    A = abd_matrices(laminate.storage)[0].real
    N = A @ np.array([eps_x, eps_y, gamma])
    assert abs(N[1]) <= TIGHT * np.abs(A).max() * 1e-3
    iso = Laminate.from_layup("0", 1e-3, Lamina.isotropic(70e9, 70e9 / 2.6, 2700.0))
    assert hoop_strain_free(iso, eps_x, 0.0) == pytest.approx(-0.3 * eps_x, rel=1e-12)


def test_ply_stresses_use_storage_moduli_uniaxial_isotropic():
    """Isotropic wall, eps_x with eps_y = -nu eps_x: sigma_1 = E' eps_x, sigma_2 = 0 (storage E')."""
    E, nu = 70e9, 0.3
    laminate = Laminate.from_layup("0", 1e-3, Lamina.isotropic(E, E / (2 * (1 + nu)), 2700.0, 0.05))
    stresses = ply_stresses(laminate, 1e-3, -nu * 1e-3, 0.0)
    np.testing.assert_allclose(stresses[0], [E * 1e-3, 0.0, 0.0], atol=1e-6)
    assert stresses.dtype == np.float64


# ------------------------------------------------------------- transverse shear, spin, thermal


def test_transverse_shear_stiffness_of_isotropic_and_unidirectional_plies():
    """Isotropic: A44 = A55 = k G t, A45 = 0 (Reissner-Mindlin). A 0 deg ply: the x-z plane is
    the fibre-thickness plane (A55 = k G_13 t), the y-z plane crosses the fibres (A44 = k G_23 t);
    a 90 deg ply swaps them. Default moduli: G_13 = G_LT, G_23 = E_T/3 (nu_23 = 0.5), k = 5/6."""
    G = 70e9 / 2.6
    iso = Laminate([0.3, -1.1], [1e-3, 2e-3], Lamina.isotropic(70e9, G, 2700.0))
    np.testing.assert_allclose(transverse_shear_stiffness(iso), 5 / 6 * G * 3e-3 * np.eye(2), rtol=TIGHT, atol=1e-6)
    ply = Lamina(140e9, 10e9, 5e9, 0.3, 1600.0, G_13=4e9, G_23=3.5e9, shear_correction=0.9)
    np.testing.assert_allclose(
        transverse_shear_stiffness(one_ply(0.0, ply)), 0.9e-3 * np.diag([4e9, 3.5e9]), rtol=TIGHT
    )
    np.testing.assert_allclose(
        transverse_shear_stiffness(one_ply(90.0, ply)), 0.9e-3 * np.diag([3.5e9, 4e9]), rtol=TIGHT, atol=1e-3
    )
    assert (CARBON_EPOXY.G_13, CARBON_EPOXY.G_23, CARBON_EPOXY.shear_correction) == (5e9, 10e9 / 3, 5 / 6)


@given(st.floats(-90.0, 90.0))
@settings(max_examples=50, deadline=None)
def test_transverse_shear_of_one_ply_rotates_as_a_tensor(angle_deg):
    """(gamma_xz, gamma_yz) rotate like a vector, so the 2x2 stiffness is a rotated
    diag(G_13, G_23): trace and determinant are invariant and A45 = k t (G_13 - G_23) c s."""
    ply = Lamina(140e9, 10e9, 5e9, 0.3, 1600.0, G_13=4e9, G_23=3e9)
    A = transverse_shear_stiffness(one_ply(angle_deg, ply)).real / (5 / 6 * 1e-3)
    a = np.radians(angle_deg)
    assert np.trace(A) == pytest.approx(7e9, rel=1e-12)
    assert np.linalg.det(A) == pytest.approx(12e18, rel=1e-9)
    assert A[0, 1] == pytest.approx(1e9 * np.cos(a) * np.sin(a), abs=1e-3)


def test_spin_hoop_resultant_of_a_ring_through_the_laminate_path():
    """A thin ring of density rho, radius r spinning at Omega carries sigma_hoop = rho Omega^2 r^2
    (radial equilibrium of a ring element, Timoshenko & Goodier sec. 32). Through the laminate
    path, N_y = rho t Omega^2 r^2, strains A^-1 (0, N_y, 0), ply stresses: an isotropic 'laminate'
    of any ply angles gives sigma_hoop in every ply and no axial stress (free ends)."""
    rho, r, omega, t = 2700.0, 0.05, 502.65, 3e-3
    iso = Laminate.from_layup("(55/-55/0/0)s", t, Lamina.isotropic(70e9, 70e9 / 2.6, rho))
    N_y = spin_hoop_resultant(rho, t, r, omega)
    stresses = ply_stresses(iso, *membrane_strains(iso, [0.0, N_y, 0.0]))
    c, s = np.cos(iso.angles), np.sin(iso.angles)
    hoop = rho * omega**2 * r**2  # sigma_y; sigma_x = tau_xy = 0 -> ply axes by rotation
    expected = np.stack([hoop * s * s, hoop * c * c, hoop * c * s], axis=-1)
    np.testing.assert_allclose(stresses, expected, rtol=1e-12, atol=1e-9 * hoop)


def test_thermal_residual_stresses_vanish_for_a_free_isotropic_or_single_ply_laminate():
    iso = Laminate.from_layup("(55/-55/0/0)s", 3e-3, Lamina.isotropic(70e9, 70e9 / 2.6, 2700.0, alpha=23e-6))
    np.testing.assert_allclose(thermal_ply_stresses(iso, -80.0), 0.0, atol=1e-6)
    single = Laminate.from_layup("30", 3e-3, Lamina(140e9, 10e9, 5e9, 0.3, 1600.0, alpha_L=-0.4e-6, alpha_T=30e-6))
    np.testing.assert_allclose(thermal_ply_stresses(single, -80.0), 0.0, atol=1e-6)


def test_thermal_residual_stresses_of_a_cross_ply_closed_form():
    """[0/90]s, equal plies: by symmetry eps_x = eps_y = eps0, and N_x = 0 gives
    eps0 = dT [(Q11 + Q12) alpha_L + (Q12 + Q22) alpha_T] / (Q11 + 2 Q12 + Q22); the 0 deg ply
    then carries sigma_1 = Q11 (eps0 - alpha_L dT) + Q12 (eps0 - alpha_T dT) and sigma_2 =
    Q12 (eps0 - alpha_L dT) + Q22 (eps0 - alpha_T dT), the 90 deg ply the same (Jones sec. 4.5)."""
    ply = Lamina.from_loss_factors(
        115e9, 0.10e9, 0.035e9, 0.35, 1650.0, 0.003, 0.12, 0.12, alpha_L=-0.4e-6, alpha_T=110e-6
    )
    dT = -65.0
    nu_TL = 0.35 * 0.10 / 115.0
    den = 1 - 0.35 * nu_TL
    Q11, Q22, Q12 = 115e9 / den, 0.10e9 / den, 0.35 * 0.10e9 / den
    eps0 = dT * ((Q11 + Q12) * -0.4e-6 + (Q12 + Q22) * 110e-6) / (Q11 + 2 * Q12 + Q22)
    m1, m2 = eps0 + 0.4e-6 * dT, eps0 - 110e-6 * dT
    expected = [Q11 * m1 + Q12 * m2, Q12 * m1 + Q22 * m2, 0.0]
    stresses = thermal_ply_stresses(Laminate.from_layup("(0/90)s", 3e-3, ply), dT)
    np.testing.assert_allclose(stresses, np.tile(expected, (4, 1)), rtol=1e-10, atol=1e-6)
    assert expected[1] > 0.5e6  # matrix in tension across the fibres after cooling: 0.71 MPa


@pytest.mark.parametrize("layup", ["(55/-55/0/0)s", "(30/75/-20)", "(55/55/0/0)s"])
def test_thermal_residual_stresses_are_self_equilibrated(layup):
    """No external load: the ply stresses, rotated back to laminate axes, integrate to N = 0."""
    ply = Lamina(140e9, 10e9, 5e9, 0.3, 1600.0, alpha_L=-0.4e-6, alpha_T=30e-6)
    laminate = Laminate.from_layup(layup, 3e-3, ply)
    stresses = thermal_ply_stresses(laminate, -100.0)
    c, s = np.cos(laminate.angles), np.sin(laminate.angles)
    s1, s2, t12 = stresses.T
    sx = c * c * s1 + s * s * s2 - 2 * c * s * t12
    sy = s * s * s1 + c * c * s2 + 2 * c * s * t12
    txy = c * s * (s1 - s2) + (c * c - s * s) * t12
    N = np.array([sx, sy, txy]) @ laminate.thicknesses
    np.testing.assert_allclose(N, 0.0, atol=1e-9 * np.abs(stresses).max() * 3e-3)


def test_out_of_plane_lamina_fields_are_checked_and_kept_by_storage():
    with pytest.raises(ValueError, match="G_23"):
        Lamina(140e9, 10e9, 5e9, 0.3, 1600.0, G_23=0.0)
    with pytest.raises(ValueError, match="shear_correction"):
        Lamina(140e9, 10e9, 5e9, 0.3, 1600.0, shear_correction=0.0)
    with pytest.raises(ValueError, match="alpha_T"):
        Lamina(140e9, 10e9, 5e9, 0.3, 1600.0, alpha_T=float("nan"))
    ply = Lamina.from_loss_factors(115e9, 0.1e9, 0.035e9, 0.35, 1650.0, 0.0, 0.12, 0.12, G_23=0.03e9, alpha_T=1e-4)
    assert ply.G_23 == pytest.approx(0.03e9 * (1 + 0.12j))
    storage = ply.storage
    assert (storage.G_13, storage.G_23, storage.alpha_T) == (0.035e9, 0.03e9, 1e-4)

"""Torsional buckling: the Ritz pieces and the reported mode against independent references.

* The axial integrals of the sine/cosine series against Gauss-Legendre quadrature.
* The shell's coupling block B of a two-ply cross-ply wall worked by hand (classical lamination
  theory, z from the mid-surface, positive outward, inner ply first).
* The reported W mode of the classical tube against the eigenvector of the documented Ritz
  pencil K a = T G a solved densely (scipy.linalg.eig), and its hand: the torque's work.
* The axial half-wave count of the shear-deformable tube against Mindlin-Donnell's closed form,
  on the Ritz path and on the endless-tube path; the governing-mode label of a short-wave
  mode below the first local minimum over n.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg
import scipy.optimize

from flexshaft.buckling import torsional_buckling_torque
from flexshaft.buckling._common import axial_integrals, shell_stiffness
from flexshaft.buckling.classical import classical_galerkin_matrices, classical_helix_torque
from flexshaft.buckling.shear import shear_helix_curve
from flexshaft.laminate import Lamina, Laminate

E, NU = 70e9, 0.3
ALUMINIUM = Lamina.isotropic(E, E / (2 * (1 + NU)), 2700.0)


def test_axial_integrals_equal_gauss_legendre_quadrature():
    """int_0^L f(a pi x/L) g(b pi x/L) dx for f, g in (sin, cos), a, b = 0..7, by 64-point
    Gauss-Legendre quadrature on [0, L]: exact to rounding for these trigonometric
    polynomials of degree <= 14 pi/L (error far below 1e-14 L); 1e-12 L allows the rounding
    of the sums."""
    length = 1.7
    m = np.arange(8)
    x, w = np.polynomial.legendre.leggauss(64)
    x, w = 0.5 * length * (x + 1.0), 0.5 * length * w
    phase = np.outer(m, x) * np.pi / length  # (m, points)
    functions = (np.sin(phase), np.cos(phase))
    integrals = axial_integrals(m, length)
    assert set(integrals) == {(0, 0), (0, 1), (1, 0), (1, 1)}  # sin-sin, sin-cos, cos-sin, cos-cos
    for (p, q), value in integrals.items():
        reference = (functions[p] * w) @ functions[q].T
        np.testing.assert_allclose(value, reference, rtol=0.0, atol=1e-12 * length)


def test_shell_coupling_block_of_a_cross_ply_pair_is_worked_by_hand():
    """[0/90], inner ply 0 deg on z in [-t/2, 0], outer ply 90 deg on z in [0, t/2]:
    B = 1/2 sum Q_bar_k (z_k^2 - z_{k-1}^2) = t^2/8 (Q_bar(90) - Q_bar(0)), so
    B11 = t^2/8 (Q22 - Q11) = -B22 and B12 = B66 = B16 = B26 = 0, with Q11 = E_L/(1 - nu nu_TL),
    Q22 = E_T/(1 - nu nu_TL) (plane stress). The shell stiffness relates (N, M) to (eps, kappa)
    through [[A, B], [B, D]]: both off-diagonal blocks are this B (1e-12 relative: a few
    roundings)."""
    E_L, E_T, G_LT, nu = 140e9, 10e9, 5e9, 0.3
    t = 2e-3
    laminate = Laminate(np.radians([0.0, 90.0]), [t / 2, t / 2], Lamina(E_L, E_T, G_LT, nu, 1600.0))
    denominator = 1.0 - nu * nu * E_T / E_L
    Q11, Q22 = E_L / denominator, E_T / denominator
    B = np.zeros((3, 3))
    B[0, 0], B[1, 1] = t**2 / 8 * (Q22 - Q11), t**2 / 8 * (Q11 - Q22)
    C = shell_stiffness(laminate)
    scale = abs(B[0, 0])
    np.testing.assert_allclose(C[:3, 3:], B, rtol=0.0, atol=1e-12 * scale)
    np.testing.assert_allclose(C[3:, :3], B, rtol=0.0, atol=1e-12 * scale)


def test_classical_mode_is_the_w_part_of_the_pencils_eigenvector():
    """BucklingResult.mode_positive is documented as the Ritz coefficients W_1..W_M of w,
    normalised to max |W_m| = 1, with dofs (U_0..U_M, V_1..V_M, W_1..W_M) of the pencil
    K a = T G a (classical_galerkin_matrices). Here the eigenvector of the lowest positive T,
    from a dense complex generalized eigen-solve, is cut to its W block and normalised; the
    V block differs from it by 6e-3 on this short tube (R/t = 200, L = 5 R, n = 6). Tolerance
    1e-8: an isolated eigenvalue, well conditioned."""
    tube = Laminate([0.0], [1.0 / 200.0], ALUMINIUM)
    result = torsional_buckling_torque(tube, 1.0, 5.0, theory="classical")
    M, n = result.n_terms, result.n_positive
    K, G = classical_galerkin_matrices(tube, 1.0, 5.0, n, M)
    values, vectors = scipy.linalg.eig(K, G)
    positive = np.where(np.isfinite(values) & (values.real > 0), values.real, np.inf)
    i = int(np.argmin(positive))
    assert values[i].real == pytest.approx(result.torque_positive, rel=1e-9)
    W = vectors[2 * M + 1 : 3 * M + 1, i]
    W = W / W[np.argmax(np.abs(W))]
    np.testing.assert_allclose(result.mode_positive, W, rtol=0.0, atol=1e-8)


def test_positive_torque_buckles_lean_along_the_tension_diagonal():
    """Energy: with N_xy = T/(2 pi R^2) positive in the sense that puts +45 deg fibres in
    tension, the prestress adds N_xy int w,x w,y dA to the second variation of the potential
    (the second-order shear strain w,x w,y). For a helix w = cos(k x + n theta), w,x w,y has the
    sign of k n, so buckling (a vanishing second variation) under T > 0 needs k n < 0: crests
    along k x + (n/R) y = const, dy/dx = -k R/n > 0, the +45 deg tension diagonal (as a sheared
    web wrinkles). So the endless tube's positive-sense wavenumber is negative and the negative
    sense's positive (n > 0), and the finite tube's mode w = Re(sum W_m sin(m pi x/L) e^{i n theta})
    holds its axial spectrum at negative wavenumbers: measured 39 times the power at positive
    ones (R/t = 200, L = 20 R); a factor 10 is asserted, its mirror image would give 1/39."""
    tube = Laminate([0.0], [1.0 / 200.0], ALUMINIUM)
    helix = classical_helix_torque(tube, 1.0)
    assert helix["positive"][2] < 0.0 < helix["negative"][2]

    length = 20.0
    result = torsional_buckling_torque(tube, 1.0, length, theory="classical")
    M = result.n_terms
    x = np.linspace(0.0, length, 4001)
    f = np.sin(np.outer(x, np.arange(1, M + 1)) * np.pi / length) @ result.mode_positive
    spectrum = np.abs(np.fft.fft(f)) ** 2  # F_j = sum f e^{-2 pi i j n/N}: e^{ikx}, k < 0 at j < 0
    frequency = np.fft.fftfreq(x.size)
    assert spectrum[frequency < 0].sum() > 10.0 * spectrum[frequency > 0].sum()


# Mindlin-Donnell endless helix of an isotropic moderately thick tube (the closed form of
# tests/test_buckling.py): tau t = [D_eff s^2 + E t k^4/(R^2 s^2)] / (2 k eta), s = k^2 + eta^2,
# D_eff = D / (1 + D s/(k G t)).
RADIUS, THICKNESS = 1.0, 0.1
D_PLATE = E * THICKNESS**3 / (12 * (1 - NU**2))
KGT = 5 / 6 * E / (2 * (1 + NU)) * THICKNESS


def helix_stress(k: float, n: int) -> float:
    """The closed form's buckling shear stress tau [Pa] of the helix (k [rad/m], n)."""
    eta = n / RADIUS
    s = k**2 + eta**2
    D_eff = D_PLATE / (1 + D_PLATE * s / KGT)
    return (D_eff * s**2 + E * THICKNESS * k**4 / (RADIUS**2 * s**2)) / (2 * k * eta * THICKNESS)


def mindlin_donnell_wavenumber(n: int) -> float:
    """The axial wavenumber k [rad/m] that minimises the helix torque at n."""
    grid = np.log(n / RADIUS) + np.linspace(-6, 3, 200)
    start = grid[np.argmin([helix_stress(np.exp(x), n) for x in grid])]
    bounds = (start - 0.1, start + 0.1)
    found = scipy.optimize.minimize_scalar(
        lambda x: helix_stress(np.exp(x), n), bounds=bounds, method="bounded", options={"xatol": 1e-10}
    )
    return float(np.exp(found.x))


@pytest.mark.parametrize("half_waves", [6, 110])
def test_axial_half_waves_of_a_long_tube_follow_the_helix_wavenumber(half_waves):
    """A long isotropic tube (R/t = 10, Donnell) buckles in the n = 2 helix of wavenumber k
    (closed form above: 0.5352 rad/m); on L = N pi/k it holds N axial half-waves. N = 6 is
    solved by Ritz (up to 32 terms over the n searched): the largest W_m of the mode on
    sin(m pi x/L) is at m = N (|W_N| = 1, its neighbours N -+ 1 about 0.77 and 0.76), so the
    reported count is N; N = 110 needs more than 140 terms, so the endless-tube value is used:
    the count is |k| L/pi = N exactly (both senses: the isotropic tube is sense-free), and the
    torque is the closed form's 2 pi R^2 t tau(k) at its minimum. Tolerances: the count is an
    integer; the torque to 1e-7, where the endless-tube search refines its minimum to about
    1e-9 (flexshaft.buckling.shear) and a torque without shear deformation (D_eff = D) is 0.96 %
    higher, one with kappa = 1 0.16 % lower."""
    k = mindlin_donnell_wavenumber(2)
    assert k == pytest.approx(0.5352, rel=1e-4)  # the value quoted above
    tube = Laminate([0.0], [THICKNESS], ALUMINIUM)
    result = torsional_buckling_torque(tube, RADIUS, half_waves * np.pi / k, kinematics="donnell")
    assert result.governing == "global helical" and result.n_positive == result.n_negative == 2
    assert result.axial_half_waves_positive == result.axial_half_waves_negative == half_waves
    if half_waves == 110:
        assert result.n_terms == 0  # the endless-tube path
        torque = 2 * np.pi * RADIUS**2 * THICKNESS * helix_stress(k, 2)
        assert result.torque_positive == pytest.approx(torque, rel=1e-7)


def test_a_short_wave_mode_below_the_first_minimum_is_labelled_shear_crimping():
    """The documented rule (flexshaft.buckling.shear, "Search and governing mode"): the global
    helical branch is the first local minimum over n; a lower mode at a larger n is a
    shorter-wave mode and is reported as "shear crimping" with its n. A thin hoop-wound tube
    (90 deg plies, 0.5 mm, soft G_13 = 5 MPa, G_23 = 20 MPa) 60 m long (every n on the
    endless-tube path) has its first minimum at n = 2 (20.08 N m, n = 3 higher) and a lower one
    at n = 10 (12.71 N m), far below the crimping limit 2 pi R^2 sqrt(A44 A55) = 63.6 N m
    (n = 10 is the lowest of n = 2..199 on the endless curve; n_max = 40 keeps the search short)."""
    radius = (0.1016 - 3e-3) / 2
    lamina = Lamina(115e9, 0.1e9, 0.035e9, 0.3, 1600.0, G_13=5e6, G_23=0.02e9)
    wall = Laminate.from_layup("(90)s", 0.5e-3, lamina)
    curve, _ = shear_helix_curve(wall, radius, np.arange(2, 12))
    assert curve[1, 0] > curve[0, 0] and np.argmin(curve[:, 0]) == 8  # first minimum n = 2, lower at n = 10
    result = torsional_buckling_torque(wall, radius, 60.0, n_max=40)  # n = 10 well inside; a shorter search
    assert result.global_n_positive == 2 and result.n_positive == 10
    assert result.torque_positive == pytest.approx(curve[8, 0], rel=1e-9)
    assert result.torque_positive < result.global_torque_positive < result.crimping_torque_positive
    # the crimping limit 2 pi R^2 kappa t sqrt(G_13 G_23) (kappa = 5/6, t = 0.5 mm in all): a
    # product and a square root, to round-off; every n on the endless-tube path (no Ritz terms)
    assert wall.thickness == 0.5e-3
    crimping = 2 * np.pi * radius**2 * 5 / 6 * 0.5e-3 * np.sqrt(5e6 * 0.02e9)
    assert result.crimping_torque_positive == pytest.approx(crimping, rel=1e-12)
    assert result.n_terms == 0
    assert result.governing_positive == "shear crimping"

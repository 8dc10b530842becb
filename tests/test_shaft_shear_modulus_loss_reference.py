"""The loss part G'' of a complex shear modulus reaches the shaft element's stiffness.

A composite shaft's hysteretic loss is carried by a complex stiffness K built from the complex
moduli E*, G* (docs/model.md, "Equations": "`K` complex: shaft `E*`, `G*` from CLT with complex
lamina moduli"); written here with a loss factor, ``E* = E'(1 + iη_E)``, ``G* = G'(1 + iη_G)``.
The shear modulus enters twice: the torsion ``G J ∫θ'θ'`` and, with the Timoshenko option, the
shear energy ``κ G A ∫(s_v² + s_w²)``. These tests keep E real, so every imaginary part of K
comes from G''.

The mutation h81a-shaft-shear-modulus-loss-dropped (G'' dropped) was already caught by
tests/test_heat_timoshenko_element_reference.py, outside the shaft module's test list; this file
adds a real E, which isolates G'', and the torsion block.
"""

import numpy as np
import pytest

from flexshaft.elements import TubeSection, shaft_element_matrices

E_STORAGE = 70e9  # [Pa]
G_STORAGE = 26e9  # [Pa]
RHO = 2700.0  # [kg/m^3]
SECTION = TubeSection(0.08, 0.05)
THETA = [3, 9]  # twist DOFs of the 12-DOF layout [u, v, w, θ, β, γ] × 2
V2, GAMMA2 = 7, 11  # lateral displacement and rotation of node 2 in the v plane


@pytest.mark.parametrize("kappa", [None, 0.6])
def test_torsion_loss_stiffness_is_g_loss_times_j_over_length(kappa):
    """Twist block of Im K = G' η_G J / L · [[1, −1], [−1, 1]], nothing else imaginary.

    Reference (derived here): θ is interpolated linearly, θ' = (θ2 − θ1)/L, so the torsion
    energy ``½ G* J ∫θ'² dx = ½ (G* J / L)(θ2 − θ1)²``; its imaginary part is the loss
    stiffness ``G' η_G J / L``. With E real and no shear term (Euler-Bernoulli) no other entry
    has an imaginary part. With the Timoshenko option the bending rows also carry G'' (the next
    test), but the twist block is still the same since θ does not couple to bending.

    Tolerance 1e-12 relative: the 4-point Gauss rule integrates the constant θ'² exactly, so
    only a few roundings (≈1e-16 each) separate the element from the closed form.
    """
    eta, L = 0.04, 0.35
    _, K, _ = shaft_element_matrices([L], SECTION, E_STORAGE, G_STORAGE * (1 + 1j * eta), RHO, kappa)
    loss = G_STORAGE * eta * SECTION.polar_moment / L
    expected = loss * np.array([[1.0, -1.0], [-1.0, 1.0]])
    np.testing.assert_allclose(K[0][np.ix_(THETA, THETA)].imag, expected, rtol=1e-12, atol=0)
    # storage stays G' J / L: the loss is not taken out of the storage part
    np.testing.assert_allclose(K[0][np.ix_(THETA, THETA)].real, expected / eta, rtol=1e-12, atol=0)
    if kappa is None:
        others = np.ones((12, 12), dtype=bool)
        others[np.ix_(THETA, THETA)] = False
        assert np.abs(K[0].imag[others]).max() <= 1e-12 * loss


def test_timoshenko_cantilever_tip_compliance_carries_the_shear_loss():
    """Tip compliance of a clamped short tube: δ = L³/(3 E' I) + L/(κ G* A), Im δ from G'' only.

    Reference (derived here): a cantilever of length L with a tip force P bends with moment
    P (L − x) and shears with force P; the complementary energy gives the tip deflection
    ``δ/P = L³/(3 E I) + L/(κ G A)`` (Timoshenko beam). With E real the imaginary part is
    ``Im δ/P = L/(κ A) · Im(1/G*) = −η_G L / (κ G' A (1 + η_G²))``.

    One element is exact for real moduli (interdependent interpolation, the shear parameter
    φ built from the same moduli). Here φ uses the storage modulus G' while the energy uses G*,
    so the shape functions are off by a shape error proportional to iη_G. The tip compliance is
    stationary in the shapes (Ritz), so its error is second order in that shape error: the
    leading term, ∝ (iη_G)² = −η_G², is real, and the imaginary part is off only at the next
    order, O(η_G³) absolute, i.e. at most O(η_G²) relative to Im δ = O(η_G). Measured at
    η_G = 1e-3: 1.07e-7 relative on the real part, 4.4e-7 on the imaginary part (1.07e-5 and
    4.4e-5 at η_G = 1e-2, both scaling as η_G²; the same under OpenBLAS Prescott and Haswell).
    rel = 1e-5 on each leaves 93x and 23x above the measured errors, while G'' dropped makes
    the imaginary part zero (a 100 % error). With E real the shear term carries all the loss;
    in this short, thick tube (L/D_o = 1.25) it is also about 43 % of the real compliance.
    """
    eta, L, kappa = 1e-3, 0.1, 0.6
    _, K, _ = shaft_element_matrices([L], SECTION, E_STORAGE, G_STORAGE * (1 + 1j * eta), RHO, kappa)
    tip = [V2, GAMMA2]
    compliance = np.linalg.solve(K[0][np.ix_(tip, tip)], np.array([1.0, 0.0]))[0]
    A, I = SECTION.area, SECTION.second_moment
    G_complex = G_STORAGE * (1 + 1j * eta)
    expected = L**3 / (3 * E_STORAGE * I) + L / (kappa * G_complex * A)
    assert compliance.real == pytest.approx(expected.real, rel=1e-5)
    assert compliance.imag == pytest.approx(expected.imag, rel=1e-5)
    assert expected.imag < 0  # the loss lags: a dissipative compliance

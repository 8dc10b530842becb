"""The ply check of :func:`shaft_safety_factor` on prescribed wall-strain fields, by hand.

A displacement field made of the polynomials the shaft element interpolates exactly (as in
tests/test_shaft_strains_reference.py: ``v = a x² + c x³``, ``w = b x²``, ``θ = k x``, node
rotations ``γ = v'``, ``β = −w'``) gives the curvatures ``κ_v = v''``, ``κ_w = w''`` and the twist
rate ``θ'`` exactly at every element end, so the outer-wall strains are known in closed form
(derived): ``ε_x = ± r_o |κ|`` with ``|κ| = √(κ_v² + κ_w²)`` (both fibres of the bending plane
pass the extreme once per turn), ``γ_xy = r_o θ'``.

* A single [0] ply with N_y = 0 carries the fibre stress ``σ₁ = E_L ε_x`` and ``σ₂ = τ₁₂ = 0``
  (σ₂ = Q₁₂ε_x + Q₂₂ε_y = 0 is the condition N_y = 0 itself; then σ₁ = (Q₁₁ − Q₁₂²/Q₂₂)ε_x =
  E_L ε_x), and Tsai-Wu under a uniaxial fibre stress meets the envelope at σ₁ = −X_c or X_t
  (thesis eq. 2.48-2.53): R = X_c/(E_L r_o |κ|) when X_c < X_t.
* A thermal residual σ_T (a fixed initial state R does not scale) moves the envelope:
  σ_T + R σ₁ = −X_c. At that point F(σ*) = F₁σ* + F₁₁σ*² = 1 gives F₁ + F₁₁σ* = 1/σ*, so the
  share φ_j = F₁σ*_j + F₁₁σ*_jσ* of a part σ*_j is σ*_j/σ* (derived): σ_T/(−X_c) for the
  residual and, for two bending planes at the critical fibre (along the total curvature),
  κ_j·κ/|κ|² for each plane: a²/(a² + b²) and b²/(a² + b²).
* A single ply at 30° under a pure twist (ε_x = 0) with N_y = 0: one ply, so σ_y = 0; the hoop
  strain ε_y that makes it so is solved by hand from the strain and stress transformations of
  Jones, *Mechanics of Composite Materials* (1999), eq. 2.80-2.84 (derived again below). An
  unbalanced ply couples shear and hoop strain (Ā₂₆ ≠ 0): ε_y ≠ 0.

Every case passes ``speed=0.0`` on a design whose operating speed is 3000 rpm (the check must use
the speed it is given) and ``thermal_residual=False`` unless the residual is the subject. The
Hermite element is exact for these fields and the reference is algebra: tolerance 1e-9
(round-off). Four elements, one model per layup, a few ms each.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict

X0, X1, D, WALL = 0.0, 1.6, 0.1, 0.003
E_L, E_T, G_LT, NU = 120.0e9, 8.0e9, 4.0e9, 0.3
X_T, X_C, Y_T, Y_C, S = 2000.0e6, 1000.0e6, 40.0e6, 140.0e6, 60.0e6
R_O = D / 2


def _tube(layup: str):
    data = {
        "name": f"[{layup}] tube",
        "materials": {
            "ply": {
                "kind": "lamina",
                "density": 1600.0,
                "E_L": E_L,
                "E_T": E_T,
                "G_LT": G_LT,
                "nu_LT": NU,
                "X_t": X_T,
                "X_c": X_C,
                "Y_t": Y_T,
                "Y_c": Y_C,
                "S": S,
            }
        },
        "shaft": {
            "x_start": X0,
            "x_end": X1,
            "outer_diameter": D,
            "wall_thickness": WALL,
            "material": "ply",
            "layup": layup,
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "stop", "kind": "contact", "x": X1, "stiffness": {}}],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 4},
    }
    return build_model(design_from_dict(data))


@pytest.fixture(scope="module")
def unidirectional():
    return _tube("0")


def _field(model, a: float = 0.0, b: float = 0.0, c: float = 0.0, k: float = 0.0) -> np.ndarray:
    """q of v = a x² + c x³, w = b x², θ = k x (γ = v', β = −w')."""
    dm = model.dofs
    x = np.asarray(dm.shaft_x, dtype=float)
    q = np.zeros(dm.size)
    fields = {
        "v": a * x**2 + c * x**3,
        "w": b * x**2,
        "theta": k * x,
        "gamma": 2 * a * x + 3 * c * x**2,
        "beta": -2 * b * x,
    }
    for name, values in fields.items():
        for node, value in enumerate(values):
            q[model.dofs.shaft(node, name)] = value
    return q


A, B = 2.0e-3, -3.0e-3  # curvatures 2A, 2B [1/m] in the two planes: different sizes and signs


def test_bending_in_two_planes_is_the_vector_sum_of_the_curvatures(unidirectional):
    """|κ| = 2√(A² + B²) everywhere: R = X_c/(E_L r_o |κ|) at every element end."""
    q = _field(unidirectional, a=A, b=B)
    result = shaft_safety_factor(unidirectional, q, speed=0.0, thermal_residual=False)
    kappa = 2 * np.hypot(A, B)
    expected = X_C / (E_L * R_O * kappa)
    assert result.safety_factor == pytest.approx(expected, rel=1e-9)
    assert result.stresses[0] == pytest.approx(-E_L * R_O * kappa, rel=1e-9)
    assert result.hoop_resultant == 0.0 and result.spin_speed == 0.0
    assert result.along_shaft == pytest.approx(np.full(result.along_shaft.shape, expected), rel=1e-9)


def test_a_curvature_growing_along_the_shaft_peaks_at_its_end(unidirectional):
    """v = c x³: κ_v = 6 c x, largest at x = 1.6 m, the end of the last element; along the
    shaft R(x) = X_c/(E_L r_o 6 c x) (at x = 0 nothing is bent but round-off:
    R there is huge)."""
    c = 1.0e-3
    q = _field(unidirectional, c=c)
    result = shaft_safety_factor(unidirectional, q, speed=0.0, thermal_residual=False)
    assert result.x == pytest.approx(X1, abs=1e-12)
    assert result.safety_factor == pytest.approx(X_C / (E_L * R_O * 6 * c * X1), rel=1e-9)
    x = result.x_along
    bent = x > 0
    assert result.along_shaft[bent] == pytest.approx(X_C / (E_L * R_O * 6 * c * x[bent]), rel=1e-9)
    assert np.all(result.along_shaft[~bent] > 1e6 * result.safety_factor)  # round-off curvature only


def test_each_planes_share_is_its_part_of_the_curvature_at_the_critical_fibre(unidirectional):
    """Two static parts, the v-plane and the w-plane bend: shares A²/(A² + B²) and B²/(A² + B²)."""
    parts = {"v_plane": _field(unidirectional, a=A), "w_plane": _field(unidirectional, b=B)}
    result = shaft_safety_factor(unidirectional, parts, speed=0.0, thermal_residual=False)
    assert result.safety_factor == pytest.approx(X_C / (E_L * R_O * 2 * np.hypot(A, B)), rel=1e-9)
    assert result.load_shares["v_plane"] == pytest.approx(A**2 / (A**2 + B**2), rel=1e-9)
    assert result.load_shares["w_plane"] == pytest.approx(B**2 / (A**2 + B**2), rel=1e-9)


def test_a_residual_fibre_stress_shifts_the_envelope_and_takes_its_unscaled_share(unidirectional):
    """σ_T = +20 MPa along the fibre: the compressed fibre fails at σ_T + R σ₁ = −X_c, so
    R = (X_c + σ_T)/|σ₁| (the tensile one at (X_t − σ_T)/|σ₁|, larger); shares σ_T/(−X_c) for the
    residual and (−X_c − σ_T)/(−X_c) for the bend."""
    sigma_t = 20.0e6
    q = _field(unidirectional, a=A)
    sigma = E_L * R_O * 2 * A
    result = shaft_safety_factor(
        unidirectional, {"bend": q}, speed=0.0, residual_stress=np.array([[sigma_t, 0.0, 0.0]])
    )
    assert result.safety_factor == pytest.approx((X_C + sigma_t) / sigma, rel=1e-9)
    assert result.load_shares["thermal"] == pytest.approx(sigma_t / -X_C, rel=1e-9)
    assert result.load_shares["bend"] == pytest.approx((-X_C - sigma_t) / -X_C, rel=1e-9)


def _ply_stresses_by_hand(theta_deg: float, eps_x: float, eps_y: float, gamma_xy: float) -> np.ndarray:
    """(σ₁, σ₂, τ₁₂) of a ply at θ: material strains by the strain transformation
    ε₁ = c²ε_x + s²ε_y + sc γ, ε₂ = s²ε_x + c²ε_y − sc γ, γ₁₂ = −2sc ε_x + 2sc ε_y + (c² − s²) γ,
    then the plane-stress reduced stiffness Q₁₁ = E_L/Δ, Q₂₂ = E_T/Δ, Q₁₂ = ν_LT E_T/Δ,
    Q₆₆ = G_LT, Δ = 1 − ν_LT²E_T/E_L (Jones 1999, eq. 2.61, 2.80)."""
    t = np.radians(theta_deg)
    c, s = np.cos(t), np.sin(t)
    e1 = c * c * eps_x + s * s * eps_y + s * c * gamma_xy
    e2 = s * s * eps_x + c * c * eps_y - s * c * gamma_xy
    g12 = -2 * s * c * eps_x + 2 * s * c * eps_y + (c * c - s * s) * gamma_xy
    delta = 1 - NU**2 * E_T / E_L
    return np.array([(E_L * e1 + NU * E_T * e2) / delta, (NU * E_T * e1 + E_T * e2) / delta, G_LT * g12])


def _sigma_y(theta_deg: float, stress: np.ndarray) -> float:
    """Hoop stress σ_y = s²σ₁ + c²σ₂ + 2sc τ₁₂ of a ply's material stresses (the stress
    transformation back to the tube's axes, the rotation by −θ of σ₁ = c²σ_x + s²σ_y + 2sc τ_xy)."""
    t = np.radians(theta_deg)
    c, s = np.cos(t), np.sin(t)
    return s * s * stress[0] + c * c * stress[1] + 2 * s * c * stress[2]


def test_a_twisted_unbalanced_ply_takes_the_hoop_strain_that_frees_its_hoop_stress():
    """[30] under θ' = k: γ_xy = r_o k, ε_x = 0, ε_y from σ_y(ε_y) = 0 (linear in ε_y: two
    evaluations solve it). The reported ply stresses are those; the free hoop strain is not
    zero (the ply is unbalanced)."""
    model = _tube("30")
    k = 0.02
    gamma = R_O * k
    s0 = _sigma_y(30.0, _ply_stresses_by_hand(30.0, 0.0, 0.0, gamma))
    s1 = _sigma_y(30.0, _ply_stresses_by_hand(30.0, 0.0, 1.0, gamma))
    eps_y = -s0 / (s1 - s0)
    expected = _ply_stresses_by_hand(30.0, 0.0, eps_y, gamma)
    assert abs(eps_y) > 0.1 * gamma  # the shear-hoop coupling matters here
    assert _sigma_y(30.0, expected) == pytest.approx(0.0, abs=1e-9 * np.abs(expected).max())
    result = shaft_safety_factor(model, _field(model, k=k), speed=0.0, thermal_residual=False)
    assert result.stresses == pytest.approx(tuple(expected), rel=1e-9, abs=1e-9 * np.abs(expected).max())

"""Tsai-Wu safety factor (thesis eq. 2.48-2.53; DESIGN.md section 6, Tsai-Wu), residual stresses,
load shares, and the shaft strength check with the centrifugal hoop and thermal residual stresses."""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from flexshaft.strength import (
    Strengths,
    dominant_stress,
    tsai_wu_coefficients,
    tsai_wu_contributions,
    tsai_wu_index,
    tsai_wu_quadratic,
    tsai_wu_safety_factor,
    tsai_wu_shares,
)

# thesis Table 3.2 (DESIGN.md section 5)
THESIS = Strengths(X_t=2185e6, X_c=2000e6, Y_t=5.1e6, Y_c=5.5e6, S=20e6)
SYMMETRIC = Strengths(X_t=1500e6, X_c=1500e6, Y_t=40e6, Y_c=40e6, S=60e6)
TIGHT = 1e-12  # R = 1 at the strengths: only round-off of a few operations


@pytest.mark.parametrize("strengths", [THESIS, SYMMETRIC])
def test_uniaxial_stress_at_each_strength_gives_R_equal_1(strengths):
    s = strengths
    sigma1 = np.array([s.X_t, -s.X_c, 0, 0, 0, 0])
    sigma2 = np.array([0, 0, s.Y_t, -s.Y_c, 0, 0])
    tau12 = np.array([0, 0, 0, 0, s.S, -s.S])
    np.testing.assert_allclose(tsai_wu_safety_factor(sigma1, sigma2, tau12, s), 1.0, rtol=TIGHT)


def test_uniaxial_fibre_tension_closed_form():
    """Pure sigma1 = sigma: a = sigma^2/(Xt Xc), b = sigma (1/Xt - 1/Xc), whose positive
    root is R = Xt/sigma exactly (factor (R sigma - Xt)(R sigma + Xc) = 0)."""
    sigma = np.array([1e6, 1e8, 7e8])
    np.testing.assert_allclose(tsai_wu_safety_factor(sigma, 0, 0, THESIS), THESIS.X_t / sigma, rtol=TIGHT)
    np.testing.assert_allclose(tsai_wu_safety_factor(-sigma, 0, 0, THESIS), THESIS.X_c / sigma, rtol=TIGHT)


@given(st.floats(-3e9, 3e9), st.floats(-3e7, 3e7), st.floats(-5e7, 5e7), st.floats(1e-3, 1e3))
@settings(max_examples=200, deadline=None)
def test_R_scales_as_inverse_load_with_only_quadratic_terms(s1, s2, t12, factor):
    """X_t = X_c and Y_t = Y_c make F1 = F2 = 0, so a R^2 = 1 and R(lambda sigma) = R(sigma)/lambda."""
    if max(abs(s1), abs(s2), abs(t12)) < 1.0:  # below 1 Pa a = O(sigma^2/X^2) may underflow
        return
    R = tsai_wu_safety_factor(s1, s2, t12, SYMMETRIC)
    R_scaled = tsai_wu_safety_factor(factor * s1, factor * s2, factor * t12, SYMMETRIC)
    assert R_scaled == pytest.approx(R / factor, rel=1e-12)


@given(st.floats(-3e9, 3e9), st.floats(-3e7, 3e7), st.floats(-5e7, 5e7))
@settings(max_examples=200, deadline=None)
def test_R_is_the_positive_root_of_the_thesis_quadratic(s1, s2, t12):
    if max(abs(s1), abs(s2), abs(t12)) < 1.0:  # below 1 Pa a = O(sigma^2/X^2) may underflow
        return
    a, b = tsai_wu_quadratic(s1, s2, t12, THESIS)
    R = tsai_wu_safety_factor(s1, s2, t12, THESIS)
    assert R > 0.0
    assert a * R**2 + b * R - 1.0 == pytest.approx(0.0, abs=1e-10)


def test_zero_stress_is_infinitely_safe_without_warnings():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        R = tsai_wu_safety_factor(np.zeros(3), 0.0, 0.0, THESIS)
        shares = tsai_wu_contributions(0.0, 0.0, 0.0, THESIS)
    assert np.all(np.isinf(R))
    np.testing.assert_array_equal(shares, 0.0)


def test_nearly_linear_criterion_is_stable():
    """X_c -> huge makes a -> 0 for sigma1 > 0 (linear term only): R -> X_t / sigma1; the naive
    (-b + sqrt(b^2 + 4a)) / (2a) would lose every digit here."""
    nearly_linear = Strengths(X_t=1e9, X_c=1e40, Y_t=1e7, Y_c=1e7, S=1e7)
    assert tsai_wu_safety_factor(2.5e8, 0.0, 0.0, nearly_linear) == pytest.approx(4.0, rel=1e-12)


def test_coefficients_are_fixed_by_the_uniaxial_strengths():
    """Tsai & Wu's coefficients are defined by the five uniaxial failure states: the index
    f₁σ + f₁₁σ² = 1 at σ₁ = X_t and at σ₁ = −X_c (two linear equations for f₁, f₁₁, solved here),
    the same for σ₂ with Y_t, Y_c, and f₆₆ S² = 1 (no linear shear term: the shear strength does
    not depend on the shear's sign). Solved by numpy, not typed: 1e-12."""
    F = tsai_wu_coefficients(THESIS)
    for (tension, compression), (linear, quadratic) in (
        ((THESIS.X_t, THESIS.X_c), (F.F1, F.F11)),
        ((THESIS.Y_t, THESIS.Y_c), (F.F2, F.F22)),
    ):
        f, ff = np.linalg.solve([[tension, tension**2], [-compression, compression**2]], [1.0, 1.0])
        assert (linear, quadratic) == pytest.approx((f, ff), rel=1e-12)
    assert F.F66 * THESIS.S**2 == pytest.approx(1.0, rel=1e-12)
    custom = Strengths(1e9, 1e9, 1e7, 1e7, 1e7, F12=0.0)
    assert tsai_wu_coefficients(custom).F12 == 0.0


def test_default_interaction_reduces_an_isotropic_ply_to_von_mises():
    """With equal strengths X in every direction and S = X/√3 (an isotropic material's shear
    yield), the default interaction F₁₂ = −½√(F₁₁F₂₂) (Tsai & Hahn) makes the Tsai-Wu index the
    von Mises plane-stress criterion (σ₁² − σ₁σ₂ + σ₂² + 3τ₁₂²)/X², so R = X/σ_vM exactly; random
    states, 1e-12."""
    X = 300e6
    iso = Strengths(X, X, X, X, X / np.sqrt(3.0))
    rng = np.random.default_rng(11)
    s1, s2, t12 = rng.normal(0.0, 1e8, (3, 50))
    von_mises = np.sqrt(s1**2 - s1 * s2 + s2**2 + 3 * t12**2)
    np.testing.assert_allclose(tsai_wu_safety_factor(s1, s2, t12, iso), X / von_mises, rtol=1e-12)


def test_invalid_strengths_are_refused():
    with pytest.raises(ValueError, match="Y_c"):
        Strengths(1e9, 1e9, 1e7, -1e7, 1e7)
    with pytest.raises(ValueError, match="F12"):
        Strengths(1e9, 1e9, 1e7, 1e7, 1e7, F12=1.0 / (1e9 * 1e7))


def test_broadcasting_over_elements_phases_plies():
    rng = np.random.default_rng(1)
    s1 = rng.normal(0, 5e8, (4, 6, 8))
    s2 = rng.normal(0, 2e6, (4, 6, 8))
    t12 = rng.normal(0, 5e6, (1, 6, 1))
    R = tsai_wu_safety_factor(s1, s2, t12, THESIS)
    assert R.shape == (4, 6, 8)
    assert R[2, 3, 5] == pytest.approx(tsai_wu_safety_factor(s1[2, 3, 5], s2[2, 3, 5], t12[0, 3, 0], THESIS))
    assert dominant_stress(s1, s2, t12, THESIS).shape == (4, 6, 8)


def test_dominant_stress_labels_and_shares_sum_to_one():
    s1 = np.array([1e9, 0.0, 0.0, 1e8])
    s2 = np.array([0.0, -3e6, 0.0, 1e5])
    t12 = np.array([0.0, 0.0, 1e7, 1.5e7])
    labels = dominant_stress(s1, s2, t12, THESIS)
    assert list(labels) == ["sigma1", "sigma2", "tau12", "tau12"]
    shares = tsai_wu_contributions(s1, s2, t12, THESIS)
    np.testing.assert_allclose(shares.sum(axis=-1), 1.0, rtol=1e-12)


# ------------------------------------------------------------------ residual stress and shares


def test_residual_stress_is_not_scaled_uniaxial_closed_form():
    """F(s_r + R s) = 1 along sigma2 alone: the envelope is reached at s_r + R s = Y_t (s > 0)
    or -Y_c (s < 0), so R = (Y_t - s_r)/s and R = (Y_c + s_r)/|s| exactly."""
    s_r, s = 0.7e6, np.array([1e6, -1e6])
    R = tsai_wu_safety_factor(0.0, s, 0.0, THESIS, residual=(0.0, s_r, 0.0))
    np.testing.assert_allclose(R, [(THESIS.Y_t - s_r) / 1e6, (THESIS.Y_c + s_r) / 1e6], rtol=TIGHT)
    # a residual that alone breaks the envelope leaves no margin; a zero residual changes nothing
    assert tsai_wu_safety_factor(0.0, 1e6, 0.0, THESIS, residual=(0.0, 6e6, 0.0)) == 0.0
    assert tsai_wu_safety_factor(1e8, 2e5, 3e6, THESIS, residual=(0.0, 0.0, 0.0)) == pytest.approx(
        tsai_wu_safety_factor(1e8, 2e5, 3e6, THESIS), rel=TIGHT
    )


@given(st.floats(-1e9, 1e9), st.floats(-3e6, 3e6), st.floats(-1e7, 1e7), st.floats(-1e8, 1e8), st.floats(-1e6, 1e6))
@settings(max_examples=200, deadline=None)
def test_R_with_residual_reaches_the_envelope(s1, s2, t12, r1, r2):
    if max(abs(s1), abs(s2), abs(t12)) < 1.0:
        return
    R = float(tsai_wu_safety_factor(s1, s2, t12, THESIS, residual=(r1, r2, 0.0)))
    if tsai_wu_index(r1, r2, 0.0, THESIS) >= 1.0:
        assert R == 0.0
        return
    assert R > 0.0
    assert tsai_wu_index(r1 + R * s1, r2 + R * s2, R * t12, THESIS) == pytest.approx(1.0, abs=1e-9)


def test_shares_are_the_integrated_gradient_and_sum_to_the_index():
    """Independent check of phi_j = f.s_j + s_j^T H s: integrate grad F(t s) . s_j over t in
    [0, 1] by 2-point Gauss-Legendre (exact: the gradient is linear in t), with the gradient
    taken by central differences of F (exact for a quadratic up to round-off)."""
    rng = np.random.default_rng(3)
    parts = rng.normal(0, 1, (4, 3)) * np.array([3e8, 1.5e6, 4e6])
    total = parts.sum(axis=0)

    def F(s):
        return float(tsai_wu_index(*s, THESIS))

    def gradient(s):
        h = np.array([1e3, 1e1, 1e1])
        return np.array([(F(s + h[i] * e) - F(s - h[i] * e)) / (2 * h[i]) for i, e in enumerate(np.eye(3))])

    nodes = 0.5 + 0.5 * np.array([-1, 1]) / np.sqrt(3)
    integrated = sum(0.5 * gradient(t * total) for t in nodes) @ parts.T
    shares = tsai_wu_shares(parts, THESIS)
    np.testing.assert_allclose(shares, integrated, rtol=1e-6, atol=1e-9)
    assert shares.sum() == pytest.approx(F(total), rel=1e-12)
    twins = tsai_wu_shares(np.array([total / 2, total / 2]), THESIS)
    assert twins[0] == pytest.approx(twins[1], rel=1e-12)  # equal loads, equal shares
    assert tsai_wu_shares(total[None, :], THESIS)[0] == pytest.approx(F(total), rel=1e-12)


# ------------------------------------------------------------------- shaft: hoop, thermal, shares


def _model(overrides):
    from flexshaft.assembly import build_model
    from flexshaft.design import baseline_design, with_overrides

    return build_model(with_overrides(baseline_design(), overrides))


NO_LOADS = {"loads.point": [], "loads.load_factor": [0.0, 0.0, 0.0], "operating.power": 0.0}


def test_spinning_free_ring_hoop_stress_through_the_laminate_path():
    """A spinning thin tube with free ends carries sigma_hoop = rho Omega^2 r^2 (ring radial
    equilibrium, r the mid-surface radius) and no axial stress. An isotropic 'lamina' in the
    (55/-55/0/0)s stack, no other load: the critical ply's stresses are the hoop stress rotated
    into its axes, sigma1 = h s^2, sigma2 = h c^2, tau12 = h c s (to 1e-9; the bar is 0.1 %),
    and R is the Tsai-Wu root of that state."""
    from flexshaft.analyses.shaft_strength import shaft_safety_factor

    G = 70e9 / 2.6
    ply = "materials.t700_adiprene."
    model = _model(
        {
            **NO_LOADS,
            ply + "E_L": 70e9,
            ply + "E_T": 70e9,
            ply + "G_LT": G,
            ply + "nu_LT": 0.3,
            ply + "G_13": G,
            ply + "G_23": G,
            ply + "alpha_L": 0.0,
            ply + "alpha_T": 0.0,
        }
    )
    result = shaft_safety_factor(model, np.zeros(model.dofs.size))
    rho, omega, r = 1650.0, 4800 * 2 * np.pi / 60, (0.1016 - 0.003) / 2
    hoop = rho * omega**2 * r**2
    a = np.radians(result.ply_angle_deg)
    expected = np.array([hoop * np.sin(a) ** 2, hoop * np.cos(a) ** 2, hoop * np.cos(a) * np.sin(a)])
    np.testing.assert_allclose(result.stresses, expected, rtol=1e-9, atol=1e-9 * hoop)
    assert result.hoop_resultant == pytest.approx(rho * 0.003 * omega**2 * r**2, rel=1e-12)
    assert result.safety_factor == pytest.approx(float(tsai_wu_safety_factor(*expected, THESIS)), rel=1e-12)
    assert result.load_shares == pytest.approx({"static": 0.0, "centrifugal": 1.0}, abs=1e-12)


@pytest.fixture(scope="module")
def baseline_strength():
    from flexshaft.analyses import imbalance_response
    from flexshaft.analyses.shaft_strength import shaft_safety_factor, static_load_parts
    from flexshaft.assembly import build_model
    from flexshaft.assembly.loads import imbalance_loads
    from flexshaft.design import baseline_design

    model = build_model(baseline_design())
    parts = static_load_parts(model)
    q_dyn = imbalance_response(model, [model.speed], imbalance_loads(model))[:, 0, 0]
    return model, parts, q_dyn, shaft_safety_factor(model, parts, q_dyn, leave_one_out=True)


def test_baseline_load_shares_sum_to_one_and_leave_one_out_matches_switches(baseline_strength):
    """Shares of the failure index at the critical ply sum to 1 (the index there). Leaving a
    load out must equal switching it off at the source: no centrifugal = speed 0, no thermal =
    thermal_residual False, no imbalance = static only; and splitting the static response into
    external + torque changes no stress (linear), so R is the same as for their sum."""
    from flexshaft.analyses.shaft_strength import shaft_safety_factor

    model, parts, q_dyn, full = baseline_strength
    assert set(full.load_shares) == {"external", "torque", "imbalance", "centrifugal", "thermal"}
    assert sum(full.load_shares.values()) == pytest.approx(1.0, abs=1e-12)
    assert full.safety_factor_without["centrifugal"] == pytest.approx(
        shaft_safety_factor(model, parts, q_dyn, speed=0.0).safety_factor, rel=1e-12
    )
    assert full.safety_factor_without["thermal"] == pytest.approx(
        shaft_safety_factor(model, parts, q_dyn, thermal_residual=False).safety_factor, rel=1e-12
    )
    assert full.safety_factor_without["imbalance"] == pytest.approx(
        shaft_safety_factor(model, parts).safety_factor, rel=1e-12
    )
    summed = shaft_safety_factor(model, parts["external"] + parts["torque"], q_dyn)
    assert summed.safety_factor == pytest.approx(full.safety_factor, rel=1e-12)
    assert summed.load_shares["static"] == pytest.approx(
        full.load_shares["external"] + full.load_shares["torque"], rel=1e-9
    )


def test_plies_of_one_angle_evaluated_once_give_every_ply_bit_for_bit(baseline_strength, monkeypatch):
    """The safety-factor grid is evaluated once per distinct ply (the baseline's 8 plies hold 3
    angles) and copied to the others: against every ply evaluated on its own (the unreduced
    grid), the result is the same bit for bit, critical point and leave-one-out included."""
    import dataclasses

    import flexshaft.analyses.shaft_strength as strength

    model, parts, q_dyn, reduced = baseline_strength
    first, copies = strength._distinct_plies(*strength._unit_ply_stresses(model.shaft.laminate.storage))
    assert first.size == 3 and np.array_equal(
        np.degrees(model.shaft.laminate.angles[first][copies]), np.degrees(model.shaft.laminate.angles)
    )

    def every_ply(*tables):
        n = tables[0].shape[0]
        return np.arange(n), np.arange(n)

    monkeypatch.setattr(strength, "_distinct_plies", every_ply)
    full = strength.shaft_safety_factor(model, parts, q_dyn, leave_one_out=True)
    for f in dataclasses.fields(full):
        a, b = getattr(full, f.name), getattr(reduced, f.name)
        assert np.array_equal(a, b) if isinstance(a, np.ndarray) else a == b, f.name


def test_baseline_failure_state_reaches_the_envelope(baseline_strength):
    """At the critical ply, R times the mechanical stresses plus the unscaled thermal residual
    stress lies on the Tsai-Wu envelope (independent re-evaluation of F from the parts)."""
    model, _, _, full = baseline_strength
    parts = full.stress_parts
    state = sum(np.array(s) * (1.0 if name == "thermal" else full.safety_factor) for name, s in parts.items())
    assert tsai_wu_index(*state, THESIS) == pytest.approx(1.0, abs=1e-12)
    assert np.allclose(full.stresses, sum(np.array(s) for s in parts.values()))
    design = model.design  # the wall at the ambient temperature, residual from the stress-free state
    expected = design.thermal.ambient_temperature_c - design.shaft_material.stress_free_temperature_c
    assert full.temperature_change == pytest.approx(expected)


ISOTROPIC_PLY_TUBE = """
name = "isotropic-ply (55/-55/0/0)s tube on pinned ends"
[materials.ply]
kind = "lamina"
density = 1650.0
E_L = 70.0e9
E_T = 70.0e9
G_LT = 26.923076923076923e9
nu_LT = 0.3
G_23 = 26.923076923076923e9
X_t = 2185.0e6
X_c = 2000.0e6
Y_t = 5.1e6
Y_c = 5.5e6
S = 20.0e6
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.1016
wall_thickness = 0.003
material = "ply"
layup = "(55/-55/0/0)s"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "stop"
kind = "contact"
x = 2.0
stiffness = {}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 20
"""


def test_thesis_strength_path_against_beam_theory_and_tsai_wu_by_hand():
    """The thesis's strength check (no hoop stress: speed 0; no thermal residual; N_y = 0,
    eq. 2.46) of a 2 m tube on pinned ends, midspan force P = 300 N and torque T = 40 N m, with
    an isotropic 'lamina' (E = 70 GPa, G = E/2.6) in the (55/-55/0/0)s stack, so the laminate is
    isotropic and every ply carries the beam stresses. By hand: the midspan moment M = PL/4,
    σ_x = ±M r_o/I on the outer wall, τ_xy = T r_o/J (J = 2I), σ_y = 0 (N_y = 0, isotropic);
    rotated into each ply's axes (σ₁ = σ_x c² + 2τ cs, σ₂ = σ_x s² − 2τ cs,
    τ₁₂ = τ (c² − s²) − σ_x cs) and R the positive root of the Tsai-Wu quadratic
    (:func:`tsai_wu_safety_factor`, verified above), the smallest over plies and both fibres.
    The Hermite beam element is exact for a point load at a node (linear moment between nodes):
    1e-9 asserted, round-off. (This replaces a value copied from an earlier run of the
    baseline.)"""
    from flexshaft.analyses.response import static_response
    from flexshaft.analyses.shaft_strength import shaft_safety_factor
    from flexshaft.assembly import build_model
    from flexshaft.assembly.loads import point_load, torque_load
    from flexshaft.design import loads_design

    P, T, L, D, wall = 300.0, 40.0, 2.0, 0.1016, 0.003
    model = build_model(loads_design(ISOTROPIC_PLY_TUBE))
    q = static_response(model, point_load(model, "shaft", (0.0, -P, 0.0), x=L / 2) + torque_load(model, T))
    result = shaft_safety_factor(model, q, speed=0.0, thermal_residual=False)
    r = D / 2
    inertia = np.pi * (D**4 - (D - 2 * wall) ** 4) / 64
    sigma, tau = P * L / 4 * r / inertia, T * r / (2 * inertia)
    strengths = Strengths(2185e6, 2000e6, 5.1e6, 5.5e6, 20e6)
    by_hand = []
    for angle in (55.0, -55.0, 0.0):
        c, s = np.cos(np.radians(angle)), np.sin(np.radians(angle))
        for sx in (sigma, -sigma):
            s1, s2, t12 = sx * c * c + 2 * tau * c * s, sx * s * s - 2 * tau * c * s, tau * (c * c - s * s) - sx * c * s
            by_hand.append(float(tsai_wu_safety_factor(s1, s2, t12, strengths)))
    assert result.safety_factor == pytest.approx(min(by_hand), rel=1e-9)
    assert result.x == pytest.approx(L / 2)

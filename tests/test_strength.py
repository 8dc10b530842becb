"""Tsai-Wu safety factor (thesis eq. 2.48-2.53; DESIGN.md section 6, Tsai-Wu)."""

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
    tsai_wu_quadratic,
    tsai_wu_safety_factor,
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


@given(
    st.floats(-3e9, 3e9), st.floats(-3e7, 3e7), st.floats(-5e7, 5e7), st.floats(1e-3, 1e3),
)
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


def test_coefficients_and_default_interaction():
    F = tsai_wu_coefficients(THESIS)
    assert F.F1 == pytest.approx(1 / 2185e6 - 1 / 2000e6)
    assert F.F22 == pytest.approx(1 / (5.1e6 * 5.5e6))
    assert F.F66 == pytest.approx(1 / 20e6**2)
    assert F.F12 == pytest.approx(-0.5 * np.sqrt(F.F11 * F.F22))
    custom = Strengths(1e9, 1e9, 1e7, 1e7, 1e7, F12=0.0)
    assert tsai_wu_coefficients(custom).F12 == 0.0


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

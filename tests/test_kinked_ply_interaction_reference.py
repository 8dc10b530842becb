"""The kink-limited ply check keeps the file's Tsai-Wu interaction F12, by hand.

A soft-matrix ply (G_LT = 100 MPa, S = 20 MPa, φ = 2°, γ_y = 0.05 given in the file) whose
datasheet X_c = 1.5 GPa exceeds its kink-band strength σ_c = G_LT/(1 + φ/γ_y) =
100 MPa/(1 + 0.0349066/0.05) = 58.89 MPa (Budiansky & Fleck 1993, as :mod:`flexshaft.strength`
quotes it; not read here, hence the checks of its limits below): the ply check uses that σ_c
as X_c and keeps the other strengths *and the interaction coefficient* the file gives
(docstring of :class:`flexshaft.design.materials.Lamina`: F12 defaults to −½ sqrt(F11 F22) only
"when omitted"). The file's F12 = +0.3 sqrt(F11 F22) (of the datasheet strengths, inside the
closed-surface bound sqrt(F11 F22) of either X_c) has the opposite sign of the default.

Under the biaxial compression σ1 = σ2 = −40 MPa, τ12 = 2 MPa the Tsai-Wu safety factor is
the positive root of a R² + b R − 1 = 0 (the criterion F(R σ) = 1 as :mod:`flexshaft.strength`
states it after Jones 1999, eq. 2.159, and Tsai & Hahn 1980, solved here by the textbook
quadratic formula) with F1 = 1/X_t − 1/X_c, F11 = 1/(X_t X_c),
F2, F22 likewise, F66 = 1/S², a = F11 σ1² + F22 σ2² + F66 τ12² + 2 F12 σ1 σ2, b = F1 σ1 + F2 σ2,
typed here from those formulas with X_c = σ_c; with the default F12 instead the factor
is 11 % larger. Tolerance: the textbook quadratic formula against the code's cancellation-free
form, both O(1e-16) relative: rtol 1e-12.

The kink-band expression is checked against the two simpler models it must reduce to (as
:mod:`flexshaft.strength` quotes them; not read here): straight fibres, φ → 0, buckle
elastically in shear mode at X_c = G_LT (Rosen 1965), exactly at φ = 0 and within the
relative φ/γ_y above it (derived: 1 − 1/(1 + a) ≤ a); a rigid-perfectly plastic matrix,
G_LT → ∞ with τ_y = G_LT γ_y fixed, kinks at X_c = τ_y/φ (Argon 1972), within the relative
γ_y/φ (derived: φ/(φ + γ_y) = 1 − γ_y/(φ + γ_y)); each bound plus 1e-15 for the round-off of
the quotients. CPU: under a millisecond.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.design.materials import Lamina
from flexshaft.strength import budiansky_fleck_strength, effective_strengths, tsai_wu_safety_factor

X_T, X_C, Y_T, Y_C, S = 1.8e9, 1.5e9, 30e6, 90e6, 20e6
G_LT, PHI_DEG, GAMMA_Y = 100e6, 2.0, 0.05
F12_FILE = 0.3 * math.sqrt(1.0 / (X_T * X_C * Y_T * Y_C))
S1, S2, T12 = -40e6, -40e6, 2e6


def _hand_safety_factor(x_c: float, f12: float) -> float:
    F1, F11 = 1 / X_T - 1 / x_c, 1 / (X_T * x_c)
    F2, F22 = 1 / Y_T - 1 / Y_C, 1 / (Y_T * Y_C)
    a = F11 * S1**2 + F22 * S2**2 + T12**2 / S**2 + 2 * f12 * S1 * S2
    b = F1 * S1 + F2 * S2
    return (-b + math.sqrt(b * b + 4 * a)) / (2 * a)


def _ply(phi_deg: float) -> Lamina:
    return Lamina(
        kind="lamina",
        density=1500.0,
        E_L=100e9,
        E_T=0.5e9,
        G_LT=G_LT,
        nu_LT=0.4,
        X_t=X_T,
        X_c=X_C,
        Y_t=Y_T,
        Y_c=Y_C,
        S=S,
        F12=F12_FILE,
        fibre_misalignment_deg=phi_deg,
        shear_yield_strain=GAMMA_Y,
    )


def test_the_kink_limited_check_keeps_the_files_f12():
    ply = _ply(PHI_DEG)
    sigma_c = G_LT / (1.0 + math.radians(PHI_DEG) / GAMMA_Y)
    strengths = effective_strengths(ply)
    assert strengths.X_c == pytest.approx(sigma_c, rel=1e-12)
    assert strengths.F12 == F12_FILE
    expected = _hand_safety_factor(sigma_c, F12_FILE)
    default = _hand_safety_factor(sigma_c, -0.5 * math.sqrt(1 / (X_T * sigma_c * Y_T * Y_C)))
    assert abs(default / expected - 1.0) > 0.05  # the state tells the two F12 apart
    assert float(tsai_wu_safety_factor(S1, S2, T12, strengths)) == pytest.approx(expected, rel=1e-12)


def test_the_kink_band_strength_tends_to_rosens_and_argons_limits():
    assert effective_strengths(_ply(0.0)).X_c == G_LT  # straight fibres: Rosen's G_LT, exactly
    for phi in (1e-3, 1e-6, 1e-9):
        assert abs(budiansky_fleck_strength(G_LT, phi, GAMMA_Y) / G_LT - 1.0) <= phi / GAMMA_Y + 1e-15
    phi, tau_y = math.radians(PHI_DEG), G_LT * GAMMA_Y  # τ_y = 5 MPa
    for stiffening in (1e3, 1e6, 1e9):  # G_LT -> inf at fixed τ_y: γ_y = τ_y/G -> 0
        shear_modulus = G_LT * stiffening
        sigma_c = budiansky_fleck_strength(shear_modulus, phi, tau_y / shear_modulus)
        assert abs(sigma_c / (tau_y / phi) - 1.0) <= (tau_y / shear_modulus) / phi + 1e-15

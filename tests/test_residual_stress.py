"""Thermal residual stress integrated over the cool-down (flexshaft.thermal.residual) against closed forms.

* Moduli that do not vary: the integral is the linear result σ₁ (T − T_sf) (exact).
* Every modulus scaled by one factor f(T) = exp(−(T − T_ref)/θ) (a table with E_L, E_T and G_LT
  columns on that exponential: the log-linear interpolation reproduces it exactly): the ply
  stress per kelvin is then f(T) σ₁_ref (A and the thermal resultant both scale with f, so the
  laminate strain does not), and the integral is σ₁_ref θ (e^{−(T_sf − T_ref)/θ} − e^{−(T − T_ref)/θ})·(−1)
  in closed form; its ratio to the secant form σ₁_ref f(T) (T − T_sf) is θ (e^{ΔT/θ} − 1)/(ΔT e^{ΔT/θ}).
* Convergence: the composite 4-point Gauss rule on the assumed law against the midpoint rule
  in 400 and 800 steps with one Richardson extrapolation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.laminate import Lamina, Laminate, thermal_ply_stresses
from flexshaft.thermal.matrix import LaminaTable, MatrixTemperatureLaw
from flexshaft.thermal.residual import residual_ply_stresses, secant_ply_stresses

T_REF, THETA = 293.15, 40.0
T_SF = 373.15
ANGLES = np.radians([55.0, -55.0, 0.0, 0.0, 0.0, 0.0, -55.0, 55.0])


def laminate() -> Laminate:
    lamina = Lamina.from_loss_factors(
        115e9, 0.1e9, 0.1e9, 0.35, 1650.0, 3e-4, 0.12, 0.12, alpha_L=-0.4e-6, alpha_T=110e-6
    )
    return Laminate(angles=ANGLES, thicknesses=np.full(8, 0.003 / 8), lamina=lamina)


ROWS = np.arange(-60.0, 121.0, 20.0) + 273.15  # [K]


def scaled_table(rows=ROWS) -> LaminaTable:
    """E_L, E_T and G_LT on exp(−(T − T_ref)/θ) with the reference values at T_ref; constant losses."""
    f = np.exp(-(rows - T_REF) / THETA)
    columns = {"E_L": 115e9 * f, "E_T": 0.1e9 * f, "G_LT": 0.1e9 * f}
    columns.update({"loss_E_L": np.full(rows.size, 3e-4), "loss_E_T": np.full(rows.size, 0.12)})
    columns["loss_G_LT"] = np.full(rows.size, 0.12)
    return LaminaTable(tuple(rows), tuple((k, tuple(v)) for k, v in columns.items()))


def test_constant_moduli_give_the_linear_result():
    """A law whose moduli do not move (θ_E huge, exp(−ΔT/θ) = 1 to 1e-12): the integral is σ₁ ΔT."""
    law = MatrixTemperatureLaw(reference_temperature=T_REF, modulus_decay=1e14, loss_growth=1e14)
    lam = laminate()
    for T in (233.15, 306.35, 361.9, 400.0):
        expected = thermal_ply_stresses(lam, T - T_SF)
        got = residual_ply_stresses(lam, law, T_SF, T)
        assert np.allclose(got, expected, rtol=1e-10, atol=1e-10 * np.abs(expected).max())


@pytest.mark.parametrize("T", [233.15, 253.15, 306.35, 361.94])
def test_moduli_scaled_together_integrate_in_closed_form(T):
    """f(T) = exp(−(T − T_ref)/θ): σ(T) = σ₁_ref ∫_{T_sf}^{T} f = −σ₁_ref θ (f(T) − f(T_sf)) (the table
    rows are samples of f, so the interpolation is exact; the 4-point Gauss rule on ≤ 10 K steps
    integrates the exponential to 1e-11: 1e-9 asserted), and the secant form is f(T) σ₁_ref (T − T_sf)."""
    law = MatrixTemperatureLaw(reference_temperature=T_REF, table=scaled_table())
    lam = laminate()
    per_kelvin = thermal_ply_stresses(lam, 1.0)  # at T_ref

    def f(t):
        return math.exp(-(t - T_REF) / THETA)

    expected = -per_kelvin * THETA * (f(T) - f(T_SF))
    got = residual_ply_stresses(lam, law, T_SF, T)
    assert np.allclose(got, expected, rtol=1e-9, atol=1e-9 * np.abs(expected).max())
    secant = secant_ply_stresses(lam, law, T_SF, T)
    assert np.allclose(secant, per_kelvin * f(T) * (T - T_SF), rtol=1e-9, atol=1e-9 * np.abs(secant).max())
    # the ratio of the two forms (module docstring), ΔT = T_sf − T
    dT = T_SF - T
    ratio = THETA * (math.exp(dT / THETA) - 1) / (dT * math.exp(dT / THETA))
    big = np.abs(secant) > 1e-3 * np.abs(secant).max()
    assert np.allclose(got[big] / secant[big], ratio, rtol=1e-9)


def test_the_cold_day_of_the_assumed_law_is_0_28_of_the_secant_form():
    """The docstring's number: 100 °C to −40 °C with θ_E = 40 K gives 40 (e^3.5 − 1)/(140 e^3.5) =
    0.2771 for a stress that follows E_T alone (σ2 of the tuned layup is E_T-dominated: the
    unscaled E_L moves it by 0.6 %, 1 % asserted)."""
    law = MatrixTemperatureLaw(reference_temperature=T_REF, modulus_decay=THETA)
    lam = laminate()
    got = residual_ply_stresses(lam, law, T_SF, 233.15)
    secant = secant_ply_stresses(lam, law, T_SF, 233.15)
    ratio = 40 * (math.exp(3.5) - 1) / (140 * math.exp(3.5))
    assert ratio == pytest.approx(0.2771, abs=5e-5)
    assert got[:, 1] / secant[:, 1] == pytest.approx(np.full(8, ratio), rel=1e-2)


def midpoint_rule(law: MatrixTemperatureLaw, lam: Laminate, steps: int) -> np.ndarray:
    """The cool-down integral from T_sf to −40 °C by the composite midpoint rule in ``steps`` steps."""
    edges = np.linspace(T_SF, 233.15, steps + 1)
    return sum(
        thermal_ply_stresses(Laminate(lam.angles, lam.thicknesses, law.lamina(lam.lamina, 0.5 * (a + b))), b - a)
        for a, b in zip(edges[:-1], edges[1:])
    )


def test_the_quadrature_converges_to_a_fine_midpoint_rule():
    """The assumed law (E_T, G_LT on exp(−ΔT/40 K), loss factors growing) from 100 °C to −40 °C:
    the composite Gauss rule against the midpoint rule in 400 and 800 steps, extrapolated
    (Richardson, (4 M(h/2) − M(h))/3). The midpoint rule's error is c₂h² + c₄h⁴ + ..., with
    c₂h² ~ (h/θ)²/24 and c₄h⁴ ~ 7 (h/θ)⁴/5760 relative for an integrand on exp(−T/θ); the
    extrapolation removes the h² term and leaves −c₄h⁴/4 ~ 2e-12 at h = 0.35 K, far below the
    1e-8 asked of the Gauss rule (a 20 000-step midpoint rule alone is at 1.3e-9, for 16 times
    the laminate evaluations)."""
    law = MatrixTemperatureLaw(reference_temperature=T_REF, modulus_decay=THETA)
    lam = laminate()
    coarse, fine = midpoint_rule(law, lam, 400), midpoint_rule(law, lam, 800)
    reference = (4.0 * fine - coarse) / 3.0
    got = residual_ply_stresses(lam, law, T_SF, 233.15)
    assert np.allclose(got, reference, rtol=1e-8, atol=1e-8 * np.abs(reference).max())


def test_bad_temperatures_are_refused():
    law = MatrixTemperatureLaw()
    with pytest.raises(ValueError, match="temperature"):
        residual_ply_stresses(laminate(), law, T_SF, -5.0)


def test_a_cool_down_from_above_the_table_holds_its_top_row_there():
    """A table whose top row (80 °C) lies below T_sf = 100 °C: the moduli are held at the top row
    above it (module docstring, no extrapolation), so with every modulus on f(T) (as above)
    σ(T) = σ₁_ref [f(T_top) (T_top − T_sf) − θ (f(T) − f(T_top))] for T below the top row, and
    σ₁_ref f(T_top) (T − T_sf) for T above it. Held at the row below the top (60 °C) the first
    part would be e^{0.5} = 1.65 times larger; 1e-9 asserted as above."""
    rows = np.arange(-20.0, 81.0, 20.0) + 273.15
    top = rows[-1]
    law = MatrixTemperatureLaw(reference_temperature=T_REF, table=scaled_table(rows))
    lam = laminate()
    per_kelvin = thermal_ply_stresses(lam, 1.0)

    def f(t):
        return math.exp(-(t - T_REF) / THETA)

    for T, expected in (
        (363.15, per_kelvin * f(top) * (363.15 - T_SF)),
        (313.15, per_kelvin * (f(top) * (top - T_SF) - THETA * (f(313.15) - f(top)))),
    ):
        got = residual_ply_stresses(lam, law, T_SF, T)
        assert np.allclose(got, expected, rtol=1e-9, atol=1e-9 * np.abs(expected).max())

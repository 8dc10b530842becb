"""The residual-stress integral across a temperature table's kink (hunt h46c).

A table is interpolated log-linearly between rows, so a property is piecewise exponential with
a kink in its slope at each row; the module's quadrature breaks at the rows inside the cool-down
(its docstring) so that each 4-point Gauss panel integrates a smooth exponential.

Closed form, as tests/test_residual_stress.py derives it: with every modulus scaled by one
factor f(T) the ply stress per kelvin is f(T) σ₁_ref, so σ(T) = σ₁_ref ∫_{T_sf}^{T} f. Here
f is e^{−(T − T_ref)/θ} with θ = 20 K below the row T_ref = 20 °C and θ = 80 K above it (rows
−40, 20, 100 °C): f = e³, 1, e^{−1} at the rows, and on each piece ∫_a^b f = θ (f(a) − f(b)).
Cooled from T_sf = 100 °C to T = −16 °C (116 K: with the table's row at 20 °C as a break, 4
panels of 9 K below it and 8 of 10 K above; without the break, twelve 9.67 K panels, none
ending at 20 °C):

    σ(T) = −σ₁_ref [20 (e^{36/20} − 1) + 80 (1 − e^{−1})].

Tolerance 1e-9 relative: the 4-point rule integrates each smooth piece to ~1e-11 (as in the
closed-form test there); a panel straddling the kink errs by ~5e-5 relative (measured). Milliseconds.
"""

from __future__ import annotations

import math

import numpy as np
from test_residual_stress import laminate

from flexshaft.laminate import thermal_ply_stresses
from flexshaft.thermal.matrix import LaminaTable, MatrixTemperatureLaw
from flexshaft.thermal.residual import residual_ply_stresses

T_REF = 293.15
ROWS = (233.15, 293.15, 373.15)
F = (math.exp(3.0), 1.0, math.exp(-1.0))  # e^{60/20}, 1, e^{-80/80}


def kinked_table() -> LaminaTable:
    f = np.array(F)
    columns = {"E_L": 115e9 * f, "E_T": 0.1e9 * f, "G_LT": 0.1e9 * f}
    columns.update({"loss_E_L": np.full(3, 3e-4), "loss_E_T": np.full(3, 0.12), "loss_G_LT": np.full(3, 0.12)})
    return LaminaTable(ROWS, tuple((k, tuple(v)) for k, v in columns.items()))


def test_the_cool_down_across_a_row_integrates_each_exponential_piece():
    law = MatrixTemperatureLaw(reference_temperature=T_REF, table=kinked_table())
    lam = laminate()
    per_kelvin = thermal_ply_stresses(lam, 1.0)  # at T_ref, the lamina's own values
    T_sf, T = 373.15, 257.15
    integral = 20.0 * (math.exp(36.0 / 20.0) - 1.0) + 80.0 * (1.0 - math.exp(-1.0))
    expected = -per_kelvin * integral
    got = residual_ply_stresses(lam, law, T_sf, T)
    assert np.allclose(got, expected, rtol=1e-9, atol=1e-9 * np.abs(expected).max())

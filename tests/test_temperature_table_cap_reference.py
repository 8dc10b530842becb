"""A lamina's temperature table: scaling from the lamina's own values and the loss-factor cap,
evaluated by hand (mutation hunt 23d).

The documented rule (flexshaft.thermal.matrix, docs/thermal.md): between rows a property is
interpolated linearly in temperature on its logarithm,

    p_table(T) = p_i (p_(i+1)/p_i)^w,   w = (T − T_i)/(T_(i+1) − T_i),

the lamina keeps its own value p_ref at the reference temperature and follows the table's
ratio from there, p(T) = p_ref · p_table(T)/p_table(T_ref), and a loss factor is capped at the
law's ``max_loss_factor`` exactly as without a table (a hysteretic loss factor above the cap
is no physical matrix: the self-heating fixed point would feed on an ever lossier one).

Table here: rows at 20 °C and 120 °C, loss_G_LT 0.3 → 3.0 and G_LT 35 → 3.5 MPa (one decade
each), reference lamina loss_G_LT 0.2 (not the table's 0.3, so the ratio rule is exercised).
At 100 °C (w = 0.8): loss_G_LT = 0.2 · 10^0.8 = 1.26 > 0.9 → capped at 0.9; G_LT = 35 MPa ·
10^−0.8 (moduli are never capped). At 40 °C (w = 0.2): 0.2 · 10^0.2 = 0.317, below the cap.
Values computed with math here; tolerance 1e-12 relative (rounding of a power).
"""

from __future__ import annotations

import pytest

from flexshaft.thermal.matrix import LaminaTable, MatrixTemperatureLaw
from flexshaft.units import celsius_to_kelvin

REFERENCE = {"E_L": 115e9, "E_T": 0.10e9, "G_LT": 35e6, "loss_E_L": 0.003, "loss_E_T": 0.12, "loss_G_LT": 0.2}
T20, T120 = celsius_to_kelvin(20.0), celsius_to_kelvin(120.0)
TABLE = LaminaTable((T20, T120), (("G_LT", (35e6, 3.5e6)), ("loss_G_LT", (0.3, 3.0))))
LAW = MatrixTemperatureLaw(reference_temperature=T20, max_loss_factor=0.9, table=TABLE)


def test_a_table_loss_factor_above_the_cap_is_capped():
    got = LAW.properties(REFERENCE, celsius_to_kelvin(100.0))
    assert 0.2 * 10**0.8 > 0.9  # the uncapped value would exceed the cap
    assert got["loss_G_LT"] == 0.9
    assert got["G_LT"] == pytest.approx(35e6 * 10**-0.8, rel=1e-12)
    for name in ("E_L", "E_T", "loss_E_L", "loss_E_T"):  # columns the table does not list are kept
        assert got[name] == REFERENCE[name]


def test_a_table_loss_factor_below_the_cap_follows_the_table_ratio():
    got = LAW.properties(REFERENCE, celsius_to_kelvin(40.0))
    assert got["loss_G_LT"] == pytest.approx(0.2 * 10**0.2, rel=1e-12)
    assert got["G_LT"] == pytest.approx(35e6 * 10**-0.2, rel=1e-12)

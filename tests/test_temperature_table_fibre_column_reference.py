"""A temperature table's optional fibre columns (E_L, loss_E_L) reach the analyses' lamina.

Reference (docs/thermal.md, "Lamina properties over temperature", hand-written): the table
lists "E_L, loss_E_L: optional columns (fibre-dominated; without them they do not vary)";
each tabled property follows p(T) = p_key · p_table(T)/p_table(T_ref), and the interpolation
is "linear in temperature on the logarithm of each property ... exact at the rows". So with
rows at −20, 20 and 60 °C, T_ref = 20 °C and an E_L column (95, 90, 80) GPa, derived here by
hand:

* at the 60 °C row, with the key equal to the table's 20 °C row: E_L = 80 GPa;
* at 40 °C (half-way, weight 1/2): E_L = 90 GPa · (80/90)^(1/2) = √(90·80) GPa;
* with the key changed to 99 GPa (a ``--set`` moves the whole curve): E_L(60 °C) = 99 · 80/90 GPa;
* loss_E_L column (0.002, 0.003, 0.006): η_L(60 °C) = 0.006, η_L(40 °C) = √(0.003·0.006);
* a table without the fibre columns leaves E_L and η_L exactly as they are.

Tolerance 1e-12 relative: one ratio and one fractional power of tabled values (a few ulp),
while ignoring the column would be off by 11 % (E_L) and a factor 2 (η_L).
"""

import math

import pytest

from flexshaft.laminate import Lamina
from flexshaft.thermal.matrix import LaminaTable, MatrixTemperatureLaw
from flexshaft.units import celsius_to_kelvin

ROWS = tuple(celsius_to_kelvin(t) for t in (-20.0, 20.0, 60.0))
MATRIX = (
    ("E_T", (8e9, 5e9, 3e9)),
    ("G_LT", (5e9, 3e9, 2e9)),
    ("loss_E_T", (0.02, 0.04, 0.08)),
    ("loss_G_LT", (0.03, 0.05, 0.1)),
)
FIBRE = (("E_L", (95e9, 90e9, 80e9)), ("loss_E_L", (0.002, 0.003, 0.006)))


def _law(columns) -> MatrixTemperatureLaw:
    return MatrixTemperatureLaw(reference_temperature=ROWS[1], table=LaminaTable(ROWS, columns))


def _lamina(E_L: float = 90e9, loss_E_L: float = 0.003) -> Lamina:
    """A lamina whose keys are the table's 20 °C row (E_L and loss_E_L as given)."""
    return Lamina.from_loss_factors(E_L, 5e9, 3e9, 0.3, 1500.0, loss_E_L, 0.04, 0.05)


def _storage_and_loss(modulus) -> tuple[float, float]:
    z = complex(modulus)
    return z.real, z.imag / z.real


def test_fibre_columns_at_a_row_and_between_rows():
    """E_L and η_L at the 60 °C row and log-linearly half-way to it (40 °C)."""
    law = _law(MATRIX + FIBRE)
    E, eta = _storage_and_loss(law.lamina(_lamina(), celsius_to_kelvin(60.0)).E_L)
    assert E == pytest.approx(80e9, rel=1e-12)
    assert eta == pytest.approx(0.006, rel=1e-12)
    E, eta = _storage_and_loss(law.lamina(_lamina(), celsius_to_kelvin(40.0)).E_L)
    assert E == pytest.approx(math.sqrt(90e9 * 80e9), rel=1e-12)
    assert eta == pytest.approx(math.sqrt(0.003 * 0.006), rel=1e-12)


def test_fibre_column_scales_a_changed_key():
    """A key off the table's reference row keeps the table's ratio: 99 GPa · 80/90."""
    E, _ = _storage_and_loss(_law(MATRIX + FIBRE).lamina(_lamina(E_L=99e9), celsius_to_kelvin(60.0)).E_L)
    assert E == pytest.approx(99e9 * 80.0 / 90.0, rel=1e-12)


def test_without_fibre_columns_the_fibre_modulus_is_kept():
    """No E_L/loss_E_L column: the fibre modulus is the lamina's own, while E_T follows its column."""
    lamina = _lamina()
    hot = _law(MATRIX).lamina(lamina, celsius_to_kelvin(60.0))
    assert complex(hot.E_L) == complex(lamina.E_L)
    assert _storage_and_loss(hot.E_T)[0] == pytest.approx(3e9, rel=1e-12)

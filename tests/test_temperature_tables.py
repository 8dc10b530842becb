"""Lamina properties over temperature: the table's validation, its interpolation, and the one
way to a lamina at a temperature (flexshaft.thermal.matrix)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.design import DesignError, tuned_design, with_overrides
from flexshaft.thermal.matrix import LaminaTable, MatrixTemperatureLaw, matrix_law_for
from flexshaft.thermal.options import matrix_law_from
from flexshaft.units import celsius_to_kelvin

TABLE = "materials.t700_adiprene.temperature_table"
PLY = "materials.t700_adiprene."


@pytest.fixture(scope="module")
def design():
    return tuned_design()


# ------------------------------------------------------------------------------------------------
# Validation: messages name the field


@pytest.mark.parametrize(
    "override, message",
    [
        (
            {TABLE + ".temperature_c": [-60.0, -40.0, -20.0, -20.0, 20.0, 40.0, 60.0, 80.0, 100.0, 120.0]},
            r"temperature_table\.temperature_c\[3\]: must be greater than the previous temperature -20 °C",
        ),
        ({TABLE + ".E_T": [1e8, 1e8]}, r"temperature_table\.E_T: must have one value per temperature: 10 values"),
        ({TABLE + ".loss_G_LT": [0.0] * 10}, r"temperature_table\.loss_G_LT\[0\]"),
        ({TABLE + ".G_LT": [-1e8] * 10}, r"temperature_table\.G_LT\[0\]"),
        (
            {TABLE + ".temperature_c": [30.0 + 10 * i for i in range(10)]},
            r"temperature_c: must span the reference temperature \[thermal\] matrix_reference_temperature_c = 20 °C",
        ),
        ({"thermal.allowable_temperature_c": 150.0}, r"temperature_c: must reach the allowable temperature"),
        (
            {"envelope.points[0].ambient_temperature_c": -70.0},
            r"envelope\.points\[0\]\.ambient_temperature_c: puts the shaft at -70 °C, outside the temperature_table "
            r'of lamina "t700_adiprene" \[-60, 120\] °C',
        ),
    ],
)
def test_bad_tables_are_refused_naming_the_field(design, override, message):
    with pytest.raises(DesignError, match=message):
        with_overrides(design, override)


def test_the_embedded_tables_repeat_the_keys_at_the_reference_temperature(design):
    """The 20 °C row of the packaged table is the lamina's own keys (the file's values today)."""
    from flexshaft.design import baseline_design

    for d in (design, baseline_design()):
        material, table = d.shaft_material, d.shaft_material.temperature_table
        row = table.temperature_c.index(d.thermal.matrix_reference_temperature_c)
        for name, column in table.columns().items():
            assert column[row] == getattr(material, name), name
        assert (material.E_T, material.G_LT, material.loss_E_T, material.loss_G_LT) == (0.1e9, 0.1e9, 0.12, 0.12)


# ------------------------------------------------------------------------------------------------
# Interpolation


def test_interpolation_is_exact_at_rows_and_geometric_between():
    """Linear in T on the logarithm: at the midpoint of two rows the geometric mean, at a quarter
    v0^(3/4) v1^(1/4) (closed forms; rel 1e-14, round-off of a power)."""
    table = LaminaTable((250.0, 300.0, 350.0), (("E_T", (4e8, 1e8, 2e7)), ("loss_E_T", (0.05, 0.1, 0.4))))
    assert table.at(300.0) == {"E_T": 1e8, "loss_E_T": 0.1}
    assert table.at(350.0) == {"E_T": 2e7, "loss_E_T": 0.4}
    mid = table.at(275.0)
    assert mid["E_T"] == pytest.approx(math.sqrt(4e8 * 1e8), rel=1e-14)
    assert mid["loss_E_T"] == pytest.approx(math.sqrt(0.05 * 0.1), rel=1e-14)
    quarter = table.at(312.5)
    assert quarter["E_T"] == pytest.approx(1e8**0.75 * 2e7**0.25, rel=1e-14)
    T = np.linspace(250.0, 350.0, 41)
    values = np.array([table.at(t)["E_T"] for t in T])
    assert np.all(np.diff(values) < 0.0)  # monotone between monotone rows


def test_no_extrapolation():
    table = LaminaTable((250.0, 300.0), (("E_T", (4e8, 1e8)),))
    with pytest.raises(ValueError, match=r"outside the lamina's temperature_table \[-23.15, 26.85\] °C"):
        table.at(249.0)
    with pytest.raises(ValueError, match="not extrapolated"):
        table.at(301.0)
    with pytest.raises(ValueError, match="strictly increasing"):
        LaminaTable((300.0, 300.0), (("E_T", (1e8, 1e8)),))
    with pytest.raises(ValueError, match="E_T must hold 2 finite values > 0"):
        LaminaTable((250.0, 300.0), (("E_T", (1e8, 0.0)),))


def test_embedded_table_reproduces_the_assumed_law(design):
    """The packaged table is the [thermal] law at its rows rounded to 6 digits; log-linear
    interpolation reproduces an exponential exactly, so between rows the table and the law's
    closed form E_T0 exp(-dT/40), eta0 exp(dT/60) agree to the rounding (rel 1e-5): the
    self-heating results of the packaged designs do not move."""
    table = matrix_law_for(design.shaft_material, matrix_law_from(design.thermal)).table
    for T_c in (-53.0, -40.0, -31.7, 0.0, 15.0, 33.2, 44.1, 88.8, 90.0, 117.0):
        dT = T_c - 20.0
        at = table.at(celsius_to_kelvin(T_c))
        assert at["E_T"] == pytest.approx(0.1e9 * math.exp(-dT / 40.0), rel=1e-5)
        assert at["G_LT"] == pytest.approx(0.1e9 * math.exp(-dT / 40.0), rel=1e-5)
        assert at["loss_E_T"] == pytest.approx(0.12 * math.exp(dT / 60.0), rel=1e-5)
        assert at["loss_G_LT"] == pytest.approx(0.12 * math.exp(dT / 60.0), rel=1e-5)


# ------------------------------------------------------------------------------------------------
# One way to a lamina at a temperature


def test_moduli_at_minus_40_and_90_follow_the_table(design):
    """-40 °C is a row (exact); 90 °C is the midpoint of the 80 and 100 °C rows: the geometric
    mean of the two (rel 1e-14)."""
    law = matrix_law_from(design.thermal, design.shaft_material)
    cold = law.material(design.shaft_material, celsius_to_kelvin(-40.0))
    assert (cold.E_T, cold.G_LT, cold.loss_E_T) == (448.169e6, 448.169e6, 0.0441455)
    assert cold.E_L == design.shaft_material.E_L and cold.X_c == design.shaft_material.X_c
    hot = law.material(design.shaft_material, celsius_to_kelvin(90.0))
    assert hot.E_T == pytest.approx(math.sqrt(22.313e6 * 13.5335e6), rel=1e-14)
    assert hot.loss_G_LT == pytest.approx(math.sqrt(0.326194 * 0.45524), rel=1e-14)


def test_reference_temperature_returns_the_lamina_itself(design):
    law = matrix_law_from(design.thermal, design.shaft_material)
    assert law.material(design.shaft_material, celsius_to_kelvin(20.0)) is design.shaft_material


def test_a_changed_key_moves_its_curve(design):
    """The keys are the values at the reference temperature and the table gives the variation:
    E_T doubled at 20 °C is doubled at every temperature (rel 1e-15)."""
    stiffer = with_overrides(design, {PLY + "E_T": 0.2e9})
    for T_c in (-40.0, 55.0):
        T = celsius_to_kelvin(T_c)
        base = matrix_law_from(design.thermal, design.shaft_material).material(design.shaft_material, T)
        new = matrix_law_from(stiffer.thermal, stiffer.shaft_material).material(stiffer.shaft_material, T)
        assert new.E_T == pytest.approx(2.0 * base.E_T, rel=1e-15)
        assert new.G_LT == base.G_LT


def test_analysis_and_design_laminae_agree(design):
    """law.lamina (complex moduli of the analyses) and law.material (the design file's lamina)
    are one computation: E' and eta agree to round-off at any temperature, with the table and
    with the law."""
    from flexshaft.assembly import build_model

    lamina = build_model(design).shaft.laminate.lamina
    for law in (matrix_law_from(design.thermal, design.shaft_material), MatrixTemperatureLaw()):
        for T_c in (-40.0, 61.0):
            T = celsius_to_kelvin(T_c)
            a, m = law.lamina(lamina, T), law.material(design.shaft_material, T)
            for name in ("E_L", "E_T", "G_LT"):
                modulus = complex(getattr(a, name))
                assert modulus.real == pytest.approx(getattr(m, name), rel=1e-14)
                assert modulus.imag / modulus.real == pytest.approx(getattr(m, "loss_" + name), rel=1e-12)
            assert complex(a.G_13) == pytest.approx(complex(a.G_LT), rel=1e-14)  # default G_13 follows G_LT
            assert complex(a.G_23) == pytest.approx(complex(a.E_T) / 3.0, rel=1e-14)  # default E_T/3 too


def test_self_heating_uses_the_table_and_matches_the_law(design):
    """The self-heating fixed point with the packaged table (which the model's design carries)
    equals the one with the law (the table without it) to the table's 6-digit rounding: the
    peak rise agrees to 1e-4 relative. A table with twice the matrix loss factors above 20 °C
    heats more: doubling a loss factor doubles the heat it carries, so the rise grows by the
    matrix terms' share of the heat; more than 10 % shows the table acts (measured +39 %: the
    matrix terms carry about 40 % of the heat, the fibre loss the rest)."""
    from flexshaft.assembly import build_model
    from flexshaft.thermal.options import thermal_options
    from flexshaft.thermal.selfheating import self_heating

    options = thermal_options(design.thermal)
    with_table = self_heating(build_model(design), options)
    law_only = self_heating(build_model(with_overrides(design, {TABLE: None})), options)
    rise = with_table.max_temperature - with_table.thermal.temperature.air_temperature
    rise_law = law_only.max_temperature - law_only.thermal.temperature.air_temperature
    assert with_table.status == law_only.status == "converged"
    assert rise == pytest.approx(rise_law, rel=1e-4)
    lossy = list(design.shaft_material.temperature_table.loss_E_T)
    lossy = [eta if i <= 4 else min(2.0 * eta, 0.99) for i, eta in enumerate(lossy)]
    hotter = with_overrides(design, {TABLE + ".loss_E_T": lossy, TABLE + ".loss_G_LT": lossy})
    heated = self_heating(build_model(hotter), options)
    assert heated.status == "converged"
    assert heated.max_temperature - heated.thermal.temperature.air_temperature > 1.1 * rise

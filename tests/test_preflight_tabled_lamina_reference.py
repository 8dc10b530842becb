"""The thermal preflight judges a lamina with a temperature table by its table, as the analyses do.

The self-heating and the envelope take a tabled lamina's properties from its table, never from
the assumed exponential law (``matrix_law_for``: the table wins), so
:func:`flexshaft.thermal.preflight.thermal_guards` must check the table's ply, not the law's.

The plane-stress condition. An orthotropic ply's in-plane normal compliance is
[[1/E_L, -nu_LT/E_L], [-nu_TL/E_T, 1/E_T]] with reciprocity nu_TL/E_T = nu_LT/E_L; its
determinant (1 - nu_LT nu_TL)/(E_L E_T) is positive, i.e. the ply's stiffness exists and is
positive definite, only while nu_LT nu_TL < 1, i.e. with nu_TL = nu_LT E_T/E_L,

    nu_LT^2 E_T / E_L < 1.

Between two rows a table is interpolated linearly in T on the logarithm of each property, so
ln(E_T/E_L) is linear in T there: the ratio is monotone between rows, and over the
self-heating's range (the shaft's air to the allowable) it is largest at an end or at a row
inside the range. A table is not extrapolated, so the range must lie within its rows.

Worked by hand on the embedded baseline (lamina t700_adiprene: E_L = 115 GPa, E_T = 0.1 GPa,
nu_LT = 0.35, its table E_T(T) = 0.1 GPa exp(-(T - 20 degC)/40 K) at rows every 20 degC from
-60 to 120 degC; the shaft's air is the sunlit hover skin at 317.27 K = 44.12 degC, closed by
its energy balance in tests/test_shaft_temperature_wiring_reference.py; allowable 100 degC):

* with [thermal] matrix_modulus_decay = 5 K and matrix_reference_temperature_c = 120 degC, the
  law would scale E_T at the air by exp((393.15 - 317.27)/5) = 3.9e6:
  0.1225 * 0.1e9 * 3.9e6 / 115e9 = 4.2e2 > 1, an invalid ply; the table scales it by
  E_T,table(T)/E_T,table(120 degC) <= E_T(40 degC)/E_T(120 degC) = e^2 = 7.39 over the range
  (44.12-100 degC, E_T decreasing), so nu^2 E_T/E_L <= 0.1225 * 0.1e9 * 7.39 / 115e9 = 7.9e-4 < 1:
  valid, and ``flexshaft check`` must accept the design;
* a table whose 60 degC row (inside the range) has E_T = 1e12 Pa gives
  0.1225 * 1e12 / 115e9 = 1.065 >= 1 there (the reference stays at its 20 degC row), while at
  the range's ends it is valid: at 44.12 degC the log-interpolated E_T between the 40 degC row
  (60.65 MPa) and 1e12 Pa is 60.65e6 * (1e12/60.65e6)^(4.12/20) = 4.5e8 Pa, ratio 4.8e-4; at
  100 degC the row's 13.5 MPa. Only the rows inside the range show it: refused, naming the table;
* a table from 60 degC up (reference 60 degC) starts above the air at 44.12 degC: the
  self-heating would evaluate the ply outside it, refused naming the table's temperature_c.

Each check is a few ms (no model is built); the CLI case runs ``check`` on the coarse-meshed
baseline, ~0.1 s.
"""

from __future__ import annotations

import copy
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.design import design_from_dict, embedded_design
from flexshaft.optimize.files import write_design_file
from flexshaft.thermal.preflight import thermal_guards

E_L, E_T, NU_LT = 115e9, 0.1e9, 0.35
AIR = 317.27  # K, the baseline's hover skin (to the 0.01 K written)
TABLE = "materials.t700_adiprene.temperature_table"


def baseline(**thermal) -> dict:
    data = copy.deepcopy(embedded_design("baseline").model_dump())
    data["mesh"]["shaft_elements"], data["mesh"]["boom_elements"] = 8, 4
    data["thermal"].update(thermal)
    return data


def test_the_hand_numbers():
    lamina = embedded_design("baseline").materials["t700_adiprene"]
    assert (lamina.E_L, lamina.E_T, lamina.nu_LT) == (E_L, E_T, NU_LT)
    table = lamina.temperature_table
    assert table.temperature_c == tuple(float(t) for t in range(-60, 121, 20))
    for t, e in zip(table.temperature_c, table.E_T, strict=True):  # E_T(T) = 0.1 GPa exp(-(T - 20)/40), 6 digits
        assert e == pytest.approx(E_T * math.exp(-(t - 20.0) / 40.0), rel=1e-5)
    assert NU_LT**2 * E_T * math.exp((393.15 - AIR) / 5.0) / E_L > 1.0  # the law: invalid at the air
    assert NU_LT**2 * E_T * math.exp(2.0) / E_L < 1e-3  # the table: valid over the range
    assert NU_LT**2 * 1e12 / E_L >= 1.0  # the 60 degC row of 1e12 Pa: invalid
    interpolated = 60.6531e6 * (1e12 / 60.6531e6) ** ((AIR - 313.15) / 20.0)
    assert NU_LT**2 * interpolated / E_L < 1e-3  # ... but not at the air's end


def test_a_tabled_lamina_is_not_judged_by_the_assumed_law(tmp_path: Path):
    data = baseline(matrix_modulus_decay=5.0, matrix_reference_temperature_c=120.0)
    assert thermal_guards(design_from_dict(data)) == []
    path = write_design_file(design_from_dict(data), tmp_path / "design.toml")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 0 and result.stdout.startswith("ok: "), result.output


def test_a_table_row_inside_the_range_that_makes_the_ply_invalid_is_refused():
    data = baseline()
    table = data["materials"]["t700_adiprene"]["temperature_table"]
    row = table["temperature_c"].index(60.0)
    table["E_T"] = tuple(1e12 if i == row else e for i, e in enumerate(table["E_T"]))
    problems = thermal_guards(design_from_dict(data))
    assert len(problems) == 1 and problems[0].path == TABLE, problems
    assert "'t700_adiprene'" in problems[0].message and "at 333.15 K" in problems[0].message


def test_a_table_that_starts_above_the_shaft_air_is_refused():
    data = baseline(matrix_reference_temperature_c=60.0)
    data["envelope"] = None  # its cold day lies below such a table too (a schema problem)
    table = data["materials"]["t700_adiprene"]["temperature_table"]
    keep = [i for i, t in enumerate(table["temperature_c"]) if t >= 60.0]
    for column, values in table.items():
        if values is not None:
            table[column] = tuple(values[i] for i in keep)
    problems = thermal_guards(design_from_dict(data))
    assert len(problems) == 1 and problems[0].path == TABLE + ".temperature_c", problems
    assert "317.27" in problems[0].message and "333.15" in problems[0].message

"""The command line's matrix tables, study JSON and verdict table (cli/tables.py) against hand
conversions of round numbers.

References (derived, unit definitions): 1 m = 1000 mm, 1 MPa = 1e6 Pa, rpm = 60·Ω/(2π) (so
Ω = 2π·N/60 rad/s prints as N rpm). The JSON keeps SI values under keys suffixed with their SI
unit, "/" read as "per" (N/m → ``N_per_m``). A check that fails one of its three findings
prints "FAIL 1/3" (failed/total). The printed cells (4 significant figures) of round inputs
are compared as exact strings. CPU: about 0.35 s, most of it rich's first table rendered.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr
from rich.console import Console

from flexshaft.cli.tables import dataset_json, dataset_table, matrix_table, unit_key, verdict_table
from flexshaft.verdict.result import Check, Finding, Verdict


def _rad_s(rpm: float) -> float:
    return 2.0 * math.pi * rpm / 60.0


def _text(table) -> str:
    console = Console(width=200, record=True, highlight=False)
    console.print(table)
    return console.export_text()


def _cells(table) -> list[list[str]]:
    """Header and body rows of a rendered rich table, cell by cell."""
    lines = _text(table).splitlines()
    return [
        [c.strip() for c in line.replace("┃", "│").split("│")[1:-1]]
        for line in lines
        if line.replace("┃", "│").count("│") > 2
    ]


def _stress() -> xr.DataArray:
    """Stress [Pa] over wall thickness [m] (down) and speed [rad/s] (across)."""
    return xr.DataArray(
        np.array([[1.5e8, 2.0e8], [2.5e8, 3.0e8]]),
        dims=("wall", "speed"),
        coords={
            "wall": ("wall", np.array([0.002, 0.003]), {"units": "m"}),
            "speed": ("speed", np.array([_rad_s(1000), _rad_s(2000)]), {"units": "rad/s"}),
        },
        name="stress",
        attrs={"units": "Pa"},
    )


def test_matrix_table_in_display_units():
    """Walls 2 and 3 mm down, speeds 1000 and 2000 rpm across, stresses 150-300 MPa."""
    table = matrix_table(_stress(), "walls")
    assert "walls: stress [MPa]" in _text(table)
    header, *body = _cells(table)
    assert header == ["wall \\ speed [rpm]", "1000", "2000"]
    assert body == [["2", "150", "200"], ["3", "250", "300"]]


def test_dataset_table_speed_in_rpm():
    """A speed coordinate of 1000 and 2000 rpm given in rad/s."""
    ds = _stress().isel(wall=0).drop_vars("wall").to_dataset()
    header, *body = _cells(dataset_table(ds, ["stress"], "speeds"))
    assert header == ["speed [rpm]", "stress [MPa]"]
    assert body == [["1000", "150"], ["2000", "200"]]


def test_study_json_is_si_under_unit_keys():
    ds = _stress().to_dataset()
    out = dataset_json(ds)
    assert out["coords"]["wall_m"] == [0.002, 0.003]
    np.testing.assert_allclose(out["coords"]["speed_rad_per_s"], [_rad_s(1000), _rad_s(2000)], rtol=1e-15)
    assert out["variables"] == {"stress_Pa": [[1.5e8, 2.0e8], [2.5e8, 3.0e8]]}
    assert out["dims"] == {"stress_Pa": ["wall_m", "speed_rad_per_s"]}
    assert unit_key("kp", "N/m") == "kp_N_per_m" and unit_key("kd", "N s/m") == "kd_N_s_per_m"


def test_verdict_table_value_limit_and_failed_count():
    """An excursion of 0.6 mm (6e-4 m) against a gap of 0.5 mm: margin −0.1 mm, one of three
    actuators failing."""
    findings = (
        Finding(6.0e-4, 5.0e-4, -1.0e-4, {"actuator": "amb_1"}),
        Finding(2.0e-4, 5.0e-4, 3.0e-4, {"actuator": "amb_2"}),
        Finding(1.0e-4, 5.0e-4, 4.0e-4, {"actuator": "amb_3"}),
    )
    check = Check(
        "actuator_orbit",
        "actuator excursion",
        "length",
        "at most",
        "fail",
        6.0e-4,
        5.0e-4,
        -1.0e-4,
        {"actuator": "amb_1"},
        findings=findings,
    )
    _, row = _cells(verdict_table(Verdict((check,))))
    assert row == ["actuator excursion", "0.6 mm", "≤ 0.5 mm", "-0.1 mm", "FAIL 1/3", "amb_1"]

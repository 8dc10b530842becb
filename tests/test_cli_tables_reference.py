"""The command line's tables (modes, study Datasets) against hand conversions of known values.

References (derived, unit definitions): 1 m = 1000 mm, 1 MPa = 1e6 Pa, 1 Hz = 60 rpm, and the
log decrement of a damping ratio ζ, δ = 2πζ/√(1 − ζ²). The inputs are round numbers, so the
printed cells (4 significant figures) are compared as exact strings.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr
from rich.console import Console

from flexshaft.cli.tables import dataset_table, modes_table


def _cells(table) -> list[list[str]]:
    """The body rows of a rendered rich table, cell by cell."""
    console = Console(width=200, record=True, highlight=False)
    console.print(table)
    lines = console.export_text().splitlines()
    return [[c.strip() for c in line.split("│")[1:-1]] for line in lines if line.count("│") > 2]


def test_modes_table_columns():
    """Mode 1 at 55.32 Hz = 3319.2 rpm with ζ = 0.02, δ = 2π·0.02/√(1 − 0.02²) = 0.12569; mode 2
    at 120 Hz = 7200 rpm, ζ = 0.1, δ = 0.63148: each in its own column."""
    rows = []
    for k, (f, zeta) in enumerate([(55.32, 0.02), (120.0, 0.1)]):
        rows.append(
            {
                "mode": k + 1,
                "frequency_Hz": f,
                "frequency_rpm": f * 60.0,
                "damping_ratio": zeta,
                "log_decrement": 2 * math.pi * zeta / math.sqrt(1 - zeta**2),
                "kind": "bending",
                "whirl": "forward",
                "component": "shaft",
            }
        )
    body = _cells(modes_table("modes", rows))
    assert body[0] == ["1", "55.32", "3319", "0.02", "0.1257", "bending", "forward", "shaft"]
    assert body[1] == ["2", "120", "7200", "0.1", "0.6315", "bending", "forward", "shaft"]


def test_dataset_table_display_units():
    """A wall of 2 mm (0.002 m) with a stress of 150 MPa (1.5e8 Pa) and a peak of 0.25 mm
    (2.5e-4 m) prints as 2, 150, 0.25 under [mm], [MPa], [mm]."""
    ds = xr.Dataset(
        {
            "stress": ("wall", np.array([1.5e8, 2.25e8]), {"units": "Pa"}),
            "peak": ("wall", np.array([2.5e-4, 1.0e-4]), {"units": "m"}),
        },
        coords={"wall": ("wall", np.array([0.002, 0.003]), {"units": "m"})},
    )
    console = Console(width=200, record=True, highlight=False)
    table = dataset_table(ds, ["stress", "peak"], "walls")
    console.print(table)
    text = console.export_text()
    assert "wall [mm]" in text and "stress [MPa]" in text and "peak [mm]" in text
    assert _cells(table) == [["2", "150", "0.25"], ["3", "225", "0.1"]]

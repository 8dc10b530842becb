"""The "design studies" section of the run report (report/studies_section.py) on hand-built studies.

A stand-in of the studies' results (plain namespaces and small xarray datasets, SI values,
every value distinct) whose displayed values are converted by hand from the unit definitions
(derived): 1 m = 1000 mm; rpm = 60·Ω/(2π), so Ω = 2π·N/60 rad/s shows as N rpm; 1 MPa = 1e6
Pa. The dominant-stress codes are those of the ply-angle study's output (0 σ1, 1 σ2, 2 τ12,
the order of the lamina stresses (σ1, σ2, τ12) in thesis §2.6). Figures are only recorded as
jobs (never drawn). CPU about 0.25 s, nearly all of it xarray's first use in the process.
"""

from __future__ import annotations

import math
from types import SimpleNamespace as NS

import numpy as np
import pytest
import xarray as xr

from flexshaft.report.studies_section import studies_section_and_jobs


def _rad_s(rpm: float) -> float:
    return 2.0 * math.pi * rpm / 60.0


ALPHA = [15.0, 30.0, 45.0, 55.0, 60.0, 75.0]
R = [1.1, 1.4, 2.9, 1.7, 1.6, 1.3]
CODES = [0, 1, 2, 1, 0, 2]  # σ1, σ2, τ12, σ2, σ1, τ12


def _ply_angle():
    n = len(ALPHA)
    return xr.Dataset(
        {
            "safety_factor": ("alpha", R),
            "dominant_stress": ("alpha", CODES),
            "critical_ply_angle": ("alpha", [-a for a in ALPHA]),
            "critical_x": ("alpha", [0.1 * (k + 1) for k in range(n)]),
            "sigma1": ("alpha", [1e6 * (k + 1) for k in range(n)]),
            "sigma2": ("alpha", [2e5 * (k + 1) for k in range(n)]),
            "tau12": ("alpha", [3e5 * (k + 1) for k in range(n)]),
        },
        coords={"alpha": ALPHA},
    )


def _tuned():
    speed = np.array([_rad_s(1000.0), _rad_s(2000.0)])
    return xr.Dataset(
        {
            "shaft_peak": (("case", "speed"), [[0.01, 0.02], [0.003, 0.002]]),
            "actuator_displacement": (("case", "speed"), [[4e-4, 5e-4], [1e-4, 2e-4]]),
            "actuator_force": (("case", "speed"), [[300.0, 200.0], [90.0, 80.0]]),
            "kp": ("case", [1e6, 3e6]),
            "kd": ("case", [500.0, 2000.0]),
        },
        coords={"case": ["design", "tuned"], "speed": speed},
    )


def _studies(**changes):
    fields = {
        "operating_speed": _rad_s(6000.0),
        "resolution": "coarse",
        "elapsed": 1.0,
        "notes": [],
        "optimal_angle": 45.0,
        "optimal_angle_safety_factor": 2.9,
        "ply_angle": _ply_angle(),
        "best_two_angle": None,
        "best_wall": 0.0035,
        "best_wall_safety_factor": 2.25,
        "wall": None,
        "gains_before": (1e6, 500.0),
        "gains_after": (3e6, 2000.0),
        "peak_before": 0.038,  # 38 mm at 1800 rpm (refined)
        "peak_after": 0.004,  # 4 mm at 2400 rpm
        "peak_speed_before": _rad_s(1800.0),
        "peak_speed_after": _rad_s(2400.0),
        "two_angle": None,
        "forced_response": None,
        "gain": None,
        "buckling": None,
        "spinup_map": None,
        "surfaces": None,
        "tuned": _tuned(),
        "stability_map": None,
    }
    fields.update(changes)
    return NS(**fields)


def _table(section, caption_start):
    (table,) = [t for t in section.tables if t.caption.startswith(caption_start)]
    return table


def test_headline_rows_in_mm_and_the_55_degree_value(tmp_path):
    """Optimum ±45° with R = 2.9 and R = 1.7 at ±55°; best wall 0.0035 m = 3.5 mm; peaks 0.038 m
    = 38 mm and 0.004 m = 4 mm with their gains."""
    section, _ = studies_section_and_jobs(_studies(), tmp_path)
    rows = {row[0]: row[1] for row in _table(section, "Headline").rows}
    assert rows["1. one ply angle (α/−α/−α/α), no imbalance"] == "±45° (R = 2.9; ±55°: R = 1.7)"
    assert rows["3. wall thickness (largest R with imbalance)"] == "3.5 mm (R = 2.25)"
    assert rows["6. tuned gains: peak spin-up deflection"] == (
        "38 mm at K_p = 1e+06 N/m, K_d = 500 N s/m → 4 mm at K_p = 3e+06 N/m, K_d = 2e+03 N s/m"
    )


def test_ply_angle_table_names_the_dominant_stress(tmp_path):
    """One row per table angle (the optimum 45° among them), σ in MPa, codes 0/1/2 as σ1/σ2/τ12."""
    section, _ = studies_section_and_jobs(_studies(), tmp_path)
    table = _table(section, "Most critical loading")
    assert [row[0] for row in table.rows] == ALPHA
    assert [row[-1] for row in table.rows] == ["σ1", "σ2", "τ12", "σ2", "σ1", "τ12"]
    k = 1  # α = 30°: R 1.4, ply −30°, x 0.2 m, σ1 2 MPa, σ2 0.4 MPa, τ12 0.6 MPa
    assert table.rows[k][1:7] == pytest.approx([1.4, -30.0, 0.2, 2.0, 0.4, 0.6], rel=1e-12)


def test_tuned_table_peaks_in_mm_at_rpm_per_case(tmp_path):
    """Design gains: refined peak 38 mm at 1800 rpm, actuator 0.5 mm and 300 N at most; tuned:
    4 mm at 2400 rpm, 0.2 mm and 90 N."""
    section, _ = studies_section_and_jobs(_studies(), tmp_path)
    table = _table(section, "Spin-up with the design and the tuned gains")
    design, tuned = table.rows
    assert design[0] == "design" and tuned[0] == "tuned"
    assert design[1:] == pytest.approx([1e6, 500.0, 38.0, 1800.0, 0.5, 300.0], rel=1e-12)
    assert tuned[1:] == pytest.approx([3e6, 2000.0, 4.0, 2400.0, 0.2, 90.0], rel=1e-12)

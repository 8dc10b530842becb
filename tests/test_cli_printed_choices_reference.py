"""The CLI picks the documented default, the right extreme and the right point before it prints.

References (derived, by hand; the analyses are stand-ins that record what the command passed them
and return numbers chosen here, run through typer's CliRunner on the embedded design; no
analysis runs):

* ``stability`` without ``--max-rpm`` sweeps rest to 1.5 × the operating speed (its help:
  "default: 1.5 × the operating speed"; docs/architecture.md): 4800 rpm → 7200 rpm = 2π·120 rad/s;
  the minimum damping ratio printed is the smallest of the sweep's margins, min(0.03, −0.02, 0.01);
* ``montecarlo``'s mean is the arithmetic mean, not the median: a skewed set 1, 2, 3, 4, 15 (×1e-4 m)
  has mean 25/5 = 5 and median 3, i.e. 0.5 mm against 0.3 mm;
* ``study ply-angle`` names the α of the largest safety factor (the thesis's optimum lies near
  ±55°): factors 1.0, 1.6, 2.4, 2.9, 2.2 at α = 15..75° (``--step 15``) give ±60° and 2.9;
* ``study two-angle`` names the best (α/−α/β/−β)s with α the first angle of the map's row: a
  symmetric 3 × 3 map (``--step 45``: 0, 45, 90°) whose largest value 3.0 sits at (45, 0) and
  (0, 45) names (45/-45/0/-0)s (the larger angle first, docs/studies.md);
* ``study all`` prints this design's best wall in mm: 2.5e-3 m · 1e3 = 2.5 mm (thesis 3e-3 m = 3 mm).
"""

from __future__ import annotations

import importlib
import json
import math
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr
from typer.testing import CliRunner

import flexshaft.assembly
from flexshaft.cli import app
from flexshaft.cli.study import _print_headline

runner = CliRunner()
STABILITY = importlib.import_module("flexshaft.analyses.stability")
SUMMARY = importlib.import_module("flexshaft.analyses.summary")
OPERATING = 2.0 * math.pi * 80.0  # 4800 rev/min [rad/s]


def _cells(line: str) -> list[str]:
    return [c.strip() for c in line.replace("┃", "│").split("│") if c.strip()]


@pytest.fixture
def analyses(monkeypatch: pytest.MonkeyPatch) -> dict:
    seen: dict = {}

    def modes_at(model, speed, n_modes):
        seen["n_modes"] = n_modes
        return []

    def stability(model, speeds, n_modes, damping_model, reference):
        seen["speeds"] = speeds
        return SimpleNamespace(
            onset_speed=None,
            unstable_mode=None,
            onset_whirl=None,
            whirl=np.full((len(speeds), 1), "forward", dtype=object),
            stability_margin=np.array([0.03, -0.02, 0.01]),
        )

    monkeypatch.setattr(flexshaft.assembly, "build_model", lambda design: SimpleNamespace(speed=OPERATING))
    monkeypatch.setattr(SUMMARY, "modes_at", modes_at)
    monkeypatch.setattr(STABILITY, "stability", stability)
    return seen


def test_stability_default_top_and_smallest_damping_ratio(analyses: dict) -> None:
    result = runner.invoke(app, ["stability", "--n-speeds", "3", "--n-modes", "1", "--json"])
    assert result.exit_code == 0, result.output
    assert analyses["speeds"][-1] == pytest.approx(2.0 * math.pi * 120.0, rel=1e-14)  # 7200 rpm
    data = json.loads(result.stdout)
    assert data["analysed_to_rpm"] == pytest.approx(7200.0, rel=1e-14)
    assert data["shafts"]["design"]["min_damping_ratio"] == -0.02
    text = runner.invoke(app, ["stability", "--n-speeds", "3", "--n-modes", "1"])
    assert text.exit_code == 0, text.output
    (row,) = [ln for ln in text.stdout.splitlines() if ln.startswith("│ design ")]
    assert _cells(row)[4] == "-0.02"  # the column "min damping ratio ζ"


def test_montecarlo_mean_is_the_mean_of_a_skewed_set(tmp_path, monkeypatch) -> None:
    peaks = np.array([1.0, 2.0, 3.0, 4.0, 15.0]) * 1e-4  # [m]

    def run(design, samples, **kw):
        return SimpleNamespace(
            gap=kw["gap"],
            force_limit=kw["force_limit"],
            limits={},
            dataset={"shaft_peak": SimpleNamespace(values=peaks)},
            plot=lambda: None,
            gap_exceedance=None,
            force_exceedance=None,
            gap_events=None,
            force_events=None,
        )

    monkeypatch.setattr("flexshaft.plot.driveline.save_figure", lambda fig, folder, stem, **kw: {})
    monkeypatch.setattr("flexshaft.netcdf.write_netcdf", lambda ds, path: None)
    monkeypatch.setattr("flexshaft.cli.bounds.check_montecarlo", lambda *a: None)
    monkeypatch.setitem(sys.modules, "flexshaft.montecarlo.steady", SimpleNamespace(run_montecarlo=run))
    result = runner.invoke(app, ["montecarlo", "--samples", "10", "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    # mean 5e-4 m = 0.5 mm (the median would be 0.3 mm)
    assert "spin-up peak shaft orbit: mean 0.5 mm" in " ".join(result.stdout.split())


@pytest.fixture
def no_files(monkeypatch):
    monkeypatch.setattr("flexshaft.plot.driveline.save_figure", lambda fig, folder, stem, **kw: {"png": Path(stem)})
    monkeypatch.setattr("flexshaft.netcdf.write_netcdf", lambda ds, path: None)


def _headline(tmp_path, args) -> str:
    result = runner.invoke(app, ["study", *args, "--json", "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)["headline"]


def test_ply_angle_names_the_largest_safety_factor(tmp_path, monkeypatch, no_files) -> None:
    def study(angles, **kw):
        assert list(angles) == [15.0, 30.0, 45.0, 60.0, 75.0]
        return xr.Dataset(
            {
                "safety_factor": ("alpha", [1.0, 1.6, 2.4, 2.9, 2.2], {"units": "1"}),
                "dominant_stress": ("alpha", [0.0, 0.0, 1.0, 1.0, 2.0], {"units": "1"}),
            },
            coords={"alpha": ("alpha", np.asarray(angles, dtype=float), {"units": "deg"})},
        )

    monkeypatch.setattr("flexshaft.thesis.ply_angle.ply_angle_study", study)
    monkeypatch.setattr("flexshaft.plot.studies.ply_angle_figure", lambda *a: None)
    assert _headline(tmp_path, ["ply-angle", "--step", "15"]) == "best α = ±60°: safety factor 2.9"


def test_two_angle_names_alpha_then_beta(tmp_path, monkeypatch, no_files) -> None:
    def study(alphas, betas, **kw):
        sf = np.array([[1.0, 3.0, 2.0], [3.0, 2.5, 1.5], [2.0, 1.5, 1.2]])  # sf[i, j] at (alpha_i, beta_j)
        return xr.Dataset(
            {"safety_factor": (("alpha", "beta"), sf, {"units": "1"})},
            coords={
                "alpha": ("alpha", np.asarray(alphas, dtype=float), {"units": "deg"}),
                "beta": ("beta", np.asarray(betas, dtype=float), {"units": "deg"}),
            },
        )

    monkeypatch.setattr("flexshaft.thesis.two_angles.two_angle_study", study)
    monkeypatch.setattr("flexshaft.plot.studies.two_angle_figure", lambda *a, **kw: None)
    assert _headline(tmp_path, ["two-angle", "--step", "45"]) == "best (45/-45/0/-0)s: safety factor 3"


def test_study_all_prints_the_best_wall_in_mm(capsys) -> None:
    data = {
        "design": "stand-in",
        "resolution": "report",
        "optimal_angle_deg": 55.0,
        "optimal_angle_safety_factor": 3.0,
        "best_two_angle_layup": "(55/-55/0/0)s",
        "best_two_angle_safety_factor": 3.5,
        "best_wall_m": 2.5e-3,
        "gains_before": None,
        "gains_after": None,
        "peak_deflection_before_m": None,
        "peak_deflection_after_m": None,
        "thesis": {
            "optimal_angle_deg": 55.0,
            "best_wall_m": 3.0e-3,
            "tuned_peak_before_m": None,
            "tuned_peak_after_m": None,
        },
        "notes": [],
    }
    _print_headline(data, Path("report.html"), "stand-in.toml")
    (row,) = [ln for ln in capsys.readouterr().out.splitlines() if "best wall [mm]" in ln]
    assert _cells(row)[1:] == ["2.5", "3"]

"""``flexshaft study ...`` states each study's finding in the units it names and hands each grid
to the axis it belongs to.

References (derived, by hand): stand-in sweeps (the study functions, figures and file writers
replaced by recorders; the commands run through typer's CliRunner on the embedded design) whose
values are chosen here, each expected headline worked out with its unit factor written beside it
(mm = m · 1e3); the spin-up map's grids are the command's documented K_p 1e5..1e8 N/m and
K_d 0 plus 10..10^4.5 N s/m. No analysis runs; the sweeps' datasets are a minimal stand-in
(xarray's first Dataset imports dask, about 0.5 s, more than every test here together).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.cli.study import _print_headline


@pytest.fixture
def no_files(monkeypatch):
    """Figures and netCDF files are not written (their writers record nothing of interest)."""
    monkeypatch.setattr("flexshaft.plot.driveline.save_figure", lambda fig, folder, stem, **kw: {"png": Path(stem)})
    monkeypatch.setattr("flexshaft.netcdf.write_netcdf", lambda ds, path: None)


def _headline(tmp_path, args) -> str:
    result = CliRunner().invoke(app, ["study", *args, "--json", "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)["headline"]


class _Variable:
    def __init__(self, dims: tuple[str, ...], values, units: str):
        self.dims, self.values, self.attrs = dims, np.asarray(values, dtype=float), {"units": units}
        self.ndim, self.shape = self.values.ndim, self.values.shape


class _Dataset:
    """What the study commands read of an xarray Dataset: items, coordinates by attribute,
    ``coords`` and ``data_vars`` (names), each with ``values``, ``dims`` and ``attrs``."""

    def __init__(self, coords: dict[str, _Variable], data_vars: dict[str, _Variable]):
        self.coords, self.data_vars = coords, data_vars

    def __getitem__(self, name: str) -> _Variable:
        return {**self.coords, **self.data_vars}[name]

    def __getattr__(self, name: str) -> _Variable:
        return self.__dict__["coords"][name]


def _walls(values: list[float], **variables: list[float]) -> _Dataset:
    coords = {"wall_thickness": _Variable(("wall_thickness",), values, "m")}
    return _Dataset(coords, {k: _Variable(("wall_thickness",), v, "1") for k, v in variables.items()})


def test_wall_headline_gives_the_best_wall_in_mm(tmp_path, monkeypatch, no_files):
    ds = _walls(
        [2.0e-3, 3.75e-3, 5.0e-3],
        safety_factor=[1.2, 2.5, 2.0],
        safety_factor_no_imbalance=[1.3, 2.6, 2.1],
        natural_frequency_1=[50.0, 60.0, 70.0],
        spinup_peak_deflection=[1e-4, 2e-4, 3e-4],
    )
    monkeypatch.setattr("flexshaft.thesis.wall.wall_thickness_study", lambda **kw: ds)
    monkeypatch.setattr("flexshaft.plot.studies.wall_thickness_figure", lambda *a: None)
    # the largest factor 2.5 is at 3.75e-3 m · 1e3 = 3.75 mm
    assert _headline(tmp_path, ["wall"]) == "largest safety factor 2.5 at a 3.75 mm wall"


def test_buckling_headline_names_the_thickest_wall_that_buckles(tmp_path, monkeypatch, no_files):
    ds = _walls(
        [1.0e-3, 2.0e-3, 3.0e-3, 4.0e-3],
        critical_torque=[100.0, 400.0, 900.0, 1600.0],
        buckling_safety_factor=[0.5, 0.9, 1.3, 2.0],
    )
    monkeypatch.setattr("flexshaft.thesis.buckling_sweep.buckling_study", lambda **kw: ds)
    monkeypatch.setattr("flexshaft.plot.studies.buckling_figure", lambda *a: None)
    # factors below 1 at 1 and 2 mm: the thickest that buckles is 2e-3 m = 2 mm
    assert _headline(tmp_path, ["buckling"]) == "walls up to 2 mm buckle (safety factor < 1)"


def test_spinup_map_hands_each_grid_to_its_gain_and_scales_only_lengths_to_mm(tmp_path, monkeypatch, no_files):
    seen: dict = {}

    def study(kp, kd, design, n_speeds):
        seen["kp"], seen["kd"] = np.asarray(kp), np.asarray(kd)
        shape = (kp.size, kd.size)
        grid = ("kp", "kd")
        return _Dataset(
            {"kp": _Variable(("kp",), kp, "N/m"), "kd": _Variable(("kd",), kd, "N s/m")},
            {
                "shaft_peak": _Variable(grid, np.arange(1.0, 10.0).reshape(shape) * 1e-4, "m"),
                "actuator_displacement_peak": _Variable(grid, np.full(shape, 2e-4), "m"),
                "actuator_force_peak": _Variable(grid, np.full(shape, 300.0), "N"),
            },
        )

    def figure(kp, kd, values, label, scale, best):
        seen[label] = scale

    monkeypatch.setattr("flexshaft.thesis.spinup_maps.spinup_gain_map", study)
    monkeypatch.setattr("flexshaft.plot.studies.gain_map_figure", figure)
    headline = _headline(tmp_path, ["spinup-map", "--n-gains", "3", "--n-speeds", "10"])
    # K_p: 10^5, 10^6.5, 10^8 N/m; K_d: 0, then 10^1, 10^4.5 N s/m
    assert seen["kp"] == pytest.approx([1e5, 10**6.5, 1e8], rel=1e-12)
    assert seen["kd"] == pytest.approx([0.0, 10.0, 10**4.5], rel=1e-12)
    # orbits in m drawn in mm (· 1e3), the force in N as it is
    assert seen["max spin-up shaft orbit [mm]"] == 1000.0
    assert seen["max actuator displacement [mm]"] == 1000.0
    assert seen["max actuator force [N]"] == 1.0
    # the smallest shaft peak is the first pair, 1e-4 m = 0.1 mm, at K_p = 1e5 N/m, K_d = 0
    assert headline == "best K_p = 100000 N/m, K_d = 0 N s/m: peak shaft orbit 0.1 mm"


def test_study_all_prints_the_gains_before_then_after_tuning(capsys):
    data = {
        "design": "stand-in",
        "resolution": "report",
        "optimal_angle_deg": 55.0,
        "optimal_angle_safety_factor": 3.0,
        "best_two_angle_layup": "(55/-55/0/0)s",
        "best_two_angle_safety_factor": 3.5,
        "best_wall_m": 3.0e-3,
        "gains_before": {"kp_N_per_m": 2.0e5, "kd_N_s_per_m": 100.0},
        "gains_after": {"kp_N_per_m": 5.0e5, "kd_N_s_per_m": 1250.0},
        "peak_deflection_before_m": 4.0e-4,
        "peak_deflection_after_m": 1.0e-4,
        "thesis": {
            "optimal_angle_deg": 55.0,
            "best_wall_m": 3.0e-3,
            "tuned_peak_before_m": 5e-4,
            "tuned_peak_after_m": 2e-4,
        },
        "notes": [],
    }
    _print_headline(data, Path("report.html"), "stand-in.toml")
    lines = capsys.readouterr().out.splitlines()
    (kp,) = [ln for ln in lines if "K_p before → tuned [N/m]" in ln]
    (kd,) = [ln for ln in lines if "K_d before → tuned [N s/m]" in ln]
    assert "200000 → 500000" in kp and "100 → 1250" in kd  # as every gain printed: sig(), no 2e+05
    # before tuning 4e-4 m = 0.4 mm (thesis 5e-4 m = 0.5 mm); after 1e-4 m = 0.1 mm (thesis 0.2 mm)
    (before,) = [ln for ln in lines if "spin-up peak orbit before tuning [mm]" in ln]
    (after,) = [ln for ln in lines if "spin-up peak orbit after tuning [mm]" in ln]
    assert _cells(before)[1:] == ["0.4", "0.5"] and _cells(after)[1:] == ["0.1", "0.2"]


def _cells(line: str) -> list[str]:
    return [c.strip() for c in line.split("│") if c.strip()]

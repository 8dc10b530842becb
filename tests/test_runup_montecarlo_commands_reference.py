"""``flexshaft runup`` and ``flexshaft montecarlo`` convert their options to SI before handing them
on, and print and write each result in the unit and column that names it.

References (derived, by hand): the commands run through typer's CliRunner on the embedded design
with the analyses replaced by stand-ins that record the arguments they receive and return values
chosen here. The unit factors are written out beside each expectation: rad/s = rpm · 2π/60,
m = mm / 1e3, mm = m · 1e3; the 99th percentile of 1..100 by linear interpolation (numpy's
default) sits at rank 0.99 · (100 − 1) = 98.01, i.e. 99.01. No analysis runs.
"""

from __future__ import annotations

import json
import math
import sys
from types import SimpleNamespace

import numpy as np
import pytest
from typer.testing import CliRunner

from flexshaft.cli import app

RPM = 2.0 * math.pi / 60.0  # rad/s per rpm


@pytest.fixture
def no_files(monkeypatch):
    monkeypatch.setattr("flexshaft.plot.driveline.save_figure", lambda fig, folder, stem, **kw: {})
    monkeypatch.setattr("flexshaft.netcdf.write_netcdf", lambda ds, path: None)


@pytest.fixture
def runup_seen(monkeypatch, no_files):
    """The run-up's stand-ins: a model at 5100 rpm (not the embedded design's speed), a run
    whose peak orbit 0.3 mm is at 2400 rpm at x = 1.5 m, and one actuator of largest orbit
    0.2 mm and force 35 N."""
    seen: dict = {}
    model = SimpleNamespace(speed=5100.0 * RPM)
    result = SimpleNamespace(
        peak=lambda: (3.0e-4, 0.0, 2400.0 * RPM),
        shaft_x=np.array([0.5, 1.5, 2.5]),
        shaft_orbit=np.array([[1e-4, 1e-4], [3e-4, 2e-4], [2e-4, 1e-4]]),  # stations × samples [m]
        actuator_names=["amb_1"],
        actuator_displacement=np.array([[1.0e-4, 2.0e-4]]),
        actuator_force=np.array([[35.0, 20.0]]),
        max_growth_rate=-1.0,
        unstable=False,
        basis_size=8,
        internal_damping="hysteretic",
        to_dataset=lambda: None,
    )

    def run_up(model, duration, start, stop, dwell):
        seen.update(duration=duration, start=start, stop=stop, dwell=dwell)
        return result

    monkeypatch.setattr("flexshaft.assembly.build_model", lambda design: model)
    monkeypatch.setattr("flexshaft.cli.bounds.check_runup", lambda *a: None)
    monkeypatch.setattr("flexshaft.analyses.transient.run_up", run_up)
    monkeypatch.setattr(
        "flexshaft.analyses.transient.steady_state_envelope",
        lambda model, speeds: SimpleNamespace(shaft_orbit=np.array([5.0e-4, 1.0e-4])),
    )
    monkeypatch.setattr(
        "flexshaft.plot.transient.runup_envelope_figure",
        lambda runs, steady, operating_rpm: seen.update(op=operating_rpm),
    )
    return seen


RUNUP = ["runup", "--start-rpm", "1000", "--stop-rpm", "3000", "--duration", "2"]


def test_runup_passes_its_speeds_in_rad_s_and_reports_rpm(tmp_path, runup_seen):
    result = CliRunner().invoke(app, [*RUNUP, "--json", "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    # 1000 rpm · 2π/60 = 104.72 rad/s, 3000 rpm · 2π/60 = 314.16 rad/s
    assert runup_seen["start"] == pytest.approx(1000.0 * RPM, rel=1e-12)
    assert runup_seen["stop"] == pytest.approx(3000.0 * RPM, rel=1e-12)
    assert runup_seen["op"] == pytest.approx(5100.0, rel=1e-12)  # the figure's operating line [rpm]
    data = json.loads(result.stdout)
    assert data["peak_speed_rpm"] == pytest.approx(2400.0, rel=1e-12)  # 2400 · 2π/60 rad/s back in rpm
    assert data["stop_rpm"] == pytest.approx(3000.0, rel=1e-12)
    assert data["peak_station_m"] == 1.5  # the station of the largest orbit (row 1)
    assert data["actuator_orbit_max_m"] == {"amb_1": 2.0e-4} and data["actuator_force_max_N"] == {"amb_1": 35.0}


def test_runup_table_puts_the_orbit_in_mm_and_the_force_in_n(tmp_path, runup_seen):
    result = CliRunner().invoke(app, [*RUNUP, "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    header = next(ln for ln in lines if "orbit [mm]" in ln)
    # the run-up's actuator outputs are the imbalance response alone, and say so
    row = next(ln for ln in lines if "amb_1" in ln)
    cells, columns = _cells(row), _cells(header)
    assert columns == ["actuator", "imbalance orbit [mm]", "imbalance force [N]"]
    assert any("the static load not included" in ln for ln in lines)
    assert cells == ["amb_1", "0.2", "35"]  # 2e-4 m · 1e3 = 0.2 mm; 35 N
    # 0.3 mm at 2400 rpm, the steady-state peak 5e-4 m = 0.5 mm
    assert any("peak shaft orbit 0.3 mm at 2400 rpm, x = 1.5 m" in ln and "0.5 mm" in ln for ln in lines)


def montecarlo_result(gap, force_limit, orbit, **fields):
    """A stand-in Monte-Carlo result: its limits, the shaft's peak orbit of each sample [m], no
    exceedance counted, no figure."""
    return SimpleNamespace(
        gap=gap,
        force_limit=force_limit,
        dataset={"shaft_peak": SimpleNamespace(values=orbit)},
        plot=lambda: None,
        gap_exceedance=None,
        force_exceedance=None,
        gap_events=None,
        force_events=None,
        **fields,
    )


def _cells(line: str) -> list[str]:
    return [c.strip() for c in line.replace("┃", "│").split("│") if c.strip()]


def test_montecarlo_passes_the_gap_in_metres_and_reports_the_99th_percentile(tmp_path, monkeypatch, no_files):
    seen: dict = {}
    orbit = np.arange(1.0, 101.0) * 1e-5  # 100 samples: 1e-5 .. 1e-3 m

    def run(design, samples, **kw):
        seen.update(kw)
        return montecarlo_result(kw["gap"], kw["force_limit"], orbit)

    monkeypatch.setattr("flexshaft.cli.bounds.check_montecarlo", lambda *a: None)
    # the study's module itself stood in for: importing flexshaft.montecarlo imports scipy.stats
    # (about 1 s, more than everything else here)
    monkeypatch.setitem(sys.modules, "flexshaft.montecarlo.steady", SimpleNamespace(run_montecarlo=run))
    args = ["montecarlo", "--samples", "100", "--gap-mm", "0.5", "--force-limit", "900", "--json"]
    result = CliRunner().invoke(app, [*args, "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    assert seen["gap"] == pytest.approx(5.0e-4, rel=1e-12)  # 0.5 mm / 1e3
    assert seen["force_limit"] == 900.0 and seen["grade_mm_s"] == 6.3
    data = json.loads(result.stdout)
    assert data["gap_m"] == pytest.approx(5.0e-4, rel=1e-12)
    # mean of 1..100 is 50.5; 99th percentile 99.01 (see the module docstring); both · 1e-5 m
    assert data["summary"]["shaft_peak"]["mean"] == pytest.approx(50.5e-5, rel=1e-12)
    assert data["summary"]["shaft_peak"]["p99"] == pytest.approx(99.01e-5, rel=1e-12)


def test_montecarlo_names_each_actuators_own_gap_when_they_differ(tmp_path, monkeypatch, no_files):
    """Each actuator is counted against its own gap: amb_1's 5e-4 m (0.5 mm) and amb_2's 2.5e-4 m
    (0.25 mm) are both printed, not the smaller alone; a force capacity both share (1500 N) is
    printed once."""

    def run(design, samples, **kw):
        events = SimpleNamespace(describe=lambda: "3 of 100 samples", to_dict=lambda: {"exceeding": 3, "samples": 100})
        return SimpleNamespace(
            gap=2.5e-4,
            force_limit=1500.0,
            limits={
                "amb_1": SimpleNamespace(gap=5e-4, force_capacity=1500.0),
                "amb_2": SimpleNamespace(gap=2.5e-4, force_capacity=1500.0),
            },
            dataset={"shaft_peak": SimpleNamespace(values=np.arange(1.0, 101.0) * 1e-5)},
            plot=lambda: None,
            gap_exceedance=(0.03, 0.017),
            force_exceedance=(0.03, 0.017),
            gap_events=events,
            force_events=events,
        )

    monkeypatch.setattr("flexshaft.cli.bounds.check_montecarlo", lambda *a: None)
    monkeypatch.setitem(sys.modules, "flexshaft.montecarlo.steady", SimpleNamespace(run_montecarlo=run))
    result = CliRunner().invoke(app, ["montecarlo", "--samples", "100", "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    text = " ".join(result.stdout.split())
    assert "gap (amb_1 0.5 mm, amb_2 0.25 mm) exceeded (static + dynamic) in 3 of 100 samples" in text
    assert "force limit 1500 N exceeded (static + dynamic) in 3 of 100 samples" in text

"""``flexshaft runup``: the speeds a run covers, and the numbers it reports for each of them.

References (derived here, by hand, and the documented rules quoted):

* the steady-state spin-up curve printed and drawn beside a run is the one over the run's own
  speeds (docs/transient.md: ``run.plot(steady=steady_state_envelope(model, run.speed[::50]))``):
  from the lower to the upper of --start-rpm and --stop-rpm, whichever is first (a run-down
  covers the same speeds as the run-up between them), not up to the design's operating speed;
* --stop-rpm defaults to the operating speed (its help: "End speed [rpm]; default the operating
  speed"): a run without it ends, and reports its end, at the operating speed;
* the output-sample bound is taken at the run's top speed (the --duration help: "8 per revolution at
  the top speed: 312 s at 4800 rpm"; docs/limits.md: at most 200,000 samples, "at most 312.5 s
  at 4800 rpm"). Derived: 8 samples per period of the fastest content, 4800 rpm = 80 rev/s, so
  a step of 1/640 s and (200,000 − 1)/640 = 312.498 s; a run-down from 4800 rpm reaches that
  speed too (at its start), so a 400-s run-down is refused as a 400-s run-up is;
* each actuator's largest orbit and force are its own row's maxima.

Unit factors: rad/s = rpm · 2π/60, mm = m · 1e3. The analyses are stand-ins that record what the
command passed them and return arrays chosen here (the same pattern as
tests/test_runup_montecarlo_commands_reference.py); nothing is built or integrated. The speeds
are compared at rel 1e-12: each is one or two float products of the given rpm (a few ulps).
"""

from __future__ import annotations

import json
import math
from types import SimpleNamespace

import numpy as np
import pytest
from typer.testing import CliRunner

from flexshaft.cli import app

RPM = 2.0 * math.pi / 60.0  # rad/s per rpm
OPERATING_RPM = 5100.0  # the stand-in model's operating speed (not the embedded design's)


@pytest.fixture
def seen(monkeypatch):
    """Stand-ins for the model, the bound, the run, the steady curve and the files; two
    actuators: amb_1 with largest orbit 2e-4 m and force 35 N, amb_2 with 4e-4 m and 70 N (each
    largest in a different sample)."""
    record: dict = {}
    model = SimpleNamespace(speed=OPERATING_RPM * RPM)
    result = SimpleNamespace(
        peak=lambda: (3.0e-4, 0.0, 2400.0 * RPM),
        shaft_x=np.array([0.5, 1.5, 2.5]),
        shaft_orbit=np.array([[1e-4, 1e-4], [3e-4, 2e-4], [2e-4, 1e-4]]),
        actuator_names=["amb_1", "amb_2"],
        actuator_displacement=np.array([[1.0e-4, 2.0e-4], [4.0e-4, 3.0e-4]]),
        actuator_force=np.array([[35.0, 20.0], [10.0, 70.0]]),
        max_growth_rate=-1.0,
        unstable=False,
        basis_size=8,
        internal_damping="hysteretic",
        to_dataset=lambda: None,
    )

    def run_up(model, duration, start, stop, dwell):
        record.update(start=start, stop=stop)
        return result

    def steady(model, speeds):
        record["steady_speeds"] = np.asarray(speeds)
        return SimpleNamespace(shaft_orbit=np.array([5.0e-4, 1.0e-4]))

    monkeypatch.setattr("flexshaft.assembly.build_model", lambda design: model)
    monkeypatch.setattr("flexshaft.cli.bounds.check_runup", lambda m, d, w, top: record.update(top=top))
    monkeypatch.setattr("flexshaft.analyses.transient.run_up", run_up)
    monkeypatch.setattr("flexshaft.analyses.transient.steady_state_envelope", steady)
    monkeypatch.setattr("flexshaft.plot.transient.runup_envelope_figure", lambda runs, steady, operating_rpm: None)
    monkeypatch.setattr("flexshaft.plot.driveline.save_figure", lambda fig, folder, stem, **kw: {})
    monkeypatch.setattr("flexshaft.netcdf.write_netcdf", lambda ds, path: None)
    return record


def _run(tmp_path, *args: str):
    result = CliRunner().invoke(app, ["runup", *args, "--duration", "2", "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    return result


@pytest.mark.parametrize("start, stop", [("1000", "3000"), ("3000", "1000")])
def test_steady_curve_spans_the_runs_own_speeds(tmp_path, seen, start, stop):
    """1000 ↔ 3000 rpm, up or down: the steady curve runs from 1000 · 2π/60 = 104.72 rad/s to
    3000 · 2π/60 = 314.16 rad/s (below the 5100 rpm operating speed), and the bound is taken at
    the top speed 3000 rpm both ways."""
    _run(tmp_path, "--start-rpm", start, "--stop-rpm", stop)
    speeds = seen["steady_speeds"]
    assert speeds.min() == pytest.approx(1000.0 * RPM, rel=1e-12)
    assert speeds.max() == pytest.approx(3000.0 * RPM, rel=1e-12)
    assert seen["top"] == pytest.approx(3000.0 * RPM, rel=1e-12)


def test_default_end_is_the_operating_speed(tmp_path, seen):
    """No --stop-rpm: the run ends at 5100 rpm = 534.07 rad/s, reported in rpm in the JSON and the
    first line; the steady curve ends there too."""
    data = json.loads(_run(tmp_path, "--json").stdout)
    assert seen["stop"] == pytest.approx(OPERATING_RPM * RPM, rel=1e-12)
    assert data["stop_rpm"] == pytest.approx(OPERATING_RPM, rel=1e-12)
    assert seen["steady_speeds"].max() == pytest.approx(OPERATING_RPM * RPM, rel=1e-12)
    lines = _run(tmp_path, "--force").stdout.splitlines()
    assert any("run-up 0 → 5100 rpm" in ln for ln in lines)


def test_each_actuator_reports_its_own_maxima(tmp_path, seen):
    """amb_1: max(1e-4, 2e-4) m and max(35, 20) N; amb_2: max(4e-4, 3e-4) m and max(10, 70) N;
    in the table 0.2 mm / 35 N and 0.4 mm / 70 N."""
    data = json.loads(_run(tmp_path, "--json").stdout)
    assert data["actuator_orbit_max_m"] == {"amb_1": 2.0e-4, "amb_2": 4.0e-4}
    assert data["actuator_force_max_N"] == {"amb_1": 35.0, "amb_2": 70.0}
    lines = _run(tmp_path, "--force").stdout.splitlines()
    rows = {c[0]: c[1:] for c in (_cells(ln) for ln in lines if "amb_" in ln)}
    assert rows == {"amb_1": ["0.2", "35"], "amb_2": ["0.4", "70"]}


def _cells(line: str) -> list[str]:
    return [c.strip() for c in line.replace("┃", "│").split("│") if c.strip()]


@pytest.mark.parametrize("start, stop", [("0", "4800"), ("4800", "0")])
def test_a_400_s_run_through_4800_rpm_is_refused_either_way(tmp_path, monkeypatch, start, stop):
    """The real bound (flexshaft.cli.bounds.check_runup) on a stand-in model: 400 s through
    4800 rpm is 400 · 640 + 1 = 256,001 samples > 200,000, refused with the longest run
    (200,000 − 1)/640 = 312.5 s (4 significant figures) whether 4800 rpm is the end or the
    start. The refusal comes before the model is looked at (its basis size), so the stand-in
    model needs only its operating speed."""
    monkeypatch.setattr("flexshaft.assembly.build_model", lambda design: SimpleNamespace(speed=4800.0 * RPM))
    args = ["runup", "--start-rpm", start, "--stop-rpm", stop, "--duration", "400", "-o", str(tmp_path / "o")]
    result = CliRunner().invoke(app, args)
    assert result.exit_code != 0
    text = " ".join(result.output.split())
    assert "256,001 output samples" in text and "at most 312.5 s" in text, text
    assert not (tmp_path / "o").exists()  # refused before the output folder is made

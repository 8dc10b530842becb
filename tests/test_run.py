"""End to end: ``flexshaft run`` on the embedded default (tuned) design writes a report that renders.

The README's quick start, ``flexshaft run`` in a fresh folder, runs once (the module's fixture,
a subprocess as a user types it: about 15 s of CPU, the full run of the tuned design at its four
envelope points with the thesis studies and every figure). Its output feeds the report's tests,
the first lines' test (the design, then the verdict) and the readme loop of issue 28, which goes
on from the folder the quick start left (a copy of it).
"""

import contextlib
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from chromium_probe import chromium_or_skip, image_load_title
from conftest import charged_to_session, session_lock
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.cli.output import MARKER
from flexshaft.design import tuned_design

WALL = re.compile(r"^wall_thickness = [0-9.e-]+", re.M)


def _flexshaft(cwd: Path, *args: str) -> subprocess.CompletedProcess:
    code = "import sys; from flexshaft.cli import app; sys.argv[0] = 'flexshaft'; app()"
    return subprocess.run(
        [sys.executable, "-c", code, *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=600,
        env={**os.environ, "OPENBLAS_NUM_THREADS": "1"},
    )


def _quick_start(folder: Path) -> dict:
    result = _flexshaft(folder, "run")
    assert result.returncode == 0, result.stderr
    return {"folder": folder, "out": folder / "flexshaft-results", "stdout": result.stdout, "stderr": result.stderr}


@pytest.fixture(scope="module")
def quick_start(tmp_path_factory) -> dict:
    """The README's quick start: ``flexshaft run`` in a fresh folder (tests only read it).

    Under pytest-xdist the module's tests may land on both workers: they share one run (the
    first worker computes it under a lock in the session's temporary folder, the other waits and
    reads it: tests/conftest.py's ``session_lock``)."""
    with session_lock(tmp_path_factory, "quick_start") as shared:
        if shared is None:
            return charged_to_session("quick_start", _quick_start, tmp_path_factory.mktemp("quick_start"))
        folder, record = shared / "quick_start", shared / "quick_start.json"
        if not record.is_file():
            shutil.rmtree(folder, ignore_errors=True)
            folder.mkdir()
            run = charged_to_session("quick_start", _quick_start, folder)
            record.write_text(json.dumps({"stdout": run["stdout"], "stderr": run["stderr"]}), encoding="utf-8")
    return {"folder": folder, "out": folder / "flexshaft-results", **json.loads(record.read_text(encoding="utf-8"))}


@pytest.fixture(scope="module")
def baseline_run(quick_start):
    return quick_start["out"], quick_start["stdout"] + quick_start["stderr"]


def test_run_writes_report_figures_and_numbers(baseline_run):
    out, output = baseline_run
    assert "report written to" in output
    data = json.loads((out / "results.json").read_text())
    for key in (
        "summary",
        "modes_at_rest",
        "modes_at_operating_speed",
        "critical_speeds",
        "imbalance",
        "static",
        "strength_static_plus_imbalance",
        "buckling",
        "stability",
        "thermal",
        "bearings",
    ):
        assert key in data
    assert len(data["modes_at_rest"]) == 10
    assert data["strength_static_plus_imbalance"]["safety_factor"] > 0
    assert data["thermal"]["self_heating"]["status"] == "converged"
    assert data["design_studies"] is not None
    # the default design is the tuned one: stable beyond the required onset speed, and every
    # requirement met; only the boom-only modes' log decrement (ζ = η_boom/2 = 0.01) may fail until
    # the whirl-damping check is restricted to modes with shaft participation
    assert "Tuned design" in output
    verdict = data["verdict"]
    onset = next(c for c in verdict["checks"] if c["key"] == "whirl_onset")
    assert onset["status"] == "pass"
    assert onset["value"] > data["summary"]["operating_speed_rpm"] * 2 * 3.141592653589793 / 60
    for check in verdict["checks"]:
        assert check["status"] != "not evaluated", check["key"]
        failed = [f for f in check["findings"] if not f["passed"]]
        assert all(check["key"] == "whirl_damping" and "boom)" in f["location"]["mode"] for f in failed), check
    # one spin-up peak: results.json and the terminal state the verdict's finding at the governing
    # point, whose analyses they show (to the highest operating speed, refined; docs/requirements.md:
    # results.json's numbers are the governing point's), and the whole scan's largest (to 1.3 x,
    # that point's scan) apart; at the governing point the scan's cannot be smaller
    spinup = next(c for c in verdict["checks"] if c["key"] == "spinup_deflection")
    governing = data["envelope"]["governing_point"]
    (there,) = [f for f in spinup["findings"] if f["location"]["point"] == governing]
    assert data["imbalance"]["max_shaft_orbit_spin_up_m"] == there["value"]
    highest = tuned_design().operating.speed_range[1]  # the quick start's design: its 1.05
    assert data["imbalance"]["speed_of_max_rpm"] <= data["summary"]["operating_speed_rpm"] * highest * (1 + 1e-9)
    assert data["imbalance"]["max_shaft_orbit_scan_m"] >= 0.99 * there["value"]  # the refined peak may exceed a sample
    # the every-root check of the tuned design's ideal PD bearings (passive): every root stable at
    # the three speeds, its basis within the accuracy it was chosen for (its estimate against the
    # full model: tests/test_root_stability.py); the report's table says so
    every = data["stability"]["every_root"]
    assert every["method"] == "passive" and every["unstable_roots"] == [0, 0, 0]
    assert 0 < every["estimated_relative_error"] <= every["tolerance"] == 1e-6
    assert "Every root of the closed loop (passive bearing laws" in (out / "report.html").read_text(encoding="utf-8")
    thesis = data["stability"]["thesis_shafts"]
    # the thesis's abstract: adding 0° plies to the (45/-45)s shaft improves its stability
    # (an onset of None: stable up to the highest speed analysed)
    onset_rpm = {k: float("inf") if v["viscous"] is None else v["viscous"] for k, v in thesis.items()}
    assert onset_rpm["(45/-45/0/0)s FMC"] > onset_rpm["(45/-45)s FMC"]
    for stem in (
        "verdict_margins",
        "campbell",
        "mode_shapes",
        "imbalance_response",
        "imbalance_bode",
        "bearing_orbits",
        "actuators",
        "static_deflection",
        "safety_factor",
        "stability_log_decrement",
        "stability_map",
        "loop_sensitivity",
        "shaft_temperature",
        "shaft_temperature_sweeps",
    ):
        assert (out / f"{stem}.png").stat().st_size > 10_000
        assert not (out / f"{stem}.svg").exists()  # SVG only on request


def test_baseline_report_renders_with_every_figure(baseline_run, tmp_path):
    out, _ = baseline_run
    chromium = chromium_or_skip()
    n_figures = len(list(out.glob("*.png")))
    assert n_figures >= 8  # every figure written is embedded in the page and must decode
    assert image_load_title(chromium, out / "report.html", tmp_path) == f"IMAGES-OK:{n_figures}"


def test_no_report_figure_is_cut_at_its_edge(baseline_run):
    """Every figure of the README's run, the studies' included: no ink in a file's outermost
    pixels (tests/test_figure_canvas_edge_reference.py: a glyph cut by the canvas' edge leaves
    some there). Before, the tuned design's thermal sweeps lost part of their axis label."""
    from test_figure_canvas_edge_reference import edge_ink

    out, _ = baseline_run
    files = sorted(out.glob("*.png"))
    assert len(files) >= 20
    cut = {f.name: ink for f in files if any((ink := edge_ink(f.read_bytes())).values())}
    assert cut == {}


def test_stability_command_compares_the_thesis_shafts():
    result = CliRunner().invoke(app, ["stability", "--compare-thesis", "--n-speeds", "25", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert set(data["shafts"]) == {"design", "aluminium 6061-T6", "(45/-45)s FMC", "(45/-45/0/0)s FMC"}


def test_run_json_option_prints_the_key_results(small_run):
    """The option's output: the session's ``run --studies none --json`` of a small baseline at one
    envelope point (tests/conftest.py's ``small_run``; the full design's JSON is the quick
    start's results.json, checked above)."""
    assert small_run["exit_code"] == 0
    data = json.loads(small_run["stdout"])
    assert data["summary"]["operating_speed_rpm"] == pytest.approx(4800.0)


def test_thermal_command_reports_boom_and_shaft_temperatures():
    result = CliRunner().invoke(app, ["thermal", "--json", "--sweeps"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert set(data["tailboom_c"]) == {"hover", "parked"}
    assert data["tailboom_c"]["parked"] > data["tailboom_c"]["hover"]  # no downwash when parked
    rises = list(data["peak_rise_K_by_convection"].values())
    assert rises[0] > rises[1] > rises[2]  # more convection, cooler shaft
    bad = CliRunner().invoke(app, ["thermal", "--loss-model", "magic"])
    assert bad.exit_code == 2 and "Traceback" not in bad.output


def test_run_names_the_design_then_the_verdict(quick_start):
    """issue 28, point 2 (tests/test_default_design.py): ``flexshaft run``'s first line names the
    default design, the second is the verdict, the third the envelope's points."""
    first, second, third = quick_start["stdout"].splitlines()[:3]
    assert first == f"design: {tuned_design().name} (embedded tuned design)"
    assert second == "verdict: PASS — 13 checks pass"  # the tuned design passes (docs/requirements.md)
    assert third.startswith("envelope: 4 points (cold_day, standard_day, hot_day, hot_soak_start); governed by ")


def _edit_wall(path: Path, wall: float) -> None:
    text = path.read_text(encoding="utf-8")
    assert WALL.search(text), "the design file has a shaft wall_thickness line"
    path.write_text(WALL.sub(f"wall_thickness = {wall}", text, count=1), encoding="utf-8")


def _flexshaft_here(cwd: Path, *args: str):
    """``flexshaft ARGS`` typed in ``cwd``, run in the test process (typer's ``CliRunner``, as
    the other CLI tests: no interpreter start, no pool of its own; tests/conftest.py)."""
    with contextlib.chdir(cwd):
        return CliRunner().invoke(app, list(args))


@pytest.mark.slow  # two full `flexshaft run`s of the baseline (three envelope points), one with the studies: ~9 s
def test_the_readme_loop_runs_without_force(quick_start, tmp_path: Path) -> None:
    """Issue 28's bar (tests/test_rerun.py): from a fresh folder, the README's quick start
    (``flexshaft run``, the embedded design into ``flexshaft-results/``: the module's fixture,
    a subprocess as a user types it), then ``flexshaft baseline > my.toml && flexshaft run
    my.toml``, an edit, and ``flexshaft run my.toml`` again: all exit 0 without ``--force``. It
    goes on in a copy of the quick start's folder (the fixture's is shared), with the whole
    design and its envelope at the report's resolution. The loop's own commands run in the test
    process, in that folder (CPU budget, issue 23: 12.6 s of CPU as subprocesses, each importing
    flexshaft, matplotlib and the run's pool of workers again, 8.9 s in process): what they
    check is the output folder's ownership and contents, not the process; the quick start
    checks ``flexshaft run`` as a process, its pool included, and a run in process computes the
    same results as on the pool (tests/test_tasks.py, tests/test_studies.py). The first run of
    ``my.toml`` is typed as the README has it (with the thesis studies), so the rerun after the
    edit meets a folder holding the studies' files as a user's does, and must replace them
    (the first run's ``studies/`` folder goes); the rerun skips them and the figures
    (``--studies none --no-figures``, CPU budget, issue 23: about 10 s of CPU), and must remove
    the first run's figures too: what it checks is the output folder's ownership (its marker:
    the command, the design's source and fingerprint, whether it is complete) and that the
    edited design's results replace the first run's.
    It is also tests/test_rerun.py's rerun of ``run`` after an edit (the edited wall's mass)."""
    shutil.copytree(quick_start["folder"], tmp_path, dirs_exist_ok=True)
    assert (tmp_path / "flexshaft-results" / "report.html").is_file()
    baseline = _flexshaft_here(tmp_path, "baseline")
    assert baseline.exit_code == 0, baseline.output
    (tmp_path / "my.toml").write_text(baseline.stdout, encoding="utf-8")  # `flexshaft baseline > my.toml`
    first = _flexshaft_here(tmp_path, "run", "my.toml")
    assert first.exit_code == 0, first.output
    assert (tmp_path / "my-results" / "studies").is_dir() and list((tmp_path / "my-results").glob("*.png"))
    results = tmp_path / "my-results" / "results.json"
    wall_before = json.loads(results.read_text())["summary"]
    assert WALL.search((tmp_path / "my.toml").read_text(encoding="utf-8")).group() == "wall_thickness = 0.003"
    _edit_wall(tmp_path / "my.toml", 0.0035)
    second = _flexshaft_here(tmp_path, "run", "my.toml", "--studies", "none", "--no-figures")
    assert second.exit_code == 0, second.output
    assert "--force" not in second.stderr
    # the first run's studies and figures (of the design before the edit) do not linger
    assert not (tmp_path / "my-results" / "studies").exists()
    assert not list((tmp_path / "my-results").glob("*.png"))
    # the folder holds the edited design's results: a 0.0035 m wall instead of 0.003 m weighs
    # 7/6 as much (the tube's mass is proportional to its wall at a fixed outer diameter, up to
    # the mean-radius change: within 3 %)
    mass = json.loads(results.read_text())["summary"]["shaft_mass_kg"]
    assert mass > wall_before["shaft_mass_kg"]
    assert mass == pytest.approx(wall_before["shaft_mass_kg"] * 7 / 6, rel=0.03)
    marker = json.loads((tmp_path / "my-results" / MARKER).read_text())
    assert marker["complete"] is True and marker["design_source"] == str((tmp_path / "my.toml").resolve())

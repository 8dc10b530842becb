"""End to end: ``flexshaft run`` on the embedded default (tuned) design writes a report that renders."""

import json

import pytest
from chromium_probe import chromium_or_skip, image_load_title
from typer.testing import CliRunner

from flexshaft.cli import app


@pytest.fixture(scope="module")
def baseline_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("run")
    result = CliRunner().invoke(app, ["run", "--out", str(out)])
    assert result.exit_code == 0, result.output
    return out, result.output


@pytest.mark.slow(
    reason="the README's main command end to end: the full run of the default design with its design "
    "studies and every figure (about 10 s of CPU, the command's own cost; the module shares the fixture)"
)
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
    # one spin-up peak: results.json and the terminal state the verdict's (to the operating speed,
    # refined), and the whole scan's largest (to 1.3 x) apart; it cannot be smaller
    spinup = next(c for c in verdict["checks"] if c["key"] == "spinup_deflection")
    assert data["imbalance"]["max_shaft_orbit_spin_up_m"] == spinup["value"]
    assert data["imbalance"]["speed_of_max_rpm"] <= data["summary"]["operating_speed_rpm"] * (1 + 1e-9)
    assert data["imbalance"]["max_shaft_orbit_scan_m"] >= 0.99 * spinup["value"]  # the refined peak may exceed a sample
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


def test_stability_command_compares_the_thesis_shafts():
    result = CliRunner().invoke(app, ["stability", "--compare-thesis", "--n-speeds", "25", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert set(data["shafts"]) == {"design", "aluminium 6061-T6", "(45/-45)s FMC", "(45/-45/0/0)s FMC"}


@pytest.mark.slow(reason="a full run of the tuned design at its four envelope points (~6 s of CPU)")
def test_run_json_option_prints_the_key_results(tmp_path):
    result = CliRunner().invoke(app, ["run", "--out", str(tmp_path), "--json", "--studies", "none"])
    assert result.exit_code == 0
    data = json.loads(result.stdout)
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

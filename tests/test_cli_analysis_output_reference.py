"""What ``modes``, ``stability`` and ``thermal`` print: units and fields, against hand conversions.

The analyses themselves are replaced by stand-ins that record what the command passed them and
return numbers chosen so that every conversion is exact and worked by hand here; the model is a
stand-in with the operating speed 4800 rev/min = 80 rev/s = 2π·80 rad/s. So what is checked is the
command's own arithmetic and choice of field, not the analyses (tested elsewhere):

* rev/min -> rad/s is 2π/60 (``--speed-rpm 600`` -> 20π rad/s; ``--max-rpm 9600`` -> 320π rad/s),
  Hz -> rad/s is 2π (``--reference-hz 50`` -> 100π rad/s), and back for what is printed;
* the onset ratio is onset / operating speed (5400 / 4800 = 1.125);
* the unstable mode's whirl direction is the result's ``onset_whirl`` (where the mode is first
  unstable: tests/test_stability_onset_bookkeeping_reference.py), not a label of its own;
* a sweep stable to 9600 rev/min passes the onset check: the requirement is (1 + margin) x 4800
  rev/min with the design's margin, below 9600 for any margin under 100 %;
* the thermal table puts each number under its header, the temperature in °C as given.

The design read is the embedded default (no file); nothing is built or solved: about 0.1 s.
"""

from __future__ import annotations

import importlib
import json
import math
import re
from types import SimpleNamespace

import numpy as np
import pytest
from typer.testing import CliRunner

import flexshaft.assembly
from flexshaft.cli import app
from flexshaft.cli.analysis import _print_thermal
from flexshaft.design import tuned_design

runner = CliRunner()
# the modules (the package re-exports a function named like its module `stability`)
STABILITY = importlib.import_module("flexshaft.analyses.stability")
SUMMARY = importlib.import_module("flexshaft.analyses.summary")
OPERATING = 2.0 * math.pi * 80.0  # 4800 rev/min [rad/s]


@pytest.fixture
def stand_ins(monkeypatch: pytest.MonkeyPatch) -> dict:
    """The model and the analyses replaced; what the command passed them is recorded."""
    seen: dict = {}

    def modes_at(model, speed, n_modes):
        seen["speed"] = speed
        return [
            {
                "mode": 1,
                "frequency_Hz": 12.5,
                "frequency_rpm": 750.0,
                "damping_ratio": 0.01,
                "log_decrement": 0.0628,
                "kind": "bending",
                "whirl": "forward",
                "component": "shaft",
            }
        ]

    def stability(model, speeds, n_modes, damping_model, reference):
        seen.update(speeds=speeds, reference=reference, damping_model=damping_model)
        whirl = np.array([["backward"]] + [["forward"]] * (len(speeds) - 1), dtype=object)
        return SimpleNamespace(
            onset_speed=seen.get("onset"),
            unstable_mode=None if seen.get("onset") is None else 0,
            whirl=whirl,
            onset_whirl=None if seen.get("onset") is None else "forward",
            stability_margin=np.array([0.02, -0.01]),
        )

    monkeypatch.setattr(flexshaft.assembly, "build_model", lambda design: SimpleNamespace(speed=OPERATING))
    monkeypatch.setattr(SUMMARY, "modes_at", modes_at)
    monkeypatch.setattr(STABILITY, "stability", stability)
    return seen


def test_modes_converts_the_speed_both_ways(stand_ins: dict) -> None:
    result = runner.invoke(app, ["modes", "--speed-rpm", "600", "--n-modes", "1", "--json"])
    assert result.exit_code == 0, result.output
    assert stand_ins["speed"] == pytest.approx(20.0 * math.pi, rel=1e-14)  # 600 rev/min = 10 rev/s
    assert json.loads(result.stdout)["speed_rpm"] == pytest.approx(600.0, rel=1e-14)
    text = runner.invoke(app, ["modes", "--speed-rpm", "600", "--n-modes", "1"])
    assert text.exit_code == 0, text.output
    assert "modes at 600 rpm" in text.stdout


def test_stability_converts_speeds_and_reports_the_onset(stand_ins: dict) -> None:
    stand_ins["onset"] = 2.0 * math.pi * 90.0  # 5400 rev/min
    args = ["stability", "--max-rpm", "9600", "--n-speeds", "3", "--n-modes", "1"]
    args += ["--damping-model", "viscous", "--reference-hz", "50"]
    result = runner.invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.output
    assert stand_ins["speeds"][-1] == pytest.approx(2.0 * math.pi * 160.0, rel=1e-14)  # 9600 rev/min
    assert stand_ins["reference"] == pytest.approx(2.0 * math.pi * 50.0, rel=1e-14)  # 50 Hz
    data = json.loads(result.stdout)
    assert data["analysed_to_rpm"] == pytest.approx(9600.0, rel=1e-14)
    design = data["shafts"]["design"]
    assert design["onset_speed_rpm"] == pytest.approx(5400.0, rel=1e-14)
    assert design["unstable_mode_whirl"] == "forward"  # the onset whirl, not the label at rest
    text = runner.invoke(app, args)
    assert text.exit_code == 0, text.output
    row = next(line for line in text.stdout.splitlines() if line.startswith("│ design "))
    cells = [c.strip() for c in row.strip("│ ").split("│")]
    assert cells[1:4] == ["5400", "1.125", "forward"]  # onset, onset / operating, whirl
    assert "analysed to 9600 rpm" in text.stdout


def test_a_sweep_stable_beyond_the_requirement_passes(stand_ins: dict) -> None:
    margin = tuned_design().requirements.min_onset_margin
    assert (1.0 + margin) * 4800.0 < 9600.0  # the premise: the requirement lies inside the sweep
    result = runner.invoke(app, ["stability", "--max-rpm", "9600", "--n-speeds", "3", "--n-modes", "1", "--json"])
    assert result.exit_code == 0, result.output
    design = json.loads(result.stdout)["shafts"]["design"]
    assert design["onset_speed_rpm"] is None and design["onset_check"] == "pass"


def test_the_thermal_table_puts_each_number_under_its_header(capsys: pytest.CaptureFixture) -> None:
    shaft = {
        "air_c": 35.0,
        "h_W_m2K": 20.0,
        "heat_vibration_W": 1.5,
        "heat_static_W": 2.5,
        "peak_rise_K": 3.0,
        "peak_x_m": 0.75,
    }
    out = {
        "loss_model": "hysteretic",
        "shaft_hysteretic_loss_model": shaft,
        "max_shaft_temperature_c": 60.0,
        "max_shaft_temperature_source": "reference_properties",
        "allowable_temperature_c": 120.0,
        "temperature_margin_K": 60.0,
    }
    _print_thermal("heading", out)
    printed = capsys.readouterr().out
    lines = printed.splitlines()
    header = next(line for line in lines if "vibration heat [W]" in line)
    row = next(line for line in lines if "hysteretic (used)" in line)
    names = [c.strip() for c in re.split("[│┃]", header.strip("│┃ "))]
    cells = [c.strip() for c in re.split("[│┃]", row.strip("│┃ "))]
    assert dict(zip(names, cells)) == {
        "loss model": "hysteretic (used)",
        "air [°C]": "35",
        "h [W/(m² K)]": "20",
        "vibration heat [W]": "1.5",
        "static heat [W]": "2.5",
        "peak rise [K]": "3",
        "peak at x [m]": "0.75",
    }
    assert "max shaft temperature 60 °C (reference-temperature properties); allowable 120 °C" in printed

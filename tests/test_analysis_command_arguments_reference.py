"""What ``modes``, ``stability --compare-thesis``, ``thermal`` and ``check`` hand to the analyses.

The analyses are stand-ins that record what the command passed them (the pattern of
tests/test_cli_analysis_output_reference.py), so the references are the documented meanings of
the options, not numbers the code produced:

* ``flexshaft modes --speed-rpm 0`` gives the modes at rest (docs/requirements.md: "the tuned
  design's first boom mode, 4.94 Hz at rest (`flexshaft modes --speed-rpm 0` ...)"): the speed
  passed is 0 rev/min = 0 rad/s exactly (0 × 2π/60 = 0 has no rounding), not the operating speed
  4800 rev/min of the default;
* ``stability --compare-thesis`` adds "the thesis's aluminium, (45/-45)s and (45/-45/0/0)s
  shafts" (the option's help text, the CLI's code contract; README names the flag): each row's
  analysis runs on a model built from its own shaft (aluminium: material ``al6061_t6``; the FMC
  rows: their layup), and each row's onset speed is the one its own analysis found;
* ``thermal --self-heating`` iterates the self-heating equilibrium and ``--sweeps`` adds the wall
  and convection sweeps (docs/thermal.md's CLI line lists the flags; their meanings are the
  options' help texts, the CLI's code contract): each flag reaches its
  own argument of ``thermal_summary``, the other stays off;
* ``flexshaft check`` "reports all three lists [model guards, thermal guards, envelope points],
  so that a design it accepts runs" (docs/limits.md section 2): a schema-valid design the model
  guards refuse (the Jeffcott rotor of tests/rotors.py with a nearly massless, unsupported tube,
  a free member whose modal basis the preflight refuses, tests/test_api_guards.py) is a user
  error, exit 2 (README: "2 a user error (bad design file ...)"), with --json ``ok: false``.

No model is built or solved except the check's preflight of the 8-element Jeffcott rotor: about
0.3 s in all.
"""

from __future__ import annotations

import importlib
import json
import math
from types import SimpleNamespace

import numpy as np
import pytest
from rotors import jeffcott_text
from typer.testing import CliRunner

import flexshaft.assembly
from flexshaft.cli import app
from flexshaft.design import tuned_design

runner = CliRunner()
STABILITY = importlib.import_module("flexshaft.analyses.stability")
SUMMARY = importlib.import_module("flexshaft.analyses.summary")
THERMAL_STUDY = importlib.import_module("flexshaft.thermal.study")
OPERATING = 2.0 * math.pi * 80.0  # 4800 rev/min [rad/s]


def model_of(design) -> SimpleNamespace:
    """A stand-in model carrying the shaft it was built from."""
    shaft = design.shaft
    return SimpleNamespace(
        speed=OPERATING, material=shaft.material, layup=None if shaft.layup is None else str(shaft.layup)
    )


def test_modes_at_zero_rpm_are_the_modes_at_rest(monkeypatch: pytest.MonkeyPatch) -> None:
    seen: list[float] = []

    def modes_at(model, speed, n_modes):
        seen.append(speed)
        return []

    monkeypatch.setattr(flexshaft.assembly, "build_model", model_of)
    monkeypatch.setattr(SUMMARY, "modes_at", modes_at)
    result = runner.invoke(app, ["modes", "--speed-rpm", "0", "--n-modes", "1", "--json"])
    assert result.exit_code == 0, result.output
    assert seen == [0.0]  # at rest, not the operating speed 2π·80 rad/s
    assert json.loads(result.stdout)["speed_rpm"] == 0.0


def test_compare_thesis_analyses_each_shaft_on_its_own_model(monkeypatch: pytest.MonkeyPatch) -> None:
    design = tuned_design()
    own = (design.shaft.material, None if design.shaft.layup is None else str(design.shaft.layup))
    # an onset speed for each shaft [rev/s], so that each row can be traced to its analysis
    onset_rev_s = {
        own: 90.0,
        ("al6061_t6", None): 100.0,
        (design.shaft.material, "(45/-45)s"): 110.0,
        (design.shaft.material, "(45/-45/0/0)s"): 120.0,
    }
    assert len(onset_rev_s) == 4  # the premise: the design's shaft is none of the thesis shafts
    analysed: list[tuple] = []

    def stability(model, speeds, n_modes, damping_model, reference):
        key = (model.material, model.layup)
        analysed.append(key)
        return SimpleNamespace(
            onset_speed=2.0 * math.pi * onset_rev_s[key],
            onset_whirl="forward",
            stability_margin=np.array([0.01, -0.01]),
        )

    monkeypatch.setattr(flexshaft.assembly, "build_model", model_of)
    monkeypatch.setattr(STABILITY, "stability", stability)
    args = ["stability", "--compare-thesis", "--max-rpm", "9600", "--n-speeds", "3", "--n-modes", "1", "--json"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    assert sorted(analysed, key=str) == sorted(onset_rev_s, key=str)  # four shafts, four models
    shafts = json.loads(result.stdout)["shafts"]
    rows = {label: row["onset_speed_rpm"] for label, row in shafts.items()}
    assert rows["design"] == pytest.approx(5400.0, rel=1e-14)  # 90 rev/s
    aluminium = next(label for label in rows if "aluminium" in label)
    assert rows[aluminium] == pytest.approx(6000.0, rel=1e-14)
    assert rows[next(label for label in rows if "(45/-45)s" in label)] == pytest.approx(6600.0, rel=1e-14)
    assert rows[next(label for label in rows if "(45/-45/0/0)s" in label)] == pytest.approx(7200.0, rel=1e-14)


@pytest.mark.parametrize(("flag", "expected"), [("--self-heating", (True, False)), ("--sweeps", (False, True))])
def test_each_thermal_flag_reaches_its_own_computation(
    monkeypatch: pytest.MonkeyPatch, flag: str, expected: tuple[bool, bool]
) -> None:
    seen: dict = {}

    def thermal_summary(design, model, loss_model=None, convection=None, self_heat=False, sweeps=False):
        seen.update(self_heat=self_heat, sweeps=sweeps)
        return {"loss_model": "thesis"}

    monkeypatch.setattr(flexshaft.assembly, "build_model", model_of)
    monkeypatch.setattr(THERMAL_STUDY, "thermal_summary", thermal_summary)
    result = runner.invoke(app, ["thermal", flag, "--json"])
    assert result.exit_code == 0, result.output
    assert (seen["self_heat"], seen["sweeps"]) == expected


def free_massless_jeffcott_text() -> str:
    """tests/rotors.py's Jeffcott rotor with a nearly massless tube (1e-6 kg/m³) and no supports
    (as tests/test_api_guards.py builds it): schema-valid, refused by the model guards."""
    return (
        jeffcott_text(0.0, 0.0)
        .replace("density = 0.1", "density = 1e-6")
        .replace('fixed_start = ["u", "v", "w", "theta"]', "")
        .replace('fixed_end = ["v", "w"]', "")
    )


def test_check_refuses_what_the_analyses_refuse(tmp_path) -> None:
    path = tmp_path / "free_massless.toml"
    path.write_text(free_massless_jeffcott_text())
    result = runner.invoke(app, ["check", str(path), "--json"])
    assert result.exit_code == 2, result.output
    data = json.loads(result.stdout)
    assert data["ok"] is False
    text = runner.invoke(app, ["check", str(path)])
    assert text.exit_code == 2 and "ok:" not in text.stdout

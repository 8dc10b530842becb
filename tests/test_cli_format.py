"""What the CLI prints (issue 10, CLI part): units in help texts and headers, choices as enums,
significant figures, JSON with unit-suffixed keys, ``--version``, per-stage progress.

The references here are the stated conventions themselves (a unit in every help text and
header, ``sig`` rounding rules, key suffixes); the numbers printed are checked against the
same numbers in the JSON output or against the unit conversions of :mod:`flexshaft.units`.
"""

from __future__ import annotations

import io
import json
import re
import typing
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flexshaft import __version__
from flexshaft.cli import app
from flexshaft.cli.options import Convection, DampingModel, LossModel, Resolution
from flexshaft.cli.tables import dataset_json, dataset_table, sig, stdout_console
from flexshaft.design import baseline_text

runner = CliRunner()

SMALL = (
    baseline_text()
    .replace("shaft_elements = 36", "shaft_elements = 8", 1)
    .replace("boom_elements = 24", "boom_elements = 4", 1)
)


@pytest.fixture(scope="module")
def small(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("format") / "small.toml"
    path.write_text(SMALL, encoding="utf-8")
    return path


def _help(*command: str) -> str:
    result = runner.invoke(app, [*command, "--help"])
    assert result.exit_code == 0, result.output
    return " ".join(result.stdout.split())


# ------------------------------------------------------------------------------------------------
# help texts, choices, version


@pytest.mark.parametrize(
    ("command", "texts"),
    [
        (["modes"], ["--speed-rpm", "Spin speed [rpm]", "--n-modes", "numbered from 1", "counts from 0"]),
        (["stability"], ["Highest speed analysed [rpm]", "model [Hz]", "<hysteretic|viscous>"]),
        (["thermal"], ["<thesis|rotating>", "<becker|kendoush>"]),
        (["run"], ["<report|full|none>", "--force", "--strict", "Exit with code 3"]),
        (["study", "ply-angle"], ["Angle step [deg]", "--jobs", "--dask", "--json", "--force"]),
        (["study", "all"], ["Actuator gap limiting the tuned gains [m]", "<report|full>"]),
        (["study", "spinup-map"], ["K_p [N/m]", "K_d [N s/m]"]),
    ],
)
def test_help_texts_show_units_and_choices(command: list[str], texts: list[str]) -> None:
    shown = _help(*command)
    for text in texts:
        assert text in shown, f"{text!r} missing from `flexshaft {' '.join(command)} --help`"


def _commands(typer_app, prefix=()):
    import typer.main

    group = typer.main.get_command(typer_app)
    stack = [(list(prefix), group)]
    while stack:
        path, command = stack.pop()
        sub = getattr(command, "commands", None)
        if sub:
            stack += [([*path, name], c) for name, c in sub.items()]
        else:
            yield path, command


def test_no_bracketed_unit_is_swallowed_by_markup() -> None:
    """Every "[...]" written in an option's help appears verbatim in --help (rich markup used
    to eat "[rpm]")."""
    checked = 0
    for path, command in _commands(app):
        shown = _help(*path)
        for param in command.params:
            for unit in re.findall(r"\[[^\]]+\]", getattr(param, "help", None) or ""):
                assert unit in shown, f"{unit} of {param.name} missing from `flexshaft {' '.join(path)} --help`"
                checked += 1
    assert checked >= 10


def test_version() -> None:
    result = runner.invoke(app, ["--version"])
    assert (result.exit_code, result.stdout) == (0, f"flexshaft {__version__}\n")


def test_choices_are_the_literals_of_the_layers_below() -> None:
    from flexshaft.analyses.stability import DampingModel as DampingLiteral
    from flexshaft.design.schema import InternalDamping
    from flexshaft.design.thermal_schema import ShaftConvection
    from flexshaft.thesis.design_studies import STUDY_GRIDS as RESOLUTIONS

    assert {m.value for m in DampingModel} == set(typing.get_args(DampingLiteral))
    assert {m.value for m in LossModel} == set(typing.get_args(InternalDamping))
    assert {m.value for m in Convection} == set(typing.get_args(ShaftConvection))
    assert {m.value for m in Resolution} == set(RESOLUTIONS)


def test_choices_are_case_insensitive(small: Path) -> None:
    result = runner.invoke(app, ["stability", str(small), "--damping-model", "Viscous", "--n-speeds", "5", "--json"])
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["damping_model"] == "viscous"
    thermal = runner.invoke(app, ["thermal", str(small), "--loss-model", "THESIS", "--convection", "Becker", "--json"])
    assert thermal.exit_code == 0, thermal.output
    assert json.loads(thermal.stdout)["loss_model"] == "thesis"
    bad = runner.invoke(app, ["stability", str(small), "--damping-model", "magic"])
    assert bad.exit_code == 2 and "'magic' is not one of 'hysteretic', 'viscous'" in " ".join(bad.stderr.split())


# ------------------------------------------------------------------------------------------------
# numbers for people


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (4e-7, "4e-07"),
        (3.1e-6, "3.1e-06"),
        (-0.00145, "-0.00145"),
        (0.0099841, "0.009984"),
        (0.5, "0.5"),
        (55.3214, "55.32"),
        (4800.0, "4800"),
        (4799.6, "4800"),
        (123456.7, "123457"),
        (1.2345e7, "1.234e+07"),
        (0.0, "0"),
        (-0.0, "0"),
        (None, "—"),
        (float("inf"), "inf"),
        (float("nan"), "nan"),
        (9.99996, "10"),
    ],
)
def test_sig_gives_significant_figures(value, text) -> None:
    assert sig(value) == text


def test_modes_table_has_unit_headers_and_numbers_from_one(small: Path) -> None:
    result = runner.invoke(app, ["modes", str(small), "--n-modes", "6"])
    assert result.exit_code == 0, result.output
    for header in (
        "f [Hz]",
        "f [rpm]",
        "ζ [-]",
        "δ [-]",
        "f damped frequency, ζ damping ratio, δ log decrement",
        "mode numbers start at 1",
    ):
        assert header in result.stdout
    rows = [line for line in result.stdout.splitlines() if re.match(r"│\s+\d+ │", line)]
    assert [int(r.split("│")[1]) for r in rows] == [1, 2, 3, 4, 5, 6]
    data = json.loads(runner.invoke(app, ["modes", str(small), "--n-modes", "6", "--json"]).stdout)
    first = rows[0].split("│")
    assert first[2].strip() == sig(data["modes"][0]["frequency_Hz"])  # the table shows the JSON's numbers
    assert first[3].strip() == sig(data["modes"][0]["frequency_rpm"])


def test_thermal_prints_tables_not_dicts(small: Path) -> None:
    result = runner.invoke(app, ["thermal", str(small), "--sweeps"])
    assert result.exit_code == 0, result.output
    text = result.stdout
    for header in ("temperature [°C]", "air [°C]", "h [W/(m² K)]", "peak rise [K]", "by wall thickness"):
        assert header in text
    assert "{" not in text and "': " not in text  # no raw Python dicts
    assert not re.search(r"\d\.\d{7,}", text), "a float printed with more than 7 decimals"
    data = json.loads(runner.invoke(app, ["thermal", str(small), "--json"]).stdout)
    assert f"max shaft temperature {sig(data['max_shaft_temperature_c'])} °C" in text


def test_json_is_strict(small: Path) -> None:
    def refuse(constant):
        raise AssertionError(f"non-standard JSON constant {constant}")

    for args in (
        ["modes", str(small), "--n-modes", "3", "--json"],
        ["check", str(small), "--json"],
        ["stability", str(small), "--n-speeds", "5", "--json"],
        ["baseline", "--json"],
    ):
        result = runner.invoke(app, args)
        assert result.exit_code == 0, result.output
        json.loads(result.stdout, parse_constant=refuse)


# ------------------------------------------------------------------------------------------------
# study tables in engineering units, JSON in SI


def _wall_dataset():
    import numpy as np
    import xarray as xr

    walls = np.array([0.0015, 0.003])
    return xr.Dataset(
        {
            "safety_factor": ("wall_thickness", [2.5, 4.0], {"units": "1"}),
            "spinup_peak_deflection": ("wall_thickness", [1.2e-3, 4.0e-4], {"units": "m"}),
            "sigma1": ("wall_thickness", [25.9e6, 12.0e6], {"units": "Pa"}),
            "natural_frequency_1": ("wall_thickness", [50.5, 55.3], {"units": "Hz"}),
        },
        coords={"wall_thickness": ("wall_thickness", walls, {"units": "m"})},
    )


def test_study_tables_use_mm_and_mpa_with_unit_headers() -> None:
    ds = _wall_dataset()
    console = stdout_console()
    with console.capture() as captured:
        console.print(
            dataset_table(ds, ["safety_factor", "spinup_peak_deflection", "sigma1", "natural_frequency_1"], "t")
        )
    text = captured.get()
    for header in (
        "wall_thickness [mm]",
        "safety_factor",
        "spinup_peak_deflection [mm]",
        "sigma1 [MPa]",
        "natural_frequency_1 [Hz]",
    ):
        assert header in text
    assert re.search(r"│\s+1\.5 │\s+2\.5 │\s+1\.2 │\s+25\.9 │\s+50\.5 │", text), text  # 1.5 mm, 1.2 mm, 25.9 MPa


def test_study_json_is_si_with_unit_suffixed_keys() -> None:
    data = dataset_json(_wall_dataset())
    assert data["coords"] == {"wall_thickness_m": [0.0015, 0.003]}
    assert set(data["variables"]) == {
        "safety_factor",
        "spinup_peak_deflection_m",
        "sigma1_Pa",
        "natural_frequency_1_Hz",
    }
    assert data["variables"]["sigma1_Pa"] == [25.9e6, 12.0e6]
    assert data["dims"]["sigma1_Pa"] == ["wall_thickness_m"]


def test_a_study_command_prints_units_and_json(tmp_path: Path, small: Path) -> None:
    out = tmp_path / "ply"
    human = runner.invoke(app, ["study", "ply-angle", str(small), "--step", "30", "--out", str(out)])
    assert human.exit_code == 0, human.output
    assert "alpha [deg]" in human.stdout and "sigma1 [MPa]" in human.stdout and "best α = ±" in human.stdout
    data = json.loads(
        runner.invoke(app, ["study", "ply-angle", str(small), "--step", "30", "--out", str(out), "--json"]).stdout
    )
    assert data["coords"]["alpha_deg"] == [30.0, 60.0]
    assert {"safety_factor", "sigma1_Pa", "critical_x_m"} <= set(data["variables"])
    assert Path(data["figures"]["ply_angle"]["png"]).is_file() and Path(data["results_file"]).is_file()


# ------------------------------------------------------------------------------------------------
# progress


def test_stage_progress_shows_stages_sub_steps_and_times() -> None:
    from rich.console import Console

    from flexshaft.cli.progress import StageProgress

    buffer = io.StringIO()
    console = Console(file=buffer, force_terminal=True, width=100, color_system=None)
    with StageProgress(console=console) as progress:
        progress.step("natural frequencies")
        progress.step("design studies (thesis chapter 3)")
        progress.step("design studies: study 1: ply angle")
        progress.step("design studies: study 2: [bold]two-angle map")
        progress.step("requirements verdict")
    text = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", buffer.getvalue())
    for label in (
        "natural frequencies",
        "design studies (thesis chapter 3)",
        "  · study 1: ply angle",
        "  · study 2: [bold]two-angle map",
        "requirements verdict",
    ):
        assert label in text
    assert re.search(r"✓ requirements verdict\s+\d+\.\d s", text), text
    assert list(progress.timings) == [
        "natural frequencies",
        "design studies (thesis chapter 3)",
        "requirements verdict",
    ]
    assert list(progress.sub_timings["design studies (thesis chapter 3)"]) == [
        "study 1: ply angle",
        "study 2: [bold]two-angle map",
    ]


def test_stage_progress_draws_nothing_off_a_terminal() -> None:
    from rich.console import Console

    from flexshaft.cli.progress import StageProgress

    buffer = io.StringIO()
    with StageProgress(console=Console(file=buffer, force_terminal=False)) as progress:
        progress.step("natural frequencies")
    assert buffer.getvalue() == "" and list(progress.timings) == ["natural frequencies"]


def test_verdict_table_shows_a_checks_note_where_it_has_no_location() -> None:
    """A check evaluated without a location (a whirl onset beyond the speeds analysed) prints
    its note in the "where" column instead of an empty cell; a located check prints its place,
    an unevaluated one its reason."""
    from flexshaft.cli.tables import verdict_table
    from flexshaft.verdict.result import Check, Verdict

    checks = (
        Check(
            "whirl_onset",
            "whirl onset speed",
            "speed",
            "at least",
            "pass",
            754.0,
            578.0,
            176.0,
            note="no onset up to the highest speed analysed",
            lower_bound=True,
        ),
        Check(
            "shaft_temperature",
            "shaft temperature",
            "temperature",
            "at most",
            "pass",
            317.0,
            373.0,
            56.0,
            location={"station": 3.21},
            note="a remark",
        ),
        Check(
            "actuator_force", "actuator force", "force", "at most", "not evaluated", note="the design has no actuator"
        ),
    )
    console = stdout_console()
    with console.capture() as captured:
        console.print(verdict_table(Verdict(checks)))
    lines = {
        line.split("│")[1].strip(): line.split("│")[-2].strip()
        for line in captured.get().splitlines()
        if line.count("│") >= 7
    }
    assert lines["whirl onset speed"] == "no onset up to the highest speed analysed"
    assert lines["shaft temperature"].startswith("x = 3.21")
    assert lines["actuator force"] == "the design has no actuator"

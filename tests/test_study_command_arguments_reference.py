"""``flexshaft study ...``: the arguments it refuses and why, the folder it writes, the file its
``--json`` names.

References (rules written in the product's hand-written text, quoted in each test):

* docs/limits.md, section 7: "Each command at its documented maximum ... | `study ply-angle
  --step 0.5` | runs (179 points) |" and "Every option's range in `--help` runs at the
  command's other defaults": a step below 0.5 deg is outside the range (exit 2, click's usage
  error, before the command body runs).
* src/flexshaft/cli/study.py, ``_check_spinup_map``: "A spin-up map needs active bearings (their
  gains are its axes) and an operating speed (its spin-up ends there)"; ``_check_laminated``:
  "The ply-angle studies vary the layup of a laminated shaft, the buckling study its wall in
  the laminated-shell model (one laminated tube): refused before the output folder is made".
* src/flexshaft/cli/study.py, module docstring: "Every command writes its ``--out`` folder
  (default ``flexshaft-study-NAME``): ``results.nc`` ..." and "The JSON's ``results_file`` is
  the path of the folder's ``results.nc`` when the sweep wrote it, null otherwise."

No sweep runs: each command's work is replaced by a recorder (or refused before it), so each
test costs the CLI's parsing and the design's loading only.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from test_study_commands_reference import _walls, no_files  # noqa: F401  (no_files: a fixture)
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.design import baseline_design, with_overrides
from flexshaft.optimize.files import write_design_file


class _Reached(Exception):
    """Raised by a recorder standing in for a study's work: the command got past its checks."""


def _stop(*args, **kwargs):
    """Stands in for a study's work: records nothing, stops the command (:class:`_Reached`)."""
    raise _Reached


def test_ply_angle_refuses_a_step_below_half_a_degree(monkeypatch, tmp_path: Path):
    """--step 0.4 is below the range whose end, 0.5 deg, docs/limits.md documents (179 points):
    a usage error (exit 2) naming the option, before the command prepares anything."""
    reached = []
    monkeypatch.setattr("flexshaft.cli.study._prepare", lambda *a, **k: reached.append(a) or _stop())
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["study", "ply-angle", "--step", "0.4", "-o", str(out)])
    assert result.exit_code == 2, result.output
    assert "--step" in result.output and not reached and not out.exists()


def test_spinup_map_refuses_a_design_at_rest_before_its_folder(monkeypatch, tmp_path: Path):
    """The embedded design at operating speed 0 (power 0, so the design is valid) has active
    bearings but no spin-up to map: refused (exit 2) for its speed, no folder made, no map."""
    design = with_overrides(baseline_design(), {"operating.speed_rpm": 0.0, "operating.power": 0.0})
    path = write_design_file(design, tmp_path / "at_rest.toml")
    monkeypatch.setattr("flexshaft.thesis.spinup_maps.spinup_gain_map", _stop)
    out = tmp_path / "out"
    args = ["study", "spinup-map", str(path), "--n-gains", "2", "--n-speeds", "10", "-o", str(out)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2, result.output
    assert "operating speed is 0" in result.output and not out.exists()


@pytest.mark.parametrize(
    ("study", "varied"),
    [
        ("ply-angle", "the study varies its ply angles"),
        ("two-angle", "the study varies its ply angles"),
        ("buckling", "the study varies the wall of the laminated-shell buckling model"),
    ],
)
def test_laminated_studies_refuse_a_metal_shaft_naming_its_material(tmp_path: Path, study, varied):
    """The embedded design with its shaft of al6061_t6 (an isotropic material of the design's
    own table; not segmented): refused before the folder, the reason the material and its kind
    (not "segmented"), and what the study varies: the ply angles, or for buckling the wall."""
    design = with_overrides(baseline_design(), {"shaft.material": "al6061_t6", "shaft.layup": None})
    assert design.materials["al6061_t6"].kind == "isotropic" and not design.segmented
    path = write_design_file(design, tmp_path / "metal.toml")
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["study", study, str(path), "-o", str(out)])
    assert result.exit_code == 2, result.output
    text = " ".join(result.output.split())  # the console wraps long lines
    assert "its material 'al6061_t6' is isotropic" in text, text
    assert "segmented" not in text and varied in text and not out.exists()


def test_default_folder_is_flexshaft_study_name(monkeypatch, tmp_path: Path):
    """Without --out, on the embedded design, the study writes flexshaft-study-ply-angle in the
    working directory (module docstring); the sweep is stopped once the folder is made."""
    folders = []

    def sweep(func, loaded, folder, *a, **k):
        folders.append(folder)
        raise _Reached

    monkeypatch.setattr("flexshaft.cli.study._sweep", sweep)
    monkeypatch.chdir(tmp_path)
    CliRunner().invoke(app, ["study", "ply-angle", "--step", "45"])
    assert folders == [Path("flexshaft-study-ply-angle")]
    assert (tmp_path / "flexshaft-study-ply-angle").is_dir()


@pytest.mark.parametrize("written", [True, False])
def test_json_names_the_results_file_only_when_written(monkeypatch, tmp_path: Path, no_files, written):  # noqa: F811
    """--json's results_file: the path of OUT/results.nc when the sweep wrote it, null when it
    did not (cli/study.py's module docstring: "The JSON's ``results_file`` is the path of the
    folder's ``results.nc`` when the sweep wrote it, null otherwise.")."""
    ds = _walls(
        [2.0e-3, 3.0e-3],
        safety_factor=[1.2, 2.5],
        safety_factor_no_imbalance=[1.3, 2.6],
        natural_frequency_1=[50.0, 60.0],
        spinup_peak_deflection=[1e-4, 2e-4],
    )

    def study(run_dir, **kw):
        if written:
            (Path(run_dir) / "results.nc").write_bytes(b"")
        return ds

    monkeypatch.setattr("flexshaft.thesis.wall.wall_thickness_study", study)
    monkeypatch.setattr("flexshaft.plot.studies.wall_thickness_figure", lambda *a: None)
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["study", "wall", "--json", "-o", str(out)])
    assert result.exit_code == 0, result.output
    expected = str(out / "results.nc") if written else None
    assert json.loads(result.stdout)["results_file"] == expected

"""The CLI's error boundary and plain-text printing (issue 12.1).

* Every command (study sub-commands included) is wrapped by one boundary: a user error ends
  with ``error: …`` and exit 2, an internal fault with exit 4, a report hint and no traceback
  unless ``flexshaft --debug``.
* User strings are printed as plain text: rich markup in a design or component name is shown
  literally (it crashed ``modes`` and ``run`` before), terminal escape sequences are escaped
  (``check`` echoed them raw).
* A design path that is not a regular file (a FIFO blocked forever, ``/dev/zero`` read until
  MemoryError) or is too large is refused before it is opened. These run in a subprocess with a
  timeout, so a regression fails instead of hanging the suite.

Designs are the baseline with a coarse mesh (8 shaft, 4 boom elements): a ``modes`` call takes
well under a second.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.cli.common import MAX_DESIGN_BYTES, is_guarded, plain
from flexshaft.design import baseline_design, baseline_text

runner = CliRunner()

SMALL = (
    baseline_text()
    .replace("shaft_elements = 36", "shaft_elements = 8", 1)
    .replace("boom_elements = 24", "boom_elements = 4", 1)
)
BASELINE_NAME = baseline_design().name


def _named(name_toml: str, bearing: str | None = None) -> str:
    """The small design with its ``name`` (a TOML string literal) and optionally amb_1 renamed."""
    assert f'name = "{BASELINE_NAME}"' in SMALL
    text = SMALL.replace(f'name = "{BASELINE_NAME}"', f"name = {name_toml}", 1)
    if bearing is not None:
        assert 'name = "amb_1"' in text
        text = text.replace('name = "amb_1"', f"name = {bearing}", 1)
    return text


def _write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _cli(*args: str, timeout: float = 120.0) -> subprocess.CompletedProcess:
    """The CLI in a fresh interpreter (for inputs that could hang or exhaust memory in-process)."""
    code = "import sys; from flexshaft.cli import app; sys.argv[0] = 'flexshaft'; app()"
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, timeout=timeout)


# ------------------------------------------------------------------------------------------------
# one boundary for every command


def _commands(typer_app, prefix=()):
    for info in typer_app.registered_commands:
        yield " ".join((*prefix, info.name or info.callback.__name__)), info.callback
    for group in typer_app.registered_groups:
        yield from _commands(group.typer_instance, (*prefix, group.name))


def test_every_command_is_wrapped_by_the_error_boundary() -> None:
    commands = dict(_commands(app))
    assert {"run", "check", "modes", "stability", "thermal", "baseline", "study wall", "study all"} <= set(commands)
    assert [name for name, callback in commands.items() if not is_guarded(callback)] == []


def test_an_internal_fault_exits_4_with_a_hint_and_no_traceback(tmp_path: Path, monkeypatch) -> None:
    import flexshaft.analyses.summary as summary

    def broken(*args, **kwargs):
        raise ZeroDivisionError("simulated fault in the modal analysis")

    monkeypatch.setattr(summary, "modes_at", broken)
    design = _write(tmp_path, "small.toml", SMALL)
    result = runner.invoke(app, ["modes", str(design)])
    assert result.exit_code == 4, result.output
    assert "internal error: ZeroDivisionError: simulated fault in the modal analysis" in result.stderr
    assert "Please report it" in result.stderr and "--debug" in result.stderr
    assert "Traceback" not in result.output and result.stdout == ""

    debug = runner.invoke(app, ["--debug", "modes", str(design)])
    assert debug.exit_code == 4
    assert "Traceback (most recent call last)" in debug.stderr
    assert "in broken" in debug.stderr and "internal error: ZeroDivisionError" in debug.stderr


def test_a_study_command_has_the_same_boundary(tmp_path: Path, monkeypatch) -> None:
    import flexshaft.thesis.ply_angle as sweeps

    def broken(*args, **kwargs):
        raise RuntimeError("simulated fault in a sweep")

    monkeypatch.setattr(sweeps, "ply_angle_study", broken)
    design = _write(tmp_path, "small.toml", SMALL)
    fault = runner.invoke(app, ["study", "ply-angle", str(design), "--out", str(tmp_path / "out")])
    assert fault.exit_code == 4 and "internal error: RuntimeError: simulated fault in a sweep" in fault.stderr
    assert "Traceback" not in fault.output
    missing = runner.invoke(app, ["study", "wall", str(tmp_path / "missing.toml"), "--out", str(tmp_path / "o2")])
    assert missing.exit_code == 2 and "no such design file" in missing.stderr and "Traceback" not in missing.output


def test_user_errors_exit_2_and_debug_adds_the_traceback(tmp_path: Path) -> None:
    bad = _write(tmp_path, "bad.toml", SMALL.replace("wall_thickness = 0.003 ", "wall_thickness = -0.003 ", 1))
    result = runner.invoke(app, ["modes", str(bad)])
    assert result.exit_code == 2
    assert result.stderr.startswith(f"error: invalid design {bad}:\nshaft.wall_thickness: must be > 0 (got -0.003)")
    assert "Traceback" not in result.output
    debug = runner.invoke(app, ["--debug", "modes", str(bad)])
    assert debug.exit_code == 2 and "Traceback" in debug.stderr
    listed = runner.invoke(app, ["check", str(bad), "--json"])  # machine-readable problems, still exit 2
    assert listed.exit_code == 2
    assert json.loads(listed.stdout) == {
        "ok": False,
        "source": str(bad),
        "problems": [
            {
                "path": "shaft.wall_thickness",
                "message": "must be > 0 (got -0.003); allowed: [1e-05, 1] m (see docs/limits.md)",
            }
        ],
    }


# ------------------------------------------------------------------------------------------------
# user strings as plain text


def test_rich_markup_in_names_is_printed_literally(tmp_path: Path) -> None:
    design = _write(tmp_path, "markup.toml", _named('"[/bold] x [red]y"', bearing='"[bold]amb[/]"'))
    check = runner.invoke(app, ["check", str(design)])
    assert (check.exit_code, check.stdout) == (0, f"ok: [/bold] x [red]y ({design})\n")
    modes = runner.invoke(app, ["modes", str(design), "--n-modes", "3"])
    assert modes.exit_code == 0, modes.output
    assert modes.stdout.splitlines()[0] == f"design: [/bold] x [red]y ({design})"
    data = json.loads(runner.invoke(app, ["modes", str(design), "--n-modes", "3", "--json"]).stdout)
    assert data["design"] == "[/bold] x [red]y"


ESCAPES = r'"\u001b[31mRED\u001b[0m \u001b]0;owned\u0007 \u202eevil"'


def test_terminal_escape_sequences_in_a_name_are_escaped(tmp_path: Path) -> None:
    design = _write(tmp_path, "escapes.toml", _named(ESCAPES))
    for args in (["check", str(design)], ["modes", str(design), "--n-modes", "2"]):
        result = runner.invoke(app, args)
        assert result.exit_code == 0, result.output
        assert "\x1b" not in result.output and "\x07" not in result.output and "\u202e" not in result.output
        assert r"\x1b[31mRED\x1b[0m \x1b]0;owned\x07 \u202eevil" in result.stdout
    data = json.loads(runner.invoke(app, ["check", str(design), "--json"]).stdout)  # JSON keeps the exact name
    assert data["design"] == "\x1b[31mRED\x1b[0m \x1b]0;owned\x07 \u202eevil"


def test_plain_escapes_control_characters_and_keeps_the_rest() -> None:
    assert plain("a\x1b[0mb\tc\x9b\u2028d") == r"a\x1b[0mb\tc\x9b\u2028d"
    assert plain("[bold]x[/] ±55° α") == "[bold]x[/] ±55° α"
    assert plain("line 1\nline\x1b 2", keep_newlines=True) == "line 1\nline\\x1b 2"


def test_a_path_with_escape_sequences_is_escaped_in_the_error(tmp_path: Path) -> None:
    result = runner.invoke(app, ["check", str(tmp_path / "evil\x1b[2J.toml")])
    assert result.exit_code == 2
    assert "\x1b" not in result.stderr and r"evil\x1b[2J.toml: no such design file" in result.stderr


# ------------------------------------------------------------------------------------------------
# design paths that are not regular files


def test_a_fifo_as_design_path_fails_fast(tmp_path: Path) -> None:
    fifo = tmp_path / "design.fifo"
    os.mkfifo(fifo)
    result = _cli("check", str(fifo), timeout=60)  # opening it would block forever
    assert result.returncode == 2, result.stderr
    assert "is a named pipe (FIFO), not a regular design file" in result.stderr
    assert "Traceback" not in result.stderr


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="no /dev/zero")
def test_dev_zero_as_design_path_fails_fast() -> None:
    result = _cli("modes", "/dev/zero", timeout=60)  # reading it would exhaust memory
    assert result.returncode == 2, result.stderr
    assert "/dev/zero: is a character device, not a regular design file" in result.stderr


def test_an_oversized_design_file_is_refused_before_reading(tmp_path: Path) -> None:
    big = tmp_path / "big.toml"
    with open(big, "wb") as file:  # sparse: no disk space used
        file.truncate(MAX_DESIGN_BYTES + 1)
    result = runner.invoke(app, ["check", str(big)])
    assert result.exit_code == 2
    assert f"{MAX_DESIGN_BYTES + 1} bytes; a design file may have at most {MAX_DESIGN_BYTES} bytes" in result.stderr


def test_ply_studies_of_a_metal_shaft_are_not_internal_errors(tmp_path: Path) -> None:
    """Was: `study gain` and `study buckling` on an aluminium shaft ended in 'internal error'
    (ply strength / laminated-shell buckling asked of an isotropic tube). Now the gain study
    reports the safety factor as not evaluated and the buckling study refuses the design (exit 2)."""
    text = "\n".join(line for line in baseline_text().splitlines() if not line.startswith("layup"))
    text = text.replace('material = "t700_adiprene"', 'material = "al6061_t6"', 1)
    text = text.replace("shaft_elements = 36", "shaft_elements = 12", 1).replace(
        "boom_elements = 24", "boom_elements = 8", 1
    )
    metal = _write(tmp_path, "metal.toml", text)
    gain = runner.invoke(app, ["study", "gain", str(metal), "--out", str(tmp_path / "g")])
    assert gain.exit_code == 0, gain.output
    assert "safety factor not evaluated (the shaft is not a lamina)" in gain.output
    buckling = runner.invoke(app, ["study", "buckling", str(metal), "--out", str(tmp_path / "b")])
    assert buckling.exit_code == 2 and "is not one laminated tube" in buckling.stderr
    assert "internal error" not in gain.output + buckling.output

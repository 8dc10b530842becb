"""The base design file's comments in an optimized design file: each kept once, as written, at
the key or table it annotates; and an integer ``--var`` with a fractional bound refused.

References (hand-written docs and the modules' docstrings, quoted):

* docs/optimizer.md, "What the command shows": the design files "keep the base design file's
  comments: its header after the optimizer's own, and every note at the key or table it
  annotates ... Comments of keys the file does not write are listed at its end." So a note of
  a key the file writes appears once, at that key, not again in the closing list; and a note is
  kept as written (its own indentation after ``# `` included).
* :mod:`flexshaft.optimize.toml_comments`' docstring: "comment lines that stand alone belong to
  the next key or table header (``before``: a section's explanation goes with the table it
  precedes); the comment lines before the file's first blank line, when no key came yet, are
  its ``preamble``". A note between blank lines after the first key is therefore not the
  preamble, but the next table's.
* :class:`flexshaft.optimize.variables.DesignVariable`: ``integer`` -- "Round to integers
  (bounds must be integers)"; the command reads ``PATH=LOWER:UPPER:int`` into one, so
  ``layup.n=1:3.5:int`` is refused, not searched over 1..3.

* docs/optimizer.md, ``--json``: "SI values, the unit in each key: `driveline_mass_kg`,
  `kp_N_per_m`"; a dimensionless output (unit ``1``) has no unit to add.

The texts are written here; every expected line is read off them by hand. No analysis: the
four text tests take a few ms of CPU each; the ``--json`` one, through the public command with
the search replaced by a stand-in, about 1.1 s of CPU alone (measured), mostly the command's
first imports and xarray's first Dataset.
"""

from __future__ import annotations

import importlib
import json

import pytest

from flexshaft.cli import app
from flexshaft.design import loads_design, with_overrides
from flexshaft.optimize.files import design_toml
from flexshaft.optimize.toml_comments import read_comments
from flexshaft.optimize.variables import OptimizeError
from tests.test_toml_comments_reference import SMALL

CLOSING = "# Comments of the base design file on keys not written here:"

# SMALL (tests/test_toml_comments_reference.py) with no preamble: its first line is a key. A
# section note between blank lines, then an indented list under the shaft's note.
BASE = SMALL.replace(
    "[materials.steel]\n", "\n# SECTION NOTE: the materials of the rotor\n\n[materials.steel]\n", 1
).replace(
    "[shaft]\n",
    "[shaft]\n# SHAFT NOTE sources:\n#   - item one, indented two spaces after '# '\n#     (its continuation)\n",
    1,
)


def _written() -> str:
    base = loads_design(BASE)
    return design_toml(with_overrides(base, {"bearings[1].kp": 3e6}), base=base, base_text=BASE)


def test_an_indented_note_is_written_as_in_the_base_file():
    """``#   - item one ...``: the text after ``# `` keeps its two leading spaces, read and
    written back; so the written file holds the three lines as the base file has them."""
    keys = read_comments(BASE).keys
    before = keys[("shaft", "x_start")].before
    assert before == ["SHAFT NOTE sources:", "  - item one, indented two spaces after '# '", "    (its continuation)"]
    lines = _written().splitlines()
    at = lines.index("# SHAFT NOTE sources:")
    assert lines[at + 1 : at + 3] == ["#   - item one, indented two spaces after '# '", "#     (its continuation)"]


def test_a_note_of_a_written_key_appears_once_and_not_in_the_closing_list():
    """Every key of BASE is written (the file has every field), so each of its notes appears
    exactly once, and the closing list holds only the line after the last key (``trailing``)."""
    text = _written()
    for note in ("LEFT NOTE", "AMB NOTE", "RIGHT NOTE", "SHAFT NOTE", "SECTION NOTE"):
        assert text.count(note) == 1, note
    lines = text.splitlines()
    assert lines.count(CLOSING) == 1
    assert lines[lines.index(CLOSING) + 1 :] == ["# END NOTE after the last key"]


def test_a_section_note_after_the_first_key_goes_with_the_next_table():
    """No comment precedes the first key ``name``: no preamble. The note standing between blank
    lines after it belongs to ``[materials.steel]`` (``before``), and the written file has no
    base-header block but the note right above that table's header."""
    comments = read_comments(BASE)
    assert comments.preamble == []
    assert comments.keys[("materials", "steel")].before == ["SECTION NOTE: the materials of the rotor"]
    lines = _written().splitlines()
    assert not any("base design file's header" in line for line in lines)
    at = lines.index("# SECTION NOTE: the materials of the rotor")
    assert lines[at + 1] == "[materials.steel]"


def test_an_integer_variable_with_a_fractional_bound_is_refused():
    """``layup.n=1:3.5:int``: 3.5 is not an integer bound (refused); ``1:3:int`` is read."""
    command = importlib.import_module("flexshaft.cli.optimize")
    with pytest.raises(OptimizeError, match="integer bounds"):
        command.parse_variable("layup.n=1:3.5:int")
    with pytest.raises(OptimizeError, match="integer bounds"):
        command.parse_variable("layup.n=1.5:3:int")
    plies = command.parse_variable("layup.n=1:3:int")
    assert (plies.lower, plies.upper, plies.integer) == (1, 3, True)


def test_json_keys_carry_a_unit_only_where_there_is_one(monkeypatch, tmp_path):
    """docs/optimizer.md: ``--json`` gives "SI values, the unit in each key: `driveline_mass_kg`,
    `kp_N_per_m`". Through the public command on SMALL as rotor.toml: the driveline mass (kg)
    is keyed ``driveline_mass_kg``, the smallest margin (a fraction, unit ``1``: no unit) is
    keyed ``min_margin`` alone. The search is replaced by a stand-in (the sibling's
    ``_Result``, no Pareto design) that keeps the real problem the command builds and hands
    back one base reference; its values are passed through (exact)."""
    import xarray as xr

    import flexshaft.optimize.nsga as nsga
    import flexshaft.plot.driveline as driveline
    from tests.test_optimize_command_reference import _Result, runner

    values = {"driveline_mass": 12.5, "min_margin": 0.4}

    class Stand(_Result):
        def __init__(self, problem) -> None:
            super().__init__(spinup_deflection=0.0)
            self.problem = problem
            self.evaluations = xr.Dataset({"feasible": ("evaluation", [True])})
            self.pareto = xr.Dataset()
            self.references = {"base": {"feasible": True, "limiting_check": "lower", **values}}

        def blocking_checks(self) -> list:
            return []

    monkeypatch.setattr(nsga, "optimize", lambda problem, budget, out, **kwargs: Stand(problem))
    monkeypatch.setattr(driveline, "save_figure", lambda figure, out, name: {"png": out / f"{name}.png"})
    design = tmp_path / "rotor.toml"
    design.write_text(SMALL, encoding="utf-8")
    args = ["optimize", str(design), "--budget", "2", "--var", "bearings[1].kd=100:400"]
    result = runner.invoke(app, [*args, "--out", str(tmp_path / "o"), "--json", "--no-verify"])
    assert result.exit_code in (0, 3), result.output  # 3: no Pareto design passed
    data = json.loads(result.stdout)
    assert data["references"]["base"]["outputs"] == {"driveline_mass_kg": 12.5, "min_margin": 0.4}

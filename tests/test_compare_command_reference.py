"""``flexshaft compare A B``: which design goes in as A and which as B, and what is printed.

Reference: the command's documented contract (flexshaft.cli.compare, ``compare --help``):
"First design (TOML). Default: the embedded tuned FMC design"; "Second design (TOML). Default:
the embedded current segmented aluminium driveline"; the designs are labelled by their files'
names, and the table has one column per design ("quantity", A, B). Two files of the same name
must still be told apart (labels "A: name" and "B: name").

No assessment runs: ``flexshaft.comparison`` and ``flexshaft.report.compare`` are replaced by
stand-ins that record the designs they are given and hand back a result whose every value is
the design's own name, so the printed table can be checked cell by cell against the files
written here (names "alpha" and "beta"). The design files are the embedded tuned and current
designs with their name changed; loading and the problem-size check are the real ones.
"""

from __future__ import annotations

import re
import sys
import types
from pathlib import Path
from types import SimpleNamespace

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.design import embedded_design
from flexshaft.design.io import embedded_text


def _renamed(embedded: str, name: str) -> str:
    """The embedded design's TOML with its top-level name (its first ``name =`` line) replaced."""
    return re.sub(r'^name = ".*"$', f'name = "{name}"', embedded_text(embedded), count=1, flags=re.M)


@pytest.fixture
def stand_ins(monkeypatch):
    """Record what the command hands to the comparison; no analysis, no report rendering."""
    calls: list[tuple[str, str, tuple[str, str]]] = []

    def compare(a, b, labels=None, progress=None):
        calls.append((a.name, b.name, labels))

        def run(design):
            verdict = SimpleNamespace(summary=f"verdict of {design.name}", passed=True)
            return SimpleNamespace(model=SimpleNamespace(design=design), verdict=verdict)

        metric = SimpleNamespace(
            title="design name", key="name", unit="-", values=(a.name, b.name), lower_bounds=(None, None)
        )
        return SimpleNamespace(labels=labels, runs=(run(a), run(b)), metrics=lambda: [metric])

    def write_compare_report(result, folder):
        page = Path(folder) / "report.html"
        page.write_text("<html></html>")
        return page

    comparison = types.ModuleType("flexshaft.comparison")
    comparison.compare = compare
    report = types.ModuleType("flexshaft.report.compare")
    report.write_compare_report = write_compare_report
    report.comparison_json = lambda result: {"labels": list(result.labels)}
    report.format_metric = lambda key, unit, value, lower_bound: str(value)
    monkeypatch.setitem(sys.modules, "flexshaft.comparison", comparison)
    monkeypatch.setitem(sys.modules, "flexshaft.report.compare", report)
    return calls


def _invoke(args):
    result = CliRunner().invoke(app, ["compare", *args])
    assert result.exit_code == 0, result.output
    return result.output


def test_first_file_is_a_and_second_is_b(stand_ins, tmp_path):
    a = tmp_path / "alpha.toml"
    b = tmp_path / "beta.toml"
    a.write_text(_renamed("tuned", "alpha"))
    b.write_text(_renamed("current", "beta"))
    output = _invoke([str(a), str(b), "--out", str(tmp_path / "out")])
    assert stand_ins == [("alpha", "beta", ("alpha", "beta"))]
    lines = output.splitlines()
    assert any(line.startswith(f"design alpha: alpha ({a})") for line in lines), output
    assert any(line.startswith(f"design beta: beta ({b})") for line in lines), output
    # The table's header and its one row: column A holds alpha's value, column B beta's.
    header = next(line for line in lines if "quantity" in line)
    row = next(line for line in lines if "design name" in line)
    assert header.index("alpha") < header.index("beta")
    assert re.search(r"design name\W+alpha\W+beta\W*$", row), row
    assert "alpha: verdict of alpha" in output and "beta: verdict of beta" in output


def test_files_of_the_same_name_are_labelled_a_and_b(stand_ins, tmp_path):
    (tmp_path / "x").mkdir()
    (tmp_path / "y").mkdir()
    a = tmp_path / "x" / "d.toml"
    b = tmp_path / "y" / "d.toml"
    a.write_text(_renamed("tuned", "alpha"))
    b.write_text(_renamed("current", "beta"))
    output = _invoke([str(a), str(b), "--out", str(tmp_path / "out")])
    assert stand_ins == [("alpha", "beta", ("A: d", "B: d"))]
    assert "design A: d: alpha" in output and "design B: d: beta" in output


def test_without_arguments_tuned_is_compared_with_current(stand_ins, tmp_path):
    output = _invoke(["--out", str(tmp_path / "out")])
    tuned, current = embedded_design("tuned").name, embedded_design("current").name
    assert stand_ins == [(tuned, current, ("tuned", "current"))]
    assert "embedded tuned design" in output and "embedded current design" in output

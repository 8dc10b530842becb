"""`flexshaft compare` bounds both designs before it makes its folder.

Reference (docs/limits.md, section 7 "The work of a command": "Each estimates its work from both
before it computes or writes anything ... and refuses, exit 2"; "`run`, `compare` and `study
all`: the design's own bound (section 5) for their assessments"; README "Exit codes": 2 a user
error). The design-size bound of the second
design (B, the embedded current driveline) is made to refuse (a DesignError, as
check_problem_size raises above 2 GiB or 4 h) while the first passes: compare must exit 2
without making its output folder and without comparing anything; the bound must have been asked
of both designs, each for an assessment. No analysis runs (< 0.5 s).
"""

from __future__ import annotations

from pathlib import Path

from typer.testing import CliRunner

from flexshaft.cli import app


def test_a_second_design_above_its_bound_is_refused_before_the_folder(monkeypatch, tmp_path: Path) -> None:
    import flexshaft.assembly.size as size
    import flexshaft.comparison as comparison
    from flexshaft.design import DesignError, Problem, embedded_design

    b_name = embedded_design("current").name
    assert embedded_design("tuned").name != b_name
    asked = []

    def bound(design, analysis="run", resolution=None, **kwargs):
        asked.append((design.name, analysis))
        if design.name == b_name:
            raise DesignError([Problem("mesh", "would need about 3 GiB (allowed: 2 GiB)")], "<problem size>")

    def forbidden(*args, **kwargs):
        raise AssertionError("compared before bounding both designs")

    monkeypatch.setattr(size, "check_problem_size", bound)
    monkeypatch.setattr(comparison, "compare", forbidden)
    out = tmp_path / "o"
    result = CliRunner().invoke(app, ["compare", "--out", str(out)])
    assert result.exit_code == 2, result.output
    assert "compared before" not in result.output
    assert not out.exists()
    assert sorted(asked) == sorted([(embedded_design("tuned").name, "assess"), (b_name, "assess")])

"""The actuator gap on the command line: ``--gap`` in metres, ``--gap-mm`` in millimetres.

``flexshaft study all`` took the gap in metres only (``--gap``) where ``flexshaft montecarlo``
takes millimetres (``--gap-mm``), and had no upper bound: ``--gap 0.5`` typed by a user who
meant 0.5 mm tuned the gains for a 0.5 m gap. Both commands now share one rule
(:func:`flexshaft.cli.common.actuator_gap`): a gap is positive and at most 0.1 m, the design
schema's largest auxiliary-bearing clearance (``BackupGap``), in either unit, and given once.

References (derived): 0.5 mm = 0.5 × 1e-3 m = 5e-4 m; 0.1 m = 100 mm. The study is a stand-in
that records the gap it is handed (CliRunner on the embedded design): no analysis runs.
"""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app


class _Handed(Exception):
    pass


@pytest.fixture
def handed(monkeypatch):
    """The gap ``study all`` hands the studies (they stop there: nothing is computed)."""
    seen: dict[str, float | None] = {}

    def design_studies(design, resolution, *, actuator_gap=None, **kwargs):
        seen["gap"] = actuator_gap
        raise _Handed

    monkeypatch.setattr("flexshaft.thesis.design_studies.design_studies", design_studies)
    return seen


def _study_all(tmp_path, *args: str):
    return CliRunner().invoke(app, ["study", "all", "-o", str(tmp_path / "out"), *args])


@pytest.mark.parametrize(
    ("args", "metres"),
    [(["--gap-mm", "0.5"], 5e-4), (["--gap", "5e-4"], 5e-4), (["--gap-mm", "100"], 0.1), ([], None)],
    ids=["0.5 mm", "5e-4 m", "100 mm: the largest", "none: each bearing's own"],
)
def test_study_all_hands_the_gap_in_metres(tmp_path, handed, args, metres):
    _study_all(tmp_path, *args)
    assert "gap" in handed, "the studies were reached"
    if metres is None:
        assert handed["gap"] is None
    else:
        assert handed["gap"] == pytest.approx(metres, rel=1e-12)


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--gap", "0.5"], ["--gap", "0.1 m", "got 0.5", "--gap-mm"]),  # 0.5 mm typed as metres
        (["--gap-mm", "150"], ["--gap-mm", "<= 100", "got 150"]),
        (["--gap", "0.0005", "--gap-mm", "0.5"], ["--gap and --gap-mm", "once"]),
        (["--gap-mm", "0"], ["--gap-mm", "must be positive", "got 0"]),
        (["--gap-mm", "5e-324"], ["--gap-mm", "must be positive", "0 m"]),  # 5e-327 m rounds to 0
        (["--gap", "0"], ["--gap", "must be positive", "got 0"]),
    ],
    ids=["mm typed as m", "over 100 mm", "both", "zero", "a subnormal millimetre count", "zero metres"],
)
def test_a_gap_out_of_range_is_refused_before_any_study(tmp_path, handed, args, words):
    result = _study_all(tmp_path, *args)
    assert result.exit_code != 0 and "gap" not in handed
    message = " ".join(result.output.split())
    for word in words:
        assert word in message, (word, message)


def test_montecarlo_takes_the_same_largest_gap(tmp_path):
    result = CliRunner().invoke(app, ["montecarlo", "--samples", "10", "--gap-mm", "150", "-o", str(tmp_path / "mc")])
    assert result.exit_code != 0
    assert "--gap-mm" in result.output and "<= 100" in " ".join(result.output.split())

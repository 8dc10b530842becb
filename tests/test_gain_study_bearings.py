"""Study 4 (the proportional gain K_p) varies the gain of every active bearing with a PD law,
wherever it sits in ``[[bearings]]``: the thesis baseline's bearings 1 and 2 (thesis §3, study 4),
a user's driveline's own. A design without one is refused before any point is computed, with a
message naming what the study needs (it used to override ``bearings[1].kp`` and
``bearings[2].kp`` whatever they were: a contact bearing there gave an "unknown key" error at
the first point, active bearings elsewhere were left at their own gains)."""

from __future__ import annotations

import pickle

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.design import baseline_design, embedded_design, embedded_text, with_overrides
from flexshaft.thesis.gain import gain_paths, proportional_gain_study


def test_the_baselines_two_active_bearings_are_the_thesis_study():
    assert gain_paths(baseline_design()) == ("bearings[1].kp", "bearings[2].kp")


def test_an_active_bearing_elsewhere_is_the_one_varied(monkeypatch):
    """The segmented ``current`` driveline with its last bearing made a PD magnet: the study's
    points carry the swept K_p on that bearing (the sweep itself stubbed: what is checked is the
    study handed to it, which must also pickle for worker processes)."""
    current = embedded_design("current")
    last = len(current.bearings) - 1
    assert gain_paths(current) == ()
    magnet = {"name": "amb", "x": current.bearings[last].x, "kind": "active", "kp": 4.0e5, "kd": 900.0}
    active = with_overrides(current, {f"bearings[{last}]": magnet})
    assert gain_paths(active) == (f"bearings[{last}].kp",)
    seen = {}
    monkeypatch.setattr("flexshaft.thesis.gain.run_sweep", lambda study, **run: seen.setdefault("study", study))
    study = proportional_gain_study([2.0e5, 8.0e5], design=active)
    pickle.loads(pickle.dumps(study))
    (variable,) = study.variables
    assert variable.overrides(8.0e5) == {f"bearings[{last}].kp": 8.0e5}


def test_a_design_without_one_is_refused_before_computing(tmp_path):
    with pytest.raises(ValueError, match="needs an active bearing"):
        proportional_gain_study([1e5], design=embedded_design("current"))
    design = tmp_path / "current.toml"
    design.write_text(embedded_text("current"), encoding="utf-8")
    result = CliRunner().invoke(app, ["study", "gain", str(design), "-o", str(tmp_path / "out")])
    assert result.exit_code == 2, result.output
    assert "study gain: the design has no active bearing" in result.output
    assert not (tmp_path / "out").exists()


def test_a_bearing_given_by_its_transfer_function_is_not_varied():
    """A lead-lag controller C(s) on the baseline's first magnet (no kp: its law is the
    transfer function): only the second magnet's K_p is a study variable; setting a kp beside
    a controller would be refused by the schema at the first point."""
    lead_lag = {"numerator": [1.0e7 / 600.0, 1.0e7], "denominator": [1.0 / 6000.0, 1.0]}
    design = with_overrides(
        baseline_design(), {"bearings[1].kp": None, "bearings[1].kd": None, "bearings[1].controller": lead_lag}
    )
    assert gain_paths(design) == ("bearings[2].kp",)

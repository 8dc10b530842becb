"""What the chapter-3 studies' driver reports about itself, on hand-built results
(:mod:`flexshaft.thesis.design_studies`): no model is solved (milliseconds).

References (documented rules, derived here where stated):

* **Total time is the sum over the studies.** ``DesignStudies.elapsed`` is documented as the
  "Total time of the studies [s]": the studies' total work, each study's task seconds added
  (not the wall time of a run whose tasks overlap on several workers), so the total of a
  ply-angle study of 1.25 s, a wall study of 2.5 s and a buckling study of 0.5 s is
  1.25 + 2.5 + 0.5 = 4.25 s, not the longest study's 2.5 s (binary-exact sums: exact
  equality). tests/test_design_studies_headline_reference.py adds up the tasks of one study,
  where the longest study is the sum too; here three studies tell them apart.
* **The headline is JSON.** docs/studies.md (line 203) documents ``headline(res)`` as
  "JSON-ready numbers beside the thesis's" (its docstring: "JSON-ready (SI units)"); JSON
  (RFC 8259, §6) forbids only the Infinity and NaN tokens, and the project's convention for
  them is ``None`` (``json_ready`` in :mod:`flexshaft.cli.common` and
  :mod:`flexshaft.report.results_json`: "non-finite floats as ``None`` (strict JSON has no
  NaN or infinity)"), so a non-finite number (an infinite safety factor of an unloaded ply, a
  NaN peak) must come out as ``null``: the headline of such a result passes
  ``json.dumps(..., allow_nan=False)`` with those fields None, the finite ones unchanged.
* **A failed study leaves the others.** :func:`~flexshaft.thesis.design_studies.finish_design_studies`
  is documented: "A study that cannot run on the design ... is left None with the reason in
  notes". So a failed buckling study (a ``ValueError``) must not remove a stability map all
  of whose K_p rows ran: the map is stacked from its rows and kept, buckling stays None.
"""

from __future__ import annotations

import json

import flexshaft.thesis.design_studies as studies
from flexshaft.parallel.tasks import Task, TaskOutcome


def _result(**fields):
    return studies.DesignStudies(design_name="hand", resolution="report", operating_speed=500.0, **fields)


class _Run:
    """A finished task run: ``outcomes`` maps (key, label) to (value, seconds, error)."""

    def __init__(self, outcomes):
        self.tasks = [Task(key, label, print) for key, label in outcomes]
        self._outcomes = {
            key: TaskOutcome(key, value, seconds, error) for (key, _), (value, seconds, error) in outcomes.items()
        }

    def results(self, progress=None):
        return self._outcomes


def test_total_time_is_the_sum_of_the_studies():
    run = _Run(
        {
            ("ply_angle", "study 1: ply angle"): ({}, 1.25, None),
            ("wall", "study 3: wall thickness"): ({}, 2.5, None),
            ("buckling", "study 5: torsional buckling"): ({}, 0.5, None),
        }
    )
    done = studies.finish_design_studies(_result(), run)
    assert done.elapsed == 4.25
    assert studies.headline(done)["elapsed_s"] == 4.25


def test_the_headline_writes_non_finite_numbers_as_null():
    out = studies.headline(
        _result(
            optimal_angle=55.0,
            optimal_angle_safety_factor=float("inf"),
            best_wall=3e-3,
            best_wall_safety_factor=2.5,
            peak_before=float("nan"),
            peak_after=4e-3,
        )
    )
    text = json.dumps(out, allow_nan=False)  # raises on Infinity / NaN
    back = json.loads(text)
    assert back["optimal_angle_safety_factor"] is None
    assert back["peak_deflection_before_m"] is None
    assert back["optimal_angle_deg"] == 55.0
    assert back["best_wall_safety_factor"] == 2.5
    assert back["peak_deflection_after_m"] == 4e-3


def test_a_failed_study_keeps_a_complete_stability_map(monkeypatch):
    stacked = []
    monkeypatch.setattr(studies, "stack_maps", lambda rows: stacked.append(list(rows)) or "stacked")
    monkeypatch.setattr(studies, "stability_dataset", lambda maps: ("map", maps))
    run = _Run(
        {
            ("buckling", "study 5: torsional buckling"): (None, 0.1, ValueError("no torque on this design")),
            ("stability:0", "stability margin map"): ({"stability_rows": ["row 0"]}, 0.2, None),
            ("stability:1", "stability margin map"): ({"stability_rows": ["row 1"]}, 0.3, None),
        }
    )
    done = studies.finish_design_studies(_result(), run)
    assert done.buckling is None
    assert any(note.startswith("study 5: torsional buckling skipped") for note in done.notes)
    assert stacked == [["row 0", "row 1"]]
    assert done.stability_map == ("map", "stacked")

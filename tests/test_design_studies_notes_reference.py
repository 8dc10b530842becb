"""The chapter-3 studies driver's notes and stability grid (:mod:`flexshaft.thesis.design_studies`),
on hand-built results: no model is solved.

References:

* **Stability grids as docs/studies.md states them.** The "Time" table: ``report`` "stability
  4 × 4 × 16 speeds", ``full`` "stability 8 × 8 × 31" (K_p rows × K_d columns × speeds), read
  here from the file: the sizes of ``stab_kp``, ``stab_kd`` and ``stab_speeds``.
* **One note per failed study** (an inference, not a quoted rule). ``finish_design_studies``'s
  docstring: "A study that cannot run on the design ... is left None with the reason in notes";
  docs/studies.md gives each study one Dataset, and the stability margin map is one study run as
  one task per K_p row. Inferred: two rows refused for the same reason leave the reason in the
  notes once (the note's exact wording is not pinned).
"""

from __future__ import annotations

import re

import flexshaft.thesis.design_studies as studies
from tests.test_design_studies_bookkeeping_reference import _result, _Run
from tests.test_design_studies_grids_reference import _row


def test_stability_grids_are_those_the_docs_state():
    for resolution in ("report", "full"):
        m = re.search(r"stability (\d+) × (\d+) × (\d+)", _row(resolution))
        assert m, resolution
        n_kp, n_kd, n_speeds = (int(v) for v in m.groups())
        grid = studies.STUDY_GRIDS[resolution]
        assert (len(grid["stab_kp"]), len(grid["stab_kd"]), grid["stab_speeds"]) == (n_kp, n_kd, n_speeds)


def test_a_study_refused_row_by_row_is_noted_once():
    error = ValueError("no active bearing with a PD law")
    run = _Run(
        {
            ("stability:0", "stability margin map"): (None, 0.1, error),
            ("stability:1", "stability margin map"): (None, 0.1, error),
        }
    )
    done = studies.finish_design_studies(_result(), run)
    assert sum(str(error) in n for n in done.notes) == 1
    assert done.stability_map is None

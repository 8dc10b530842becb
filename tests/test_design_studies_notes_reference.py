"""The chapter-3 studies driver's notes and stability grid (:mod:`flexshaft.thesis.design_studies`),
on hand-built results: no model is solved.

References:

* **Stability grids as docs/studies.md states them.** The "Time" table: ``report`` "stability
  4 × 4 × 16 speeds", ``full`` "stability 8 × 8 × 31" (K_p rows × K_d columns × speeds), read
  here from the file: the sizes of ``stab_kp``, ``stab_kd`` and ``stab_speeds``.
* **The best wall's edge note is in millimetres.** The note says "the best wall (X mm) is at the
  end of the range studied": a best wall of 6e-3 m (the thickest of 1, 2, 6 mm with a safety
  factor rising with the wall, hand-set) reads "6 mm".
* **One note per failed study.** ``finish_design_studies``: "A study that cannot run on the
  design ... is left None with the reason in notes"; the stability margin map is one study
  (one Dataset, docs/studies.md) run as one task per K_p row, so two rows refused for the same
  reason give one "stability margin map skipped" note.
"""

from __future__ import annotations

import re

import numpy as np
import xarray as xr

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


def test_best_wall_at_the_range_end_is_noted_in_millimetres(monkeypatch):
    walls = np.array([1e-3, 2e-3, 6e-3])
    ds = xr.Dataset({"safety_factor": ("wall_thickness", np.array([1.0, 2.0, 3.0]))}, coords={"wall_thickness": walls})
    monkeypatch.setattr(studies, "wall_thickness_study", lambda walls, design=None, **run: ds)
    out = studies._wall_task(None, walls, {}, True)
    assert out["best_wall"] == 6e-3
    assert len(out["notes"]) == 1 and out["notes"][0].startswith("the best wall (6 mm) is at the end")


def test_a_study_refused_row_by_row_is_noted_once():
    error = ValueError("no active bearing with a PD law")
    run = _Run(
        {
            ("stability:0", "stability margin map"): (None, 0.1, error),
            ("stability:1", "stability margin map"): (None, 0.1, error),
        }
    )
    done = studies.finish_design_studies(_result(), run)
    skipped = [n for n in done.notes if n.startswith("stability margin map skipped")]
    assert skipped == ["stability margin map skipped: no active bearing with a PD law"]
    assert done.stability_map is None

"""Two sweep behaviours outside the serial, single-interruption path.

1. ``on_error="nan"`` with local worker processes (``jobs=2``). Reference, the docstring of
   :func:`flexshaft.sweep.run_sweep` (src/flexshaft/sweep/run.py): ``on_error : {"raise",
   "nan"}`` -- "What a point whose evaluation raises becomes: stop the run, or NaN outputs." The
   study is the 3 x 4 one of tests/test_sweep_integrity.py whose point (kp = 3e6 N/m, speed =
   30 rad/s) raises; every other point has the closed form ``kp 1e-6 + speed**2`` and the wall
   in mm, exact in binary floating point, so the comparison is exact.

2. A resumed run interrupted again. Reference, the same module's interruption note ("N of M
   chunks are stored in RUN: the same command with the same options resumes from them") with M
   the grid's chunks, as tests/test_sweep_chunks_reference.py counts it for a first run; worked
   by hand for the 2 x 3 grid in chunks of 2, [0, 2), [2, 4), [4, 6): Ctrl-C at point 2 keeps
   chunk 0; the resumed run, stopped at point 4, adds chunk 1, so 2 of the 3 chunks are stored.

Tiny grids and closed-form outputs (no model built): well under 1 s of CPU, the pool's start
included.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

xr = pytest.importorskip("xarray")

from flexshaft.sweep import finished_chunks, run_sweep
from tests.test_sweep_chunks_reference import CALLS, STOP_AT
from tests.test_sweep_chunks_reference import _study as two_by_three
from tests.test_sweep_integrity import CHUNK, _closed_form, failing_study


def test_workers_turn_a_failing_point_into_nan():
    study = failing_study("failing with workers", fixed={"shaft.wall_thickness": 0.003})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the failing point's own warning is not the subject here
        ds = run_sweep(study, jobs=2, chunk_size=CHUNK, progress=False, on_error="nan")
    expected = _closed_form(0.003)
    expected["stiffness_speed"][2, 3] = np.nan  # kp = 3e6 N/m, speed = 30 rad/s: raised
    expected["wall_mm"][2, 3] = np.nan
    for name, values in expected.items():
        np.testing.assert_array_equal(ds[name].values[..., 0], values)


def test_resumed_run_interrupted_again_counts_the_grid_chunks(tmp_path):
    run = tmp_path / "run"
    CALLS.clear()
    STOP_AT.append(2)  # Ctrl-C at the first point of chunk 1 [2, 4)
    with pytest.raises(KeyboardInterrupt):
        run_sweep(two_by_three(), run, chunk_size=2, progress=False)
    assert finished_chunks(run) == [0]
    STOP_AT.append(4)  # the resumed run stops at the first point of chunk 2 [4, 6)
    with pytest.raises(KeyboardInterrupt) as interrupted:
        run_sweep(two_by_three(), run, progress=False)
    assert finished_chunks(run) == [0, 1]
    assert interrupted.value.__notes__ == [
        f"2 of 3 chunks are stored in {run}: the same command with the same options resumes from them"
    ]

"""A run folder swept one point per chunk resumes from all of its chunks.

References (hand-written docs and docstrings, quoted):

* docs/studies.md, "Resume": the manifest holds "the study's specification, fingerprint and
  chunk size, with a SHA-256 of its own content"; "Re-running the same study on the same folder
  verifies every stored chunk and computes only the missing ones and those that fail a check";
  only "a missing or damaged manifest" sends the old chunks to ``RUN/chunks.discarded-N/``.
* :func:`flexshaft.sweep.store.open_run`: "A folder whose manifest reads and matches ``study``
  resumes with its stored chunk size."

A chunk size of 1 (one point per chunk) is the smallest a run can use: ``chunk_bounds`` of
``n`` points in chunks of 1 is ``[k, k + 1)`` for ``k = 0..n-1``, so the 2 x 3 grid below gives
6 chunk files. Its manifest is intact, so a second run over the same folder must reuse all 6:
the output function is called 0 times (counted here), no warning is issued, nothing is moved
aside, and ``f`` is the hand value 100 a + b at every point (exact in binary floating point:
integers below 2**53, so the comparison needs no tolerance). Special axes only, serial: no
model is built and the file costs well under 1 s of CPU.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("xarray")

from flexshaft.sweep import Output, Study, Variable, run_sweep

A = [1.0, 2.0]
B = [10.0, 20.0, 30.0]
CALLS: list[tuple[float, float]] = []


def hundred_a_plus_b(point):
    """f = 100 a + b, counting the calls."""
    a, b = point.axes["a"], point.axes["b"]
    CALLS.append((a, b))
    return {"f": 100.0 * a + b}


def _study() -> Study:
    return Study(
        "two by three", [Variable("a", A, units="1"), Variable("b", B, units="1")], [Output("f", "1")], hundred_a_plus_b
    )


def test_one_point_chunks_are_all_reused_on_resume(tmp_path: Path) -> None:
    """Run in chunks of 1 (6 chunk files, each computed once), then run again with no chunk
    size given: the folder's stored size 1 is in force, all 6 chunks are reused (0 calls, no
    SweepWarning, no ``chunks.discarded-N/``) and ``f`` is 100 a + b at the 6 points in C order
    (a outer, b inner)."""
    run = tmp_path / "run"
    CALLS.clear()
    run_sweep(_study(), run, chunk_size=1, progress=False)
    assert len(CALLS) == 6
    assert sorted(p.name for p in (run / "chunks").iterdir()) == [f"chunk_{k:06d}.npz" for k in range(6)]
    CALLS.clear()
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a SweepWarning (chunks moved aside or recomputed) fails
        ds = run_sweep(_study(), run, progress=False)
    assert CALLS == []
    assert not list(tmp_path.glob("run/chunks.discarded-*"))
    expected = np.array([[100.0 * a + b for b in B] for a in A])
    np.testing.assert_array_equal(np.asarray(ds["f"].values), expected)

"""Chunks of a 2 x 3 sweep enumerated by hand: which points each chunk holds, that every point
is computed exactly once, at its own coordinates, and that an interrupted run resumes from its
stored chunks point by point.

Reference (worked by hand, not printed by the code): the grid ``a`` = [1, 2] (outer) x ``b`` =
[10, 20, 30] (inner) in C order has the flat points

    index   0    1    2    3    4    5
    (a, b)  1,10 1,20 1,30 2,10 2,20 2,30

and the output ``f = 100 a + b`` is exact in binary floating point (integers below 2**53), so
every comparison below is exact. With ``chunk_size`` = 4 the chunks are [0, 4) and [4, 6)
(the last one short); with ``chunk_size`` = 2 they are [0, 2), [2, 4), [4, 6). The study has
special axes only (no design variable), so no model is built: the file costs a few runs of the
engine on the embedded baseline (well under 1 s of CPU).
"""

from __future__ import annotations

import json
import shutil
import warnings

import numpy as np
import pytest

xr = pytest.importorskip("xarray")

from flexshaft.sweep import Output, Study, SweepError, SweepWarning, Variable, finished_chunks, run_sweep
from flexshaft.sweep.store import chunk_path

A = [1.0, 2.0]
B = [10.0, 20.0, 30.0]
#: (a, b) of flat points 0..5, C order (the last variable varies fastest), by hand.
POINTS = [(1.0, 10.0), (1.0, 20.0), (1.0, 30.0), (2.0, 10.0), (2.0, 20.0), (2.0, 30.0)]
CALLS: list[int] = []
STOP_AT: list[int] = []  # flat index at which the evaluation raises KeyboardInterrupt (Ctrl-C)


def hundred_a_plus_b(point):
    """f = 100 a + b, and the index and coordinates the engine handed over."""
    if STOP_AT and point.index == STOP_AT[0]:
        STOP_AT.clear()
        raise KeyboardInterrupt
    CALLS.append(point.index)
    a, b = point.axes["a"], point.axes["b"]
    return {"f": 100.0 * a + b, "index": float(point.index)}


def _study() -> Study:
    return Study(
        "two by three",
        [Variable("a", A, units="1"), Variable("b", B, units="1")],
        [Output("f", "1"), Output("index", "1")],
        hundred_a_plus_b,
    )


def _chunk(run_dir, k):
    with np.load(chunk_path(run_dir, k)) as archive:
        return json.loads(str(archive["header"][()])), archive["values"].copy()


def _expected_rows(start: int, stop: int) -> np.ndarray:
    return np.array([[100.0 * a + b, float(i)] for i, (a, b) in enumerate(POINTS)][start:stop])


def test_two_by_three_grid_in_chunks_of_four(tmp_path):
    CALLS.clear()
    ds = run_sweep(_study(), tmp_path / "run", chunk_size=4, progress=False)
    # every point exactly once (none recomputed by an overlapping chunk, none skipped)
    assert sorted(CALLS) == [0, 1, 2, 3, 4, 5]
    # two chunk files, [0, 4) and [4, 6), each under its own index with its own points
    assert finished_chunks(tmp_path / "run") == [0, 1]
    for k, (start, stop) in enumerate([(0, 4), (4, 6)]):
        header, values = _chunk(tmp_path / "run", k)
        assert (header["chunk"], header["start"], header["stop"]) == (k, start, stop)
        np.testing.assert_array_equal(values, _expected_rows(start, stop))
    # the labelled result: each value at its own coordinates
    assert ds["f"].dims == ("a", "b")
    np.testing.assert_array_equal(ds["a"].values, A)
    np.testing.assert_array_equal(ds["b"].values, B)
    for i, (a, b) in enumerate(POINTS):
        assert float(ds["f"].sel(a=a, b=b)) == 100.0 * a + b
        assert float(ds["index"].sel(a=a, b=b)) == i
    assert ds["a"].attrs["kind"] == "axis"


def test_interrupted_sweep_resumes_point_by_point(tmp_path):
    run = tmp_path / "run"
    CALLS.clear()
    STOP_AT.append(4)  # Ctrl-C at the first point of the third chunk [4, 6)
    with pytest.raises(KeyboardInterrupt) as interrupted:
        run_sweep(_study(), run, chunk_size=2, progress=False)
    # what is kept, for the command to say (two chunks of three: [0, 2) and [2, 4))
    assert interrupted.value.__notes__ == [
        f"2 of 3 chunks are stored in {run}: the same command with the same options resumes from them"
    ]
    assert CALLS == [0, 1, 2, 3]
    assert finished_chunks(run) == [0, 1] and not (run / "results.nc").exists()
    for k, (start, stop) in enumerate([(0, 2), (2, 4)]):
        header, values = _chunk(run, k)
        assert (header["start"], header["stop"]) == (start, stop)
        np.testing.assert_array_equal(values, _expected_rows(start, stop))
    # another chunk size on the same folder is refused, naming the one it started with
    with pytest.raises(SweepError, match="chunk_size=2"):
        run_sweep(_study(), run, chunk_size=3, progress=False)
    # resumed without giving the chunk size: the stored one (2) is kept, the two stored chunks
    # are reused silently and only points 4 and 5 are computed
    CALLS.clear()
    with warnings.catch_warnings():
        warnings.simplefilter("error", SweepWarning)
        ds = run_sweep(_study(), run, progress=False)
    assert CALLS == [4, 5]
    assert finished_chunks(run) == [0, 1, 2]
    header, values = _chunk(run, 2)
    assert (header["start"], header["stop"]) == (4, 6)
    np.testing.assert_array_equal(values, _expected_rows(4, 6))
    for i, (a, b) in enumerate(POINTS):
        assert float(ds["f"].sel(a=a, b=b)) == 100.0 * a + b
        assert float(ds["index"].sel(a=a, b=b)) == i


def test_chunk_file_one_past_the_grid_is_ignored(tmp_path):
    """Three chunks [0, 2), [2, 4), [4, 6): a file named chunk 3 is past the last chunk (2) and
    is no chunk of this run: ignored with a warning naming it, nothing recomputed."""
    run = tmp_path / "run"
    run_sweep(_study(), run, chunk_size=2, progress=False)
    shutil.copyfile(chunk_path(run, 2), chunk_path(run, 3))
    CALLS.clear()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ds = run_sweep(_study(), run, chunk_size=2, progress=False)
    assert CALLS == []
    messages = [str(w.message) for w in caught if issubclass(w.category, SweepWarning)]
    assert len(messages) == 1 and "ignoring 1 file(s)" in messages[0] and "chunk_000003.npz" in messages[0]
    np.testing.assert_array_equal(ds["f"].values, np.array([[110.0, 120.0, 130.0], [210.0, 220.0, 230.0]]))

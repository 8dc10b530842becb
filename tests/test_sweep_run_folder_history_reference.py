"""A sweep's run folder keeps every finished chunk and reuses only the right ones.

References (hand-written docs and docstrings, quoted):

* docs/studies.md, "Resume": a stored chunk is recomputed when it fails a check, among them
  "another chunk's range"; "A missing or damaged manifest means the folder's history is
  unknown: the old chunks are moved to ``RUN/chunks.discarded-N/``, never reused, and everything
  is recomputed. A folder whose intact manifest is another study's is refused."
* :func:`flexshaft.cli.output.into_run_folder` (the path of ``flexshaft montecarlo`` and every
  ``flexshaft study`` command): a folder holding another study's chunks "is refused [...] with
  the way out: ``--force`` moves its chunks aside (``chunks.discarded-N/``: finished work is
  never deleted) and starts afresh".

The study is the hand-enumerated 2 x 3 grid of ``tests/test_sweep_chunks_reference.py``:
``a`` = [1, 2] (outer) x ``b`` = [10, 20, 30] (inner), flat points in C order

    index   0    1    2    3    4    5
    (a, b)  1,10 1,20 1,30 2,10 2,20 2,30

with the output ``f = 100 a + b``, exact in binary floating point (integers below 2**53), so
every comparison is exact, with no tolerance. Special axes only: no model is built; the file
costs well under 1 s of CPU.
"""

from __future__ import annotations

import json
import warnings
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("xarray")

from flexshaft.cli.common import UserError
from flexshaft.cli.output import into_run_folder
from flexshaft.sweep import Output, Study, SweepWarning, Variable, run_sweep
from flexshaft.sweep.store import ChunkError, chunk_path, load_chunks, read_chunk, write_chunk

A = [1.0, 2.0]
B = [10.0, 20.0, 30.0]
POINTS = [(1.0, 10.0), (1.0, 20.0), (1.0, 30.0), (2.0, 10.0), (2.0, 20.0), (2.0, 30.0)]


def hundred_a_plus_b(point):
    """f = 100 a + b."""
    return {"f": 100.0 * point.axes["a"] + point.axes["b"]}


def _study(b=B) -> Study:
    return Study(
        "two by three", [Variable("a", A, units="1"), Variable("b", b, units="1")], [Output("f", "1")], hundred_a_plus_b
    )


def _f(points) -> np.ndarray:
    """Column of ``f`` for the given (a, b) points, by hand."""
    return np.array([[100.0 * a + b] for a, b in points])


def test_a_chunk_of_the_same_index_but_another_range_is_not_reused(tmp_path: Path) -> None:
    """Chunk 1 of a 12-point sweep in chunks of 10 holds points 10..11; in chunks of 2 it holds
    points 2..3: both have 2 rows and the same index, so only the stored point range tells them
    apart (docs/studies.md: "another chunk's range" fails the check)."""
    run = tmp_path / "run"
    path = chunk_path(run, 1)
    path.parent.mkdir(parents=True)
    stored = np.array([[10.0, 1.0], [11.0, 1.0]])  # the outputs of points 10 and 11
    write_chunk(path, stored, fingerprint="f" * 64, index=1, start=10, stop=12)
    # the chunk as it was written reads back exactly
    np.testing.assert_array_equal(
        read_chunk(path, fingerprint="f" * 64, index=1, start=10, stop=12, n_outputs=2), stored
    )
    with pytest.raises(ChunkError, match="points 10..12"):
        read_chunk(path, fingerprint="f" * 64, index=1, start=2, stop=4, n_outputs=2)
    # on resume with the chunks of 2 (bounds [0, 2), [2, 4), ...) it is deleted, with a warning
    # naming it, and nothing is reused for points 2..3
    bounds = [(0, 2), (2, 4), (4, 6), (6, 8), (8, 10), (10, 12)]
    with pytest.warns(SweepWarning, match="chunk_000001.npz"):
        good = load_chunks(run, bounds, fingerprint="f" * 64, n_outputs=2)
    assert good == {} and not path.exists()


def _discarded_values(folder: Path) -> np.ndarray:
    """The values of the two chunks (size 3: points 0..2 and 3..5) moved into ``folder``."""
    rows = []
    for k in (0, 1):
        with np.load(folder / f"chunk_{k:06d}.npz") as archive:
            rows.append(archive["values"].copy())
    return np.vstack(rows)


def test_each_fresh_start_moves_the_old_chunks_to_a_new_folder(tmp_path: Path) -> None:
    """Three runs after a deleted manifest: each set of finished chunks goes to its own
    ``chunks.discarded-N`` (N = 1, 2, 3), none is merged into or renamed onto an earlier one,
    and every set still holds the values f = 100 a + b of the points it computed."""
    run = tmp_path / "run"
    first = _study()
    ds = run_sweep(first, run, chunk_size=3, progress=False)
    np.testing.assert_array_equal(ds["f"].values.reshape(-1, 1), _f(POINTS))
    for n in (1, 2, 3):
        (run / "manifest.json").unlink()  # the folder's history is now unknown
        with pytest.warns(SweepWarning, match=f"chunks.discarded-{n}/"):
            ds = run_sweep(first, run, chunk_size=3, progress=False)
        np.testing.assert_array_equal(ds["f"].values.reshape(-1, 1), _f(POINTS))
    assert sorted(p.name for p in run.iterdir() if p.name.startswith("chunks.")) == [
        "chunks.discarded-1",
        "chunks.discarded-2",
        "chunks.discarded-3",
    ]
    for n in (1, 2, 3):
        folder = run / f"chunks.discarded-{n}"
        assert sorted(p.name for p in folder.iterdir()) == ["chunk_000000.npz", "chunk_000001.npz"]
        np.testing.assert_array_equal(_discarded_values(folder), _f(POINTS))


def test_force_on_a_folder_of_another_study_starts_afresh(tmp_path: Path) -> None:
    """``--force`` (into_run_folder with force) on a folder of another study: its chunks are
    moved to ``chunks.discarded-1`` and the new study runs in the folder, which then holds the
    new study's manifest; without ``--force`` the folder is refused (a user error)."""
    run = tmp_path / "run"
    old, new = _study(), _study([10.0, 20.0, 40.0])  # another value of b: another study
    run_sweep(old, run, chunk_size=3, progress=False)
    old_fingerprint = json.loads((run / "manifest.json").read_text())["fingerprint"]

    def compute():
        return run_sweep(new, run, chunk_size=3, progress=False)

    with pytest.raises(UserError, match="--force"):
        into_run_folder(compute, run, force=False)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ds = into_run_folder(compute, run, force=True)
    assert any("chunks.discarded-1/" in str(w.message) for w in caught)
    new_points = [(a, b) for a in A for b in (10.0, 20.0, 40.0)]
    np.testing.assert_array_equal(ds["f"].values.reshape(-1, 1), _f(new_points))
    manifest = json.loads((run / "manifest.json").read_text())
    assert manifest["fingerprint"] != old_fingerprint
    # the old study's finished work is kept aside, its values intact
    np.testing.assert_array_equal(_discarded_values(run / "chunks.discarded-1"), _f(POINTS))
    # and the folder now resumes the new study silently, computing nothing again
    with warnings.catch_warnings():
        warnings.simplefilter("error", SweepWarning)
        again = into_run_folder(compute, run, force=False)
    np.testing.assert_array_equal(again["f"].values, ds["f"].values)

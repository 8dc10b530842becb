"""A sweep's run folder keeps every finished chunk and reuses only the right ones.

References (hand-written docs and docstrings, quoted):

* docs/studies.md, "Resume": a stored chunk is recomputed when it fails a check, among them
  "another chunk's range", "each named with its reason in a `SweepWarning`"; "A missing or
  damaged manifest means the folder's history is unknown: the old chunks are moved to
  ``RUN/chunks.discarded-N/``, never reused, and everything is recomputed. A folder whose intact
  manifest is another study's is refused. The commands that sweep into a folder (``flexshaft
  study ...``, ``flexshaft montecarlo``) refuse it too; with ``--force`` they move its chunks
  aside to ``RUN/chunks.discarded-N/`` (kept, never deleted) and run the new study afresh in it."
* :mod:`flexshaft.sweep.store`'s docstring: "On resume a chunk is reused only if it reads,
  carries this study's fingerprint, this chunk's index and point range, the expected shape, and
  a checksum that matches its bytes. Any other chunk is deleted and recomputed with a
  :class:`~flexshaft.sweep.study.SweepWarning` naming the file and the reason".
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
import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("xarray")

from flexshaft.cli.common import UserError
from flexshaft.cli.output import into_run_folder
from flexshaft.sweep import Output, Study, SweepWarning, Variable, run_sweep
from flexshaft.sweep.store import chunk_path, read_chunk

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
    """Chunk 1 of the grid holds points 4..5 in chunks of 4 ([0, 4), [4, 6)) and points 2..3 in
    chunks of 2 ([0, 2), [2, 4), [4, 6)): both have 2 rows, the same index and the same study
    fingerprint, so only the stored point range tells them apart. Folder A is run in chunks of
    4, folder B in chunks of 2; B's chunk 1 copied over A's and A run again: the chunk fails the
    check ("another chunk's range"), a SweepWarning names it, and it is recomputed, so that
    ``f`` is 100 a + b at every point (reused, it would put f(2..3) = 130, 210 at points 4..5,
    whose values are 220, 230). The file then holds A's own chunk 1 again: points 4..5, f = 220,
    230 (store.py: the rejected chunk "is deleted and recomputed")."""
    first, second = tmp_path / "A", tmp_path / "B"
    run_sweep(_study(), first, chunk_size=4, progress=False)
    run_sweep(_study(), second, chunk_size=2, progress=False)
    fingerprint = json.loads((first / "manifest.json").read_text())["fingerprint"]
    # B's chunk 1, by hand: points 2..3 = (1, 30), (2, 10)
    np.testing.assert_array_equal(
        read_chunk(chunk_path(second, 1), fingerprint=fingerprint, index=1, start=2, stop=4, n_outputs=1),
        _f(POINTS[2:4]),
    )
    shutil.copyfile(chunk_path(second, 1), chunk_path(first, 1))
    with pytest.warns(SweepWarning, match="chunk_000001.npz"):
        ds = run_sweep(_study(), first, progress=False)  # resumes with the stored chunk size, 4
    np.testing.assert_array_equal(ds["f"].values.reshape(-1, 1), _f(POINTS))
    np.testing.assert_array_equal(
        read_chunk(chunk_path(first, 1), fingerprint=fingerprint, index=1, start=4, stop=6, n_outputs=1),
        _f(POINTS[4:6]),
    )


def _discarded_values(folder: Path) -> np.ndarray:
    """The values of the two chunks (size 3: points 0..2 and 3..5) moved into ``folder``."""
    rows = []
    for k in (0, 1):
        with np.load(folder / f"chunk_{k:06d}.npz") as archive:
            rows.append(archive["values"].copy())
    return np.vstack(rows)


def test_each_fresh_start_moves_the_old_chunks_to_a_new_folder(tmp_path: Path) -> None:
    """Three runs after a deleted manifest: each set of finished chunks goes to its own
    ``chunks.discarded-N`` (N = 1, 2, 3), never renamed onto an earlier one (which fails on a
    non-empty folder and replaces an empty one), and every set still holds the values
    f = 100 a + b of the points it computed."""
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

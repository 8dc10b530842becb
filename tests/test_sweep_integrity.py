"""A resumed sweep never reuses damaged, edited or foreign stored data.

Each test runs a cheap study through the real engine into a run folder, damages the folder
the way the fuzzing did (truncated or random chunk bytes, wrong shapes, values scaled by 1.01
or set to NaN, stray files, a broken or deleted manifest, chunks of another study), runs the
study again on it, and checks

* the results (returned and in ``results.nc``) are bit for bit those of an uninterrupted run,
  which itself equals the closed form of the output function exactly (IEEE arithmetic on the
  same operands: no tolerance is needed);
* exactly the damaged chunk's points were evaluated again, and
* a :class:`SweepWarning` names the file and the reason.
"""

from __future__ import annotations

import io
import json
import re
import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest

xr = pytest.importorskip("xarray")

from flexshaft.sweep import Output, Study, SweepError, SweepWarning, Variable, run_sweep
from flexshaft.sweep.store import chunk_path, finished_chunks, write_chunk

KP = np.array([1e6, 2e6, 3e6])  # [N/m]
SPEED = np.array([0.0, 10.0, 20.0, 30.0])  # [rad/s]
CHUNK = 3  # points per chunk: 12 points, 4 chunks
CALLS: list[int] = []  # flat indices evaluated in this process


def analytic(point):
    """Closed-form outputs of the design and the axis (no model built)."""
    CALLS.append(point.index)
    kp = point.design.bearings[1].kp
    speed = point.axes["speed"]
    if speed == 30.0 and kp == 3e6 and point.axes.get("fail", False):
        raise RuntimeError("a point that fails")
    return {"stiffness_speed": kp * 1e-6 + speed**2, "wall_mm": 1e3 * point.design.shaft.wall_thickness}


def _study(wall: float = 0.003) -> Study:
    return Study(
        "integrity",
        [Variable(path="bearings[1].kp", name="kp", values=KP, units="N/m"), Variable("speed", SPEED, units="rad/s")],
        [Output("stiffness_speed"), Output("wall_mm", "mm")],
        analytic,
        fixed={"shaft.wall_thickness": wall},
    )


def _closed_form(wall: float = 0.003) -> dict[str, np.ndarray]:
    return {"stiffness_speed": KP[:, None] * 1e-6 + SPEED[None, :] ** 2, "wall_mm": np.full((3, 4), 1e3 * wall)}


@pytest.fixture()
def reference(tmp_path):
    """results.nc of an uninterrupted run, checked against the closed form."""
    ds = run_sweep(_study(), tmp_path / "reference", chunk_size=CHUNK, progress=False)
    for name, expected in _closed_form().items():
        assert ds[name].values.tobytes() == expected.tobytes()
    return xr.load_dataset(tmp_path / "reference" / "results.nc")


@pytest.fixture()
def run_dir(tmp_path):
    """A finished run folder of the study (all 4 chunks stored)."""
    folder = tmp_path / "run"
    run_sweep(_study(), folder, chunk_size=CHUNK, progress=False)
    assert finished_chunks(folder) == [0, 1, 2, 3]
    CALLS.clear()
    return folder


def _resume_and_compare(folder: Path, reference, study: Study | None = None):
    """Run again on ``folder``; assert bit-identical results; return the warnings' texts."""
    CALLS.clear()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ds = run_sweep(study or _study(), folder, chunk_size=CHUNK, progress=False)
    on_disk = xr.load_dataset(folder / "results.nc")
    for result in (ds, on_disk):
        xr.testing.assert_identical(result, reference)
        for name in reference.data_vars:
            assert result[name].values.tobytes() == reference[name].values.tobytes()
    return [str(w.message) for w in caught if issubclass(w.category, SweepWarning)]


def _rewrite(path: Path, values=None, header=None) -> None:
    """Write a chunk file again with other values or header, keeping the rest as stored."""
    with np.load(path) as archive:
        old_values, old_header = archive["values"], archive["header"]
    np.savez(path, values=old_values if values is None else values, header=old_header if header is None else header)


def _values(path: Path) -> np.ndarray:
    with np.load(path) as archive:
        return archive["values"]


def _npy_bytes(values: np.ndarray) -> bytes:
    buffer = io.BytesIO()
    np.save(buffer, values)
    return buffer.getvalue()


def _flip_last_bit(path: Path) -> None:
    values = _values(path).copy()
    values.view(np.uint64)[1, 0] ^= np.uint64(1)  # one ulp on one value (uint64: numpy 1.26 too)
    _rewrite(path, values=values)


def _forge_consistent_short_chunk(path: Path) -> None:
    """A self-consistent chunk (valid checksum, right study and range) with a row missing."""
    start, stop = 2 * CHUNK, 3 * CHUNK
    write_chunk(path, _values(path)[:-1], fingerprint=_study().fingerprint(), index=2, start=start, stop=stop)


DAMAGE = {
    "truncated": (lambda p: p.write_bytes(p.read_bytes()[: p.stat().st_size // 2]), "unreadable"),
    "empty": (lambda p: p.write_bytes(b""), "empty file"),
    "random bytes": (lambda p: p.write_bytes(np.random.default_rng(1).bytes(p.stat().st_size)), "not an .npz"),
    "bare npy": (lambda p: p.write_bytes(_npy_bytes(_values(p))), "not an .npz"),
    "other members": (lambda p: np.savez(p, values=_values(p)), "not a chunk archive"),
    "header not json": (lambda p: _rewrite(p, header=np.array("{oops")), "unreadable header"),
    "wrong shape": (lambda p: _rewrite(p, values=_values(p)[:-1]), r"shape \(2, 2\)"),
    "wrong shape, forged header": (_forge_consistent_short_chunk, r"shape \(2, 2\)"),
    "transposed": (lambda p: _rewrite(p, values=np.ascontiguousarray(_values(p)[:2].T)), "shape"),
    "float32": (lambda p: _rewrite(p, values=_values(p).astype(np.float32)), "float32"),
    "scaled by 1.01": (lambda p: _rewrite(p, values=_values(p) * 1.01), "checksum mismatch"),
    "all NaN": (lambda p: _rewrite(p, values=np.full_like(_values(p), np.nan)), "checksum mismatch"),
    "one bit flipped": (_flip_last_bit, "checksum mismatch"),
    "copy of chunk 1": (lambda p: shutil.copyfile(p.with_name("chunk_000001.npz"), p), "holds chunk 1"),
}


@pytest.mark.parametrize("damage", list(DAMAGE))
def test_damaged_chunk_is_recomputed_with_a_warning(run_dir, reference, damage):
    corrupt, reason = DAMAGE[damage]
    corrupt(chunk_path(run_dir, 2))
    messages = _resume_and_compare(run_dir, reference)
    assert sorted(CALLS) == list(range(2 * CHUNK, 3 * CHUNK)), "only chunk 2's points are recomputed"
    assert len(messages) == 1
    assert "recomputing 1 chunk" in messages[0]
    assert any(line.strip().startswith("chunk_000002.npz:") for line in messages[0].splitlines())
    assert re.search(reason, messages[0]), messages[0]
    # the recomputed chunk is stored properly and reused silently afterwards
    assert _resume_and_compare(run_dir, reference) == [] and CALLS == []


def test_chunks_of_another_study_are_recomputed(tmp_path, run_dir, reference):
    other = tmp_path / "other"
    run_sweep(_study(wall=0.004), other, chunk_size=CHUNK, progress=False)  # same grid, other design
    for k in (0, 3):
        shutil.copyfile(chunk_path(other, k), chunk_path(run_dir, k))
    messages = _resume_and_compare(run_dir, reference)
    assert sorted(CALLS) == [0, 1, 2, 9, 10, 11]
    assert len(messages) == 1 and "recomputing 2 chunk" in messages[0]
    for name in ("chunk_000000.npz", "chunk_000003.npz"):
        assert f"{name}: belongs to another study" in messages[0]


def test_stray_files_are_ignored_and_named(run_dir, reference):
    chunks = run_dir / "chunks"
    np.save(chunks / "chunk_000001.npy", np.full((CHUNK, 2), np.nan))  # the old, unchecked format
    (chunks / "chunk_12.npz").write_bytes(b"not a chunk")
    shutil.copyfile(chunk_path(run_dir, 1), chunks / "chunk_000099.npz")  # beyond the grid
    (chunks / "notes.txt").write_text("hello")
    (chunks / "subfolder").mkdir()
    (chunks / ".tmp-k3j2h1.npz").write_bytes(b"half a chunk")  # left by a write cut short
    messages = _resume_and_compare(run_dir, reference)
    assert CALLS == []
    assert len(messages) == 1 and "ignoring 5 file(s)" in messages[0]
    for name in ("chunk_000001.npy", "chunk_12.npz", "chunk_000099.npz", "notes.txt", "subfolder"):
        assert name in messages[0]
    assert ".tmp-" not in messages[0]


def _old_format_manifest(p: Path) -> None:
    stored = json.loads(p.read_text())
    p.write_text(json.dumps({k: stored[k] for k in ("fingerprint", "chunk_size", "size", "study")}))


def _edit_manifest(p: Path) -> None:
    stored = json.loads(p.read_text())
    stored["chunk_size"] = 4
    p.write_text(json.dumps(stored))


MANIFEST_DAMAGE = {
    "deleted": (lambda p: p.unlink(), "manifest.json is missing"),
    "truncated": (lambda p: p.write_bytes(p.read_bytes()[:40]), "unreadable"),
    "random bytes": (lambda p: p.write_bytes(np.random.default_rng(2).bytes(300)), "unreadable"),
    "empty": (lambda p: p.write_text(""), "unreadable"),
    "not an object": (lambda p: p.write_text("[1, 2]"), "not a JSON object"),
    "old format": (_old_format_manifest, "missing"),
    "edited": (_edit_manifest, "checksum mismatch"),
}


@pytest.mark.parametrize("damage", list(MANIFEST_DAMAGE))
def test_missing_or_broken_manifest_starts_afresh(run_dir, reference, damage):
    corrupt, reason = MANIFEST_DAMAGE[damage]
    corrupt(run_dir / "manifest.json")
    messages = _resume_and_compare(run_dir, reference)
    assert sorted(CALLS) == list(range(12)), "no old chunk is reused"
    assert len(messages) == 1
    assert reason in messages[0] and "moved to chunks.discarded-1/" in messages[0]
    assert sorted(p.name for p in (run_dir / "chunks.discarded-1").iterdir()) == [
        f"chunk_{k:06d}.npz" for k in range(4)
    ]
    assert _resume_and_compare(run_dir, reference) == [] and CALLS == []


def test_deleted_manifest_never_reuses_chunks_of_another_design(tmp_path, reference):
    """The fuzzed case: manifest gone, the chunks on disk are another design's."""
    folder = tmp_path / "shared"
    other = run_sweep(_study(wall=0.004), folder, chunk_size=CHUNK, progress=False)
    assert other["wall_mm"].values.tobytes() == _closed_form(0.004)["wall_mm"].tobytes()
    (folder / "manifest.json").unlink()
    messages = _resume_and_compare(folder, reference)
    assert sorted(CALLS) == list(range(12))
    assert len(messages) == 1 and "manifest.json is missing" in messages[0]


def test_broken_manifest_without_chunks_warns_and_starts(tmp_path, reference):
    folder = tmp_path / "run"
    folder.mkdir()
    (folder / "manifest.json").write_text("{")
    messages = _resume_and_compare(folder, reference)
    assert len(messages) == 1 and "manifest.json cannot be trusted" in messages[0]


def failing_study(name: str = "failing", **options) -> Study:
    """The 3 x 4 study whose point (kp = 3e6 N/m, speed = 30 rad/s) raises (``fail``)."""
    return Study(
        name,
        [
            Variable(path="bearings[1].kp", name="kp", values=KP, units="N/m"),
            Variable("speed", SPEED, units="rad/s"),
            Variable("fail", [True]),
        ],
        [Output("stiffness_speed"), Output("wall_mm", "mm")],
        analytic,
        **options,
    )


def test_clean_resume_is_silent_and_keeps_nan_of_failed_points(tmp_path):
    """on_error='nan' chunks are reused as stored: their NaN are results, not damage."""
    study = failing_study()
    first = run_sweep(study, tmp_path / "run", chunk_size=CHUNK, progress=False, on_error="nan")
    failed = np.isnan(first["stiffness_speed"].values[..., 0])
    assert failed.sum() == 1 and failed[2, 3]
    CALLS.clear()
    with warnings.catch_warnings():
        warnings.simplefilter("error", SweepWarning)
        again = run_sweep(study, tmp_path / "run", chunk_size=CHUNK, progress=False, on_error="nan")
    assert CALLS == []
    xr.testing.assert_identical(again, first)


def test_default_chunk_size_is_used_with_a_run_folder(tmp_path):
    run_sweep(_study(), tmp_path / "run", progress=False)  # 12 points, 1 worker: 2 per chunk
    assert json.loads((tmp_path / "run" / "manifest.json").read_text())["chunk_size"] == 2
    assert finished_chunks(tmp_path / "run") == list(range(6))


def test_chunk_name_taken_by_a_folder_is_refused(run_dir):
    chunk_path(run_dir, 1).unlink()
    chunk_path(run_dir, 1).mkdir()
    with pytest.raises(SweepError, match=r"chunk_000001\.npz is not a file"):
        run_sweep(_study(), run_dir, chunk_size=CHUNK, progress=False)

"""Sweep engine: grid, validation, netCDF output, parallel runs and resume after a real kill.

The kill test runs a sweep of cheap points (each sleeps 40 ms and leaves a marker file) in a
subprocess, SIGKILLs (or SIGTERMs) it once a few chunks are on disk, resumes it, and checks that
no point of a stored chunk was evaluated twice and that the final netCDF equals an uninterrupted
run's. The uninterrupted run and the resume run the script's study in this process (CPU budget,
issue 23: each new process imports the engine and xarray again, about 1 s of CPU).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

xr = pytest.importorskip("xarray")

from flexshaft.sweep import Output, Study, SweepError, Variable, chunk_bounds, finished_chunks, run_sweep


def cheap_outputs(point):
    """Closed-form outputs, so the expected grid is known exactly."""
    kp = point.design.bearings[1].kp
    return {"stiffness_sum": kp + point.axes["speed"], "wall_mm": 1e3 * point.design.shaft.wall_thickness}


def shaft_mass(point):
    return {"shaft_mass": point.model.shaft_mass}


def _study(**kw):
    return Study(
        name="cheap",
        variables=[
            Variable(path="shaft.wall_thickness", name="wall", values=[0.002, 0.003], units="m"),
            Variable(path="bearings[1].kp", name="kp", values=np.array([1e6, 2e6, 3e6]), units="N/m"),
            Variable("speed", [0.0, 10.0], units="rad/s"),
        ],
        outputs=[Output("stiffness_sum", "N/m"), Output("wall_mm", "mm")],
        evaluate=cheap_outputs,
        **kw,
    )


def test_grid_values_units_and_netcdf(tmp_path):
    ds = run_sweep(_study(), tmp_path / "run", progress=False, chunk_size=5)
    assert ds["stiffness_sum"].dims == ("wall", "kp", "speed")
    expected = np.array([1e6, 2e6, 3e6])[None, :, None] + np.array([0.0, 10.0])[None, None, :]
    np.testing.assert_array_equal(ds["stiffness_sum"].values, np.broadcast_to(expected, (2, 3, 2)))
    np.testing.assert_allclose(ds["wall_mm"].sel(wall=0.003).values, 3.0)
    assert ds["kp"].attrs["units"] == "N/m" and ds["kp"].attrs["design_path"] == "bearings[1].kp"
    assert ds["speed"].attrs["kind"] == "axis"
    on_disk = xr.load_dataset(tmp_path / "run" / "results.nc")
    xr.testing.assert_identical(on_disk, ds)
    assert finished_chunks(tmp_path / "run") == list(range(len(chunk_bounds(12, 5))))


def test_model_built_per_design_and_processes_match_serial():
    study = Study(
        "mass",
        [Variable(path="shaft.wall_thickness", name="wall", values=[0.002, 0.003, 0.004], units="m")],
        [Output("shaft_mass", "kg")],
        shaft_mass,
    )
    serial = run_sweep(study, progress=False)
    parallel = run_sweep(study, jobs=2, chunk_size=1, progress=False)
    xr.testing.assert_identical(serial, parallel)
    mass = serial["shaft_mass"].values
    np.testing.assert_allclose(
        mass / mass[0],
        [1.0, (0.1016**2 - 0.0956**2) / (0.1016**2 - 0.0976**2), (0.1016**2 - 0.0936**2) / (0.1016**2 - 0.0976**2)],
        rtol=1e-12,
    )


@pytest.mark.parametrize(
    "variable, field",
    [
        (Variable(path="shaft.wal_thickness", values=[0.003]), "shaft.wal_thickness"),
        (Variable(path="shaft.wall_thickness", values=[0.003, -0.001]), "shaft.wall_thickness"),
        (Variable(path="bearings[9].kp", values=[1e6]), "bearings[9]"),
        (Variable(path="shaft.layup", values=["(55/-55/0/0)s", "(55/400)s"]), "shaft.layup"),
    ],
)
def test_bad_variable_is_refused_before_any_computation(variable, field):
    calls = []

    def evaluate(point):  # never reached
        calls.append(point.index)
        return {"x": 0.0}

    with pytest.raises(SweepError, match=field.replace("[", r"\[").replace("]", r"\]")):
        run_sweep(Study("bad", [variable], ["x"], evaluate), progress=False)
    assert calls == []


def test_undeclared_outputs_and_foreign_run_folder(tmp_path):
    with pytest.raises(SweepError, match="missing"):
        run_sweep(Study("o", [Variable("a", [1.0])], ["y"], lambda p: {"x": 1.0}), progress=False)
    run_sweep(_study(), tmp_path, progress=False)
    other = Study("other", [Variable("a", [1.0])], ["x"], lambda p: {"x": 1.0})
    with pytest.raises(SweepError, match="different study"):
        run_sweep(other, tmp_path, progress=False)


#: The killable sweep's study, a module of its own (:func:`killable`) that both the script and
#: this process import by one name: the study's fingerprint names its function
#: ``killable_sweep_study.evaluate``, so a run here and one of the script share their chunks, and
#: a pool's workers find the function by that name.
_STUDY = textwrap.dedent(
    """
    import os, time, uuid
    from pathlib import Path
    import numpy as np
    from flexshaft.sweep import Output, Study, Variable

    def evaluate(point):
        markers = Path(os.environ["SWEEP_MARKERS"])
        (markers / f"{point.index:04d}-{uuid.uuid4().hex}").touch()   # one marker per evaluation
        time.sleep(0.04)
        kp = point.design.bearings[1].kp
        return {"response": np.sin(kp * 1e-6 + point.axes["speed"]), "kp_out": kp}

    study = Study(
        "killable",
        [Variable(path="bearings[1].kp", name="kp", values=np.linspace(1e6, 8e6, 8), units="N/m"),
         Variable("speed", np.linspace(0.0, 1.0, 6), units="rad/s")],
        [Output("response", "1"), Output("kp_out", "N/m")],
        evaluate,
    )
    """
)
_SCRIPT = textwrap.dedent(
    """
    import sys
    from flexshaft.sweep import run_sweep
    from killable_sweep_study import study  # beside this script: its folder is sys.path[0]

    if __name__ == "__main__":
        run_sweep(study, sys.argv[1], jobs=int(sys.argv[2]), chunk_size=4, progress=False)
    """
)


@pytest.fixture(scope="module")
def killable(tmp_path_factory):
    """(folder, study): the folder holding the study's module and the script that runs it, and
    the study as this process imports it from there."""
    folder = tmp_path_factory.mktemp("killable")
    (folder / "killable_sweep_study.py").write_text(_STUDY)
    (folder / "killable_sweep.py").write_text(_SCRIPT)
    with pytest.MonkeyPatch.context() as patch:
        patch.syspath_prepend(str(folder))
        import killable_sweep_study

        try:
            yield folder, killable_sweep_study.study
        finally:
            sys.modules.pop("killable_sweep_study", None)


def _run_script(folder: Path, run_dir: Path, markers: Path, jobs: int = 1):
    markers.mkdir(exist_ok=True)
    env = dict(os.environ, SWEEP_MARKERS=str(markers))
    return subprocess.Popen([sys.executable, str(folder / "killable_sweep.py"), str(run_dir), str(jobs)], env=env)


def _markers_per_point(markers: Path) -> np.ndarray:
    counts = np.zeros(48, int)
    for p in markers.iterdir():
        counts[int(p.name.split("-")[0])] += 1
    return counts


def _run_here(study, run_dir: Path, markers: Path, jobs: int = 1) -> None:
    """The script's sweep run to the end in this process, as ``python killable_sweep.py run_dir
    jobs`` runs it (CPU budget, issue 23: a new process imports the engine and xarray again,
    about 1 s of CPU; the resume reads only the run folder, and a new process would hold
    nothing of the killed one either)."""
    markers.mkdir(exist_ok=True)
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("SWEEP_MARKERS", str(markers))  # before the pool's workers start
        run_sweep(study, run_dir, jobs=jobs, chunk_size=4, progress=False)


@pytest.fixture(scope="module")
def uninterrupted_sweep(tmp_path_factory, killable) -> Path:
    """results.nc of the killable sweep run to the end, once for both kill tests (in this
    process): a sweep's file does not depend on its worker count (the run with ``jobs=1`` and
    ``jobs=2`` are identical, attributes included)."""
    tmp_path = tmp_path_factory.mktemp("uninterrupted")
    _run_here(killable[1], tmp_path / "reference", tmp_path / "ref_markers")
    return tmp_path / "reference" / "results.nc"


@pytest.mark.parametrize("sig, jobs", [(signal.SIGKILL, 1), (signal.SIGTERM, 2)])
def test_killed_sweep_resumes_without_recomputing(tmp_path, sig, jobs, killable, uninterrupted_sweep):
    # interrupted run: kill once at least 3 of the 12 chunks are stored
    folder, study = killable
    run_dir = tmp_path / "run"
    markers = tmp_path / "markers"
    proc = _run_script(folder, run_dir, markers, jobs)
    deadline = time.monotonic() + 60
    while len(finished_chunks(run_dir)) < 3:
        assert proc.poll() is None, "sweep finished before it could be killed"
        assert time.monotonic() < deadline
        time.sleep(0.01)
    proc.send_signal(sig)
    proc.wait(timeout=30)
    stored = finished_chunks(run_dir)
    assert proc.returncode != 0, f"the sweep ended normally before the signal (chunks {stored})"
    assert 3 <= len(stored) < 12 and not (run_dir / "results.nc").exists(), f"stored chunks {stored}"
    before = _markers_per_point(markers)
    # resume, with as many workers, in this process
    _run_here(study, run_dir, markers, jobs)
    after = _markers_per_point(markers)
    stored_points = np.concatenate([np.arange(4 * k, 4 * k + 4) for k in stored])
    assert np.all(after[stored_points] == 1), "a point of a finished chunk was recomputed"
    assert np.all(after - before >= 0) and np.all(after >= 1)
    assert np.all((after - before)[stored_points] == 0)
    final = xr.load_dataset(run_dir / "results.nc")
    reference = xr.load_dataset(uninterrupted_sweep)
    xr.testing.assert_identical(final, reference)
    assert np.isfinite(final["response"].values).all()


def test_thesis_ply_angle_study_runs_and_labels(tmp_path):
    from flexshaft.thesis.ply_angle import one_angle_layup, ply_angle_study

    assert one_angle_layup(55.0) == {"shaft.layup": "(55/-55/-55/55)"}
    ds = ply_angle_study([45.0, 55.0], run_dir=tmp_path, progress=False)
    assert ds["safety_factor"].dims == ("alpha",) and ds["alpha"].attrs["units"] == "deg"
    assert np.all(ds["safety_factor"].values > 1.0)
    # no imbalance in this study: the total equals the static safety factor
    np.testing.assert_allclose(ds["safety_factor"].values, ds["safety_factor_static"].values, rtol=1e-12)

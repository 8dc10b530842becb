"""Pool workers end with the sweep process, even when it is killed with SIGKILL.

A subprocess runs a cheap sweep with ``jobs=2``; every evaluation leaves a marker naming the
worker's pid and how it watches its parent. Once both workers have computed and a few chunks
are stored, the test SIGKILLs the subprocess (which can run no cleanup), then checks that
every worker is gone within a few seconds and that the subprocess's stdout pipe, which the
workers inherited, reaches end of file. The run is then resumed (in this process: the chunks
are the killed process's, written before the kill) and must give exactly the closed form
``y = x**2`` (an IEEE-exact square; no tolerance), with no chunk rejected.

Both mechanisms are exercised: Linux's parent-death signal and the portable watchdog thread
(the fallback elsewhere, forced here through the engine's switch).
"""

from __future__ import annotations

import os
import select
import signal
import subprocess
import sys
import textwrap
import time
import warnings
from pathlib import Path

import numpy as np
import pytest

xr = pytest.importorskip("xarray")

from flexshaft.sweep import SweepWarning, finished_chunks, run_sweep

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")

_STUDY = textwrap.dedent(
    """
    import os, sys, threading, time
    from pathlib import Path
    import numpy as np
    from flexshaft.sweep import Output, Study, Variable, run_sweep

    MARKERS = Path(os.environ["SWEEP_MARKERS"])

    def evaluate(point):
        watchdog = any(t.name == "flexshaft-parent-watch" for t in threading.enumerate())
        (MARKERS / f"{os.getpid()}-{'watchdog' if watchdog else 'pdeathsig'}").touch()
        time.sleep(0.04)
        return {"y": point.axes["x"] ** 2}

    study = Study("orphans", [Variable("x", np.arange(80.0))], [Output("y")], evaluate)
    """
)
_SCRIPT = (
    textwrap.dedent(
        """
        import os
        import flexshaft.sweep.run as engine
        if os.environ.get("SWEEP_WATCHDOG"):
            engine._USE_PDEATHSIG = False        # inherited by the forked workers
        """
    )
    + _STUDY
    + textwrap.dedent(
        """
        if __name__ == "__main__":
            import multiprocessing
            multiprocessing.set_start_method(os.environ["SWEEP_START"])
            print("started", flush=True)
            run_sweep(study, sys.argv[1], jobs=2, chunk_size=2, progress=False)
        """
    )
)


def _resume_here(run_dir: Path, markers: Path) -> list[warnings.WarningMessage]:
    """Run the script's sweep to the end in this process, with one process (the resume reads
    only the run folder: a pool of its own would resume the same chunks), and return the
    warnings it gave. The study is the script's own, defined in a module named ``__main__``:
    the study's fingerprint names its function ``__main__.evaluate``, so this run and the
    script's share their chunks."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("SWEEP_MARKERS", str(markers))
        script = {"__name__": "__main__"}
        exec(compile(_STUDY, "orphan_sweep.py", "exec"), script)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        run_sweep(script["study"], run_dir, jobs=1, chunk_size=2, progress=False)
    return caught


def _stat(pid: int) -> tuple[str, int] | None:
    """(state, start time [clock ticks]) of a process, or None if it is gone."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except (FileNotFoundError, ProcessLookupError):
        return None
    return fields[0], int(fields[19])


def _alive(pid: int, started: int) -> bool:
    """True if process ``pid`` (the one started at ``started``) has not exited (a zombie has)."""
    stat = _stat(pid)
    return stat is not None and stat[1] == started and stat[0] not in ("Z", "X")


def _worker_markers(markers: Path, parent: int) -> dict[int, str]:
    found = {}
    for p in markers.iterdir():
        pid, how = p.name.split("-")
        if int(pid) != parent:
            found[int(pid)] = how
    return found


@pytest.mark.parametrize(
    "mechanism, start",
    [("pdeathsig", "fork"), ("watchdog", "fork"), ("pdeathsig", "forkserver")],
    ids=["pdeathsig", "watchdog", "forkserver-default"],
)
def test_sigkilled_sweep_leaves_no_worker_and_resumes(tmp_path, mechanism, start):
    """``start``: the script's default start method (a forkserver default is replaced by spawn)."""
    script = tmp_path / "orphan_sweep.py"
    script.write_text(_SCRIPT)
    markers = tmp_path / "markers"
    markers.mkdir()
    run_dir = tmp_path / "run"
    env = dict(os.environ, SWEEP_MARKERS=str(markers))
    if mechanism == "watchdog":
        env["SWEEP_WATCHDOG"] = "1"
    env["SWEEP_START"] = start
    proc = subprocess.Popen([sys.executable, str(script), str(run_dir)], env=env, stdout=subprocess.PIPE)
    workers: dict[int, str] = {}
    started: dict[int, int] = {}  # pid -> start time, so a reused pid is not mistaken for a worker
    try:
        deadline = time.monotonic() + 60
        while len(workers) < 2 or len(finished_chunks(run_dir)) < 3:
            assert proc.poll() is None, "sweep finished before it could be killed"
            assert time.monotonic() < deadline, "workers did not start"
            time.sleep(0.01)
            workers = _worker_markers(markers, proc.pid)
            started.update({pid: stat[1] for pid in workers if pid not in started and (stat := _stat(pid))})
        assert set(workers.values()) == {mechanism} and set(started) == set(workers)
        proc.kill()
        proc.wait(timeout=10)
        # The kernel signal is immediate; the watchdog looks every 0.5 s. 5 s is ample for both.
        deadline = time.monotonic() + 5
        while any(_alive(pid, t) for pid, t in started.items()) and time.monotonic() < deadline:
            time.sleep(0.05)
        survivors = [pid for pid, t in started.items() if _alive(pid, t)]
        assert survivors == [], f"workers {survivors} outlived the killed sweep"
        # nothing holds the sweep's stdout any more: the pipe reaches end of file
        fd = proc.stdout.fileno()
        while time.monotonic() < deadline + 5:
            ready, _, _ = select.select([fd], [], [], 0.5)
            if ready and os.read(fd, 4096) == b"":
                break
        else:
            pytest.fail("the sweep's stdout is still held open")
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        proc.stdout.close()
        for pid, t in started.items():  # only if the test failed: leave no orphan on the machine
            if _alive(pid, t):
                os.kill(pid, signal.SIGKILL)
    stored = finished_chunks(run_dir)
    assert 3 <= len(stored) < 40 and not (run_dir / "results.nc").exists()
    # the resume, in this process (CPU budget, issue 23: a new process imports the engine and
    # xarray again, and its pool's workers, spawned in the forkserver case, import them too)
    caught = _resume_here(run_dir, markers)
    rejected = [str(w.message) for w in caught if issubclass(w.category, SweepWarning)]
    assert rejected == [], "a chunk written before SIGKILL was rejected"
    final = xr.load_dataset(run_dir / "results.nc")
    assert final["y"].values.tobytes() == (np.arange(80.0) ** 2).tobytes()


def _start_worker_whose_parent_is_gone(use_pdeathsig: bool) -> None:
    """In a child: set up as a worker whose parent is recorded as pid 1 (not ours: "gone")."""
    from flexshaft.sweep import run as engine

    engine._USE_PDEATHSIG = use_pdeathsig
    engine._die_with_parent(1)
    time.sleep(10)  # the check must end the process before this returns


@pytest.mark.parametrize("use_pdeathsig", [True, False], ids=["pdeathsig", "watchdog"])
def test_worker_whose_parent_died_before_setup_exits(use_pdeathsig):
    """The race the PID check closes: the parent died between the fork and the prctl call."""
    import multiprocessing

    child = multiprocessing.get_context("fork").Process(
        target=_start_worker_whose_parent_is_gone, args=(use_pdeathsig,)
    )
    child.start()
    child.join(timeout=5)
    if child.is_alive():
        child.kill()
        child.join()
        pytest.fail("the worker did not notice that its parent was gone")
    assert child.exitcode == 1

"""Independent tasks on a pool of forked workers (``flexshaft run``'s parallel stages): the same
results as in this process, errors kept or raised as declared, and the pool's own contract."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np
import pytest

from flexshaft.parallel.pool import worker_pool
from flexshaft.parallel.tasks import Task, start_tasks

needs_fork = pytest.mark.skipif(not hasattr(os, "fork"), reason="the pool needs fork")


def _square(x):
    return x * x, os.getpid()


def _refuse(x):
    raise ValueError(f"refused {x}")


def _broken(x):
    raise KeyError(x)


def test_one_process_gives_no_pool():
    with worker_pool(1) as pool:
        assert pool is None
    with pytest.raises(ValueError, match="processes"):
        with worker_pool(0):
            pass


@needs_fork
def test_tasks_run_in_workers_and_come_back_in_task_order():
    tasks = [Task(f"t{k}", f"task {k}", _square, (k,), cost=float(k)) for k in range(6)]
    with worker_pool(2) as pool:
        outcomes = start_tasks(tasks, pool).results()
    assert list(outcomes) == [t.key for t in tasks]  # task order, although submitted longest first
    assert [o.value[0] for o in outcomes.values()] == [k * k for k in range(6)]
    assert {o.value[1] for o in outcomes.values()} - {os.getpid()}, "nothing ran in a worker"
    assert all(o.error is None and o.seconds >= 0 for o in outcomes.values())


def _collected(module: str, name: str) -> bool:
    """Whether the collector's generations hold ``module.name`` (frozen objects are in none)."""
    import gc

    tracked = {id(o) for o in gc.get_objects()}
    return id(getattr(sys.modules[module], name)) in tracked


@needs_fork
def test_a_worker_freezes_what_it_imported_at_start():
    """The collector's full passes skip the warm imports (flexshaft.parallel.pool._start_worker)."""
    assert "wave" not in sys.modules  # a module this process has not imported
    assert _collected("json", "JSONDecodeError")  # a class this process has: tracked here
    with worker_pool(2, ("wave",)) as pool:
        assert not pool.submit(_collected, "wave", "Wave_read").result()


@pytest.mark.parametrize("pooled", [False, pytest.param(True, marks=needs_fork)])
def test_declared_errors_are_kept_and_others_raised(pooled):
    with worker_pool(2 if pooled else 1) as pool:
        out = start_tasks(
            [Task("a", "a", _square, (3,)), Task("b", "b", _refuse, (4,))], pool, errors=(ValueError,)
        ).results()
        assert out["a"].value[0] == 9 and out["a"].error is None
        assert isinstance(out["b"].error, ValueError) and "refused 4" in str(out["b"].error)
        with pytest.raises(KeyError):
            start_tasks([Task("c", "c", _broken, (1,))], pool, errors=(ValueError,)).results()


def test_task_keys_must_be_unique():
    with pytest.raises(ValueError, match="unique"):
        start_tasks([Task("a", "a", _square, (1,)), Task("a", "b", _square, (2,))])


@needs_fork
def test_a_design_error_crosses_the_process_boundary_intact():
    from flexshaft.design import DesignError, baseline_design, with_overrides

    bad = {"bearings[1].kp": -1.0}
    with worker_pool(2) as pool:
        out = start_tasks(
            [Task("d", "d", with_overrides, (baseline_design(), bad))], pool, errors=(DesignError,)
        ).results()
    err = out["d"].error
    assert isinstance(err, DesignError) and err.problems and err.problems[0].path.startswith("bearings[1]")


def test_stacked_single_row_maps_equal_the_map_in_one_call():
    """The run computes the (K_p, K_d) onset map one K_p row per task: stacking the rows gives
    the map computed in one call (each row is an independent model and modal basis)."""
    from flexshaft.design import baseline_design, with_overrides
    from flexshaft.thesis.whirl import gain_stability_map, stack_maps

    design = with_overrides(baseline_design(), {"mesh.shaft_elements": 18, "mesh.boom_elements": 12})
    speeds = np.linspace(0.0, 1.5 * design.operating.speed_rad_s, 9)
    kp, kd = [3e5, 1e7], [0.0, 1170.0]
    whole = gain_stability_map(design, kp, kd, speeds, n_modes=6)
    rows = stack_maps([gain_stability_map(design, [k], kd, speeds, n_modes=6) for k in kp])
    np.testing.assert_array_equal(rows.kp, whole.kp)
    np.testing.assert_array_equal(rows.onset_speed, whole.onset_speed)
    np.testing.assert_array_equal(rows.margin_at_operating, whole.margin_at_operating)
    with pytest.raises(ValueError, match="K_d"):
        stack_maps([whole, gain_stability_map(design, [1e6], [0.0], speeds, n_modes=6)])


@needs_fork
def test_an_assessment_on_a_pool_equals_the_one_in_process():
    """`flexshaft run` computes the design's analyses as tasks on its worker pool: the numbers
    (results.json) are exactly those of the run in one process. On a coarse mesh (8 shaft, 4
    boom elements: an equality of two ways to run the same analyses, whatever the model's
    size; CPU budget, issue 23)."""
    from dataclasses import replace

    from flexshaft.design import baseline_design, design_from_dict, with_overrides
    from flexshaft.report.results_json import json_ready, results_json
    from flexshaft.resolution import REPORT
    from flexshaft.verdict.assess import assess

    design = with_overrides(baseline_design(), {"mesh.shaft_elements": 8, "mesh.boom_elements": 4})
    data = design.model_dump()  # two of its envelope points: each point's tasks on the pool
    data["envelope"]["points"] = data["envelope"]["points"][:2]
    design = design_from_dict(data)
    resolution = replace(REPORT, spinup_speeds=101, campbell_speeds=11)
    serial = assess(design, resolution)
    with worker_pool(2) as pool:
        pooled = assess(design, resolution, executor=pool)

    def text(res):
        return json.dumps(json_ready(results_json(res)), sort_keys=True)

    assert text(serial) == text(pooled)
    np.testing.assert_array_equal(np.asarray(serial.spinup.response), np.asarray(pooled.spinup.response))


def test_cli_sets_one_blas_thread_unless_the_user_chose():
    """The CLI limits BLAS to one thread per process (it parallelises over processes) but
    keeps a value the user set."""
    code = (
        "import os, sys; from flexshaft.cli import _one_blas_thread_per_process as f; f(); "
        "print(os.environ['OPENBLAS_NUM_THREADS'], os.environ['MKL_NUM_THREADS'])"
    )
    env = {
        k: v for k, v in os.environ.items() if k not in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "OMP_NUM_THREADS")
    }
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["1", "1"]
    out = subprocess.run(
        [sys.executable, "-c", code],
        env={**env, "OPENBLAS_NUM_THREADS": "2"},
        capture_output=True,
        text=True,
        check=True,
    )
    assert out.stdout.split() == ["2", "1"]


_LIFETIME = """
import os, signal, sys, time
from flexshaft.parallel.pool import worker_pool

def sleep(seconds):
    time.sleep(seconds)
    return os.getpid()

if __name__ == "__main__":
    # a terminal's Ctrl-C raises KeyboardInterrupt; the test runner may have left SIGINT ignored
    signal.signal(signal.SIGINT, signal.default_int_handler)
    with worker_pool(2) as pool:
        futures = [pool.submit(sleep, 30.0) for _ in range(4)]
        time.sleep(1.0)  # both workers are in a task now
        print(" ".join(str(p.pid) for p in pool._processes.values()), flush=True)
        if sys.argv[1] == "kill":
            os.kill(os.getpid(), signal.SIGKILL)
        os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C
        time.sleep(30)
"""


def _gone(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/status") as f:
            return f.read().split("State:")[1].split()[0] == "Z"  # dead, not yet reaped by init
    except FileNotFoundError:
        return True


@needs_fork
@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")
@pytest.mark.parametrize("how", ["interrupt", "kill"])
def test_workers_end_with_the_command(tmp_path, how):
    """Ctrl-C ends the pool at once (queued work cancelled, running tasks killed: 30 s tasks,
    the command ends within seconds); a SIGKILL of the command ends its workers too
    (PR_SET_PDEATHSIG), so no worker outlives it either way."""
    import time

    script = tmp_path / "lifetime.py"
    script.write_text(_LIFETIME)
    start = time.monotonic()
    proc = subprocess.run([sys.executable, str(script), how], capture_output=True, text=True, timeout=25)
    elapsed = time.monotonic() - start
    # an uncaught KeyboardInterrupt ends Python by SIGINT (-2); SIGKILL is -9
    assert proc.returncode == (-9 if how == "kill" else -2), proc.stderr[-2000:]
    pids = [int(p) for p in proc.stdout.split()]
    assert len(pids) == 2
    deadline = time.monotonic() + 5
    while not all(_gone(p) for p in pids) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert all(_gone(p) for p in pids), "a worker outlived its command"
    assert elapsed < 15, f"the command took {elapsed:.1f} s to end"


def test_one_blas_thread_limits_and_restores_every_blas_library():
    """Reference: threadpoolctl's own report of the loaded BLAS libraries (a fresh process with
    two BLAS threads, so that the limit is visible)."""
    code = (
        "import numpy, scipy.linalg; from threadpoolctl import threadpool_info as info; "
        "from flexshaft.parallel.threads import one_blas_thread\n"
        "before = [i['num_threads'] for i in info() if i['user_api'] == 'blas']\n"
        "for _ in range(3):\n"
        "    with one_blas_thread(): inside = [i['num_threads'] for i in info() if i['user_api'] == 'blas']\n"
        "after = [i['num_threads'] for i in info() if i['user_api'] == 'blas']\n"
        "import json; print(json.dumps([before, inside, after]))"
    )
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "2", "OMP_NUM_THREADS": "2", "MKL_NUM_THREADS": "2"}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True).stdout
    before, inside, after = json.loads(out)
    assert before and all(n == 2 for n in before)
    assert inside == [1] * len(before) and after == before

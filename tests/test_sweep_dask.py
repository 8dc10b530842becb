"""The same sweep on a dask.distributed LocalCluster gives the local run's numbers exactly."""

from __future__ import annotations

import numpy as np
import pytest

xr = pytest.importorskip("xarray")
distributed = pytest.importorskip("distributed")
dask = pytest.importorskip("dask")

from flexshaft.sweep import Output, Study, Variable, run_sweep


def peak_actuator_force(point):
    """A real (small) analysis per point: the actuator force at the operating speed."""
    from flexshaft.analyses import imbalance_response
    from flexshaft.analyses.reactions import actuator_response
    from flexshaft.assembly.loads import imbalance_loads

    model = point.model
    speed = point.axes["speed"]
    q = imbalance_response(model, [speed], imbalance_loads(model))[:, 0]
    disp, force = actuator_response(model, q, np.array([speed]))
    return {"force": float(max(f[0] for f in force.values())), "mass": model.shaft_mass}


def test_local_cluster_matches_local_run(tmp_path):
    study = Study(
        "dask check",
        [
            Variable(path="shaft.wall_thickness", name="wall", values=[0.0025, 0.003, 0.0035], units="m"),
            Variable("speed", [300.0, 500.0], units="rad/s"),
        ],
        [Output("force", "N"), Output("mass", "kg")],
        peak_actuator_force,
    )
    local = run_sweep(study, progress=False, chunk_size=2)
    with (
        dask.config.set({"temporary-directory": str(tmp_path / "dask-scratch")}),  # not /tmp/dask-scratch-space
        distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None) as cluster,
    ):
        with distributed.Client(cluster) as client:
            remote = run_sweep(study, tmp_path / "run", client=client, progress=False, chunk_size=2)
    xr.testing.assert_identical(local, remote)
    xr.testing.assert_identical(xr.load_dataset(tmp_path / "run" / "results.nc"), local)
    assert np.all(remote["force"].values > 0)


_FAULTS = """
import resource, sys
import numpy as np
from flexshaft.sweep.dask import worker_heap
def faults():
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    for _ in range(50):
        a = np.ones(2**18)  # 2 MiB, above glibc's 128 kB mmap threshold
        del a
    return resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before
faults()
plain = faults()
state = worker_heap()
faults()
print(state, plain, faults())
"""


@pytest.mark.parametrize("trim", [None, "65536", str(2**30)])
def test_worker_heap_undoes_only_dasks_small_trim_threshold(trim):
    """Dask's nanny starts workers with MALLOC_TRIM_THRESHOLD_=65536, which turns off glibc's
    adaptive mmap threshold: every 2 MiB array is then a fresh mmap whose 512 pages fault in
    again (50 arrays: about 25 600 minor page faults, counted by getrusage). worker_heap() sets
    the thresholds back above that size (the same loop then faults a few times at most) and
    leaves any other setting alone.

    One fresh process per setting (glibc reads the variable at start): the loop once to warm
    up, then counted ("plain"), then worker_heap(), the loop once more to warm up, then
    counted ("fix"). The plain loops' arrays are mmapped and unmapped again, or reuse the
    heap the warm-up grew: they leave the heap as they found it for the fix's loops."""
    import os
    import subprocess
    import sys

    env = {k: v for k, v in os.environ.items() if k != "MALLOC_TRIM_THRESHOLD_"}
    if trim is not None:
        env["MALLOC_TRIM_THRESHOLD_"] = trim
    out = subprocess.run([sys.executable, "-c", _FAULTS], env=env, capture_output=True, text=True, check=True)
    state, plain, fix = out.stdout.strip().rsplit(" ", 2)
    plain, fix = int(plain), int(fix)
    if trim == "65536":
        assert state == "heap thresholds set"
        assert plain > 50 * 512 * 0.9  # every array faults in anew
        assert fix < 50 * 512 * 0.05
    else:
        assert state == "unchanged"
        if trim is None:  # glibc's adaptive threshold: the heap reuses the pages
            assert plain < 50 * 512 * 0.05
        else:  # the user's own setting is left alone: it faults as before
            assert abs(fix - plain) < 50 * 512 * 0.1

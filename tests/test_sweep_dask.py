"""The same sweep on a dask.distributed LocalCluster gives the local run's numbers exactly."""

from __future__ import annotations

import numpy as np
import pytest

xr = pytest.importorskip("xarray")
distributed = pytest.importorskip("distributed")

from flexshaft.sweep import Output, Study, Variable, run_sweep


def peak_actuator_force(point):
    """A real (small) analysis per point: the actuator force at the operating speed."""
    from flexshaft.analyses import imbalance_response
    from flexshaft.analyses.response import actuator_response
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
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None
    ) as cluster:
        with distributed.Client(cluster) as client:
            remote = run_sweep(study, tmp_path / "run", client=client, progress=False, chunk_size=2)
    xr.testing.assert_identical(local, remote)
    xr.testing.assert_identical(xr.load_dataset(tmp_path / "run" / "results.nc"), local)
    assert np.all(remote["force"].values > 0)

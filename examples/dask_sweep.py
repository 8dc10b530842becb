"""A design sweep on a Dask cluster: wall thickness × actuator stiffness, saved as netCDF.

Physics. On the tuned driveline, the shaft wall thickness t and the proportional gain K_p of
both active magnetic bearings are varied together. For every pair the model is rebuilt and the
damped eigenvalues at the operating speed are computed: the lowest lateral natural frequency
of the shaft-dominated modes and the smallest logarithmic decrement δ = 2πζ/√(1 − ζ²) of the
whirl modes (lateral modes with at least 10 % of their kinetic energy in the shaft, the modes
the whirl-damping requirement δ ≥ 0.1 applies to). A stiffer actuator
raises the frequencies of the modes it holds; the wall sets the shaft's mass and bending
stiffness and, through the composite's loss, its internal damping.

How. :class:`flexshaft.sweep.Study` names the design-file fields by their dotted paths
(``"shaft.wall_thickness"``, ``"bearings[1].kp"``); :func:`flexshaft.sweep.run_sweep` runs the
grid in chunks on a ``dask.distributed`` client (here a ``LocalCluster``; a scheduler address
or a ``dask_jobqueue`` cluster work the same), stores each finished chunk so that a killed run
resumes, and returns an ``xarray.Dataset`` (``results.nc`` in the run folder). The same study
run in this process gives the same numbers bit for bit, which the example checks.

Needs ``dask[distributed]`` (``pip install "flexshaft[dask]"``); without it the example says
so and exits cleanly.

Run: ``python examples/dask_sweep.py [--quick] [--out DIR]``. ``--quick``: 2 × 2 points on a
cluster of threads instead of 3 × 3 points on two worker processes.
"""

from __future__ import annotations

import argparse
import shutil
from pathlib import Path

import numpy as np

from flexshaft.design import embedded_design
from flexshaft.sweep import Output, Study, Variable, run_sweep


def whirl_modes(point) -> dict:
    """Lowest shaft-mode frequency [Hz] and smallest whirl-mode log decrement [-] at the operating speed."""
    from flexshaft.analyses import modes

    model = point.model
    result = modes(model, model.speed, n_modes=12)
    lateral = result.kind == "lateral"
    shaft_dominated = lateral & (result.shaft_fractions > 0.5)
    whirl = lateral & (result.shaft_fractions >= 0.1)
    return {
        "shaft_frequency": float(result.frequencies[shaft_dominated].min()),
        "min_log_decrement": float(result.log_decrements[whirl].min()),
    }


def both_actuators(kp: float) -> dict:
    """The same proportional gain [N/m] on both active bearings (bearings 1 and 2 of the design)."""
    return {"bearings[1].kp": kp, "bearings[2].kp": kp}


def make_study(quick: bool) -> Study:
    walls = [0.0025, 0.0035] if quick else [0.0025, 0.003, 0.0035]
    gains = [3e5, 1e6] if quick else [2e5, 5e5, 1e6]
    return Study(
        name="wall and actuator stiffness",
        variables=[
            Variable(path="shaft.wall_thickness", name="wall", values=walls, units="m"),
            Variable(name="kp", values=gains, units="N/m", overrides=both_actuators),
        ],
        outputs=[
            Output("shaft_frequency", "Hz", "lowest shaft-dominated lateral frequency"),
            Output("min_log_decrement", "1", "smallest whirl-mode log decrement"),
        ],
        evaluate=whirl_modes,
        base=embedded_design("tuned"),
    )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="4 points on threads (for the test suite)")
    parser.add_argument("--out", type=Path, default=Path("example-output/dask_sweep"), help="output folder")
    args = parser.parse_args(argv)
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        print('dask.distributed is not installed: pip install "flexshaft[dask]"; nothing to do')
        return 0

    study = make_study(args.quick)
    run_dir = args.out / "run"
    shutil.rmtree(run_dir, ignore_errors=True)  # start afresh (an existing folder would resume)
    with (
        LocalCluster(n_workers=2, threads_per_worker=1, processes=not args.quick, dashboard_address=None) as cluster,
        Client(cluster) as client,
    ):
        results = run_sweep(study, run_dir, client=client, progress=False)

    for name in ("shaft_frequency", "min_log_decrement"):
        table = results[name]
        print(f"{name} [{table.attrs.get('units', '')}] (rows: wall [m], columns: kp [N/m])")
        print(np.array2string(table.values, precision=4))
    local = run_sweep(study, progress=False)
    same = all(np.array_equal(results[name].values, local[name].values) for name in local.data_vars)
    print(f"\nDask and in-process results identical: {same}; saved to {run_dir / 'results.nc'}")
    return 0 if same else 1


if __name__ == "__main__":
    raise SystemExit(main())

"""The sweep engine on a Dask LocalCluster against the local process pool and serial.

Two workloads, each on the sweep engine (:func:`flexshaft.sweep.run_sweep`):

* ``montecarlo``: :func:`flexshaft.montecarlo.run_montecarlo` of the baseline, ``--samples``
  imbalance samples (default 400, the sweep size of issue 30);
* ``optimize``: :func:`flexshaft.optimize.optimize`, NSGA-II on the Table 3.1 problem (mass and
  Tsai-Wu safety factor), ``--budget`` evaluations (one evaluation per chunk).

Each runs serially (``jobs=1``), on the local pool (``jobs=W``) and on a ``LocalCluster`` of W
single-threaded worker processes (``client=``), for W in ``--workers``. The cluster is started
before the clock and kept for all its runs; a first, untimed run on it lets its workers import
flexshaft (a long-lived cluster pays that once). The pool starts its workers inside every call
(fork), as ``flexshaft montecarlo --jobs`` does. Printed: median wall time, CPU of this process,
speed-up = serial wall / wall, efficiency per worker = speed-up / W, Dask / pool at the same W,
the CPU time of every process of the run (this one, the pool's workers, the Dask workers; the
scheduler runs in this process) and the CPU efficiency = serial CPU / that (the share of the
work that is the study's own, which the shared VM's load moves less than the wall times).
Results are checked equal to the serial run's.

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/dask_scaling.py --workers 1 2 --repeats 3
    .venv/bin/python benchmarks/dask_scaling.py --cases montecarlo --samples 100 --repeats 1   # quick
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

import bench_util as bu

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")


def _forget_unit_responses() -> None:
    from flexshaft.montecarlo import steady

    cached = getattr(steady, "_unit_responses", None)
    if hasattr(cached, "cache_clear"):
        cached.cache_clear()


def _montecarlo(samples: int):
    from flexshaft.design import baseline_design
    from flexshaft.montecarlo import run_montecarlo

    design = baseline_design()

    def run(**backend):
        # every run computes the unit responses once per process, as a fresh command does: the
        # per-process cache is emptied here (the pool's workers fork from here) and on the workers
        _forget_unit_responses()
        if "client" in backend:
            backend["client"].run(_forget_unit_responses)
        res = run_montecarlo(design, samples, seed=7, grade_mm_s=6.3, **backend)
        ds = res.dataset
        return {k: ds[k].values.copy() for k in ds.data_vars}

    return run


def _optimize(budget: int):
    from flexshaft.design import baseline_design
    from flexshaft.optimize import DesignProblem, default_variables, optimize

    variables, layup = default_variables(baseline_design())
    problem = DesignProblem(variables, layup=layup, objectives=("shaft_mass", "safety_factor"), name="Table 3.1")

    def run(**backend):
        with tempfile.TemporaryDirectory(prefix="flexshaft-dask-") as out:
            res = optimize(problem, budget, Path(out) / "run", seed=3, pop_size=max(8, budget // 3), **backend)
            ev = res.evaluations
            return {k: ev[k].values.copy() for k in ("shaft_mass", "safety_factor")}

    return run


def _same(a: dict, b: dict) -> bool:
    import numpy as np

    return a.keys() == b.keys() and all(np.array_equal(a[k], b[k], equal_nan=True) for k in a)


def _children_cpu() -> float:
    import resource

    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _process_cpu() -> float:
    return time.process_time()


def _timed(run, **backend) -> tuple[float, float, dict, float]:
    """(wall, CPU of this process, results, CPU of every process: this one, the pool's workers
    (reaped at the end of the call) or the Dask workers (asked before and after))."""
    client = backend.get("client")
    workers0 = sum(client.run(_process_cpu).values()) if client is not None else 0.0
    w0, c0, k0 = time.perf_counter(), time.process_time(), _children_cpu()
    out = run(**backend)
    wall, cpu, children = time.perf_counter() - w0, time.process_time() - c0, _children_cpu() - k0
    workers = sum(client.run(_process_cpu).values()) - workers0 if client is not None else 0.0
    return wall, cpu, out, cpu + children + workers


def measure(name: str, run, workers: list[int], repeats: int) -> list[dict]:
    from distributed import Client, LocalCluster

    rows = []
    serial = [_timed(run, jobs=1) for _ in range(repeats)]
    reference = serial[0][2]
    rows.append(
        {
            "backend": "serial",
            "workers": 1,
            "walls": [s[0] for s in serial],
            "cpus": [s[1] for s in serial],
            "all": [s[3] for s in serial],
        }
    )
    for w in workers:
        if w == 1:  # jobs=1 runs in this process: the pool's row is the serial one
            rows.append({**rows[0], "backend": "pool", "workers": 1, "ok": True})
        else:
            pool = [_timed(run, jobs=w) for _ in range(repeats)]
            ok = all(_same(p[2], reference) for p in pool)
            walls, cpus, every = [p[0] for p in pool], [p[1] for p in pool], [p[3] for p in pool]
            rows.append({"backend": "pool", "workers": w, "walls": walls, "cpus": cpus, "all": every, "ok": ok})
        start = time.perf_counter()
        with (
            LocalCluster(n_workers=w, threads_per_worker=1, processes=True, dashboard_address=None) as cluster,
            Client(cluster) as client,
        ):
            started = time.perf_counter() - start
            run(client=client)  # untimed: the workers import flexshaft once
            dask = [_timed(run, client=client) for _ in range(repeats)]
        ok = all(_same(d[2], reference) for d in dask)
        rows.append(
            {
                "backend": "dask",
                "workers": w,
                "walls": [d[0] for d in dask],
                "cpus": [d[1] for d in dask],
                "all": [d[3] for d in dask],
                "ok": ok,
                "cluster_start": started,
            }
        )
    base = statistics.median(rows[0]["walls"])
    base_cpu = statistics.median(rows[0]["all"])
    pool_wall = {r["workers"]: statistics.median(r["walls"]) for r in rows if r["backend"] == "pool"}
    print(f"\n{name}")
    print(
        f"  {'backend':7s} {'W':>2s} {'wall [s]':>8s} {'min-max':>11s} {'speed-up':>8s} {'eff./worker':>11s} "
        f"{'/ pool':>6s} {'CPU all [s]':>11s} {'CPU eff.':>8s}  same results"
    )
    for r in rows:
        wall = statistics.median(r["walls"])
        speedup = base / wall
        vs_pool = f"{wall / pool_wall[r['workers']]:6.2f}" if r["backend"] == "dask" else " " * 6
        every = statistics.median(r["all"])
        extra = f"; cluster start {r['cluster_start']:.1f} s" if "cluster_start" in r else ""
        print(
            f"  {r['backend']:7s} {r['workers']:2d} {wall:8.2f} {min(r['walls']):5.2f}-{max(r['walls']):<5.2f} "
            f"{speedup:8.2f} {speedup / r['workers']:11.2f} {vs_pool} {every:11.2f} {base_cpu / every:8.2f}  "
            f"{r.get('ok', True)}{extra}"
        )
    return rows


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--cases", nargs="+", choices=("montecarlo", "optimize"), default=["montecarlo", "optimize"])
    p.add_argument("--workers", nargs="+", type=int, default=[1, 2])
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--samples", type=int, default=400)
    p.add_argument("--budget", type=int, default=48)
    a = p.parse_args(argv)
    m = bu.machine_info()
    print(
        f"sweep engine: serial, local pool, Dask LocalCluster; {m['cores']} cores, load average "
        f"{m['load_average_1_5_15']}, {m['date']}, git {m['git_commit']}; BLAS threads {m['blas_threads_env']}"
    )
    import dask
    import distributed

    print(f"dask {dask.__version__}, distributed {distributed.__version__}; medians of {a.repeats}")
    if "montecarlo" in a.cases:
        measure(f"montecarlo: {a.samples} samples of the baseline", _montecarlo(a.samples), a.workers, a.repeats)
    if "optimize" in a.cases:
        measure(
            f"optimize: NSGA-II, {a.budget} evaluations, Table 3.1 problem", _optimize(a.budget), a.workers, a.repeats
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())

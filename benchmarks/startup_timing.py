"""Start-up of ``flexshaft run``: process start to the first analysis call, CPU and wall.

Each repeat starts a fresh interpreter that runs ``flexshaft run --studies X`` through the CLI
(``flexshaft.cli.app``) with two entry points wrapped: the thesis studies' start
(``start_thesis_studies``, the first analysis call of ``--studies report|full``) and the
assessment (``assess``, the first with ``--studies none``). At the first of them the child
records its own CPU time since it started (``time.process_time``: the interpreter, the imports,
the design's parsing, the pool's fork; not the workers) and the wall clock, and exits: nothing
after that point is timed. The wall time runs from just before the parent starts the child.

With ``--reference SRC`` (another checkout's ``src``, e.g. ``git worktree add --detach
/tmp/ref <commit>``) every repeat also runs the same on that code, right after, and the table
gives the median of the pairs' ratios. Both trees are byte-compiled first (a user's every run
but the first starts from compiled modules; this VM sets ``PYTHONDONTWRITEBYTECODE``).

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/startup_timing.py --repeats 7 --reference /tmp/ref/src
    .venv/bin/python benchmarks/startup_timing.py --importtime    # the 25 costliest imports, once

``--importtime`` runs one child under ``python -X importtime`` and prints the modules with the
largest cumulative import time up to the first analysis call (nested modules included).
"""

from __future__ import annotations

import argparse
import compileall
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import bench_util as bu

#: The child: the CLI with its first analysis call replaced by a probe that writes the times.
CHILD = r"""
import json, os, sys, time
out = os.environ["STARTUP_PROBE_OUT"]

def _first_analysis(*args, **kwargs):
    cpu, wall = time.process_time(), time.time()
    with open(out, "w") as f:
        json.dump({"cpu": cpu, "wall_end": wall, "modules": len(sys.modules),
                   "xarray": "xarray" in sys.modules, "matplotlib": "matplotlib" in sys.modules,
                   "dask": "dask" in sys.modules, "pandas": "pandas" in sys.modules}, f)
    os._exit(0)  # the pool's workers die with their parent (prctl PDEATHSIG)

class _Patch:
    # after these modules are imported (wherever the CLI imports them), wrap the entry points
    targets = {"flexshaft.verdict.assess": "assess", "flexshaft.thesis.report_studies": "start_thesis_studies"}
    def find_spec(self, name, path, target=None):
        if name not in self.targets:
            return None
        sys.meta_path.remove(self)
        try:
            import importlib.util
            spec = importlib.util.find_spec(name)
        finally:
            sys.meta_path.insert(0, self)
        loader = spec.loader
        attr = self.targets[name]
        class _Loader:
            def create_module(self, spec):
                return loader.create_module(spec)
            def exec_module(self, module):
                loader.exec_module(module)
                setattr(module, attr, _first_analysis)
        spec.loader = _Loader()
        return spec

sys.meta_path.insert(0, _Patch())
sys.argv = ["flexshaft", *sys.argv[1:]]
from flexshaft.cli import app
app()
"""


def _env(src: str | None) -> dict:
    env = dict(os.environ)
    env.setdefault("OPENBLAS_NUM_THREADS", "1")
    env["MPLBACKEND"] = "Agg"
    if src is not None:
        env["PYTHONPATH"] = src
    return env


def _package(src: str | None) -> str:
    if src is not None:
        return os.path.join(src, "flexshaft")
    import flexshaft

    return os.path.dirname(os.path.abspath(flexshaft.__file__))


def probe_once(src: str | None, studies: str) -> dict:
    """One child process; returns its CPU [s] and wall [s] up to the first analysis call."""
    with tempfile.TemporaryDirectory(prefix="flexshaft-startup-") as tmp:
        out = os.path.join(tmp, "probe.json")
        env = {**_env(src), "STARTUP_PROBE_OUT": out}
        start = time.time()
        proc = subprocess.run(
            [sys.executable, "-c", CHILD, "run", "--studies", studies, "--out", os.path.join(tmp, "r")],
            capture_output=True,
            text=True,
            env=env,
        )
        if not os.path.isfile(out):
            sys.stderr.write(proc.stderr[-3000:])
            raise SystemExit(f"the child did not reach the first analysis call (status {proc.returncode})")
        with open(out) as f:
            data = json.load(f)
    data["wall"] = data.pop("wall_end") - start
    return data


def importtime(src: str | None, studies: str, top: int) -> None:
    """The ``top`` costliest imports (cumulative, microseconds) up to the first analysis call."""
    with tempfile.TemporaryDirectory(prefix="flexshaft-startup-") as tmp:
        env = {**_env(src), "STARTUP_PROBE_OUT": os.path.join(tmp, "probe.json")}
        proc = subprocess.run(
            [sys.executable, "-X", "importtime", "-c", CHILD, "run", "--studies", studies, "--out", f"{tmp}/r"],
            capture_output=True,
            text=True,
            env=env,
        )
    rows = []
    for line in proc.stderr.splitlines():
        if line.startswith("import time:") and "|" in line and "cumulative" not in line:
            own, cumulative, name = (part.strip() for part in line[len("import time:") :].split("|"))
            rows.append((int(cumulative), int(own), name))
    print(f"costliest imports before the first analysis call ({src or 'this checkout'}), cumulative [ms]:")
    for cumulative, own, name in sorted(rows, reverse=True)[:top]:
        print(f"  {cumulative / 1e3:8.1f} {own / 1e3:8.1f}  {name}")


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--studies", choices=("report", "full", "none"), default="report")
    p.add_argument("--repeats", type=int, default=7)
    p.add_argument("--reference", default=None, help="another checkout's src folder, timed in pairs")
    p.add_argument("--importtime", action="store_true", help="print the costliest imports instead")
    p.add_argument("--top", type=int, default=25)
    a = p.parse_args(argv)
    codes = {"now": None} if a.reference is None else {"now": None, "reference": os.path.abspath(a.reference)}
    for src in codes.values():
        compileall.compile_dir(_package(src), quiet=1)
    if a.importtime:
        for src in codes.values():
            importtime(src, a.studies, a.top)
        return 0
    runs: dict[str, list[dict]] = {name: [] for name in codes}
    for src in codes.values():  # one untimed round: the file cache
        probe_once(src, a.studies)
    for _ in range(a.repeats):
        for name, src in codes.items():
            runs[name].append(probe_once(src, a.studies))
    m = bu.machine_info()
    print(
        f"flexshaft run --studies {a.studies}: process start to the first analysis call; {a.repeats} repeats, "
        f"{m.get('cpu_count', os.cpu_count())} CPUs, load average {os.getloadavg()[0]:.2f}, "
        f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}"
    )
    print(f"{'code':10s} {'CPU median [s]':>14s} {'min-max':>13s} {'wall median [s]':>15s} {'min-max':>13s}  imported")
    for name, rs in runs.items():
        cpu, wall = [r["cpu"] for r in rs], [r["wall"] for r in rs]
        last = rs[-1]
        loaded = (
            ", ".join(k for k in ("xarray", "pandas", "dask", "matplotlib") if last[k])
            or "none of xarray/pandas/dask/matplotlib"
        )
        print(
            f"{name:10s} {statistics.median(cpu):14.3f} {min(cpu):6.3f}-{max(cpu):<6.3f} "
            f"{statistics.median(wall):15.3f} {min(wall):6.3f}-{max(wall):<6.3f}  {last['modules']} modules; {loaded}"
        )
    if a.reference is not None:
        for key in ("cpu", "wall"):
            ratio = statistics.median(r[key] / n[key] for r, n in zip(runs["reference"], runs["now"]))
            print(f"reference / now, {key}: {ratio:.2f} (median of the pairs' ratios)")
    return 0


if __name__ == "__main__":
    sys.exit(main())

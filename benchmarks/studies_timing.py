"""Wall time of the design studies and of ``flexshaft run`` (timing lives here, not in tests).

    .venv/bin/python benchmarks/studies_timing.py [--cases studies-coarse run-none run-report]
                                                  [--repeats 3] [--blas-threads 1] [--json FILE]
                                                  [--reference OTHER_CHECKOUT/src]

Cases:

* ``studies-coarse``: ``flexshaft.thesis.design_studies.design_studies(design, "report")`` on the
  baseline with the reduced mesh of ``tests/test_studies.py`` (18 shaft, 12 boom elements), in
  this process: the first call (cold: lazy imports included) and ``--repeats`` more (warm).
  The test used to assert that this takes under 25 s;
* ``studies-report``: the same on the baseline's own mesh (what ``flexshaft run`` does);
* ``run-none``, ``run-report``, ``run-full``: the command ``flexshaft run --studies X --out DIR``
  as a fresh process per repeat (interpreter start, imports, every analysis and the report
  written), timed from outside; its CPU time is the child's user + system time
  (``getrusage(RUSAGE_CHILDREN)`` difference), split into the command's own process (main: the
  assessment's serial part, the report's data files) and its pool workers (the studies, the
  assessment's tasks, the figures), which the command reports at exit. ``run-full`` is not in
  the default set (long);
* ``run-nofigures``: ``flexshaft run --studies none --no-figures`` (a scripted ``--strict``
  gate's run: the verdict and the data files, no figure drawn), beside ``run-none``.

With ``--reference``, each ``run-*`` repeat also runs the same command on another checkout's
code (``PYTHONPATH=OTHER/src``, e.g. ``git worktree add --detach /tmp/old <commit>``) right
after, and the table gives the median of the pairs' ratios (reference / now).

Bytecode (``--bytecode``): every code's modules are byte-compiled before the ``run-*`` repeats
(``cached``, the default), as Python does on a first run and ``pip install .`` at install time,
so the repeats time a user's every run. ``source`` times the first run after an editable install
instead: the checkouts' ``__pycache__`` folders are removed before each repeat and the runs do
not write them (``PYTHONDONTWRITEBYTECODE=1``), so every process compiles flexshaft's ~140
modules from source (the workers compile again what they import themselves). A machine that sets
``PYTHONDONTWRITEBYTECODE`` (this VM does) runs an editable install like ``source`` every time.

Printed: median (min–max) wall time and median CPU time per case, and the CPU of the ``run-*``
cases' main process and workers.
"""

from __future__ import annotations

import argparse
import compileall
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import bench_util as bu  # noqa: E402

COARSE = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}  # as in tests/test_studies.py
CASES = ("studies-coarse", "studies-report", "run-none", "run-nofigures", "run-report", "run-full")
DEFAULT_CASES = ("studies-coarse", "run-none", "run-report")


def time_studies(coarse: bool, repeats: int) -> dict:
    from flexshaft.design import baseline_design, with_overrides
    from flexshaft.thesis.design_studies import design_studies

    design = with_overrides(baseline_design(), COARSE) if coarse else baseline_design()
    cold_wall, cold_cpu, _ = bu.timed(lambda: design_studies(design, "report"))
    runs = [bu.timed(lambda: design_studies(design, "report"))[:2] for _ in range(repeats)]
    return {
        "cold_s": cold_wall,
        "cold_cpu_s": cold_cpu,
        "warm": {**bu.stats([w for w, _ in runs]), "cpu": bu.stats([c for _, c in runs])},
    }


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


#: ``flexshaft`` as ``python -c``, writing at exit the CPU time of its own process (the run's
#: main process) and of its waited-for children (the run's pool workers, joined before the
#: command ends) to the JSON file named by FLEXSHAFT_BENCH_CPU. Imports nothing before the CLI
#: (it sets one BLAS thread only if numpy is not loaded yet).
_SPLIT_CPU = """
import atexit, json, os, resource, sys

def _split():
    s, c = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.environ["FLEXSHAFT_BENCH_CPU"], "w") as f:
        json.dump({"main": s.ru_utime + s.ru_stime, "workers": c.ru_utime + c.ru_stime}, f)

atexit.register(_split)
sys.argv[0] = "flexshaft"
from flexshaft.cli import main
main()
"""


def _time_command(cmd: list[str], env: dict | None) -> tuple[float, float, dict]:
    """Run ``flexshaft`` with the arguments ``cmd``: (wall [s], CPU of the process and its
    children [s], {"main": CPU of the command's own process, "workers": CPU of its children})."""
    env = dict(os.environ if env is None else env)
    fd, split_file = tempfile.mkstemp(prefix="flexshaft-cpu-", suffix=".json")
    os.close(fd)
    env["FLEXSHAFT_BENCH_CPU"] = split_file
    full = [sys.executable, "-c", _SPLIT_CPU, *cmd]
    try:
        c0, w0 = _children_cpu(), time.perf_counter()
        proc = subprocess.run(full, capture_output=True, text=True, env=env)
        wall, cpu = time.perf_counter() - w0, _children_cpu() - c0
        if proc.returncode != 0:
            sys.stderr.write(proc.stderr[-3000:])
            raise SystemExit(f"flexshaft {' '.join(cmd)} failed with status {proc.returncode}")
        with open(split_file) as f:
            split = json.load(f)
    finally:
        os.remove(split_file)
    return wall, cpu, split


def speed_probe() -> float:
    """Seconds of a fixed pure-Python loop (2.5 million additions): the shared VM's speed drifts
    by up to 1.7x from one minute to the next, and this says how fast it ran beside a repeat
    (compare runs by it: a run at a probe 1.5x longer is about 1.5x slower for that reason)."""
    start = time.process_time()
    total = 0
    for i in range(2_500_000):
        total += i
    return time.process_time() - start


def wait_for_speed(fastest: float | None, patience: float = 120.0) -> float:
    """The probe now (best of 3); with ``fastest``, first wait (probing every 5 s, at most
    ``patience`` seconds) until it is at most ``fastest``: repeats then run at the VM's fast
    moments only."""
    deadline = time.monotonic() + patience
    while True:
        probe = min(speed_probe() for _ in range(3))
        if fastest is None or probe <= fastest or time.monotonic() > deadline:
            return probe
        time.sleep(5.0)


def _package_folder(src: str | None) -> str:
    """The flexshaft package a run imports: ``src/flexshaft`` of a checkout, or this one's."""
    if src is not None:
        return os.path.join(src, "flexshaft")
    import flexshaft

    return os.path.dirname(os.path.abspath(flexshaft.__file__))


def _prepare_bytecode(package: str, bytecode: str) -> None:
    """``cached``: byte-compile the package (no-op when up to date); ``source``: remove its
    ``__pycache__`` folders (a checkout only: an installed package keeps its bytecode)."""
    if bytecode == "cached":
        compileall.compile_dir(package, quiet=1)
        return
    if os.path.basename(os.path.dirname(package)) != "src":
        raise SystemExit(f"--bytecode source needs a source checkout (src/flexshaft), not {package}")
    for root, dirs, _ in os.walk(package):
        if "__pycache__" in dirs:
            shutil.rmtree(os.path.join(root, "__pycache__"))
            dirs.remove("__pycache__")


def time_run(
    studies: str,
    repeats: int,
    reference: str | None = None,
    fastest: float | None = None,
    bytecode: str = "cached",
    extra: tuple[str, ...] = (),
) -> dict:
    """``flexshaft run --studies X`` as a fresh process, ``repeats`` times; with a
    ``reference`` source folder (another checkout's ``src``), each repeat also runs the same
    command on that code right after (PYTHONPATH), so that both see the same machine load.
    ``bytecode``: see the module docstring; ``extra``: more options of the command."""
    codes = {"now": None} if reference is None else {"now": None, "reference": os.path.abspath(reference)}
    times = {name: ([], [], [], []) for name in codes}  # wall, CPU, CPU of the main process, of the workers
    probes = []
    for _ in range(repeats):
        probes.append(wait_for_speed(fastest))
        for name, src in codes.items():
            _prepare_bytecode(_package_folder(src), bytecode)
            env = dict(os.environ)
            if src is not None:
                env["PYTHONPATH"] = src
            if bytecode == "source":
                env["PYTHONDONTWRITEBYTECODE"] = "1"
            with tempfile.TemporaryDirectory(prefix="flexshaft-timing-") as out:
                wall, cpu, split = _time_command(["run", "--studies", studies, *extra, "--out", out], env)
            for series, value in zip(times[name], (wall, cpu, split["main"], split["workers"])):
                series.append(value)
    walls, cpus, mains, workers = times["now"]
    probes.append(speed_probe())
    result = {
        "warm": {
            **bu.stats(walls),
            "cpu": bu.stats(cpus),
            "main_cpu": bu.stats(mains),
            "workers_cpu": bu.stats(workers),
        },
        "command": " ".join(["flexshaft run --studies", studies, *extra]),
        "probe": bu.stats(probes),
        "bytecode": bytecode,
    }
    if reference is not None:
        ref_walls, ref_cpus, ref_mains, ref_workers = times["reference"]
        result["reference"] = {
            **bu.stats(ref_walls),
            "cpu": bu.stats(ref_cpus),
            "main_cpu": bu.stats(ref_mains),
            "workers_cpu": bu.stats(ref_workers),
            "source": codes["reference"],
        }
        result["cpu_ratio"] = statistics.median(r / c for r, c in zip(ref_cpus, cpus))
        result["speedup"] = statistics.median(r / w for r, w in zip(ref_walls, walls))
    return result


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--cases", nargs="+", default=list(DEFAULT_CASES), choices=list(CASES))
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument(
        "--blas-threads", type=int, default=1, help="BLAS/OpenMP threads (default 1; 0 = the libraries' defaults)"
    )
    p.add_argument("--json", help="also write the measurements to this JSON file")
    p.add_argument(
        "--reference",
        metavar="SRC",
        help="another checkout's src folder: each run-* repeat also runs it (PYTHONPATH), back to back",
    )
    p.add_argument(
        "--fast-probe",
        type=float,
        metavar="SECONDS",
        help="run each run-* repeat only once the speed probe is at most SECONDS (waits up to 2 min): "
        "compares codes at the shared VM's fast moments",
    )
    p.add_argument(
        "--bytecode",
        choices=("cached", "source"),
        default="cached",
        help="run-* cases: modules byte-compiled beforehand (cached: every run but the first after an "
        "editable install) or compiled from source by every run (source: the first run)",
    )
    a = p.parse_args(argv)
    if a.repeats < 1:
        p.error(f"--repeats must be at least 1 (got {a.repeats})")
    bu.reexec_with_threads(a.blas_threads, __file__)
    results = {}
    for name in a.cases:
        print(f"[studies_timing] {name} ...", flush=True)
        if name.startswith("studies-"):
            results[name] = time_studies(name == "studies-coarse", a.repeats)
        elif name == "run-nofigures":  # a scripted gate: the verdict and results.json, no figures drawn
            results[name] = time_run("none", a.repeats, a.reference, a.fast_probe, a.bytecode, ("--no-figures",))
        else:
            results[name] = time_run(name.split("-", 1)[1], a.repeats, a.reference, a.fast_probe, a.bytecode)
        r = results[name]
        cold = f"cold {r['cold_s']:.2f} s, " if "cold_s" in r else ""
        ref = (
            f"; reference {bu.fmt_stats(r['reference'], 2)} s, {r['speedup']:.2f}x faster now"
            if "reference" in r
            else ""
        )
        print(
            f"[studies_timing] {name}: {cold}{bu.fmt_stats(r['warm'], 2)} s "
            f"(CPU {r['warm']['cpu']['median']:.2f} s){ref}",
            flush=True,
        )

    import flexshaft

    m = bu.machine_info()
    print()
    print(
        f"machine: {m['cpu']}, {m['cores']} cores, load average {m['load_average_1_5_15']} "
        f"(shared); {m['date']}; flexshaft {flexshaft.__version__} (git {m['git_commit']}), "
        f"Python {m['python']}; BLAS threads {m['blas_threads_env']}; run-* bytecode: {a.bytecode}"
    )
    print()
    print(
        "| case | cold [s] | wall, median (min–max) [s] | CPU median [s] | reference wall [s] (CPU) "
        "| reference / now | repeats | speed probe [s] |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for name, r in results.items():
        cold = f"{r['cold_s']:.2f}" if "cold_s" in r else "–"
        ref = (
            f"{bu.fmt_stats(r['reference'], 2)} ({r['reference']['cpu']['median']:.2f}) | {r['speedup']:.2f}×"
            if "reference" in r
            else "– | –"
        )
        probe = bu.fmt_stats(r["probe"], 3) if "probe" in r else "–"
        print(
            f"| {name} | {cold} | {bu.fmt_stats(r['warm'], 2)} | {r['warm']['cpu']['median']:.2f} | {ref} "
            f"| {r['warm']['n']} | {probe} |"
        )
    runs = {name: r for name, r in results.items() if "main_cpu" in r["warm"]}
    if runs:
        print()
        print(
            "| case | CPU main process [s] | CPU workers [s] | CPU total [s] | reference main [s] "
            "| reference workers [s] | reference total [s] | reference / now (CPU, paired) |"
        )
        print("|---|---:|---:|---:|---:|---:|---:|---:|")
        for name, r in runs.items():
            now = [r["warm"][k]["median"] for k in ("main_cpu", "workers_cpu", "cpu")]
            ref = r.get("reference")
            ref_cells = (
                [f"{ref[k]['median']:.2f}" for k in ("main_cpu", "workers_cpu", "cpu")] + [f"{r['cpu_ratio']:.2f}×"]
                if ref is not None
                else ["–"] * 4
            )
            print(f"| {name} | " + " | ".join([*(f"{v:.2f}" for v in now), *ref_cells]) + " |")
    print()
    print(
        "studies-*: design_studies(..., 'report') in one process; cold = its first call, the "
        "others after it. run-*: `flexshaft run --studies X` as a fresh process each time "
        "(start-up, imports, analyses, report). Speed probe: a fixed pure-Python loop timed before "
        "each repeat and after the last (wall times scale with it on the shared VM). CPU split "
        "(medians): the command's own process (main) and its pool workers (its children)."
    )
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"machine": m, "results": results}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Small helpers shared by the benchmark scripts: repeat statistics, memory, machine facts.

Pure Python (no numpy, no flexshaft, no ross) so that the ROSS interpreters import it too.
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

__all__ = [
    "THREAD_VARS",
    "timed",
    "stats",
    "fmt_stats",
    "maxrss_mb",
    "current_rss_mb",
    "machine_info",
    "blas_env",
    "single_thread_env",
    "reexec_with_threads",
]

THREAD_VARS = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS")


def timed(fn):
    """Call ``fn()`` once; returns (wall time [s], CPU time of this process [s], result).

    The CPU time (``time.process_time``, all threads of the process) is less sensitive than the
    wall time to other processes competing for the cores of a shared machine."""
    w0, c0 = time.perf_counter(), time.process_time()
    result = fn()
    return time.perf_counter() - w0, time.process_time() - c0, result


def stats(times: list[float]) -> dict:
    """Median, min and max of repeated timings [s]."""
    return {
        "median": statistics.median(times),
        "min": min(times),
        "max": max(times),
        "n": len(times),
        "all": list(times),
    }


def fmt_stats(s: dict, digits: int = 3) -> str:
    """``median (min–max)`` in seconds, for tables."""
    f = _fmt_seconds
    return f"{f(s['median'], digits)} ({f(s['min'], digits)}–{f(s['max'], digits)})"


def _fmt_seconds(t: float, digits: int) -> str:
    if t >= 10:
        return f"{t:.1f}"
    if t >= 1:
        return f"{t:.2f}"
    return f"{t:.{digits}f}"


def maxrss_mb() -> float:
    """Peak resident set size of this process so far [MB] (Linux ``ru_maxrss`` is in KiB)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def current_rss_mb() -> float:
    """Current resident set size of this process [MB] (Linux /proc; NaN elsewhere)."""
    try:
        with open("/proc/self/statm") as f:
            pages = int(f.read().split()[1])
        return pages * os.sysconf("SC_PAGE_SIZE") / 2**20
    except (OSError, ValueError, IndexError):
        return float("nan")


def blas_env() -> dict:
    return {k: os.environ.get(k, "default") for k in THREAD_VARS}


def single_thread_env(threads: int) -> dict:
    """The environment with every BLAS/OpenMP/numba thread count set to ``threads``."""
    return dict(os.environ, **{k: str(threads) for k in THREAD_VARS})


def run_in_tree(source, job: str, *args, threads: int = 1) -> dict:
    """Run the Python code ``job`` (with ``args`` as its ``sys.argv[1:]``) in a fresh process
    on the flexshaft source tree ``source`` (its ``src`` first on PYTHONPATH) with ``threads``
    BLAS threads (0: no thread variable set, the libraries' defaults, as in a notebook's
    kernel); returns the JSON object of its last line of output."""
    if threads:
        base = single_thread_env(threads)
    else:
        base = {k: v for k, v in os.environ.items() if k not in THREAD_VARS}
    env = dict(base, PYTHONPATH=os.path.join(str(source), "src"))
    out = subprocess.run([sys.executable, "-c", job, *map(str, args)], env=env, capture_output=True, text=True)
    if out.returncode:
        raise SystemExit(f"the job failed in {source}:\n{out.stderr}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def paired_runs(checkout, reference, rounds: int, job: str, *args, threads: int = 1) -> tuple[dict, dict]:
    """``(trees, runs)``: this checkout and, when given, the ``reference`` source tree by name,
    and the results of :func:`run_in_tree` of ``job`` in each (``threads`` BLAS threads), the
    trees alternating ``rounds`` times (so a change of the machine's load falls on both)."""
    trees = {"this checkout": checkout}
    if reference:
        trees["reference"] = reference.resolve()
    runs: dict[str, list[dict]] = {name: [] for name in trees}
    for _ in range(rounds):
        for name, path in trees.items():
            runs[name].append(run_in_tree(path, job, *args, threads=threads))
    return trees, runs


def paired_parser(
    description: str, repeats: int, repeats_help: str = "warm calls per round"
) -> argparse.ArgumentParser:
    """The options of a benchmark paired against a reference tree (:func:`paired_runs`):
    ``--reference``, ``--repeats``, ``--rounds`` and ``--blas-threads``; add the script's own."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--reference", type=Path, help="another flexshaft source tree to compare with")
    parser.add_argument("--repeats", type=int, default=repeats, help=repeats_help)
    parser.add_argument("--rounds", type=int, default=2, help="alternating runs of each tree")
    parser.add_argument("--blas-threads", type=int, default=1)
    return parser


def print_heading(title: str, blas_threads: int) -> dict:
    """Print a paired benchmark's first two lines (what, when, which commit; the machine, its
    load and the BLAS threads) and return :func:`machine_info`."""
    info = machine_info()
    print(f"{title}, {info.get('date', '')} commit {info.get('git_commit', '?')}")
    print(f"  {info.get('cpu', '')}, load {info.get('load_average_1_5_15')}, BLAS threads {blas_threads}")
    return info


def reexec_with_threads(threads: int, script: str) -> None:
    """Restart ``script`` with the thread variables set, unless they already are.

    Thread counts are read when numpy (OpenBLAS) loads, so they must be in the environment
    before the first import; child processes inherit them. ``threads = 0`` leaves the
    libraries' defaults.
    """
    if threads and any(os.environ.get(k) != str(threads) for k in THREAD_VARS):
        env = single_thread_env(threads)
        os.execve(sys.executable, [sys.executable, os.path.abspath(script), *sys.argv[1:]], env)


def _cpu_model() -> str:
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def _mem_total_gb() -> float:
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal"):
                    return int(line.split()[1]) / 2**20
    except OSError:
        pass
    return float("nan")


def _git_commit() -> str:
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        out = subprocess.run(
            ["git", "-C", here, "rev-parse", "--short", "HEAD"], capture_output=True, text=True, timeout=10
        )
        return out.stdout.strip() or "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def machine_info() -> dict:
    """Facts that qualify a timing: CPU, cores, memory, load, date, Python, BLAS threads."""
    try:
        load = os.getloadavg()
    except OSError:
        load = (float("nan"),) * 3
    return {
        "date": datetime.datetime.now().astimezone().isoformat(timespec="seconds"),
        "cpu": _cpu_model(),
        "cores": os.cpu_count(),
        "memory_gb": round(_mem_total_gb(), 1),
        "load_average_1_5_15": [round(x, 2) for x in load],
        "platform": platform.platform(),
        "python": platform.python_version(),
        "blas_threads_env": blas_env(),
        "openblas_coretype": os.environ.get("OPENBLAS_CORETYPE", "unset"),
        "git_commit": _git_commit(),
    }

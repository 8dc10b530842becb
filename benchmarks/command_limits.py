"""Every command at its documented maximum: it finishes in the time stated, or is refused up front.

Runs each command of ``flexshaft`` on the embedded default design at the largest values its
``--help`` allows (and at the combinations its bound refuses), one after another in a
temporary folder, and prints the exit code, CPU time, wall time and peak resident memory of
each, with the first line of a refusal. The table in docs/limits.md ("6. The work of a
command") comes from this script.

    python benchmarks/command_limits.py            # all (about 15 min of CPU)
    python benchmarks/command_limits.py --quick    # the refusals and the cheap maxima only
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from bench_util import machine_info

#: (command line, slow): the documented maxima and the combinations the bounds refuse.
CASES = [
    (["modes", "--n-modes", "500"], False),
    (["stability", "--n-speeds", "2000"], False),
    (["stability", "--n-modes", "100"], True),
    (["stability", "--n-speeds", "2000", "--n-modes", "100"], False),
    (["stability", "--compare-thesis", "--n-speeds", "2000"], True),
    (["thermal", "--self-heating", "--sweeps"], False),
    (["runup", "--duration", "312"], True),
    (["runup", "--duration", "3600"], False),
    (["runup", "--dwell", "3600"], False),
    (["study", "spinup-map", "--n-speeds", "10000"], True),
    (["study", "spinup-map", "--n-gains", "400"], True),
    (["study", "spinup-map", "--n-gains", "400", "--n-speeds", "10000"], False),
    (["study", "ply-angle", "--step", "0.5"], False),
    (["study", "two-angle", "--step", "1"], True),
    (["study", "all", "--resolution", "full"], True),
    (["montecarlo", "--samples", "2000"], True),
    (["optimize", "--budget", "100000"], False),
    (["run", "--studies", "full"], True),
    (["compare"], True),
    (["validate"], True),
]

OUTPUT = {"runup", "study", "montecarlo", "optimize", "run", "compare"}


def measure(args: list[str], folder: str, index: int) -> dict:
    command = [sys.executable, "-c", "import sys; from flexshaft.cli import app; sys.argv[0] = 'flexshaft'; app()"]
    command += args + (["--out", f"out{index}"] if args[0] in OUTPUT else [])
    start = time.perf_counter()
    # the children run in a temporary folder: a relative PYTHONPATH (``src``) would not reach the
    # checkout measured, so they get this process's flexshaft by its absolute path
    import flexshaft

    source = str(Path(flexshaft.__file__).resolve().parents[1])
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([source, *filter(None, [os.environ.get("PYTHONPATH")])]))
    process = subprocess.Popen(
        command, cwd=folder, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True
    )
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    stderr = process.stderr.read()
    process.stderr.close()
    code = os.waitstatus_to_exitcode(status)
    first = next((line for line in stderr.splitlines() if line.startswith("error:")), "")
    return {
        "code": code,
        "cpu": usage.ru_utime + usage.ru_stime,
        "wall": wall,
        "memory_mb": usage.ru_maxrss / 1024,
        "error": first,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="skip the cases that take minutes")
    parser.add_argument("--blas-threads", type=int, default=1)
    options = parser.parse_args()
    if options.blas_threads:
        for name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
            os.environ[name] = str(options.blas_threads)
    print(json.dumps(machine_info(), default=str))
    print("| command | exit | CPU [s] | wall [s] | peak memory [MB] | refusal |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as folder:
        for index, (args, slow) in enumerate(CASES):
            if slow and options.quick:
                continue
            r = measure(args, folder, index)
            print(
                f"| `flexshaft {' '.join(args)}` | {r['code']} | {r['cpu']:.1f} | {r['wall']:.1f} | "
                f"{r['memory_mb']:.0f} | {r['error'][:160]} |",
                flush=True,
            )


if __name__ == "__main__":
    main()

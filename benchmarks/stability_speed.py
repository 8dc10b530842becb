"""Whirl-stability speed: the thesis's three-shaft comparison, this checkout against a reference.

Runs the same job in two source trees, each in its own process with one BLAS thread:
``flexshaft.thesis.whirl.compare_shafts(baseline, speeds, method, n_modes=8)`` for the thesis's
aluminium, (45/-45)s and (45/-45/0/0)s shafts on the embedded baseline, speeds 0 to 1.5× the
operating speed. Prints the median and spread of ``--repeats`` warm runs (one untimed run
first), the onset speeds of both, and the speed ratio.

    .venv/bin/python benchmarks/stability_speed.py --reference /path/to/old/checkout

The reference is any flexshaft source tree (e.g. ``git worktree add /tmp/old <commit>``); its
``src/`` is put first on PYTHONPATH. Without ``--reference`` only this checkout is timed.
"""

from __future__ import annotations

import argparse
import statistics
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import bench_util as bu  # noqa: E402

JOB = r"""
import json, sys, time
import numpy as np
import flexshaft as fs
from flexshaft.thesis.whirl import compare_shafts
method, n_speeds, repeats = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
design = fs.baseline_design()
speeds = np.linspace(0.0, 1.5 * design.operating.speed_rad_s, n_speeds)
compare_shafts(design, speeds, method, n_modes=8)  # warm-up (imports, first calls)
times = []
for _ in range(repeats):
    t = time.perf_counter()
    res = compare_shafts(design, speeds, method, n_modes=8)
    times.append(time.perf_counter() - t)
onsets = {k: (None if r.onset_speed is None else r.onset_speed * 60 / (2 * np.pi)) for k, r in res.items()}
print(json.dumps({"times": times, "onsets_rpm": onsets}))
"""


def run(source: Path, method: str, n_speeds: int, repeats: int) -> dict:
    return bu.run_in_tree(source, JOB, method, n_speeds, repeats)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reference", type=Path, help="another flexshaft source tree to compare with")
    parser.add_argument("--method", default="hysteretic", choices=["hysteretic", "viscous"])
    parser.add_argument("--speeds", type=int, default=31)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    trees = {"this checkout": HERE.parent}
    if args.reference:
        trees["reference"] = args.reference.resolve()
    results = {name: run(path, args.method, args.speeds, args.repeats) for name, path in trees.items()}
    print(f"three-shaft {args.method} stability, {args.speeds} speeds, 8 modes, {args.repeats} warm repeats")
    for name, r in results.items():
        t = r["times"]
        print(f"  {name:14s} median {statistics.median(t):7.3f} s  (min {min(t):.3f}, max {max(t):.3f})")
        for shaft, onset in r["onsets_rpm"].items():
            print(f"      {shaft:22s} onset {'stable' if onset is None else f'{onset:8.1f} rpm'}")
    if "reference" in results:
        ratio = statistics.median(results["reference"]["times"]) / statistics.median(results["this checkout"]["times"])
        print(f"  speed-up: {ratio:.1f}x")


if __name__ == "__main__":
    main()

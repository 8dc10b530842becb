"""Torsional-buckling speed: the report's wall-thickness buckling study, this checkout against a reference.

Runs the same job in two source trees, each in its own process with one BLAS thread:
``flexshaft.analyses.shaft_buckling.shaft_buckling`` (shear-deformable shell, as study 5 and
the verdict use it) on the embedded tuned design at each wall of the report resolution
(1 to 6 mm), plus the design's own analysis with the classical shell compared. Prints the
median and spread of ``--repeats`` warm runs (one untimed run first), the critical torques of
both trees, their largest relative difference, and the speed ratio.

    .venv/bin/python benchmarks/buckling_speed.py --reference /path/to/old/checkout

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
from flexshaft.analyses.shaft_buckling import shaft_buckling
from flexshaft.design import tuned_design, with_overrides
from flexshaft.assembly import build_model
from flexshaft.thesis.design_studies import STUDY_GRIDS as RESOLUTIONS
repeats = int(sys.argv[1])
design = tuned_design()
models = [build_model(with_overrides(design, {"shaft.wall_thickness": float(w)}))
          for w in RESOLUTIONS["report"]["walls"]]
own = build_model(design)

def job():
    torques = [min(r.result.torque_positive, r.result.torque_negative)
               for r in (shaft_buckling(m, compare_classical=False) for m in models)]
    mine = shaft_buckling(own)
    return torques + [mine.result.torque_positive, mine.result.torque_negative]

job()  # warm-up (imports, first calls)
times = []
for _ in range(repeats):
    t = time.perf_counter()
    torques = job()
    times.append(time.perf_counter() - t)
print(json.dumps({"times": times, "torques": torques}))
"""


def run(source: Path, repeats: int) -> dict:
    return bu.run_in_tree(source, JOB, repeats)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reference", type=Path, help="another flexshaft source tree to compare with")
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    trees = {"this checkout": HERE.parent}
    if args.reference:
        trees["reference"] = args.reference.resolve()
    results = {name: run(path, args.repeats) for name, path in trees.items()}
    print(
        f"shear-deformable torsional buckling at the report's 9 walls + the design's own analysis, "
        f"{args.repeats} warm repeats"
    )
    for name, r in results.items():
        t = r["times"]
        print(f"  {name:14s} median {statistics.median(t):7.3f} s  (min {min(t):.3f}, max {max(t):.3f})")
        print(f"      critical torques [N m]: {', '.join(f'{x:.1f}' for x in r['torques'])}")
    if "reference" in results:
        a, b = results["this checkout"]["torques"], results["reference"]["torques"]
        diff = max(abs(x - y) / abs(y) for x, y in zip(a, b))
        ratio = statistics.median(results["reference"]["times"]) / statistics.median(results["this checkout"]["times"])
        print(f"  largest relative difference of the torques: {diff:.1e}")
        print(f"  speed-up: {ratio:.1f}x")


if __name__ == "__main__":
    main()

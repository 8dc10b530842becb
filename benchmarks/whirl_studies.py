"""CPU of the run's chapter-4 whirl studies, this checkout against a reference tree (paired).

The "whirl studies (thesis chapter 4)" stage of ``flexshaft run`` on the packaged tuned design,
its tasks called one after the other in one process: :func:`~flexshaft.thesis.whirl.shaft_whirl`
of the three thesis shafts (viscous and hysteretic) and the three rows of
:func:`~flexshaft.thesis.whirl.gain_stability_map` (K_p the design's, a fifth and a thirtieth
of it; K_d of :data:`~flexshaft.thesis.report_studies.GAIN_MAP_KD`), on the REPORT resolution's
whirl speeds and modes, as :func:`~flexshaft.thesis.report_studies.start_thesis_studies` asks
for them. Each round runs every tree in a fresh process (one untimed call first, then
``--repeats`` timed ones); printed: the median CPU (``time.process_time``) per tree and task,
the median of the rounds' ratios (reference / now), and the largest relative difference of the
results (eigenvalues, onsets, gain-map onsets and margins) between the trees.

    .venv/bin/python benchmarks/whirl_studies.py --reference /tmp/ref/  [--rounds 5 --repeats 1]
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import bench_util as bu  # noqa: E402

JOB = r"""
import json, statistics, sys, time
import numpy as np
from flexshaft.assembly import build_model
from flexshaft.design import tuned_design
from flexshaft.resolution import REPORT
from flexshaft.thesis import report_studies as rs
from flexshaft.thesis.whirl import gain_stability_map, shaft_whirl, thesis_shaft_designs

design = tuned_design()
model = build_model(design)
speeds = REPORT.stability_speeds(model.speed)
n = rs._WHIRL_MODES
kp0 = model.actuators[0].controller.kp
tasks = {f"shaft {label}": (shaft_whirl, (d, speeds)) for label, d in thesis_shaft_designs(design).items()}
tasks.update({f"gain map K_p {kp:.4g}": (gain_stability_map, (design, [kp], list(rs.GAIN_MAP_KD), speeds))
              for kp in (kp0 / 30, kp0 / 5, kp0)})

def numbers(out):
    if isinstance(out, dict):  # {damping: StabilityResult}
        return [v for r in out.values() for v in (*np.ravel(r.eigenvalues), r.onset_speed or 0.0)]
    return [*np.ravel(out.onset_speed), *np.ravel(out.margin_at_operating)]

def once():
    cpu, values = {}, []
    for name, (fn, args) in tasks.items():
        t = time.process_time()
        out = fn(*args, n_modes=n)
        cpu[name] = time.process_time() - t
        values += numbers(out)
    return cpu, values

once()
runs = [once() for _ in range(int(sys.argv[1]))]
cpu = {name: statistics.median(r[0][name] for r in runs) for name in tasks}
values = [[v.real, v.imag] if isinstance(v, complex) else [float(v), 0.0] for v in runs[-1][1]]
print(json.dumps({"total": statistics.median(sum(r[0].values()) for r in runs), "cpu": cpu, "values": values}))
"""


def largest_relative_difference(a: list, b: list) -> float:
    """Largest |x − y| / |y| over the results' numbers (NaN where both are: equal)."""
    import numpy as np

    x = np.array([complex(*v) for v in a])
    y = np.array([complex(*v) for v in b])
    both_nan = np.isnan(x) & np.isnan(y)
    with np.errstate(divide="ignore", invalid="ignore"):
        rel = np.abs(x - y) / np.abs(y)
    rel = np.where(both_nan | ((x == y) & ~np.isnan(x)), 0.0, rel)
    return float(np.max(rel)) if rel.size else 0.0


def main() -> None:
    parser = bu.paired_parser(__doc__.splitlines()[0], repeats=1, repeats_help="timed calls per process")
    args = parser.parse_args()
    bu.reexec_with_threads(args.blas_threads, __file__)
    bu.print_heading("whirl studies of `flexshaft run` (tuned design, REPORT)", args.blas_threads)
    trees, runs = bu.paired_runs(HERE.parent, args.reference, args.rounds, JOB, args.repeats, threads=args.blas_threads)
    for name, results in runs.items():
        print(f"  {name:14s} CPU median {statistics.median(r['total'] for r in results):.3f} s")
        for task in results[0]["cpu"]:
            print(f"      {task:32s} {statistics.median(r['cpu'][task] for r in results):.3f} s")
    if "reference" in runs:
        ratios = [r["total"] / n["total"] for n, r in zip(runs["this checkout"], runs["reference"])]
        print(
            f"  reference / now: median {statistics.median(ratios):.2f} (min {min(ratios):.2f}, max {max(ratios):.2f})"
        )
        diff = largest_relative_difference(runs["this checkout"][-1]["values"], runs["reference"][-1]["values"])
        print(f"  largest relative difference of the results: {diff:.2e}")


if __name__ == "__main__":
    main()

"""The magnetic-bearing loops alone (issue 30, point 2): this checkout against a reference tree.

Runs ``bearing_loops`` as the assessment calls it (``_roots_and_loops``: the every-root check's
resolved closed-loop poles at the operating speed, above which the natural frequencies stand
in), on the embedded tuned design at its own operating point, at the screening's one grid point
per lightly damped pole (``peak_samples=1``) and the report's three, and the all-full reference
(``projected=False``, a full banded solve at every refinement step) for the margins' agreement.
Each tree runs in its own process with one BLAS thread; the trees alternate ``--rounds`` times
and the medians are over all their warm calls.
Prints the CPU and wall medians, the number of full banded solves (points handed to the
solver's sweeps) and the largest relative difference from the all-full reference of the margins
(peak |S|, the gain and phase margins, the phase margin's frequency) and, apart, of the peak's
frequency (a golden-section search to 1e-6 in ln ω on either side).

    .venv/bin/python benchmarks/loop_speed.py --reference /tmp/ref-main
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import bench_util as bu  # noqa: E402

JOB = r"""
import json, math, sys, time
from flexshaft.analyses.banded import solver_for
from flexshaft.analyses.bearing_loops import bearing_loops
from flexshaft.analyses.root_stability import root_stability
from flexshaft.assembly import build_model
from flexshaft.design.io import tuned_design
from flexshaft.verdict.point_tasks import root_speeds
repeats = int(sys.argv[1])
model = build_model(tuned_design().model_copy(update={"envelope": None}))
poles = root_stability(model, root_speeds(model)).resolved_roots_at(model.speed)  # as _roots_and_loops passes them
solver = solver_for(model)
count = [0]
sweep = solver.sweep
def counting(points, rhs):
    points = list(points)
    count[0] += len(points)
    return sweep(points, rhs)
solver.sweep = counting
def margins(loops):
    out = []
    for lp in loops:
        m = lp.margins
        out.append([m.peak_sensitivity, m.peak_frequency, m.gain_margin_upper_db, m.gain_margin_lower_db,
                    m.phase_margin_deg, m.phase_margin_frequency])
    return out
out = {}
for name, samples in (("SCREENING", 1), ("REPORT", 3)):
    count[0] = 0
    fast = bearing_loops(model, poles=poles, peak_samples=samples)
    solves = count[0]
    full = bearing_loops(model, poles=poles, peak_samples=samples, projected=False)
    worst = [0.0, 0.0]  # the margins and their frequencies; the peak frequency
    for a, b in zip(margins(fast), margins(full)):
        for j, (x, y) in enumerate(zip(a, b)):
            which = 1 if j == 1 else 0
            if y is not None and math.isfinite(y) and y != 0:
                worst[which] = max(worst[which], abs(x - y) / abs(y))
            elif x != y:
                worst[which] = math.inf
    cpu, wall = [], []
    for _ in range(repeats):
        w, c = time.perf_counter(), time.process_time()
        bearing_loops(model, poles=poles, peak_samples=samples)
        cpu.append(time.process_time() - c)
        wall.append(time.perf_counter() - w)
    out[name] = {"cpu": cpu, "wall": wall, "solves": solves, "worst": worst}
print(json.dumps(out))
"""


def main() -> None:
    args = bu.paired_parser(__doc__.splitlines()[0], repeats=7).parse_args()
    bu.reexec_with_threads(args.blas_threads, __file__)
    trees, runs = bu.paired_runs(HERE.parent, args.reference, args.rounds, JOB, args.repeats, threads=args.blas_threads)
    bu.print_heading("bearing loops, tuned design at its operating point", args.blas_threads)
    print(f"  {args.rounds} rounds x {args.repeats} warm calls per tree")
    medians: dict[str, dict[str, float]] = {}
    for name, results in runs.items():
        print(f"  {name} ({trees[name]}):")
        medians[name] = {}
        for case in results[0]:
            cpu = statistics.median([t for r in results for t in r[case]["cpu"]])
            wall = statistics.median([t for r in results for t in r[case]["wall"]])
            medians[name][case] = cpu
            margin, peak = results[0][case]["worst"]
            print(
                f"    {case:10s} CPU {1e3 * cpu:6.1f} ms   wall {1e3 * wall:6.1f} ms   full solves "
                f"{results[0][case]['solves']:4d}   vs all-full: margins {margin:.1e}, peak frequency {peak:.1e}"
            )
    if "reference" in medians:
        for case, ref in medians["reference"].items():
            print(f"  speed-up {case:10s} {ref / medians['this checkout'][case]:5.2f}x (reference/this, CPU)")


if __name__ == "__main__":
    main()

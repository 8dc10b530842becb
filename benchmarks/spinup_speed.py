"""Spin-up scan and critical speeds (issue 30, point 2): the work of one assessment's spin-up task.

Times what ``flexshaft.verdict.point_tasks._spinup`` does, ``spinup_response`` over the
resolution's scan and ``scan_critical_speeds`` on it, on the embedded tuned design at its own
operating point, at SCREENING (261 speeds) and REPORT (651), CPU time with one BLAS thread, warm
medians of ``--repeats`` runs. This checkout runs it twice: the scan from the greedy reduced basis
(:mod:`flexshaft.analyses.sweep_projection`, the default) and all-full (``projected=False``); a
reference tree (``--reference``, e.g. ``git worktree add /tmp/ref main``) runs its default. The
trees alternate, ``--rounds`` times. Each run also counts the banded solves
(``BandedHarmonicSolver._solve_permuted`` calls), and this checkout prints the largest difference
of the projected results from the all-full ones, relative to each quantity's peak (the tested
tolerance is 1e-7, tests/test_spinup_projection.py).

    .venv/bin/python benchmarks/spinup_speed.py --reference /tmp/ref-spin
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import bench_util as bu  # noqa: E402

JOB = r"""
import inspect, json, sys, time
import numpy as np
import flexshaft as fs
from flexshaft.analyses import banded
from flexshaft.analyses.criticals import scan_critical_speeds
from flexshaft.analyses.spinup_response import spinup_response
from flexshaft.assembly import build_model
from flexshaft.design.io import tuned_design

repeats = int(sys.argv[1])
solves = [0]
plain = banded.BandedHarmonicSolver._solve_permuted
def counted(self, *args, **kwargs):
    solves[0] += 1
    return plain(self, *args, **kwargs)
banded.BandedHarmonicSolver._solve_permuted = counted
model = build_model(tuned_design().model_copy(update={"envelope": None}))
modes = {"default": {}}
if "projected" in inspect.signature(spinup_response).parameters:
    modes["all-full"] = {"projected": False}
seeded = "responses" in inspect.signature(scan_critical_speeds).parameters
based = "basis" in inspect.signature(scan_critical_speeds).parameters
out = {}
for resolution in (fs.SCREENING, fs.REPORT):
    speeds = resolution.spin_speeds(model.speed)
    for label, options in modes.items():
        def run():
            solves[0] = 0
            c0 = time.process_time()
            scan = spinup_response(model, speeds, **options)
            c1 = time.process_time()
            n_scan = solves[0]
            extra = {"responses": scan.response} if seeded else {}  # as the assessment's spin-up task
            if based:
                extra["basis"] = scan.basis
            criticals = scan_critical_speeds(model, scan.speeds, scan.orbits, resolution.scan_top, **extra)
            c2 = time.process_time()
            return c1 - c0, c2 - c1, n_scan, solves[0] - n_scan, scan, criticals
        run()  # warm
        runs = [run() for _ in range(repeats)]
        scan, criticals = runs[-1][4], runs[-1][5]
        out[f"{resolution.name} {label}"] = {
            "spinup": [r[0] for r in runs],
            "criticals": [r[1] for r in runs],
            "solves": [runs[-1][2], runs[-1][3]],
            "envelope": scan.envelope.tolist(),
            "actuators": {
                k: [v.tolist(), scan.actuator_force[k].tolist()] for k, v in scan.actuator_displacement.items()
            },
            "peaks": [
                [c.speed, c.amplification_factor, c.location.get("peak_orbit", 0.0)] for c in criticals.criticals
            ],
        }
print(json.dumps(out))
"""


def _difference(a, b) -> float:
    """Largest |a − b| relative to the peak of |b|."""
    import numpy as np

    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.abs(a - b).max() / np.abs(b).max())


def _accuracy(fast: dict, full: dict) -> str:
    """The projected scan's largest differences from the all-full one (relative to each peak)."""
    import numpy as np

    envelope = _difference(fast["envelope"], full["envelope"])
    actuators = max(
        [_difference(fast["actuators"][k][i], full["actuators"][k][i]) for k in full["actuators"] for i in (0, 1)],
        default=0.0,
    )
    a, b = np.asarray(fast["peaks"]), np.asarray(full["peaks"])
    if a.shape != b.shape:
        return f"envelope {envelope:.1e}, actuators {actuators:.1e}, critical speeds DIFFER ({len(a)} vs {len(b)})"
    peaks = float(np.max(np.abs(a - b) / np.abs(b))) if b.size else 0.0
    return f"envelope {envelope:.1e}, actuator orbit/force {actuators:.1e}, critical speed/AF/peak orbit {peaks:.1e}"


def main() -> None:
    args = bu.paired_parser(__doc__.splitlines()[0], repeats=5).parse_args()
    bu.reexec_with_threads(args.blas_threads, __file__)
    trees, runs = bu.paired_runs(HERE.parent, args.reference, args.rounds, JOB, args.repeats, threads=args.blas_threads)
    bu.print_heading("spin-up scan + critical speeds, tuned design at one point", args.blas_threads)
    print(f"  {args.rounds} rounds x {args.repeats} warm repeats per tree; CPU medians [ms]; banded solves per run")
    print(f"  {'tree / scan':34s} {'spin-up':>8s} {'criticals':>10s} {'total':>8s}   solves (scan + peaks)")
    totals: dict[str, float] = {}
    for name, results in runs.items():
        for case in results[0]:
            spin = statistics.median([t for r in results for t in r[case]["spinup"]]) * 1e3
            crit = statistics.median([t for r in results for t in r[case]["criticals"]]) * 1e3
            totals[f"{name} {case}"] = spin + crit
            n_scan, n_peaks = results[0][case]["solves"]
            label = f"{name}: {case}"
            print(f"  {label:34s} {spin:8.1f} {crit:10.1f} {spin + crit:8.1f}   {n_scan} + {n_peaks}")
    ours = runs["this checkout"][0]
    for resolution in ("screening", "report"):
        fast, full = ours.get(f"{resolution} default"), ours.get(f"{resolution} all-full")
        if fast and full:
            print(f"  {resolution}: projected / all-full (this checkout): {_accuracy(fast, full)}")
            ratio = totals[f"this checkout {resolution} all-full"] / totals[f"this checkout {resolution} default"]
            print(f"  {resolution}: speed-up of spin-up + criticals over the all-full scan {ratio:5.2f}x (CPU)")
        if "reference" in trees:
            ratio = totals[f"reference {resolution} default"] / totals[f"this checkout {resolution} default"]
            print(f"  {resolution}: speed-up of spin-up + criticals, reference / this checkout {ratio:5.2f}x (CPU)")


if __name__ == "__main__":
    main()

"""Screening-assessment speed (issue 30, point 2): one point and the envelope, this checkout
against a reference tree.

Runs the same job in each source tree, in its own process with one BLAS thread:
``flexshaft.assess(design, resolution)`` on the embedded tuned design, at one point (the design
with its ``[envelope]`` removed: its own operating point) and over its envelope (4 points).
Prints the CPU and wall medians of ``--repeats`` warm runs, the cold first call (after the
imports), the envelope's cost over one point's, and the paired ratio reference/this checkout
(the trees run alternately, ``--rounds`` times, and the medians are over all their runs).
``--report`` adds the REPORT resolution (for information; fewer repeats). ``--verdicts``
compares the verdicts of every embedded design at SCREENING between the trees: pass/fail of
each check, the governing point, and the largest relative difference of the checks' values, which
must stay within ``--tolerance`` (1e-6 by default: the modal analyses' eigenvalue tolerance, the
loosest accuracy the screening's reduced and projected models are held to; exit status 1 else).

    .venv/bin/python benchmarks/assessment_speed.py --reference /tmp/ref-main --verdicts

``--blas-threads 0`` runs the jobs with no BLAS thread variable set, as a notebook's kernel
does (the libraries' default: one thread per core); the API's analyses limit themselves to
one thread (:mod:`flexshaft.parallel.threads`), which this measures.

The reference is any flexshaft source tree (e.g. ``git worktree add /tmp/ref-main <commit>``);
its ``src/`` is put first on PYTHONPATH. Without ``--reference`` only this checkout is timed.
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import bench_util as bu  # noqa: E402

JOB = r"""
import json, sys, time
t0 = time.process_time()
import flexshaft as fs
from flexshaft.design.io import tuned_design
import_cpu = time.process_time() - t0
repeats, report = int(sys.argv[1]), sys.argv[2] == "1"
envelope = tuned_design()
one = envelope.model_copy(update={"envelope": None})
def timed(design, resolution):
    w, c = time.perf_counter(), time.process_time()
    a = fs.assess(design, resolution)
    return time.process_time() - c, time.perf_counter() - w, a
out = {"import_cpu": import_cpu}
cpu, wall, _ = timed(one, fs.SCREENING)
out["cold"] = {"cpu": cpu, "wall": wall}
cases = [("one point", one, fs.SCREENING, repeats), ("envelope", envelope, fs.SCREENING, repeats)]
if report:
    cases += [("one point REPORT", one, fs.REPORT, 1), ("envelope REPORT", envelope, fs.REPORT, 1)]
for name, design, resolution, n in cases:
    timed(design, resolution)  # warm
    runs = [timed(design, resolution)[:2] for _ in range(n)]
    out[name] = {"cpu": [r[0] for r in runs], "wall": [r[1] for r in runs]}
print(json.dumps(out))
"""

VERDICTS = r"""
import json, math
import flexshaft as fs
from flexshaft.design.io import embedded_design
out = {}
for name in ("baseline", "tuned", "current"):
    a = fs.assess(embedded_design(name), fs.SCREENING)
    out[name] = {
        "governing": a.governing_point,
        "checks": {c.key: [c.status, c.passed, c.value] for c in a.verdict.checks},
    }
print(json.dumps(out))
"""


def _median(values: list[float]) -> float:
    return statistics.median(values)


def compare_verdicts(ours: dict, theirs: dict, tolerance: float = 1e-6) -> bool:
    """Print the verdicts' differences; True when pass/fail and the governing point agree and
    every check's value agrees to ``tolerance`` (relative)."""
    same = True
    for design, a in ours.items():
        b = theirs[design]
        status = all(a["checks"][k][:2] == b["checks"].get(k, [None, None])[:2] for k in a["checks"])
        status &= set(a["checks"]) == set(b["checks"])
        worst = 0.0
        for key, (_, _, value) in a["checks"].items():
            other = b["checks"].get(key, [None, None, None])[2]
            if value is not None and other is not None and other != 0 and abs(other) != float("inf"):
                worst = max(worst, abs(value - other) / abs(other))
        governing = a["governing"] == b["governing"]
        same &= status and governing and worst <= tolerance
        print(
            f"  {design:18s} pass/fail {'identical' if status else 'DIFFERENT'}, governing point "
            f"{'identical' if governing else 'DIFFERENT'} ({a['governing']}), largest relative "
            f"difference of a check's value {worst:.1e} ({'within' if worst <= tolerance else 'ABOVE'} {tolerance:g})"
        )
    return same


def main() -> None:
    parser = bu.paired_parser(__doc__.splitlines()[0], repeats=5)
    parser.add_argument("--report", action="store_true", help="also time the REPORT resolution")
    parser.add_argument("--verdicts", action="store_true", help="compare the embedded designs' verdicts")
    parser.add_argument("--tolerance", type=float, default=1e-6, help="largest relative difference of a value")
    args = parser.parse_args()
    bu.reexec_with_threads(args.blas_threads, __file__)
    trees, runs = bu.paired_runs(
        HERE.parent, args.reference, args.rounds, JOB, args.repeats, int(args.report), threads=args.blas_threads
    )
    bu.print_heading("assessment speed, tuned design", args.blas_threads)
    print(f"  {args.rounds} rounds x {args.repeats} warm repeats per tree")
    medians: dict[str, dict[str, float]] = {}
    for name, results in runs.items():
        print(f"  {name} ({trees[name]}):")
        cold_cpu = _median([r["cold"]["cpu"] for r in results])
        cold_wall = _median([r["cold"]["wall"] for r in results])
        imports = _median([r["import_cpu"] for r in results])
        print(f"    import flexshaft        CPU {imports:6.3f} s")
        print(f"    cold first call (1 pt)  CPU {cold_cpu:6.3f} s   wall {cold_wall:6.3f} s")
        medians[name] = {}
        for case in [k for k in results[0] if k not in ("cold", "import_cpu")]:
            cpu = _median([t for r in results for t in r[case]["cpu"]])
            wall = _median([t for r in results for t in r[case]["wall"]])
            medians[name][case] = cpu
            print(f"    {case:22s}  CPU {cpu:6.3f} s   wall {wall:6.3f} s   (warm median)")
        one, env = medians[name]["one point"], medians[name]["envelope"]
        print(f"    envelope / one point    {env / one:5.2f}x (CPU)")
    if "reference" in medians:
        for case, ref in medians["reference"].items():
            print(f"  speed-up {case:22s} {ref / medians['this checkout'][case]:5.2f}x (reference/this, CPU)")
    if args.verdicts:
        verdicts = {name: bu.run_in_tree(path, VERDICTS) for name, path in trees.items()}
        if "reference" in verdicts:
            print("  verdicts at SCREENING, this checkout against the reference:")
            if not compare_verdicts(verdicts["this checkout"], verdicts["reference"], args.tolerance):
                raise SystemExit(1)
        else:
            for design, v in verdicts["this checkout"].items():
                print(f"  {design}: governed by {v['governing']}")


if __name__ == "__main__":
    main()

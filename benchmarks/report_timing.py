"""Time of writing the ``flexshaft run`` report from one precomputed assessment.

The analyses run once (or are loaded from ``--cache``, a pickle of the assessment and the
thesis studies); then
``write_run_report`` is timed ``--repeats`` times (after one untimed warm-up that imports
matplotlib and loads the fonts) in each configuration: serial or with ``--processes`` forked
workers, PNG only or PNG and SVG. Prints the median wall time with its spread (min-max), the
CPU time of this process and of the workers, and the ratios to the serial PNG-only run; then
the time of each figure (draw and save, serial PNG-only, median over the repeats).

    OMP_NUM_THREADS=1 .venv/bin/python benchmarks/report_timing.py                 # full report
    OMP_NUM_THREADS=1 .venv/bin/python benchmarks/report_timing.py --studies none  # no studies
    .venv/bin/python benchmarks/report_timing.py --cache /tmp/run.pkl --repeats 5

On a shared machine the wall times move with the other processes' load; the CPU times and the
ratios are the steadier numbers.
"""

from __future__ import annotations

import argparse
import datetime as dt
import os
import pickle
import statistics
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("MPLBACKEND", "Agg")
GENERATED = dt.datetime(2024, 1, 1)


def load_results(studies: str, cache: Path | None):
    """The baseline's (Assessment, ThesisStudies or None): from ``cache`` when it exists, else
    computed (and cached)."""
    if cache is not None and cache.is_file():
        with cache.open("rb") as f:
            return pickle.load(f)
    from flexshaft.design import baseline_design
    from flexshaft.thesis.report_studies import start_thesis_studies
    from flexshaft.verdict.assess import assess

    start = time.perf_counter()
    design = baseline_design()
    res = (assess(design), None if studies == "none" else start_thesis_studies(design, studies).result())
    print(f"analyses: {time.perf_counter() - start:.1f} s (not part of the timings below)")
    if cache is not None:
        with cache.open("wb") as f:
            pickle.dump(res, f)
    return res


def children_cpu() -> float:
    t = os.times()
    return t.children_user + t.children_system


def time_report(res, processes: int, svg: bool, repeats: int) -> dict:
    from flexshaft.report.driveline import write_run_report

    walls, cpus, workers = [], [], []
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as folder:
            c0, w0, t0 = time.process_time(), children_cpu(), time.perf_counter()
            write_run_report(res[0], folder, generated=GENERATED, processes=processes, svg=svg, thesis=res[1])
            walls.append(time.perf_counter() - t0)
            cpus.append(time.process_time() - c0)
            workers.append(children_cpu() - w0)
    return {"wall": walls, "cpu": cpus, "workers": workers}


def figure_times(res, repeats: int) -> dict[str, float]:
    from flexshaft.plot.output import render_figures
    from flexshaft.report.driveline import plan_run_report

    per: dict[str, list[float]] = {}
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as folder:
            plan = plan_run_report(res[0], folder, thesis=res[1])
            for stem, done in render_figures(plan.jobs, folder).items():
                per.setdefault(stem, []).append(done.seconds)
    return {stem: statistics.median(v) for stem, v in per.items()}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--studies",
        choices=("report", "none"),
        default="report",
        help="thesis design studies beside the assessment (default: report)",
    )
    parser.add_argument(
        "--cache", type=Path, default=None, help="pickle of the assessment and thesis studies, reused or written"
    )
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--processes", type=int, default=2, help="workers of the parallel runs (default 2)")
    args = parser.parse_args(argv)
    if args.repeats < 1 or args.processes < 2:
        parser.error("--repeats must be >= 1 and --processes >= 2")

    res = load_results(args.studies, args.cache)
    from flexshaft.report.driveline import write_run_report

    with tempfile.TemporaryDirectory() as folder:  # warm-up: imports, font cache, first figures
        write_run_report(res[0], folder, generated=GENERATED, thesis=res[1])
    configs = [
        ("serial, PNG", 1, False),
        (f"{args.processes} processes, PNG", args.processes, False),
        ("serial, PNG + SVG", 1, True),
        (f"{args.processes} processes, PNG + SVG", args.processes, True),
    ]
    print(
        f"write_run_report, studies={args.studies}, {args.repeats} repeats, {os.cpu_count()} CPUs, "
        f"load average {os.getloadavg()[0]:.1f}"
    )
    print(
        f"{'configuration':28s} {'median wall [s]':>15s} {'min-max [s]':>14s} {'CPU here [s]':>12s} "
        f"{'CPU workers [s]':>15s} {'wall / serial PNG':>17s}"
    )
    base = None
    for name, processes, svg in configs:
        r = time_report(res, processes, svg, args.repeats)
        wall = statistics.median(r["wall"])
        base = base or wall
        print(
            f"{name:28s} {wall:15.2f} {min(r['wall']):6.2f}-{max(r['wall']):<7.2f} "
            f"{statistics.median(r['cpu']):12.2f} {statistics.median(r['workers']):15.2f} {wall / base:17.2f}"
        )
    times = figure_times(res, args.repeats)
    print(
        f"\nper figure (serial, PNG only, draw + save, median of {args.repeats}); {len(times)} figures, "
        f"sum {sum(times.values()):.2f} s"
    )
    for stem, seconds in sorted(times.items(), key=lambda item: -item[1]):
        print(f"  {stem:36s} {seconds:6.3f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())

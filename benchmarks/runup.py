"""Benchmark: run-up transient and Monte-Carlo imbalance of the baseline driveline (issue 15).

Run-up. Constant acceleration 0 → 4800 rpm in each of ``--durations`` seconds (default 5, 10
and 30 s) with the default basis (modes below 4x the top speed, static correction) and
tolerance (rtol 1e-5): wall time, steps, peak shaft deflection and its speed, peak actuator orbit and
force, against the steady-state spin-up curve (banded direct solve with the exact hysteretic
loss on 400 speeds, and its peak refined by golden-section search). Then the convergence of
the 10-s peak with the basis size (12, 25, 50 modes) and the integration tolerance, and the
same run-up with the thesis's fixed-frame loss model.

Monte Carlo. ``--samples`` imbalance samples per balance grade (G 6.3 and G 16, each bay's
eccentricity uniform over the grade's tolerance disk, random angle and position) on the sweep
engine with ``--jobs`` processes: quantiles and the probability that the largest actuator
orbit exceeds ``--gap`` and the largest actuator force exceeds ``--force-limit`` on the
steady-state spin-up; then the same draws (mid-bay) over a 10-s run-up.

Figures go to ``--figures`` (PNG): the run-up envelopes against the steady curve and the
Monte-Carlo histograms / exceedance curves.

Run: ``OMP_NUM_THREADS=1 .venv/bin/python benchmarks/runup.py [--samples 1000 --jobs 2]``
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from flexshaft.analyses.transient import default_basis_size, run_up, steady_state_envelope
from flexshaft.assembly import build_model
from flexshaft.design import baseline_design, with_overrides
from flexshaft.parallel.threads import single_blas_thread

RPM = 30.0 / np.pi


def steady_peak(model, lo: float, hi: float, iterations: int = 60) -> tuple[float, float]:
    """Golden-section maximum of the steady shaft envelope on [lo, hi] [rad/s]."""
    ratio = (np.sqrt(5.0) - 1.0) / 2.0

    def f(s):
        return float(steady_state_envelope(model, [s]).shaft_peak[0])

    x1, x2 = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
    f1, f2 = f(x1), f(x2)
    for _ in range(iterations):
        if f1 >= f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - ratio * (hi - lo)
            f1 = f(x1)
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + ratio * (hi - lo)
            f2 = f(x2)
    return (f1, x1) if f1 >= f2 else (f2, x2)


@single_blas_thread
def runup_section(durations, figures: Path | None) -> None:
    model = build_model(baseline_design())
    top = model.speed
    print(
        f"baseline: {model.dofs.free.size} free DOFs, operating speed {top * RPM:.0f} rpm, "
        f"internal damping '{model.internal_damping}', default basis {default_basis_size(model, top)} modes"
    )
    speeds = np.linspace(0.02, 1.0, 400) * top
    t0 = time.perf_counter()
    steady = steady_state_envelope(model, speeds)
    t_steady = time.perf_counter() - t0
    k = int(np.argmax(steady.shaft_peak))
    grid_peak, grid_speed = steady.shaft_peak[k], speeds[k]
    true_peak, true_speed = steady_peak(model, speeds[max(k - 1, 0)], speeds[min(k + 1, speeds.size - 1)])
    print(
        f"steady spin-up ({speeds.size} speeds, {t_steady:.2f} s): peak {grid_peak * 1e3:.2f} mm at "
        f"{grid_speed * RPM:.0f} rpm on the grid; refined {true_peak * 1e3:.1f} mm at {true_speed * RPM:.2f} rpm"
    )
    print(
        f"  actuator orbit peak {steady.actuator_displacement.max() * 1e3:.4f} mm, "
        f"force peak {steady.actuator_force.max():.0f} N on the grid"
    )
    print()
    print(
        f"{'run-up':>8} {'wall [s]':>9} {'steps':>6} {'peak [mm]':>10} {'at [rpm]':>9} {'/steady':>8} "
        f"{'act orbit [mm]':>15} {'act force [N]':>14} {'growth [1/s]':>13}"
    )
    runs = {}
    for duration in durations:
        t0 = time.perf_counter()
        run = run_up(model, duration)
        wall = time.perf_counter() - t0
        value, _, at = run.peak()
        runs[f"{duration:g} s run-up ({top / duration:.1f} rad/s²)"] = run
        print(
            f"{duration:>7g}s {wall:>9.2f} {run.steps:>6} {value * 1e3:>10.3f} {at * RPM:>9.0f} "
            f"{value / true_peak:>8.4f} {run.actuator_displacement.max() * 1e3:>15.4f} "
            f"{run.actuator_force.max():>14.0f} {run.max_growth_rate:>13.4f}"
        )
    print("  (/steady: against the refined steady-state peak; growth > 0: whirl-unstable speeds inside the run)")
    print()
    print("convergence of the 10-s peak:")
    reference = run_up(model, 10.0, basis_size=50, rtol=1e-8).peak()[0]
    for nb, rtol in ((12, 1e-5), (25, 1e-5), (50, 1e-5), (25, 1e-4), (25, 1e-6)):
        t0 = time.perf_counter()
        value = run_up(model, 10.0, basis_size=nb, rtol=rtol).peak()[0]
        print(
            f"  {nb:>3} modes, rtol {rtol:.0e}: {value * 1e3:.5f} mm ({value / reference - 1:+.2e} against 50 modes, "
            f"rtol 1e-8), {time.perf_counter() - t0:.2f} s"
        )
    thesis = build_model(with_overrides(baseline_design(), {"analysis.internal_damping": "thesis"}))
    run = run_up(thesis, 10.0)
    steady_thesis = steady_state_envelope(thesis, speeds)
    print(
        f"thesis loss model, 10-s run-up: peak {run.peak()[0] * 1e3:.3f} mm at {run.peak()[2] * RPM:.0f} rpm; "
        f"steady grid peak {steady_thesis.shaft_peak.max() * 1e3:.3f} mm; growth {run.max_growth_rate:.3f} 1/s"
    )
    if figures is not None:
        from flexshaft.plot.driveline import save_figure
        from flexshaft.plot.transient import runup_envelope_figure

        fig = runup_envelope_figure(runs, steady, operating_rpm=top * RPM, gap=2.5e-4, force_limit=2e3)
        print("figure:", save_figure(fig, figures, "runup_envelope")["png"])


def montecarlo_section(samples: int, jobs: int, gap: float, force_limit: float, figures: Path | None) -> None:
    from flexshaft.analyses.transient import SpeedProfile
    from flexshaft.montecarlo import EccentricityDistribution, run_montecarlo, runup_montecarlo

    design = baseline_design()
    model = build_model(design)
    top = model.speed
    profile = SpeedProfile.constant_acceleration(0.0, top, top / 10.0)
    print()
    print(
        f"Monte Carlo: {samples} samples per grade, {jobs} process(es); gap {gap * 1e3:.3g} mm, "
        f"force limit {force_limit:.4g} N; eccentricity uniform over the grade's disk, random angle and position"
    )
    results = {}
    for grade in (6.3, 16.0):
        t0 = time.perf_counter()
        result = run_montecarlo(
            design, samples, seed=2024, grade_mm_s=grade, gap=gap, force_limit=force_limit, jobs=jobs
        )
        wall = time.perf_counter() - t0
        ds = result.dataset
        results[f"G {grade:g}"] = ds
        p_gap, e_gap = result.gap_exceedance
        p_force, e_force = result.force_exceedance

        def q(name, scale=1.0, ds=ds):
            return np.nanpercentile(ds[name].values, [50, 95, 99]) * scale

        print(f"G {grade:g} (e_per {ds.attrs['eccentricity_scale_m'] * 1e6:.2f} µm): {wall:.1f} s")
        print(f"  peak deflection  p50/p95/p99 {np.array2string(q('shaft_peak', 1e3), precision=2)} mm")
        print(
            f"  actuator orbit   p50/p95/p99 {np.array2string(q('actuator_orbit_max', 1e3), precision=4)} mm; "
            f"P(> gap) = {p_gap:.4f} ± {e_gap:.4f}"
        )
        print(
            f"  actuator force   p50/p95/p99 {np.array2string(q('actuator_force_max'), precision=0)} N; "
            f"P(> limit) = {p_force:.4f} ± {e_force:.4f}"
        )
        print(
            f"  safety factor    min {np.nanmin(ds['safety_factor'].values):.2f}, "
            f"p1 {np.nanpercentile(ds['safety_factor'].values, 1):.2f}"
        )
        t0 = time.perf_counter()
        runup = runup_montecarlo(
            model, profile, samples, seed=2024, distribution=EccentricityDistribution.from_grade(grade, top)
        )
        wall = time.perf_counter() - t0
        p_gap, e_gap = runup.exceedance("actuator_orbit_max", gap)
        p_force, e_force = runup.exceedance("actuator_force_max", force_limit)
        print(
            f"  10-s run-up instead (mid-bay unbalances, {wall:.1f} s): peak deflection p50/p95/p99 "
            f"{np.array2string(np.percentile(runup.shaft_peak, [50, 95, 99]) * 1e3, precision=2)} mm"
        )
        print(
            f"    actuator orbit p99 {np.percentile(runup.actuator_orbit_max, 99) * 1e3:.4f} mm, "
            f"P(> gap) = {p_gap:.4f} ± {e_gap:.4f}; force p99 {np.percentile(runup.actuator_force_max, 99):.0f} N, "
            f"P(> limit) = {p_force:.4f} ± {e_force:.4f}"
        )
    if figures is not None:
        from flexshaft.plot.driveline import save_figure
        from flexshaft.plot.transient import montecarlo_figure

        fig = montecarlo_figure(results, gap=gap, force_limit=force_limit)
        print("figure:", save_figure(fig, figures, "montecarlo_imbalance")["png"])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--durations", type=float, nargs="+", default=[5.0, 10.0, 30.0], help="run-up times [s]")
    parser.add_argument("--samples", type=int, default=400, help="Monte-Carlo samples per grade (0: skip)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--gap", type=float, default=2.5e-4, help="actuator radial gap [m]")
    parser.add_argument("--force-limit", type=float, default=2e3, help="actuator force capacity [N]")
    parser.add_argument("--figures", type=Path, default=None, help="folder for PNG figures")
    args = parser.parse_args()
    runup_section(args.durations, args.figures)
    if args.samples > 0:
        montecarlo_section(args.samples, args.jobs, args.gap, args.force_limit, args.figures)


if __name__ == "__main__":
    main()

"""Benchmark: the (K_p, K_d) spin-up map of the baseline driveline (issue 6, thesis study 6).

30 × 30 PD gain pairs (the same law on both active bearings) × 400 spin speeds up to the
operating speed; per gain pair the peak shaft orbit, actuator relative orbit and actuator force.
Prints the wall time with BLAS limited to one thread and with the library's default threads,
an estimate of the direct solve (a few full spin-ups timed and extrapolated), the agreement of
the map's peaks with direct solves at sampled gain pairs, and the best gains against the
thesis baseline setting (K_p = 1e7 N/m, K_d = 0).

Run: ``.venv/bin/python benchmarks/spinup_map.py [--n-gains 30] [--n-speeds 400]``
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from flexshaft.analyses import imbalance_response
from flexshaft.analyses.response import orbit_amplitude
from flexshaft.analyses.spinup import actuator_receptance, spinup_curves, spinup_map, spinup_speeds
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import baseline_design, with_overrides


def direct_peak(design, speeds, kp, kd) -> float:
    """Peak shaft orbit [m] by one banded solve per speed on the full model."""
    overrides = {f"bearings[{i}].{g}": v for i in (1, 2) for g, v in (("kp", kp), ("kd", kd))}
    model = build_model(with_overrides(design, overrides))
    q = imbalance_response(model, speeds, imbalance_loads(model))
    n = np.arange(model.dofs.n_shaft_nodes)
    return float(orbit_amplitude(q[model.dofs.shaft(n, "v")], q[model.dofs.shaft(n, "w")]).max())


def timed_map(model, kp, kd, speeds, limit_threads: bool):
    receptance_fn = actuator_receptance if limit_threads else actuator_receptance.__wrapped__
    map_fn = spinup_map if limit_threads else spinup_map.__wrapped__
    t0 = time.perf_counter()
    rec = receptance_fn(model, speeds)
    t1 = time.perf_counter()
    result = map_fn(model, kp, kd, receptance=rec)
    t2 = time.perf_counter()
    return result, rec, t1 - t0, t2 - t1


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n-gains", type=int, default=30)
    parser.add_argument("--n-speeds", type=int, default=400)
    args = parser.parse_args()

    from threadpoolctl import threadpool_info

    blas = [(i["internal_api"], i["num_threads"]) for i in threadpool_info() if i["user_api"] == "blas"]
    print(f"BLAS libraries (default threads): {blas}")
    design = baseline_design()
    t0 = time.perf_counter()
    model = build_model(design)
    print(
        f"model: {model.dofs.free.size} free DOFs, {len(model.actuators)} actuators, "
        f"built in {time.perf_counter() - t0:.2f} s"
    )
    speeds = spinup_speeds(model, args.n_speeds)
    kp = np.logspace(5, 8, args.n_gains)  # [N/m]
    kd = np.concatenate([[0.0], np.logspace(1, 4.5, args.n_gains - 1)])  # [N s/m]
    n_points = kp.size * kd.size * speeds.size
    print(f"map: {kp.size} K_p × {kd.size} K_d × {speeds.size} speeds = {n_points:,} response points")

    timings = {}
    for label, limit in (("1 BLAS thread", True), ("default threads", False)):
        best = None
        for _ in range(3):
            result, rec, t_rec, t_map = timed_map(model, kp, kd, speeds, limit)
            total = t_rec + t_map
            if best is None or total < best[0]:
                best = (total, t_rec, t_map)
        timings[label] = best
        print(
            f"  {label:16s}: {best[0]:.2f} s  (structure solves {best[1]:.2f} s + "
            f"{kp.size * kd.size} gain pairs {best[2]:.2f} s; best of 3)"
        )

    # direct estimate: a few full spin-ups with a banded solve per speed
    sample = [(kp[0], kd[0]), (kp[kp.size // 2], kd[kd.size // 3]), (kp[-1], kd[-1])]
    t0 = time.perf_counter()
    for a, b in sample:
        direct_peak(design, speeds, a, b)
    per_pair = (time.perf_counter() - t0) / len(sample)
    estimate = per_pair * kp.size * kd.size
    print(
        f"direct banded solve: {per_pair:.3f} s per gain pair → {estimate:.0f} s for the map "
        f"({estimate / timings['1 BLAS thread'][0]:.0f}× the fast path)"
    )

    # agreement at sampled gain pairs
    rng = np.random.default_rng(6)
    picks = [(0, 0), (kp.size - 1, kd.size - 1)] + [tuple(rng.integers(0, [kp.size, kd.size])) for _ in range(6)]
    errors = []
    for i, j in picks:
        ref = direct_peak(design, speeds, kp[i], kd[j])
        errors.append(abs(result.shaft_peak[i, j] - ref) / ref)
        print(
            f"  K_p = {kp[i]:9.3e} N/m, K_d = {kd[j]:9.3e} N s/m: map {1e3 * result.shaft_peak[i, j]:.4f} mm, "
            f"direct {1e3 * ref:.4f} mm, rel. diff {errors[-1]:.1e}"
        )
    print(f"largest relative difference of the peaks over {len(picks)} sampled pairs: {max(errors):.1e} (bar: 1e-2)")

    before = spinup_curves(rec, (1e7, 0.0))
    kp_best, kd_best, peak_best = result.best()
    i, j = int(np.argmin(np.abs(kp - kp_best))), int(np.argmin(np.abs(kd - kd_best)))
    print(
        f"baseline gains K_p = 1e7 N/m, K_d = 0: peak shaft orbit {1e3 * before.shaft_peak.max():.2f} mm "
        f"at {before.speeds[np.argmax(before.shaft_peak)] * 60 / (2 * np.pi):.0f} rpm, "
        f"actuator {1e3 * before.actuator_displacement.max():.3f} mm / {before.actuator_force.max():.0f} N"
    )
    print(
        f"best gains on the grid K_p = {kp_best:.3e} N/m, K_d = {kd_best:.3e} N s/m: peak {1e3 * peak_best:.2f} mm "
        f"at {result.shaft_peak_speed[i, j] * 60 / (2 * np.pi):.0f} rpm, actuator "
        f"{1e3 * result.actuator_displacement_peak[i, j].max():.3f} mm / {result.actuator_force_peak[i, j].max():.0f} N"
    )
    print("thesis: 38 mm → 4 mm")


if __name__ == "__main__":
    main()

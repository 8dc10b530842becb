"""ROSS side of the flexshaft-vs-ROSS benchmark (run with the ROSS interpreter, not flexshaft's).

    /work/ross-venv/bin/python benchmarks/ross_model.py [--out ross.json] [--elements 20 50 100]
                                                      [--cases unbalance frf campbell]
                                                      [--max-repeat 3] [--no-isolate]

Builds the case of ``shaft_case.py`` in ROSS 2.3.0 (``ross-rotordynamics``) and times

* ``unbalance``: ``rotor.run_unbalance_response`` at the mid node, 500 speeds 0..SPEED_MAX;
* ``frf``: the frequency response at a fixed spin speed over 500 frequencies. ROSS 2.3.0's
  ``run_freq_response`` has no fixed-speed option (it evaluates H at speed = frequency, or at
  speed 0 with ``free_free=True``), so this loops over ``rotor.transfer_matrix(speed, frequency)``,
  the exact per-frequency kernel ``run_freq_response`` calls, and keeps one column;
* ``campbell``: ``rotor.run_campbell`` over 50 speeds, lowest 8 damped frequencies.

Only the analysis call is timed (``time.perf_counter``); rotor construction is timed apart.
Each timing is the best of up to ``--max-repeat`` runs (repeats only while a run is < 10 s);
every run uses a freshly built rotor because ROSS caches ``run_modal`` and ``run_freq_response``
results per rotor (methodtools ``lru_cache``), which would make a repeat free.

By default every (case, n_el) runs in its own child process, so that the peak resident memory
(``ru_maxrss``) reported is that case's (after its first run: import + build + one analysis). Output: JSON (stdout, or ``--out FILE``).
"""

from __future__ import annotations

import argparse
import gc
import json
import os
import resource
import subprocess
import sys
import time
import warnings

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import shaft_case as case  # noqa: E402

REPEAT_BELOW_S = 10.0


def _quiet_import_ross():
    """ROSS pulls in ``ccp``, which prints a REFPROP banner and warns: silence the import.

    If ``import ross`` fails, the exception (not the silenced output) still propagates."""
    t0 = time.perf_counter()
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 1)
        os.dup2(devnull, 2)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            import ross  # noqa: F401
    finally:
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in (*saved, devnull):
            os.close(fd)
    return time.perf_counter() - t0


def build_rotor(n_el: int):
    import ross as rs

    steel = rs.Material(name="bench_steel", rho=case.DENSITY, E=case.E, G_s=case.G)
    le = case.LENGTH / n_el
    shaft = [
        rs.ShaftElement(
            L=le, idl=case.INNER_DIAMETER, odl=case.OUTER_DIAMETER, material=steel, n=i,
            shear_effects=False, rotary_inertia=True, gyroscopic=True,
        )
        for i in range(n_el)
    ]
    bearings = [
        rs.BearingElement(n=node, kxx=case.BEARING_STIFFNESS, kyy=case.BEARING_STIFFNESS,
                          cxx=case.BEARING_DAMPING, cyy=case.BEARING_DAMPING)
        for node in (0, n_el)
    ]
    return rs.Rotor(shaft_elements=shaft, bearing_elements=bearings)


def _dof(rotor, node: int, local: int) -> int:
    return rotor.number_dof * node + local


def run_unbalance(rotor, np):
    mid = len(rotor.nodes) // 2
    speeds = np.array(case.unbalance_speeds())
    t0 = time.perf_counter()
    res = rotor.run_unbalance_response(node=mid, unbalance_magnitude=case.UNBALANCE,
                                       unbalance_phase=0.0, frequency=speeds)
    dt = time.perf_counter() - t0
    x = res.forced_resp[_dof(rotor, mid, 0)]
    y = res.forced_resp[_dof(rotor, mid, 1)]
    return dt, {"speeds_rad_s": speeds.tolist(), "x": _c(x), "y": _c(y)}


def run_frf(rotor, np):
    mid = len(rotor.nodes) // 2
    freqs = np.array(case.frf_frequencies())
    inp = _dof(rotor, mid, 0)
    out = np.empty((rotor.ndof, len(freqs)), dtype=complex)
    t0 = time.perf_counter()
    for k, w in enumerate(freqs):
        H = rotor.transfer_matrix(speed=case.FRF_SPEED, frequency=w)
        out[:, k] = H[:, inp] * case.FRF_FORCE
    dt = time.perf_counter() - t0
    return dt, {"frequencies_rad_s": freqs.tolist(), "speed_rad_s": case.FRF_SPEED,
                "x": _c(out[_dof(rotor, mid, 0)]), "y": _c(out[_dof(rotor, mid, 1)])}


def run_campbell(rotor, np):
    speeds = np.array(case.campbell_speeds())
    nf = case.N_CAMPBELL_FREQ
    t0 = time.perf_counter()
    camp = rotor.run_campbell(speeds, frequencies=nf)
    dt = time.perf_counter() - t0
    # lateral check on the (MAC-tracked) modes that run_campbell kept
    n = rotor.ndof
    lateral = []
    for w in speeds:
        vec = camp.modal_results[w].evectors[:n, :nf]
        lat = sum(np.sum(np.abs(vec[j::rotor.number_dof]) ** 2, axis=0) for j in (0, 1, 3, 4))
        oth = sum(np.sum(np.abs(vec[j::rotor.number_dof]) ** 2, axis=0) for j in (2, 5))
        lateral.append((lat > oth).tolist())
    return dt, {"speeds_rad_s": speeds.tolist(),
                "wd_hz": (np.asarray(camp.wd) / (2 * np.pi)).tolist(),
                "whirl_values": np.asarray(camp.whirl_values).tolist(),
                "lateral": lateral}


CASES = {"unbalance": run_unbalance, "frf": run_frf, "campbell": run_campbell}


def _c(z) -> dict:
    return {"re": [float(v) for v in z.real], "im": [float(v) for v in z.imag]}


def _maxrss_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # Linux: KiB


def run_single(name: str, n_el: int, max_repeat: int) -> dict:
    import_s = _quiet_import_ross()
    import numpy as np

    warnings.simplefilter("ignore")  # ROSS warns (singular LU) at ω = 0 and on units
    times, build_times, data = [], [], None
    rss_before = None
    for _ in range(max(1, max_repeat)):
        t0 = time.perf_counter()
        rotor = build_rotor(n_el)
        build_times.append(time.perf_counter() - t0)
        if rss_before is None:
            rss_before = _maxrss_mb()
        dt, d = CASES[name](rotor, np)
        times.append(dt)
        if data is None:
            data, peak_first = d, _maxrss_mb()
        # ROSS results hold the rotor and the rotor's lru_cache holds the results: a cycle
        del rotor, d
        gc.collect()
        if dt >= REPEAT_BELOW_S:
            break
    return {
        "case": name, "n_el": n_el, "ndof": 6 * (n_el + 1),
        "time_s": min(times), "times_s": times, "build_s": min(build_times),
        "import_ross_s": import_s,
        "peak_rss_mb": peak_first, "rss_before_case_mb": rss_before,
        "peak_rss_all_repeats_mb": _maxrss_mb(),
        "result": data,
    }


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--out", help="write JSON here instead of stdout")
    p.add_argument("--elements", type=int, nargs="+", default=list(case.ELEMENTS))
    p.add_argument("--cases", nargs="+", default=list(CASES), choices=list(CASES))
    p.add_argument("--max-repeat", type=int, default=3)
    p.add_argument("--no-isolate", action="store_true",
                   help="run every case in this process (peak memory is then cumulative)")
    p.add_argument("--single", nargs=2, metavar=("CASE", "N_EL"), help=argparse.SUPPRESS)
    a = p.parse_args(argv)

    if a.single:
        json.dump(run_single(a.single[0], int(a.single[1]), a.max_repeat), sys.stdout)
        return 0

    import platform

    runs = []
    for n_el in a.elements:
        for name in a.cases:
            print(f"[ross] {name:9s} n_el={n_el:4d} ...", file=sys.stderr, flush=True)
            if a.no_isolate:
                r = run_single(name, n_el, a.max_repeat)
            else:
                proc = subprocess.run(
                    [sys.executable, os.path.abspath(__file__), "--single", name, str(n_el),
                     "--max-repeat", str(a.max_repeat)],
                    stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                )
                if proc.returncode != 0:  # show the child's stderr only when it failed
                    sys.stderr.write(proc.stderr.decode(errors="replace"))
                    raise SystemExit(f"ROSS child {name} n_el={n_el} failed ({proc.returncode})")
                r = json.loads(proc.stdout)
            print(f"[ross] {name:9s} n_el={n_el:4d} {r['time_s']:9.3f} s  "
                  f"peak {r['peak_rss_mb']:7.0f} MB", file=sys.stderr, flush=True)
            runs.append(r)

    _quiet_import_ross()
    import numpy
    import ross
    import scipy

    out = {
        "ross_version": ross.__version__, "numpy": numpy.__version__, "scipy": scipy.__version__,
        "python": platform.python_version(), "isolated_processes": not a.no_isolate,
        "blas_threads": {k: os.environ.get(k, "default")
                         for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")},
        "parameters": case.parameters(), "runs": runs,
    }
    text = json.dumps(out)
    if a.out:
        with open(a.out, "w") as f:
            f.write(text)
    else:
        print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())

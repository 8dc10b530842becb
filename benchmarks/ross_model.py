"""ROSS side of the flexshaft-vs-ROSS benchmark (run with a ROSS interpreter, not flexshaft's).

    /work/ross-2.3-venv/bin/python benchmarks/ross_model.py [--out ross.json] [--elements 20 50 100]
                                                          [--cases unbalance frf campbell]
                                                          [--repeats 3]
    /work/ross-2.3-venv/bin/python benchmarks/ross_model.py --single unbalance 100 [--repeats 3]

Builds the case of ``shaft_case.py`` in ROSS (``ross-rotordynamics``; works with 2.3.0 and
3.x, the API differences are handled in :func:`unbalance_kwargs`) and times

* ``unbalance``: ``rotor.run_unbalance_response`` at the mid node, 500 speeds 0..SPEED_MAX
  (the speed argument is ``frequency=`` in 2.x, ``speed_range=`` in 3.x);
* ``frf``: the frequency response at a fixed spin speed over 500 frequencies. ROSS 2.3.0's
  ``run_freq_response`` has no fixed-speed option (3.x has ``speed=``, but it still stores the
  full H, iωH and −ω²H), so with both versions this loops over
  ``rotor.transfer_matrix(speed, frequency)``, the exact per-frequency kernel
  ``run_freq_response`` calls, and keeps one column: the same work in both versions, and less
  than ``run_freq_response`` does;
* ``campbell``: ``rotor.run_campbell`` over 50 speeds, lowest 8 damped frequencies.

Only the analysis call is timed; rotor construction is timed apart. Every (case, n_el) runs in
a fresh process (``--single``, or one child per pair by default):

* cold: the first build and the first analysis call in that process (``ross`` already
  imported: its import time is reported apart);
* warm: ``--repeats`` further calls, each on a freshly built rotor (the build outside the
  clock), because ROSS caches ``run_modal`` and ``run_freq_response`` results per rotor
  (methodtools ``lru_cache``), which would make a repeat on the same rotor free.

Each call is timed by wall clock (``time.perf_counter``) and by the process's CPU time
(``time.process_time``). Memory: ``ru_maxrss`` of the process (whole-process peak resident
set, interpreter and imports included), after the cold call and at the end; the resident size
after ``import ross`` is reported for reference. Output: JSON (stdout, or ``--out FILE``).
"""

from __future__ import annotations

import argparse
import gc
import inspect
import json
import os
import subprocess
import sys
import time
import warnings

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import bench_util as bu  # noqa: E402
import shaft_case as case  # noqa: E402


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
            L=le,
            idl=case.INNER_DIAMETER,
            odl=case.OUTER_DIAMETER,
            material=steel,
            n=i,
            shear_effects=False,
            rotary_inertia=True,
            gyroscopic=True,
        )
        for i in range(n_el)
    ]
    bearings = [
        rs.BearingElement(
            n=node,
            kxx=case.BEARING_STIFFNESS,
            kyy=case.BEARING_STIFFNESS,
            cxx=case.BEARING_DAMPING,
            cyy=case.BEARING_DAMPING,
        )
        for node in (0, n_el)
    ]
    return rs.Rotor(shaft_elements=shaft, bearing_elements=bearings)


def _dof(rotor, node: int, local: int) -> int:
    return rotor.number_dof * node + local


def unbalance_kwargs(rotor, speeds) -> dict:
    """The speed argument of ``run_unbalance_response``: ``frequency`` (ROSS 2.x) or
    ``speed_range`` (ROSS 3.x)."""
    params = inspect.signature(rotor.run_unbalance_response).parameters
    for name in ("speed_range", "frequency"):
        if name in params:
            return {name: speeds}
    raise RuntimeError(f"unknown run_unbalance_response signature: {list(params)}")


def run_unbalance(rotor, np):
    mid = len(rotor.nodes) // 2
    speeds = np.array(case.unbalance_speeds())
    kwargs = unbalance_kwargs(rotor, speeds)
    wall, cpu, res = bu.timed(
        lambda: rotor.run_unbalance_response(
            node=mid, unbalance_magnitude=case.UNBALANCE, unbalance_phase=0.0, **kwargs
        )
    )
    x = res.forced_resp[_dof(rotor, mid, 0)]
    y = res.forced_resp[_dof(rotor, mid, 1)]
    return (wall, cpu), {"speeds_rad_s": speeds.tolist(), "x": _c(x), "y": _c(y)}


def run_frf(rotor, np):
    mid = len(rotor.nodes) // 2
    freqs = np.array(case.frf_frequencies())
    inp = _dof(rotor, mid, 0)
    out = np.empty((rotor.ndof, len(freqs)), dtype=complex)

    def sweep():
        for k, w in enumerate(freqs):
            H = rotor.transfer_matrix(speed=case.FRF_SPEED, frequency=w)
            out[:, k] = H[:, inp] * case.FRF_FORCE

    wall, cpu, _ = bu.timed(sweep)
    return (wall, cpu), {
        "frequencies_rad_s": freqs.tolist(),
        "speed_rad_s": case.FRF_SPEED,
        "x": _c(out[_dof(rotor, mid, 0)]),
        "y": _c(out[_dof(rotor, mid, 1)]),
    }


def run_campbell(rotor, np):
    speeds = np.array(case.campbell_speeds())
    nf = case.N_CAMPBELL_FREQ
    wall, cpu, camp = bu.timed(lambda: rotor.run_campbell(speeds, frequencies=nf))
    # lateral check on the (MAC-tracked) modes that run_campbell kept
    n = rotor.ndof
    lateral = []
    for w in speeds:
        vec = camp.modal_results[w].evectors[:n, :nf]
        lat = sum(np.sum(np.abs(vec[j :: rotor.number_dof]) ** 2, axis=0) for j in (0, 1, 3, 4))
        oth = sum(np.sum(np.abs(vec[j :: rotor.number_dof]) ** 2, axis=0) for j in (2, 5))
        lateral.append((lat > oth).tolist())
    return (wall, cpu), {
        "speeds_rad_s": speeds.tolist(),
        "wd_hz": (np.asarray(camp.wd) / (2 * np.pi)).tolist(),
        "whirl_values": np.asarray(camp.whirl_values).tolist(),
        "lateral": lateral,
    }


CASES = {"unbalance": run_unbalance, "frf": run_frf, "campbell": run_campbell}


def _c(z) -> dict:
    return {"re": [float(v) for v in z.real], "im": [float(v) for v in z.imag]}


def run_single(name: str, n_el: int, repeats: int) -> dict:
    """One case on one mesh in this (fresh) process: cold call, then ``repeats`` warm calls."""
    import_s = _quiet_import_ross()
    import numpy as np

    warnings.simplefilter("ignore")  # ROSS warns (singular LU) at ω = 0 and on units
    rss_import = bu.current_rss_mb()
    build_s, _, rotor = bu.timed(lambda: build_rotor(n_el))
    (cold_wall, cold_cpu), data = CASES[name](rotor, np)
    peak_cold = bu.maxrss_mb()
    walls, cpus, builds = [], [], []
    for _ in range(repeats):
        # ROSS results hold the rotor and the rotor's lru_cache holds the results: a cycle
        del rotor
        gc.collect()
        b, _, rotor = bu.timed(lambda: build_rotor(n_el))
        (w, c), _ = CASES[name](rotor, np)
        builds.append(b)
        walls.append(w)
        cpus.append(c)
    import ross
    import scipy

    return {
        "code": "ross",
        "version": ross.__version__,
        "case": name,
        "n_el": n_el,
        "ndof": 6 * (n_el + 1),
        "import_s": import_s,
        "build_s": build_s,
        "warm_build_s": bu.stats(builds) if builds else None,
        "cold_s": cold_wall,
        "cold_cpu_s": cold_cpu,
        "warm": {**bu.stats(walls), "cpu": bu.stats(cpus)} if walls else None,
        "rss_after_import_mb": rss_import,
        "peak_rss_cold_mb": peak_cold,
        "peak_rss_mb": bu.maxrss_mb(),
        "result": data,
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "python": sys.version.split()[0],
    }


def run_isolated(name: str, n_el: int, repeats: int, python: str = sys.executable) -> dict:
    """:func:`run_single` in a fresh child process of ``python``; raises on failure."""
    proc = subprocess.run(
        [python, os.path.abspath(__file__), "--single", name, str(n_el), "--repeats", str(repeats)], capture_output=True
    )
    if proc.returncode != 0:  # show the child's stderr only when it failed
        sys.stderr.write(proc.stderr.decode(errors="replace")[-4000:])
        raise RuntimeError(f"ROSS child {name} n_el={n_el} failed ({proc.returncode})")
    return json.loads(proc.stdout)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--out", help="write JSON here instead of stdout")
    p.add_argument("--elements", type=int, nargs="+", default=list(case.ELEMENTS))
    p.add_argument("--cases", nargs="+", default=list(CASES), choices=list(CASES))
    p.add_argument("--repeats", type=int, default=3, help="warm calls after the cold one")
    p.add_argument(
        "--single", nargs=2, metavar=("CASE", "N_EL"), help="run one case in this process and print its JSON"
    )
    a = p.parse_args(argv)

    if a.single:
        if a.single[0] not in CASES:
            p.error(f"--single: case must be one of {list(CASES)}, got {a.single[0]!r}")
        json.dump(run_single(a.single[0], int(a.single[1]), a.repeats), sys.stdout)
        return 0

    runs = []
    for n_el in a.elements:
        for name in a.cases:
            print(f"[ross] {name:9s} n_el={n_el:4d} ...", file=sys.stderr, flush=True)
            r = run_isolated(name, n_el, a.repeats)
            print(
                f"[ross] {name:9s} n_el={n_el:4d} cold {r['cold_s']:8.3f} s  warm median "
                f"{r['warm']['median']:8.3f} s  peak {r['peak_rss_mb']:7.0f} MB",
                file=sys.stderr,
                flush=True,
            )
            runs.append(r)
    out = {
        "ross_version": runs[0]["version"] if runs else None,
        "machine": bu.machine_info(),
        "parameters": case.parameters(),
        "runs": runs,
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

"""How flexshaft's sweeps scale with mesh size, and how close the imbalance sweep is to LAPACK.

    .venv/bin/python benchmarks/scaling.py [--elements 100 200 400 800] [--repeats 5]
                                           [--n-speeds 500] [--n-campbell 50] [--blas-threads 1]
                                           [--json FILE]

Model: the plain benchmark shaft of ``shaft_case.py`` (uniform steel tube on two damped end
bearings, built by ``flexshaft_side.build``), meshed with 100, 200, 400 and 800 elements.

Cases, each timed warm (model built and one call made before timing, then ``--repeats`` timed
calls on the same model; median and min–max printed). The imbalance sweep and its zgbsv floor
are timed in pairs, back to back, and their ratio is the median of the pairs' ratios: on a
shared machine whose load drifts, timing all of one and then all of the other biased it by
±20 %.

* ``imbalance``: ``flexshaft.analyses.imbalance_response`` at 500 speeds 0..SPEED_MAX, the
  imbalance at mid-span (the whole public call: band set-up, 500 factorizations and solves);
* ``campbell``: ``flexshaft.analyses.campbell`` over 50 speeds, 14 tracked modes (8 lateral
  + 6 spare, as in the ROSS comparison);
* ``zgbsv`` (the "LAPACK floor"): ``scipy.linalg.lapack.zgbsv`` called directly at every speed
  on the same band matrices Z(Ω, Ω) and the same right-hand side. Only the zgbsv calls are
  timed (the band matrix of each speed is formed outside the clock), so this is what the
  imbalance sweep would cost if it did nothing but factorize and solve. The band matrices come
  from ``BandedHarmonicSolver.matrix`` (so the ordering and bandwidth are flexshaft's); if that
  API is gone, they are assembled here from ``model.M/K/G/C`` with reverse Cuthill-McKee, and
  the script says so. The zgbsv solution is checked against ``imbalance_response``.

Printed: a table of times, the ratio imbalance / zgbsv per size, and the fitted exponent p of
t ∝ n_el^p (least-squares slope of log t against log n_el over all sizes, and the local slope
between neighbouring sizes). The project's bars (information, not asserted): imbalance within
1.5x of zgbsv, p <= 1.15 (imbalance) and p <= 1.3 (Campbell) from 100 to 800 elements.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import sys
from functools import partial

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import bench_util as bu  # noqa: E402

BARS = {"imbalance_over_zgbsv": 1.5, "exponent_imbalance": 1.15, "exponent_campbell": 1.3}


def _band_source(model):
    """(kl, ku, perm, free, matrix(ω, Ω)) of the band matrices; ``how`` says where they came from."""
    import numpy as np

    from flexshaft.analyses import BandedHarmonicSolver

    s = BandedHarmonicSolver(model)
    if all(hasattr(s, a) for a in ("kl", "ku", "perm", "free", "matrix")):
        return s.kl, s.ku, np.asarray(s.perm), np.asarray(s.free), s.matrix, "BandedHarmonicSolver.matrix"
    return (*_own_bands(model), "assembled here (model.M/K/G/C, reverse Cuthill-McKee)")


def _own_bands(model):
    """Fallback: Z(ω, Ω) = K − ω²M + iω(ΩG + C) in LAPACK band layout, RCM-ordered."""
    import numpy as np
    import scipy.sparse as sp
    from scipy.sparse.csgraph import reverse_cuthill_mckee

    if getattr(model, "actuators", None):
        raise SystemExit("the fallback band assembly has no actuator terms; the plain shaft has none")
    free = np.asarray(model.dofs.free)
    mats = {k: sp.csr_matrix(getattr(model, k))[free][:, free] for k in ("M", "K", "G", "C")}
    pattern = sum(abs(m) for m in mats.values())
    pattern = (pattern + pattern.T).tocsr()
    perm = reverse_cuthill_mckee(pattern, symmetric_mode=True)
    P = pattern[perm][:, perm].tocoo()
    kl = int(np.max(P.row - P.col, initial=0))
    ku = int(np.max(P.col - P.row, initial=0))
    n = free.size

    def band(A):
        c = A[perm][:, perm].tocoo()
        ab = np.zeros((2 * kl + ku + 1, n), dtype=complex)
        np.add.at(ab, (kl + ku + c.row - c.col, c.col), c.data)
        return ab

    b = {k: band(v) for k, v in mats.items()}

    def matrix(omega, speed):
        return b["K"] - omega**2 * b["M"] + 1j * omega * (speed * b["G"] + b["C"])

    return kl, ku, perm, free, matrix


def zgbsv_floor(model, speeds, Q):
    """Wall and CPU time of the zgbsv calls summed over all speeds [s], the response
    (ndof, n_speeds), and facts about the bands."""
    import numpy as np
    from scipy.linalg import lapack

    kl, ku, perm, free, matrix, how = _band_source(model)
    rhs = np.asarray(Q, dtype=complex)[free][perm]
    inverse = np.argsort(perm)
    out = np.zeros((model.dofs.size, len(speeds)), dtype=complex)
    wall = cpu = 0.0
    for k, s in enumerate(speeds):
        ab = np.array(matrix(s, s), dtype=complex, order="F")  # formed outside the clock
        b = (s * s) * rhs
        dw, dc, (_, _, x, info) = bu.timed(partial(lapack.zgbsv, kl, ku, ab, b, overwrite_ab=True, overwrite_b=True))
        wall, cpu = wall + dw, cpu + dc
        if info != 0:
            raise RuntimeError(f"zgbsv info = {info} at Ω = {s} rad/s")
        out[free, k] = x[inverse]
    return wall, cpu, out, {"kl": kl, "ku": ku, "n_free": int(free.size), "bands": how}


def _timed(fn, repeats: int):
    """One untimed warm-up call, then ``repeats`` timed calls; returns (wall stats with the
    CPU-time stats under "cpu", warm-up result), or (``{"error": message}``, None) when the
    call raises: the failure is reported in the table, and the other cases still run."""
    try:
        result = fn()
    except Exception as exc:  # noqa: BLE001 - any failure of the code under test is a result
        return {"error": f"{type(exc).__name__}: {exc}"}, None
    if repeats == 0:
        return {}, result
    runs = [bu.timed(fn)[:2] for _ in range(repeats)]
    return {**bu.stats([w for w, _ in runs]), "cpu": bu.stats([c for _, c in runs])}, result


def _ok(s) -> bool:
    return s is not None and "error" not in s


def run(elements, repeats: int, n_speeds: int, n_campbell: int) -> dict:
    import flexshaft_side as fx
    import numpy as np
    import shaft_case as case

    import flexshaft
    import flexshaft.analyses as fa

    speeds = np.linspace(0.0, case.SPEED_MAX, n_speeds)
    cspeeds = np.linspace(0.0, case.SPEED_MAX, n_campbell)
    n_modes = case.N_CAMPBELL_FREQ + 6
    rows = []
    for n_el in elements:
        build_s, _, model = bu.timed(partial(fx.build, n_el))
        Q = fx.unbalance_loads(model)
        row = {"n_el": n_el, "ndof": int(model.dofs.size), "build_s": build_s}

        imbalance = partial(fa.imbalance_response, model, speeds, Q)
        imb, q = _timed(imbalance, 0)  # the warm-up call (its result is checked below)
        # the floor: a warm-up pass (also the check); then the timed passes, each right after a
        # timed imbalance call, so that both see the same load of a shared machine
        try:
            first, floor = zgbsv_floor(model, speeds, Q), {}
        except Exception as exc:  # noqa: BLE001
            first, floor = None, {"error": f"{type(exc).__name__}: {exc}"}
        if first is not None and _ok(imb):
            pairs = [(bu.timed(imbalance)[:2], zgbsv_floor(model, speeds, Q)[:2]) for _ in range(repeats)]
            imb = {**bu.stats([i[0] for i, _ in pairs]), "cpu": bu.stats([i[1] for i, _ in pairs])}
            floor = {**bu.stats([f[0] for _, f in pairs]), "cpu": bu.stats([f[1] for _, f in pairs])}
            q_lapack, facts = first[2], first[3]
            row.update(facts)
            row["zgbsv_vs_imbalance_max_rel"] = float(
                np.max(np.abs(np.asarray(q) - q_lapack)) / np.max(np.abs(q_lapack))
            )
            # the median of the pairs' ratios (each pair timed back to back)
            row["imbalance_over_zgbsv"] = statistics.median(i[0] / f[0] for i, f in pairs)
            row["imbalance_over_zgbsv_cpu"] = statistics.median(i[1] / f[1] for i, f in pairs)
        elif _ok(imb):
            imb, q = _timed(imbalance, repeats)
        camp, c = _timed(partial(fa.campbell, model, cspeeds, n_modes=n_modes), repeats)
        if _ok(camp):
            row["campbell_lowest_hz"] = float(np.min(np.asarray(c.frequencies)[0]))
        row.update({"imbalance": imb, "zgbsv": floor, "campbell": camp})
        rows.append(row)
        print(
            f"[scaling] n_el={n_el:4d} ndof={row['ndof']:5d} kl/ku={row.get('kl')}/{row.get('ku')}  "
            + "  ".join(f"{k} {_cell(row[k], 4)}" for k in ("imbalance", "zgbsv", "campbell"))
            + f"  (build {build_s:.2f} s)",
            flush=True,
        )
    return {
        "machine": bu.machine_info(),
        "flexshaft": flexshaft.__version__,
        "numpy": np.__version__,
        "scipy": _scipy_version(),
        "blas": _blas_info(),
        "repeats": repeats,
        "n_speeds": n_speeds,
        "n_campbell_speeds": n_campbell,
        "campbell_modes": n_modes,
        "rows": rows,
    }


def _cell(s, digits: int) -> str:
    if _ok(s):
        return bu.fmt_stats(s, digits)
    return "FAILED (" + s["error"].split(":")[0] + ")"


def _scipy_version():
    import scipy

    return scipy.__version__


def _blas_info():
    try:
        from threadpoolctl import threadpool_info
    except ImportError:
        return []
    return [
        {k: i.get(k) for k in ("internal_api", "num_threads", "version", "architecture")}
        for i in threadpool_info()
        if i.get("user_api") == "blas"
    ]


def slope(ns, ts) -> float:
    """Least-squares slope of log t against log n."""
    x = [math.log(n) for n in ns]
    y = [math.log(t) for t in ts]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    sxx = sum((a - mx) ** 2 for a in x)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx if sxx > 0 else float("nan")


def _fits(rows, key: str, clock: str):
    """(sizes, times) of the sizes where ``key`` ran; clock "wall" or "cpu" medians."""
    ok = [r for r in rows if _ok(r[key])]
    ns = [r["n_el"] for r in ok]
    ts = [r[key]["median"] if clock == "wall" else r[key]["cpu"]["median"] for r in ok]
    return ns, ts


def report(data: dict) -> None:
    rows = data["rows"]
    m = data["machine"]
    print()
    print(
        f"machine: {m['cpu']}, {m['cores']} cores, {m['memory_gb']} GB; load average "
        f"{m['load_average_1_5_15']} (shared machine); {m['date']}"
    )
    print(
        f"flexshaft {data['flexshaft']} (git {m['git_commit']}), Python {m['python']}, "
        f"numpy {data['numpy']}, scipy {data['scipy']}; BLAS {data['blas']}"
    )
    print(
        f"warm timings, median (min–max) of {data['repeats']} calls after one untimed call; "
        f"imbalance {data['n_speeds']} speeds, Campbell {data['n_campbell_speeds']} speeds "
        f"({data['campbell_modes']} modes)"
    )
    print()
    print(
        "| n_el | free DOFs | band kl/ku | imbalance [s] | zgbsv floor [s] | imbalance / zgbsv "
        "(CPU) | zgbsv vs flexshaft | Campbell [s] | Campbell CPU [s] |"
    )
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        ratio = (
            f"{r['imbalance_over_zgbsv']:.2f}× ({r['imbalance_over_zgbsv_cpu']:.2f}×)"
            if "imbalance_over_zgbsv" in r
            else "–"
        )
        check = f"{r['zgbsv_vs_imbalance_max_rel']:.1e}" if "zgbsv_vs_imbalance_max_rel" in r else "–"
        ccpu = f"{r['campbell']['cpu']['median']:.4f}" if _ok(r["campbell"]) else "–"
        print(
            f"| {r['n_el']} | {r.get('n_free', '–')} | {r.get('kl', '–')}/{r.get('ku', '–')} "
            f"| {_cell(r['imbalance'], 4)} | {_cell(r['zgbsv'], 4)} | {ratio} | {check} "
            f"| {_cell(r['campbell'], 4)} | {ccpu} |"
        )
    print()
    for name, key in (("imbalance", "imbalance"), ("zgbsv floor", "zgbsv"), ("Campbell", "campbell")):
        for clock in ("wall", "cpu"):
            ns, ts = _fits(rows, key, clock)
            if len(ns) < 2:
                continue
            local = ", ".join(f"{a}→{b}: {slope([a, b], [ta, tb]):.2f}" for a, b, ta, tb in zip(ns, ns[1:], ts, ts[1:]))
            print(
                f"exponent p (t ∝ n_el^p), {name:11s} {clock:4s}: {slope(ns, ts):.2f} over "
                f"{ns[0]}–{ns[-1]} (local {local})"
            )
    for r in rows:
        for key in ("imbalance", "zgbsv", "campbell"):
            if not _ok(r[key]):
                print(f"FAILED: {key} at {r['n_el']} elements: {r[key]['error']}")
    print(
        "time columns: wall time, median (min–max); CPU: median process CPU time, less "
        "sensitive to other load on a shared machine"
    )
    print(
        "'zgbsv vs flexshaft': max |q_flexshaft − q_zgbsv| / max |q_zgbsv| (a check that the "
        "floor solves the same problem)"
    )
    print(f"bands: {next((r['bands'] for r in rows if 'bands' in r), '–')}")
    _bars(data)


def _bars(data: dict) -> None:
    rows = data["rows"]
    print()
    print("project bars (information only):")
    for r in rows:
        if "imbalance_over_zgbsv" not in r:
            print(
                f"  MISS imbalance / zgbsv at {r['n_el']} elements: not measured "
                f"({_cell(r['imbalance'], 4)}; zgbsv {_cell(r['zgbsv'], 4)})"
            )
            continue
        v = r["imbalance_over_zgbsv"]
        print(
            f"  {'met ' if v <= BARS['imbalance_over_zgbsv'] else 'MISS'} imbalance / zgbsv at "
            f"{r['n_el']} elements = {v:.2f} wall, {r['imbalance_over_zgbsv_cpu']:.2f} CPU "
            f"(bar <= {BARS['imbalance_over_zgbsv']}, on wall)"
        )
    all_ns = [r["n_el"] for r in rows]
    for key, bar in (("imbalance", BARS["exponent_imbalance"]), ("campbell", BARS["exponent_campbell"])):
        ns, ts = _fits(rows, key, "wall")
        if ns != all_ns:
            print(f"  MISS exponent {key}: it failed at {sorted(set(all_ns) - set(ns))} elements")
            if len(ns) < 2:
                continue
        p = slope(ns, ts)
        pc = slope(*_fits(rows, key, "cpu"))
        print(
            f"  {'met ' if p <= bar else 'MISS'} exponent {key} {ns[0]}–{ns[-1]} = {p:.2f} wall, "
            f"{pc:.2f} CPU (bar <= {bar}, on wall)"
        )


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--elements", type=int, nargs="+", default=[100, 200, 400, 800])
    p.add_argument("--repeats", type=int, default=5, help="timed calls per case after one warm-up (>= 3)")
    p.add_argument("--n-speeds", type=int, default=500)
    p.add_argument("--n-campbell", type=int, default=50)
    p.add_argument(
        "--blas-threads", type=int, default=1, help="BLAS/OpenMP threads (default 1; 0 = the libraries' defaults)"
    )
    p.add_argument("--json", help="also write the measurements to this JSON file")
    a = p.parse_args(argv)
    if a.repeats < 3:
        p.error(f"--repeats must be at least 3 (got {a.repeats})")
    if any(n < 2 or n % 2 for n in a.elements):
        p.error(f"--elements must be even and >= 2 (a node at mid-span), got {a.elements}")
    bu.reexec_with_threads(a.blas_threads, __file__)
    data = run(sorted(a.elements), a.repeats, a.n_speeds, a.n_campbell)
    report(data)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(data, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""flexshaft vs ROSS on the same model: speed ratios and agreement of results.

    .venv/bin/python benchmarks/compare_ross.py [--elements 20 50 100] [--ross-json FILE]
                                              [--save FILE] [--enforce-bars]

The model (``shaft_case.py``): a uniform steel tube, 1.5 m, D_o 50 mm, D_i 30 mm, on two
isotropic bearings at its ends (k = 1e7 N/m, c = 1e3 N s/m), no disk, meshed with 20, 50 and
100 elements; Euler-Bernoulli bending with rotary inertia and gyroscopic terms, no shear, in
both codes. Cases: imbalance response at mid-span over 500 speeds, frequency response over 500
frequencies at a fixed spin speed, Campbell diagram over 50 speeds (lowest 8 lateral damped
natural frequencies).

ROSS (``ross-rotordynamics`` 2.3.0) runs in its own environment, as a subprocess:
``$ROSS_PYTHON benchmarks/ross_model.py`` (default ``/work/ross-venv/bin/python``). When that
interpreter is missing, this prints how to create it and runs the flexshaft side alone (exit 0).
``--ross-json FILE`` reuses a ROSS result file written by ``ross_model.py --out FILE``.

Checks (printed as PASS/FAIL lines):

* agreement, every case and size: max relative difference <= 0.1 % (exit status 1 otherwise);
* the issue's bars, on the 100-element shaft: imbalance response >= 100x faster than ROSS,
  Campbell >= 20x faster, flexshaft peak memory < 500 MB (in the exit status only with
  ``--enforce-bars``: timings depend on the machine).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import numpy as np  # noqa: E402

import flexshaft_side as fx  # noqa: E402
import shaft_case as case  # noqa: E402

DEFAULT_ROSS_PYTHON = "/work/ross-venv/bin/python"
REPEAT_BELOW_S = 10.0
BARS = {"unbalance": 100.0, "campbell": 20.0}  # minimum speed-up on the largest mesh
MEMORY_BAR_MB = 500.0
THREAD_VARS = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")

SETUP_HINT = """\
ROSS interpreter not found at {path}. To create it (Python 3.11):
    python3.11 -m venv /work/ross-venv
    /work/ross-venv/bin/pip install "ross-rotordynamics==2.3.0" "plotly<7"
or point ROSS_PYTHON at an interpreter that has ross-rotordynamics installed."""


# -------------------------------------------------------------------------------------------------
# running the two sides


def run_ross(elements, max_repeat: int) -> dict | None:
    py = os.environ.get("ROSS_PYTHON", DEFAULT_ROSS_PYTHON)
    if not (os.path.isfile(py) and os.access(py, os.X_OK)):
        print(SETUP_HINT.format(path=py))
        return None
    cmd = [py, os.path.join(HERE, "ross_model.py"), "--elements", *map(str, elements),
           "--max-repeat", str(max_repeat)]
    print("running ROSS:", " ".join(cmd), flush=True)
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, text=True)
    if proc.returncode != 0:
        raise SystemExit(f"ross_model.py failed with status {proc.returncode}")
    return json.loads(proc.stdout)


def _best_of(fn, max_repeat: int):
    times, result = [], None
    for _ in range(max(1, max_repeat)):
        t0 = time.perf_counter()
        r = fn()
        times.append(time.perf_counter() - t0)
        result = r if result is None else result
        if times[-1] >= REPEAT_BELOW_S:
            break
    return min(times), times, result


def _maxrss_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def run_flexshaft(elements, max_repeat: int) -> dict:
    """The same three cases in-process; returns results in ROSS's layout (x = v, y = w)."""
    runs = []
    for n_el in elements:
        t0 = time.perf_counter()
        model = fx.build(n_el)
        build_s = time.perf_counter() - t0
        mid = fx.mid_node(model)
        iv, iw = fx.lateral_dofs(model, mid)

        speeds = np.array(case.unbalance_speeds())
        t, ts, q = _best_of(lambda: fx.unbalance_response(model, speeds), max_repeat)
        runs.append({"case": "unbalance", "n_el": n_el, "time_s": t, "times_s": ts,
                     "build_s": build_s, "path": "sweep" if fx.has_imbalance_sweep() else "fallback",
                     "result": {"x": q[iv], "y": q[iw]}, "peak_rss_mb": _maxrss_mb()})
        _progress(runs[-1])

        freqs = np.array(case.frf_frequencies())
        t, ts, q = _best_of(lambda: fx.frf(model, freqs, case.FRF_SPEED), max_repeat)
        runs.append({"case": "frf", "n_el": n_el, "time_s": t, "times_s": ts,
                     "build_s": build_s, "path": "frequency_response",
                     "result": {"x": q[iv], "y": q[iw]}, "peak_rss_mb": _maxrss_mb()})
        _progress(runs[-1])

        cs = np.array(case.campbell_speeds())
        other = fx.nonlateral_frequencies(model)  # untimed: picks out flexshaft's twist/axial modes
        t, ts, (f, w) = _best_of(lambda: fx.campbell(model, cs, case.N_CAMPBELL_FREQ, other),
                                 max_repeat)
        runs.append({"case": "campbell", "n_el": n_el, "time_s": t, "times_s": ts,
                     "build_s": build_s, "path": "sweep" if fx.has_campbell_sweep() else "fallback",
                     "result": {"wd_hz": f, "whirl": w}, "peak_rss_mb": _maxrss_mb()})
        _progress(runs[-1])
    return {"runs": runs, "peak_rss_mb": _maxrss_mb()}


def _progress(r):
    print(f"[flexshaft] {r['case']:9s} n_el={r['n_el']:4d} {r['time_s']:9.4f} s ({r['path']})",
          flush=True)


# -------------------------------------------------------------------------------------------------
# comparison


def _complex(d) -> np.ndarray:
    return np.asarray(d["re"]) + 1j * np.asarray(d["im"])


def _rel(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """|a − b| / |b| where not both are zero (0/0 points, e.g. Ω = 0 imbalance, are skipped)."""
    a, b = np.asarray(a), np.asarray(b)
    both_zero = (a == 0) & (b == 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.abs(a - b) / np.abs(b)
    return r[~both_zero]


def compare(case_name: str, fxr: dict, rsr: dict) -> dict:
    """Max relative differences; ``metric`` is the one checked against the tolerance."""
    if case_name in ("unbalance", "frf"):
        rx, ry = _complex(rsr["x"]), _complex(rsr["y"])
        fxv, fxw = np.asarray(fxr["x"]), np.asarray(fxr["y"])
        if case_name == "unbalance":
            # orbit size at mid-span: sqrt(|lat1|^2 + |lat2|^2)
            metric = _rel(np.hypot(np.abs(fxv), np.abs(fxw)), np.hypot(np.abs(rx), np.abs(ry)))
            label = "|q| mid"
        else:
            # driven direction: |v| (flexshaft) vs |x| (ROSS)
            metric = _rel(np.abs(fxv), np.abs(rx))
            label = "|v| mid"
        # extra (not checked): complex amplitude incl. phase, relative to that component's peak
        cplx = max(np.max(np.abs(fxv - rx)) / np.max(np.abs(rx)),
                   np.max(np.abs(fxw - ry)) / max(np.max(np.abs(ry)), 1e-300))
        return {"max_rel": float(np.max(metric)), "label": label, "complex_rel_peak": float(cplx)}
    # Campbell: both sides give the lowest lateral frequencies per speed; sorted, compared
    # one-to-one (falls back to nearest-value matching if the counts differ)
    rf = np.sort(np.asarray(rsr["wd_hz"]), axis=1)
    ff = np.sort(np.asarray(fxr["wd_hz"], dtype=float), axis=1)
    if rf.shape == ff.shape:
        worst, label = float(np.max(np.abs(ff - rf) / rf)), "f_d sorted"
    else:
        worst, label = 0.0, "f_d nearest"
        for r_row, f_row in zip(rf, ff):
            for r in r_row:
                worst = max(worst, float(np.min(np.abs(f_row - r)) / r))
    extra = {}
    if "lateral" in rsr:
        extra["ross_non_lateral_modes"] = int(np.sum(~np.asarray(rsr["lateral"], dtype=bool)))
    extra.update(_whirl_agreement(fxr, rsr))
    return {"max_rel": worst, "label": label, **extra}


def _whirl_agreement(fxr, rsr) -> dict:
    """Whirl labels at Ω > 0 (ROSS whirl value 0 = forward, 1 = backward)."""
    rw = np.asarray(rsr.get("whirl_values", []), dtype=float)
    if rw.size == 0:
        return {}
    speeds = np.asarray(rsr["speeds_rad_s"])
    rf = np.asarray(rsr["wd_hz"])
    ff = np.asarray(fxr["wd_hz"], dtype=float)
    fw = np.asarray(fxr["whirl"])
    bad = total = 0
    for i in np.flatnonzero(speeds > 0):
        for f, w in zip(rf[i], rw[i]):
            j = int(np.argmin(np.abs(ff[i] - f)))
            want = {0.0: "forward", 1.0: "backward"}.get(float(w))
            if want is None:
                continue
            total += 1
            bad += fw[i][j] != want
    return {"whirl_mismatch": f"{bad}/{total}"}


# -------------------------------------------------------------------------------------------------
# report


def _fmt_t(t):
    return f"{t:10.4f}" if t is not None else f"{'-':>10s}"


def report(fxs: dict, ross: dict | None) -> tuple[bool, bool]:
    ok_agree, ok_bars = True, True
    rs_runs = {(r["case"], r["n_el"]): r for r in (ross or {}).get("runs", [])}
    print()
    if ross:
        print(f"ROSS {ross['ross_version']} (Python {ross['python']}, numpy {ross['numpy']}, "
              f"scipy {ross['scipy']}); flexshaft {_flexshaft_version()}")
    hdr = (f"{'case':10s} {'n_el':>5s} {'ROSS [s]':>10s} {'flexsh [s]':>10s} {'ratio':>9s} "
           f"{'max rel diff':>13s} {'metric':>12s} {'ROSS MB':>8s}  agree  notes")
    print(hdr)
    print("-" * len(hdr))
    largest = max(r["n_el"] for r in fxs["runs"])
    for fr in fxs["runs"]:
        key = (fr["case"], fr["n_el"])
        rr = rs_runs.get(key)
        notes = [] if fr["path"] in ("sweep", "frequency_response") else [f"flexshaft {fr['path']}"]
        if rr is None:
            print(f"{fr['case']:10s} {fr['n_el']:5d} {_fmt_t(None)} {_fmt_t(fr['time_s'])}")
            continue
        c = compare(fr["case"], fr["result"], rr["result"])
        ratio = rr["time_s"] / fr["time_s"]
        agree = c["max_rel"] <= case.TOLERANCE
        ok_agree &= agree
        if "complex_rel_peak" in c:
            notes.append(f"complex/peak {c['complex_rel_peak']:.1e}")
        if "whirl_mismatch" in c:
            notes.append(f"whirl mismatch {c['whirl_mismatch']}")
        if c.get("ross_non_lateral_modes"):
            notes.append(f"ROSS non-lateral modes {c['ross_non_lateral_modes']}")
        print(f"{fr['case']:10s} {fr['n_el']:5d} {_fmt_t(rr['time_s'])} {_fmt_t(fr['time_s'])} "
              f"{ratio:8.1f}x {c['max_rel']:13.2e} {c['label']:>12s} {rr['peak_rss_mb']:8.0f}  "
              f"{'yes' if agree else 'NO':5s}  {'; '.join(notes)}")
        fr["ross_time_s"], fr["ratio"], fr["comparison"] = rr["time_s"], ratio, c
    print()
    print(f"flexshaft peak RSS (whole process, all cases and sizes): {fxs['peak_rss_mb']:.0f} MB")
    if ross:
        print(f"{'PASS' if ok_agree else 'FAIL'}: results agree to {case.TOLERANCE:.1%} "
              f"(every case and size)")
        for name, bar in BARS.items():
            fr = next(r for r in fxs["runs"] if r["case"] == name and r["n_el"] == largest)
            ratio = fr.get("ratio")
            if ratio is None:
                continue
            good = ratio >= bar
            ok_bars &= good
            print(f"{'PASS' if good else 'FAIL'}: {name} on {largest} elements is {ratio:.1f}x "
                  f"faster than ROSS (bar {bar:.0f}x)")
    good = fxs["peak_rss_mb"] < MEMORY_BAR_MB
    ok_bars &= good
    print(f"{'PASS' if good else 'FAIL'}: flexshaft peak memory {fxs['peak_rss_mb']:.0f} MB "
          f"(bar {MEMORY_BAR_MB:.0f} MB)")
    return ok_agree, ok_bars


def _flexshaft_version() -> str:
    import flexshaft

    return flexshaft.__version__


def _jsonable(o):
    if isinstance(o, np.ndarray):
        if np.iscomplexobj(o):
            return {"re": o.real.tolist(), "im": o.imag.tolist()}
        return o.tolist()
    if isinstance(o, (np.floating, np.integer)):
        return o.item()
    if isinstance(o, np.bool_):
        return bool(o)
    raise TypeError(type(o))


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--elements", type=int, nargs="+", default=list(case.ELEMENTS))
    p.add_argument("--ross-json", help="reuse a ross_model.py --out (or this script's --save) "
                                       "file instead of running ROSS")
    p.add_argument("--max-repeat", type=int, default=3, help="best of up to N runs (runs < 10 s)")
    p.add_argument("--save", help="write both sides' times, results and comparisons as JSON")
    p.add_argument("--blas-threads", type=int, default=1,
                   help="BLAS/OpenMP threads for both codes (sets OPENBLAS/OMP/MKL_NUM_THREADS); "
                        "default 1: on a small shared machine a busy core makes multi-threaded "
                        "OpenBLAS stall and the timings erratic; 0 = the libraries' default")
    p.add_argument("--enforce-bars", action="store_true",
                   help="exit 1 when a speed or memory bar is missed, not only on disagreement")
    a = p.parse_args(argv)
    if a.blas_threads and os.environ.get("OPENBLAS_NUM_THREADS") != str(a.blas_threads):
        # thread counts are read when numpy loads: restart with them set (the ROSS child inherits)
        env = dict(os.environ, **{k: str(a.blas_threads) for k in THREAD_VARS})
        os.execve(sys.executable, [sys.executable, os.path.abspath(__file__), *sys.argv[1:]], env)
    print("BLAS threads:", {k: os.environ.get(k, "default") for k in THREAD_VARS})

    if a.ross_json:
        with open(a.ross_json) as f:
            ross = json.load(f)
        ross = ross.get("ross", ross)  # a --save file holds the ROSS output under "ross"
        ross["runs"] = [r for r in ross["runs"] if r["n_el"] in a.elements]
    else:
        ross = run_ross(a.elements, a.max_repeat)
    if ross is not None and ross["parameters"] != case.parameters():
        raise SystemExit("ROSS results were made with different case parameters; rerun ross_model.py")
    fxs = run_flexshaft(a.elements, a.max_repeat)
    ok_agree, ok_bars = report(fxs, ross)
    if a.save:
        with open(a.save, "w") as f:
            json.dump({"parameters": case.parameters(), "ross": ross, "flexshaft": fxs}, f,
                      default=_jsonable)
    if ross is None:
        print("ROSS side skipped (no ROSS interpreter): flexshaft timings only.")
        return 0
    return 0 if ok_agree and (ok_bars or not a.enforce_bars) else 1


if __name__ == "__main__":
    sys.exit(main())

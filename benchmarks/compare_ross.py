"""flexshaft vs ROSS on the same model: warm and cold times, peak memory, agreement of results.

    .venv/bin/python benchmarks/compare_ross.py [--elements 20 50 100] [--repeats 3]
                                              [--ross-python PY [PY ...]] [--save FILE]
                                              [--reuse-ross FILE] [--enforce-bars]
    .venv/bin/python benchmarks/compare_ross.py --table FILE [--update-readme]

The model (``shaft_case.py``): a uniform steel tube, 1.5 m, D_o 50 mm, D_i 30 mm, on two
isotropic bearings at its ends (k = 1e7 N/m, c = 1e3 N s/m), no disk, meshed with 20, 50 and
100 elements; Euler-Bernoulli bending with rotary inertia and gyroscopic terms, no shear, in
both codes. Cases: imbalance response at mid-span over 500 speeds, frequency response over 500
frequencies at a fixed spin speed, Campbell diagram over 50 speeds (lowest 8 lateral damped
natural frequencies).

Protocol, identical for both codes: every (code, case, mesh) runs in its own fresh process
(``flexshaft_side.py CASE N_EL`` with this interpreter, ``ross_model.py --single CASE N_EL``
with each ROSS interpreter).

* cold: the first model build and the first analysis call in that process (the import of the
  package is done before and reported apart), so one-time costs (lazy imports, JIT or
  first-touch page faults, caches) are in it;
* warm: ``--repeats`` (>= 3) more calls, each on a freshly built model (build outside the
  clock; ROSS caches results per rotor, so a repeat on the same rotor would be free); median
  and min–max printed. Wall time (``perf_counter``) and process CPU time (``process_time``) are
  both recorded; ratios are given for both, the CPU one being less sensitive to other load on
  a shared machine;
* memory: ``ru_maxrss`` of that process (Linux, ``getrusage(RUSAGE_SELF)`` read inside the
  child at its end): the whole process's peak resident set, interpreter and imported
  libraries included, not a Python-level (tracemalloc) figure.

Only the analysis call is timed; the comparison of results is done afterwards from what the
cold call returned. ROSS interpreters: ``--ross-python`` paths, else ``$ROSS_PYTHON``
(``os.pathsep``-separated), else ``/work/ross-2.3-venv/bin/python`` and
``/work/ross-latest-venv/bin/python``. A missing interpreter is skipped with a message saying
how to create it; with none, the flexshaft side runs alone (exit 0).

Checks (printed as PASS/FAIL lines):

* agreement, every case, size and ROSS version: max relative difference <= 0.1 % (exit
  status 1 otherwise);
* the project's bars, warm, on the largest mesh (in the exit status only with
  ``--enforce-bars``: timings depend on the machine).

``--table FILE`` prints the README tables (markdown) from a ``--save`` file;
``--update-readme`` also writes them between the markers in ``benchmarks/README.md`` and
``README.md``, so those tables are regenerated, never edited by hand.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)

import bench_util as bu  # noqa: E402
import shaft_case as case  # noqa: E402
from ross_tables import header_lines, headline, lookup, speedups, tables, update_readme, versions_of  # noqa: E402

CASES = ("unbalance", "frf", "campbell")
DEFAULT_ROSS_PYTHONS = ("/work/ross-2.3-venv/bin/python", "/work/ross-latest-venv/bin/python")
BARS = {"unbalance": 150.0, "frf": 100.0, "campbell": 100.0}  # warm speed-up, largest mesh
MEMORY_BAR_MB = 500.0

SETUP_HINT = """\
ROSS interpreter not found at {path}: skipped. To create the two used here (outside the
repository; ROSS 3.x needs Python >= 3.12, 3.1 needs >= 3.13):
    python3.11 -m venv /work/ross-2.3-venv
    /work/ross-2.3-venv/bin/pip install "ross-rotordynamics==2.3.0" "plotly<7"
    python3.13 -m venv /work/ross-latest-venv
    /work/ross-latest-venv/bin/pip install ross-rotordynamics
or pass --ross-python / set ROSS_PYTHON to interpreters that have ross-rotordynamics."""


# -------------------------------------------------------------------------------------------------
# running the workers


def _child(cmd: list[str], label: str) -> dict:
    print(f"[{label}] {' '.join(cmd[-4:])} ...", flush=True)
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.stderr.write(proc.stderr[-4000:])
        raise SystemExit(f"{label} worker failed with status {proc.returncode}: {' '.join(cmd)}")
    r = json.loads(proc.stdout)
    print(
        f"[{label}] {r['case']:9s} n_el={r['n_el']:4d} cold {r['cold_s']:9.4f} s  warm "
        f"{bu.fmt_stats(r['warm'], 4)} s  peak {r['peak_rss_mb']:6.0f} MB",
        flush=True,
    )
    return r


def run_flexshaft(name: str, n_el: int, repeats: int) -> dict:
    return _child(
        [sys.executable, os.path.join(HERE, "flexshaft_side.py"), name, str(n_el), "--repeats", str(repeats)],
        "flexshaft",
    )


def run_ross(python: str, name: str, n_el: int, repeats: int) -> dict:
    return _child(
        [python, os.path.join(HERE, "ross_model.py"), "--single", name, str(n_el), "--repeats", str(repeats)], "ross"
    )


def ross_pythons(cli: list[str] | None) -> list[str]:
    if cli:
        paths = cli
    elif os.environ.get("ROSS_PYTHON"):
        paths = [p for p in os.environ["ROSS_PYTHON"].split(os.pathsep) if p]
    else:
        paths = list(DEFAULT_ROSS_PYTHONS)
    found = []
    for p in paths:
        if os.path.isfile(p) and os.access(p, os.X_OK):
            found.append(p)
        else:
            print(SETUP_HINT.format(path=p))
    return found


# -------------------------------------------------------------------------------------------------
# comparison of results


def _complex(d):
    import numpy as np

    return np.asarray(d["re"]) + 1j * np.asarray(d["im"])


def _rel(a, b):
    """|a − b| / |b| where not both are zero (0/0 points, e.g. Ω = 0 imbalance, are skipped)."""
    import numpy as np

    a, b = np.asarray(a), np.asarray(b)
    both_zero = (a == 0) & (b == 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.abs(a - b) / np.abs(b)
    return r[~both_zero]


def compare(case_name: str, fxr: dict, rsr: dict) -> dict:
    """Max relative differences; ``max_rel`` is the one checked against the tolerance."""
    import numpy as np

    if case_name in ("unbalance", "frf"):
        rx, ry = _complex(rsr["x"]), _complex(rsr["y"])
        fxv, fxw = _complex(fxr["x"]), _complex(fxr["y"])
        if case_name == "unbalance":
            # orbit size at mid-span: sqrt(|lat1|^2 + |lat2|^2)
            metric = _rel(np.hypot(np.abs(fxv), np.abs(fxw)), np.hypot(np.abs(rx), np.abs(ry)))
            label = "|q| mid"
        else:
            # driven direction: |v| (flexshaft) vs |x| (ROSS)
            metric = _rel(np.abs(fxv), np.abs(rx))
            label = "|v| mid"
        # extra (not checked): complex amplitude incl. phase, relative to that component's peak
        cplx = max(
            np.max(np.abs(fxv - rx)) / np.max(np.abs(rx)), np.max(np.abs(fxw - ry)) / max(np.max(np.abs(ry)), 1e-300)
        )
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
    extra = _accuracy(ff, rf, fxr)
    if "lateral" in rsr:
        extra["ross_non_lateral_modes"] = int(np.sum(~np.asarray(rsr["lateral"], dtype=bool)))
    extra.update(_whirl_agreement(fxr, rsr))
    return {"max_rel": worst, "label": label, **extra}


def _accuracy(ff, rf, fxr) -> dict:
    """Each code's Campbell frequencies against the full (unreduced) dense eigensolution
    (``flexshaft_side.campbell_reference``, untimed): max |f − f_full| / f_full over the
    reference speeds and the lowest lateral modes; with flexshaft's own error estimate."""
    import numpy as np

    ref = fxr.get("reference")
    if not ref:
        return {}
    idx = np.asarray(ref["speed_index"])
    full = np.asarray(ref["wd_hz"], dtype=float)
    out = {}
    for code, f in (("flexshaft", ff), ("ross", rf)):
        if f.shape[1] >= full.shape[1]:
            out[f"{code}_accuracy"] = float(np.max(np.abs(f[idx, : full.shape[1]] - full) / full))
    if "error_estimate_max" in fxr:
        out["flexshaft_estimate"] = fxr["error_estimate_max"]
        out["flexshaft_basis"] = fxr.get("basis_size")
        out["flexshaft_tolerance"] = fxr.get("tolerance")
    return out


def _whirl_agreement(fxr, rsr) -> dict:
    """Whirl labels at Ω > 0 (ROSS whirl value 0 = forward, 1 = backward)."""
    import numpy as np

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
# the whole run


def run_all(elements, cases, repeats: int, pythons: list[str], reuse: dict | None) -> dict:
    load_start = bu.machine_info()["load_average_1_5_15"]
    reused = {}
    if reuse:
        for r in reuse["ross_runs"]:
            reused[(r["python_path"], r["case"], r["n_el"])] = r
    fx_runs, ross_runs = [], []
    for n_el in elements:
        for name in cases:
            fx_runs.append(run_flexshaft(name, n_el, repeats))
            for py in pythons:
                r = reused.get((py, name, n_el))
                if r is None:
                    r = run_ross(py, name, n_el, repeats)
                    r["python_path"] = py
                ross_runs.append(r)
    for r in ross_runs:
        fr = next(f for f in fx_runs if (f["case"], f["n_el"]) == (r["case"], r["n_el"]))
        r["comparison"] = compare(r["case"], fr["result"], r["result"])
    data = {
        "machine": {**bu.machine_info(), "load_average_at_start": load_start},
        "parameters": case.parameters(),
        "repeats": repeats,
        "flexshaft_runs": fx_runs,
        "ross_runs": ross_runs,
    }
    if reuse and reused:
        data["ross_reused"] = ross_reuse_note(reuse)
    return data


def ross_reuse_note(reuse: dict) -> dict:
    """Where the reused ROSS timings come from: their run's date, commit and machine load."""
    m = reuse["machine"]
    return {
        "date": m["date"],
        "git_commit": m.get("git_commit"),
        "load_average_at_start": m.get("load_average_at_start", ["?"])[0],
        "load_average_at_end": m["load_average_1_5_15"][0],
    }


def report(data: dict) -> tuple[bool, bool]:
    """The text report; returns (all agree, all bars met)."""
    fx, rs = lookup(data)
    versions = versions_of(data)
    print()
    print(header_lines(data))
    print()
    hdr = (
        f"{'case':9s} {'n_el':>4s} {'code':>11s} {'cold [s]':>9s} {'warm median (min–max) [s]':>30s} "
        f"{'x warm':>8s} {'x CPU':>7s} {'x cold':>7s} {'peak MB':>8s} {'max rel':>9s}  notes"
    )
    print(hdr)
    print("-" * len(hdr))
    ok_agree = True
    for (name, n_el), f in fx.items():
        print(
            f"{name:9s} {n_el:4d} {'flexshaft':>11s} {f['cold_s']:9.4f} {bu.fmt_stats(f['warm'], 4):>30s} "
            f"{'':8s} {'':7s} {'':7s} {f['peak_rss_mb']:8.0f}"
            + ("" if f["path"] in ("sweep", "frequency_response") else f"  flexshaft {f['path']}")
        )
        for v in versions:
            r = rs.get((v, name, n_el))
            if r is None:
                continue
            c = r["comparison"]
            agree = c["max_rel"] <= case.TOLERANCE
            ok_agree &= agree
            notes = [] if agree else ["DISAGREE"]
            if "complex_rel_peak" in c:
                notes.append(f"complex/peak {c['complex_rel_peak']:.1e}")
            if "whirl_mismatch" in c:
                notes.append(f"whirl mismatch {c['whirl_mismatch']}")
            if "flexshaft_accuracy" in c:
                notes.append(
                    f"vs full: flexshaft {c['flexshaft_accuracy']:.1e} "
                    f"(estimate {c.get('flexshaft_estimate', float('nan')):.1e}), "
                    f"ROSS {c.get('ross_accuracy', float('nan')):.1e}"
                )
            if c.get("ross_non_lateral_modes"):
                notes.append(f"ROSS non-lateral modes {c['ross_non_lateral_modes']}")
            sp = speedups(f, r)
            print(
                f"{'':9s} {'':4s} {'ROSS ' + v:>11s} {r['cold_s']:9.3f} {bu.fmt_stats(r['warm'], 3):>30s} "
                f"{sp['warm']:7.1f}x {sp['cpu']:6.1f}x {sp['cold']:6.1f}x {r['peak_rss_mb']:8.0f} "
                f"{c['max_rel']:9.1e}  {'; '.join(notes)}"
            )
    print()
    print(
        "x warm / x CPU: ROSS warm median / flexshaft warm median (wall / process CPU time); "
        "x cold: first call in a fresh process"
    )
    print("peak MB: whole-process peak resident set (ru_maxrss) of the child that ran the case")
    ok_bars = True
    if versions:
        print(
            f"{'PASS' if ok_agree else 'FAIL'}: results agree to {case.TOLERANCE:.1%} "
            f"(every case, size and ROSS version)"
        )
        largest = max(n for _, n in fx)
        for v in versions:
            for name, bar in BARS.items():
                f, r = fx.get((name, largest)), rs.get((v, name, largest))
                if f is None or r is None:
                    continue
                sp = speedups(f, r)
                s = sp["warm"]
                ok_bars &= s >= bar
                print(
                    f"{'PASS' if s >= bar else 'FAIL'}: {name} on {largest} elements, warm, "
                    f"{s:.0f}x faster than ROSS {v} (bar {bar:.0f}x; CPU-time ratio "
                    f"{sp['cpu']:.0f}x)"
                )
    peak = max(f["peak_rss_mb"] for f in fx.values())
    ok_bars &= peak < MEMORY_BAR_MB
    print(
        f"{'PASS' if peak < MEMORY_BAR_MB else 'FAIL'}: flexshaft peak memory {peak:.0f} MB "
        f"(largest over cases; bar {MEMORY_BAR_MB:.0f} MB)"
    )
    return ok_agree, ok_bars


# -------------------------------------------------------------------------------------------------


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--elements", type=int, nargs="+", default=list(case.ELEMENTS))
    p.add_argument("--cases", nargs="+", default=list(CASES), choices=list(CASES))
    p.add_argument("--repeats", type=int, default=3, help="warm calls after the cold one (>= 3)")
    p.add_argument(
        "--ross-python",
        nargs="+",
        help="ROSS interpreters (default: $ROSS_PYTHON, else " + ", ".join(DEFAULT_ROSS_PYTHONS) + ")",
    )
    p.add_argument("--no-ross", action="store_true", help="flexshaft side only")
    p.add_argument(
        "--reuse-ross",
        metavar="FILE",
        help="take the ROSS runs from an earlier --save file (same interpreter paths, "
        "cases and sizes) and re-time flexshaft only",
    )
    p.add_argument("--save", help="write all times, results and comparisons as JSON")
    p.add_argument("--table", metavar="FILE", help="print the README tables from a --save file")
    p.add_argument(
        "--update-readme", action="store_true", help="with --table: rewrite the generated blocks of the READMEs"
    )
    p.add_argument(
        "--blas-threads",
        type=int,
        default=1,
        help="BLAS/OpenMP/numba threads for both codes (sets OPENBLAS/OMP/MKL/"
        "NUMBA_NUM_THREADS); default 1: on a small shared machine a busy core "
        "makes multi-threaded OpenBLAS stall and the timings erratic; 0 = the "
        "libraries' defaults",
    )
    p.add_argument(
        "--enforce-bars",
        action="store_true",
        help="exit 1 when a speed or memory bar is missed, not only on disagreement",
    )
    a = p.parse_args(argv)

    if a.table:
        with open(a.table) as f:
            data = json.load(f)
        full, short = tables(data), headline(data)
        print(full)
        print()
        print(short)
        if a.update_readme:
            update_readme("full", full)
            update_readme("headline", short)
        return 0
    if a.repeats < 3:
        p.error(f"--repeats must be at least 3 (got {a.repeats})")
    bu.reexec_with_threads(a.blas_threads, __file__)
    print("BLAS threads:", bu.blas_env())

    pythons = [] if a.no_ross else ross_pythons(a.ross_python)
    reuse = None
    if a.reuse_ross:
        with open(a.reuse_ross) as f:
            reuse = json.load(f)
        if reuse["parameters"] != case.parameters():
            raise SystemExit("the reused ROSS runs were made with other case parameters")
    data = run_all(a.elements, a.cases, a.repeats, pythons, reuse)
    ok_agree, ok_bars = report(data)
    if a.save:
        with open(a.save, "w") as f:
            json.dump(data, f)
        print(f"saved {a.save}; README tables: {sys.argv[0]} --table {a.save} [--update-readme]")
    if not pythons:
        print("ROSS side skipped (no ROSS interpreter): flexshaft timings only.")
        return 0
    return 0 if ok_agree and (ok_bars or not a.enforce_bars) else 1


if __name__ == "__main__":
    sys.exit(main())

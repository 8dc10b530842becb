"""The README tables of ``compare_ross.py`` (markdown) from its saved JSON: speed-ups warm and
cold, wall and CPU, peak memory, agreement, and the accuracy each ratio is measured at."""

from __future__ import annotations

import os
import re

import bench_util as bu

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CASES = ("unbalance", "frf", "campbell")
README_FILES = {"full": os.path.join(HERE, "README.md"), "headline": os.path.join(ROOT, "README.md")}
MARK = "<!-- compare_ross.py --table: {} begin (generated, do not edit) -->"
MARK_END = "<!-- compare_ross.py --table: {} end -->"


def versions_of(data: dict) -> list[str]:
    seen = []
    for r in data["ross_runs"]:
        if r["version"] not in seen:
            seen.append(r["version"])
    return sorted(seen, key=lambda v: [int(x) for x in re.findall(r"\d+", v)])


def lookup(data: dict):
    fx = {(r["case"], r["n_el"]): r for r in data["flexshaft_runs"]}
    rs = {(r["version"], r["case"], r["n_el"]): r for r in data["ross_runs"]}
    return fx, rs


def speedups(f: dict, r: dict) -> dict:
    return {
        "warm": r["warm"]["median"] / f["warm"]["median"],
        "cpu": r["warm"]["cpu"]["median"] / f["warm"]["cpu"]["median"],
        "cold": r["cold_s"] / f["cold_s"],
        "cold_cpu": r["cold_cpu_s"] / f["cold_cpu_s"],
    }


def accuracy_text(name: str, r: dict | None) -> str:
    """What the ratio of a case is measured at: each code's accuracy against the full problem
    (Campbell), or the agreement of two direct solutions (imbalance, FRF: no reduction)."""
    if r is None:
        return "–"
    c = r["comparison"]
    if "flexshaft_accuracy" in c:
        return (
            f"f_d vs full dense: flexshaft {c['flexshaft_accuracy']:.0e} (estimated "
            f"{c.get('flexshaft_estimate', float('nan')):.0e}), ROSS {c.get('ross_accuracy', float('nan')):.0e}"
        )
    return f"both direct (no reduction); agree to {c['max_rel']:.0e}"


# -------------------------------------------------------------------------------------------------
# README tables


def header_lines(data: dict) -> str:
    m = data["machine"]
    fx0 = data["flexshaft_runs"][0]
    threads = m["blas_threads_env"]
    one = all(v == "1" for v in threads.values())
    lines = [
        f"Measured {m['date'][:10]} on {m['cpu']}, {m['cores']} cores, {m['memory_gb']:.0f} GB "
        f"(a machine shared with other jobs; 1-min load average "
        f"{m.get('load_average_at_start', ['?'])[0]} at the start of the run, "
        f"{m['load_average_1_5_15'][0]} at its end), "
        + (
            "one BLAS thread (OPENBLAS/OMP/MKL/NUMBA_NUM_THREADS=1) for both codes."
            if one
            else f"BLAS threads {threads}."
        ),
        f"flexshaft {fx0['version']} (git {m['git_commit']}), Python {m['python']}, "
        f"numpy {fx0['numpy']}, scipy {fx0['scipy']}.",
    ]
    if "ross_reused" in data:
        old = data["ross_reused"]
        # how long each side waited for a core: median warm wall / CPU time of its runs
        waits = {
            code: _median([r["warm"]["median"] / r["warm"]["cpu"]["median"] for r in data[key]])
            for code, key in (("flexshaft", "flexshaft_runs"), ("ROSS", "ross_runs"))
        }
        lean = "flexshaft" if waits["ROSS"] > waits["flexshaft"] else "ROSS"
        lines.append(
            f"The ROSS timings are reused from the run of {old['date'][:16]} (git {old.get('git_commit')}; "
            f"`--reuse-ross`: ROSS takes most of the hour), when the 1-min load average was "
            f"{old['load_average_at_start']} to {old['load_average_at_end']}; flexshaft was re-timed on this "
            f"commit. Wall time over CPU time (median over the runs; 1 on an idle core): flexshaft "
            f"{waits['flexshaft']:.1f}, ROSS {waits['ROSS']:.1f}, so the wall-time ratios favour {lean}; "
            "the CPU-time ratios in brackets are the fairer figure."
        )
    for v in versions_of(data):
        r = next(r for r in data["ross_runs"] if r["version"] == v)
        lines.append(f"ROSS {v} (ross-rotordynamics), Python {r['python']}, numpy {r['numpy']}, scipy {r['scipy']}.")
    lines.append(
        f"Warm: median (min–max) of {data['repeats']} calls, each on a freshly built model, "
        "after a first call in the same process. Cold: the first call in a fresh process "
        "(package imported, model built, not timed). Speed-ups are ratios of wall-time "
        "medians; in brackets, of process CPU-time medians, the steadier figure when "
        "other jobs load the machine (wall time then includes waiting for a core)."
    )
    return "\n".join("* " + line for line in lines)


def _ratio(x: float) -> str:
    return f"{x:.0f}×" if x >= 10 else f"{x:.1f}×"


def tables(data: dict, elements=None) -> str:
    """Markdown: the header lines, then warm, cold and memory/agreement tables."""
    fx, rs = lookup(data)
    versions = versions_of(data)
    keys = [k for k in fx if elements is None or k[1] in elements]
    out = [header_lines(data), ""]

    def row_head(cols):
        return "| case | n_el | " + " | ".join(cols) + " |\n|---|---:|" + "---:|" * len(cols)

    for title, get_fx, get_r, key in (
        ("Warm [s]", lambda f: bu.fmt_stats(f["warm"], 3), lambda r: bu.fmt_stats(r["warm"], 2), "warm"),
        ("Cold [s]", lambda f: f"{f['cold_s']:.3f}", lambda r: f"{r['cold_s']:.2f}", "cold"),
    ):
        cols = ["flexshaft"]
        for v in versions:
            cols += [f"ROSS {v}", "speed-up (CPU)"]
        out += [f"**{title}**", "", row_head(cols)]
        for k in keys:
            f = fx[k]
            cells = [get_fx(f)]
            for v in versions:
                r = rs.get((v, *k))
                if r is None:
                    cells += ["–", "–"]
                    continue
                s = speedups(f, r)
                cells += [
                    get_r(r),
                    _ratio(s["warm"]) + f" ({_ratio(s['cpu'])})"
                    if key == "warm"
                    else _ratio(s["cold"]) + f" ({_ratio(s['cold_cpu'])})",
                ]
            out.append(f"| {k[0]} | {k[1]} | " + " | ".join(cells) + " |")
        out.append("")
    cols = ["flexshaft peak MB"] + [f"ROSS {v} peak MB" for v in versions] + [f"max rel. diff vs {v}" for v in versions]
    out += ["**Peak memory (whole process, ru_maxrss) and agreement**", "", row_head(cols)]
    for k in keys:
        f = fx[k]
        cells = [f"{f['peak_rss_mb']:.0f}"]
        rr = [rs.get((v, *k)) for v in versions]
        cells += [f"{r['peak_rss_mb']:.0f}" if r else "–" for r in rr]
        cells += [f"{r['comparison']['max_rel']:.1e}" if r else "–" for r in rr]
        out.append(f"| {k[0]} | {k[1]} | " + " | ".join(cells) + " |")
    acc_rows = [(k, rs.get((v, *k)), v) for k in keys if k[0] == "campbell" for v in versions]
    acc_rows = [(k, r, v) for k, r, v in acc_rows if r is not None and "flexshaft_accuracy" in r["comparison"]]
    if acc_rows:
        out += [
            "",
            "**Campbell accuracy** (max |f_d − f_full| / f_full of the 8 lowest lateral damped frequencies at "
            "every 7th speed and the last, against the full dense eigensolution of the unreduced model; "
            "flexshaft's a-posteriori estimate is the largest over all its tracked eigenvalues)",
            "",
            "| n_el | ROSS | flexshaft basis | flexshaft vs full | flexshaft estimate | ROSS vs full "
            "| speed-up warm (CPU) |",
            "|---:|---|---:|---:|---:|---:|---:|",
        ]
        for k, r, v in acc_rows:
            c, s_ = r["comparison"], speedups(fx[k], r)
            out.append(
                f"| {k[1]} | {v} | {c.get('flexshaft_basis')} | {c['flexshaft_accuracy']:.1e} | "
                f"{c.get('flexshaft_estimate', float('nan')):.1e} | {c.get('ross_accuracy', float('nan')):.1e} | "
                f"{_ratio(s_['warm'])} ({_ratio(s_['cpu'])}) |"
            )
    imports = [f"flexshaft {_median([f['import_s'] for f in fx.values()]):.1f} s"]
    for v in versions:
        imports.append(f"ROSS {v} {_median([r['import_s'] for r in data['ross_runs'] if r['version'] == v]):.1f} s")
    out += ["", "Import time (median over the worker processes, not in the cold times): " + ", ".join(imports) + "."]
    return "\n".join(out)


def _median(xs):
    xs = sorted(xs)
    n = len(xs)
    return (xs[n // 2] + xs[(n - 1) // 2]) / 2


def headline(data: dict) -> str:
    """The short table for the top-level README: warm and cold speed-ups on the largest mesh."""
    fx, rs = lookup(data)
    largest = max(n for _, n in fx)
    versions = versions_of(data)
    out = [
        header_lines(data),
        "",
        "| case ("
        + str(largest)
        + " elements) | flexshaft warm [s] | "
        + " | ".join(f"ROSS {v} warm [s] | speed-up warm (CPU) / cold (CPU) | accuracy of the ratio" for v in versions)
        + " |",
        "|---|---:|" + "---:|---:|---|" * len(versions),
    ]
    for name in CASES:
        f = fx.get((name, largest))
        if f is None:
            continue
        cells = [f"{f['warm']['median']:.3f}"]
        for v in versions:
            r = rs.get((v, name, largest))
            if r is None:
                cells += ["–", "–", "–"]
                continue
            s = speedups(f, r)
            cells += [
                f"{r['warm']['median']:.1f}",
                f"{_ratio(s['warm'])} ({_ratio(s['cpu'])}) / {_ratio(s['cold'])} ({_ratio(s['cold_cpu'])})",
                accuracy_text(name, r),
            ]
        out.append(f"| {name} | " + " | ".join(cells) + " |")
    peak_fx = max(f["peak_rss_mb"] for f in fx.values())
    peaks = [
        f"ROSS {v} {max(r['peak_rss_mb'] for r in data['ross_runs'] if r['version'] == v):.0f} MB" for v in versions
    ]
    out += [
        "",
        f"Peak memory (whole process, largest case): flexshaft {peak_fx:.0f} MB"
        + ("".join(f", {p}" for p in peaks))
        + ".",
    ]
    return "\n".join(out)


def update_readme(kind: str, text: str) -> None:
    path = README_FILES[kind]
    with open(path) as f:
        doc = f.read()
    begin, end = MARK.format(kind), MARK_END.format(kind)
    if begin not in doc or end not in doc:
        raise SystemExit(f"{path}: markers for the {kind!r} table not found ({begin!r})")
    head, rest = doc.split(begin, 1)
    _, tail = rest.split(end, 1)
    with open(path, "w") as f:
        f.write(f"{head}{begin}\n{text}\n{end}{tail}")
    print(f"updated {path}")

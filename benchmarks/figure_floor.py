"""Each report figure's cost against its floor: the same layout drawn with the least machinery.

The figures of ``flexshaft run``'s report (the baseline's assessment and the thesis studies,
computed once or loaded from ``--cache``) are drawn in this process, serially, after one
untimed round (matplotlib imported, fonts loaded). For each figure, median of ``--repeats``:

* **cost**: what the report does: the figure function (``job.function``: figure, axes,
  artists) and the PNG writer of ``save_figure`` (``flexshaft.plot.output.write_png``; in
  older checkouts ``Figure.savefig``) to a PNG in memory at the report's resolution and options,
  in the scope ``render_figures`` draws each figure in (``output.one_collection``: Python's
  collector paused, then one young collection that frees the figure; counted in encode+);
* **floor** (the redraw floor): the same figure, built and drawn once untimed, its every tick then frozen
  (each axis's ticks at the positions just drawn, ``FixedLocator``, with the labels just drawn,
  ``FixedFormatter``: no locating, formatting or label measuring), drawn again (``canvas.draw``)
  and encoded with one zlib pass at level 1 and no PNG row filters (the least work a PNG can
  take; Pillow tries four filters on every row, five with ``optimize``). What is left is the
  artists themselves: lines, patches, text, images;
* **fresh** (the first-draw floor): the same figure built again and, before its one draw, given
  the ticks and labels the floor froze (``FixedLocator``, ``FixedFormatter``), drawn once and
  encoded with the floor's zlib pass: the least a figure drawn for the first time costs
  (its Axes and artists built, its Tick objects created, its text measured once), with no
  locating, formatting or row-filter search. Its pixels are the cost's.

The ratio cost / floor is the overhead of the machinery the report uses (locators,
formatters, building the figure, the encoder). Each table splits cost - floor three ways:
``build`` (the figure function: none of it is in the floor), ``draw+`` (a first draw of the
figure above its frozen redraw: Tick objects created, ticks located and formatted, text
measured for the first time) and ``encode+`` (the report's PNG writer above one zlib pass).
A minimal figure (one Axes, one line, labels, title; matplotlib only) is measured the same way
and printed last, outside the totals: the ratio no figure drawn with matplotlib's Axes gets
below, whatever the figure code does.

Which floor to hold the figures to: the redraw floor leaves out work no first draw can skip
(building the Axes, creating Tick objects, measuring each text once: the text-metrics cache is
the canvas renderer's, warm in a redraw), so the minimal figure itself sits near 2x it and a
bar of 1.3x it cannot be met by any figure drawn with matplotlib. The first-draw floor keeps
that work and drops only what a figure's code chooses (locators and formatters at draw time)
and the encoder's filter search: ``cost / fresh`` is the overhead a figure's code could still
remove, and the minimal figure's own ``cost / fresh`` is its baseline.
CPU times of this process (``process_time``): the costs of a round drawn one after the other
as the report draws them (collections included), then the floors with the collector off, each
figure's garbage collected untimed; the shared VM's load moves them less than wall times.

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/figure_floor.py --cache /tmp/run-now.pkl
    .venv/bin/python benchmarks/figure_floor.py --cache /tmp/run-now.pkl \
        --reference /tmp/ref/src --reference-cache /tmp/run-ref.pkl

With ``--reference SRC`` the same script runs on that checkout in a subprocess (its own cache
file: the pickles hold that code's classes) and both tables are printed with the ratio of the
totals.
"""

from __future__ import annotations

import argparse
import gc
import io
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
import zlib
from pathlib import Path
from types import SimpleNamespace

os.environ.setdefault("MPLBACKEND", "Agg")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def _results(cache: Path | None):
    from report_timing import load_results  # the same assessment and studies as the report timing

    return load_results("report", cache)


def _axes_axis(fig):
    """Every axis of ``fig`` (x, y and a 3D axes' z), in a fixed order."""
    for ax in fig.axes:
        yield from ax._axis_map.values() if hasattr(ax, "_axis_map") else (ax.xaxis, ax.yaxis)


def _tick_state(fig) -> list[tuple[list, list, list, list]]:
    """Each axis's ticks and labels as ``fig`` (drawn once) just drew them: (major positions,
    major labels, minor positions, minor labels), in :func:`_axes_axis` order."""
    state = []
    for axis in _axes_axis(fig):
        major = [t for t in axis.get_major_ticks() if t.get_visible()]
        locs = list(axis.get_majorticklocs())[: len(major)]
        labels = [t.get_text() for t in axis.get_majorticklabels()][: len(locs)]
        minor_locs = list(axis.get_minorticklocs())
        minor_labels = [t.get_text() for t in axis.get_minorticklabels()][: len(minor_locs)]
        state.append((locs, labels, minor_locs, minor_labels))
    return state


def _fix_ticks(fig, state) -> None:
    """Every axis of ``fig`` gets the ticks and labels of ``state`` (:func:`_tick_state` of the
    same figure), fixed: no locating or formatting at draw time."""
    from matplotlib.ticker import FixedFormatter, FixedLocator, NullFormatter

    for axis, (locs, labels, minor_locs, minor_labels) in zip(_axes_axis(fig), state, strict=True):
        axis.set_major_locator(FixedLocator(locs))
        axis.set_major_formatter(FixedFormatter(labels))
        axis.set_minor_locator(FixedLocator(minor_locs))
        axis.set_minor_formatter(FixedFormatter(minor_labels) if any(minor_labels) else NullFormatter())


def _least_png(rgba) -> bytes:
    """One zlib pass (level 1) over unfiltered rows: the PNG encoder's least work (the IDAT
    payload; the few header bytes cost nothing)."""
    import numpy as np

    pixels = np.asarray(rgba)
    rows = np.empty((pixels.shape[0], 1 + pixels.shape[1] * 4), dtype=np.uint8)
    rows[:, 0] = 0
    rows[:, 1:] = pixels.reshape(pixels.shape[0], -1)
    return zlib.compress(rows.data, 1)


#: Stem of the smallest figure measured alongside (not part of the totals).
MINIMAL = "(minimal: 1 axes, 1 line)"


def _minimal_figure():
    """What no figure can be cheaper than: a Figure on an Agg canvas, one Axes, one line of
    200 points, two axis labels and a title (matplotlib only, its default style). Its ratio
    is the overhead of building and first drawing any matplotlib figure, whatever its code."""
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8.0, 4.8))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    x = np.linspace(0.0, 6000.0, 200)
    ax.plot(x, np.sin(x / 700.0))
    ax.set_xlabel("spin speed Ω [rpm]")
    ax.set_ylabel("amplitude [mm]")
    ax.set_title("one line")
    return fig


def _save_like_the_report(fig) -> None:
    from flexshaft.plot import output

    if hasattr(output, "write_png"):  # what save_figure calls
        output.write_png(fig, io.BytesIO(), output.PNG_DPI)
        return
    kwargs = {"pil_kwargs": {"compress_level": getattr(output, "PNG_COMPRESSION", 1)}}  # older checkouts
    fig.savefig(io.BytesIO(), dpi=output.PNG_DPI, format="png", **kwargs)


def _as_the_report():
    """The scope ``render_figures`` draws and writes each figure in (``output.one_collection``:
    the collector paused, then one young collection); none in older checkouts."""
    import contextlib

    from flexshaft.plot import output

    return output.one_collection() if hasattr(output, "one_collection") else contextlib.nullcontext()


def _time_cost(job) -> tuple[float, float]:
    """(cost, its figure function) [s CPU]: the figure drawn and written as ``render_figures``
    does it (:func:`_as_the_report`), collections included."""
    c0 = time.process_time()
    with _as_the_report():
        fig = job.function(*job.args, **job.kwargs)
        c1 = time.process_time()
        _save_like_the_report(fig)
        del fig
    return time.process_time() - c0, c1 - c0


def _built(job, dpi: float):
    """The job's figure on an Agg canvas at ``dpi``."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = job.function(*job.args, **job.kwargs)
    if not isinstance(fig.canvas, FigureCanvasAgg):
        FigureCanvasAgg(fig)
    fig.set_dpi(dpi)
    return fig


def _time_floor(job, dpi: float) -> tuple[float, float, float, float]:
    """(floor, a first draw, the floor's zlib pass, the first-draw floor) [s CPU], the
    collector off (the least work); each figure's garbage collected afterwards, untimed."""
    gc.disable()
    try:
        fig = _built(job, dpi)
        c3 = time.process_time()
        fig.canvas.draw()
        c4 = time.process_time()
        state = _tick_state(fig)
        _fix_ticks(fig, state)
        c5 = time.process_time()
        fig.canvas.draw()
        c6 = time.process_time()
        _least_png(fig.canvas.buffer_rgba())
        c7 = time.process_time()
        del fig
        gc.collect()
        c8 = time.process_time()
        fresh = _built(job, dpi)
        _fix_ticks(fresh, state)
        fresh.canvas.draw()
        _least_png(fresh.canvas.buffer_rgba())
        c9 = time.process_time()
        del fresh
    finally:
        gc.enable()
    gc.collect()
    return c7 - c5, c4 - c3, c7 - c6, c9 - c8


def measure(cache: Path | None, repeats: int) -> dict:
    """Each round draws every figure at its cost, one after the other as the report does
    (each pays for the collections its allocations start, whatever garbage they find), then
    every figure at its floors. Medians over the rounds of (cost, floor, build, first draw,
    zlib pass, first-draw floor) [s CPU]."""
    from flexshaft.plot.output import PNG_DPI
    from flexshaft.report.driveline import plan_run_report

    res = _results(cache)
    with tempfile.TemporaryDirectory() as folder:
        jobs = plan_run_report(res[0], folder, thesis=res[1]).jobs
    minimal = SimpleNamespace(stem=MINIMAL, function=_minimal_figure, args=(), kwargs={})
    times: dict[str, list[tuple[float, ...]]] = {}
    for round_ in range(repeats + 1):  # round 0: warm-up, not counted
        costs = {job.stem: _time_cost(job) for job in jobs}
        gc.collect()
        for job in jobs:
            floor, first, zlib_pass, fresh = _time_floor(job, PNG_DPI)
            if round_:
                cost, build = costs[job.stem]
                times.setdefault(job.stem, []).append((cost, floor, build, first, zlib_pass, fresh))
    for round_ in range(repeats + 1):  # on its own, from a collected heap
        gc.collect()
        cost, build = _time_cost(minimal)
        floor, first, zlib_pass, fresh = _time_floor(minimal, PNG_DPI)
        if round_:
            times.setdefault(MINIMAL, []).append((cost, floor, build, first, zlib_pass, fresh))
    return {stem: tuple(statistics.median(t[k] for t in ts) for k in range(6)) for stem, ts in times.items()}


def _print(title: str, data: dict) -> None:
    """Cost and floor of each figure, and where the difference goes: the figure function
    (``build``: all of it is above the floor), the first draw above the frozen redraw (``draw+``:
    tick objects created, ticks located and formatted, text measured), and the rest of the
    save above one zlib pass (``encode+``: Pillow's row filters, the canvas). The three add up
    to cost - floor (medians of separate runs: up to the noise). Then the first-draw floor
    (``fresh``) and the cost over it. The minimal figure (:data:`MINIMAL`) is printed last,
    outside the totals."""
    minimal = data.get(MINIMAL)
    data = {k: v for k, v in data.items() if k != MINIMAL}
    total_cost = sum(v[0] for v in data.values())
    total_floor = sum(v[1] for v in data.values())
    total_fresh = sum(v[5] for v in data.values())
    print(
        f"\n{title}: {len(data)} figures, cost {total_cost:.2f} s, floor {total_floor:.2f} s, "
        f"ratio {total_cost / total_floor:.2f}; first-draw floor {total_fresh:.2f} s, "
        f"ratio {total_cost / total_fresh:.2f}"
    )
    print(
        f"  {'figure':34s} {'cost':>7s} {'floor':>7s} {'ratio':>6s} {'build':>7s} {'draw+':>7s} {'encode+':>7s}"
        f" {'fresh':>7s} {'ratio':>6s}  [ms]"
    )
    sums = [0.0, 0.0, 0.0]
    for stem, v in sorted(data.items(), key=lambda item: -item[1][0]):
        sums = [a + b for a, b in zip(sums, _overheads(v))]
        print(_row(stem, v))
    over = total_cost - total_floor
    print(
        f"  above the floor: {over:.2f} s = build {sums[0]:.2f} s ({sums[0] / over:.0%}), draw+ {sums[1]:.2f} s "
        f"({sums[1] / over:.0%}), encode+ {sums[2]:.2f} s ({sums[2] / over:.0%})"
    )
    if minimal is not None:
        print(_row(MINIMAL, minimal))


def _row(stem: str, v) -> str:
    """One figure's line of the table: times [ms] and the two ratios."""
    c, f, fresh = v[0], v[1], v[5]
    parts = " ".join(f"{x * 1e3:7.1f}" for x in _overheads(v))
    return f"  {stem:34s} {c * 1e3:7.1f} {f * 1e3:7.1f} {c / f:6.2f} {parts} {fresh * 1e3:7.1f} {c / fresh:6.2f}"


def _overheads(v) -> tuple[float, float, float]:
    """(build, draw+, encode+) of one figure's (cost, floor, build, first draw, zlib, fresh) [s]."""
    c, f, build, first, zlib_pass = v[:5]
    return build, first - (f - zlib_pass), c - build - first - zlib_pass


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--cache", type=Path, default=None, help="pickle of the assessment and studies (reused or written)")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--reference", default=None, help="another checkout's src folder, measured in a subprocess")
    p.add_argument("--reference-cache", type=Path, default=None)
    p.add_argument("--json", action="store_true", help="print the measurements as JSON only")
    a = p.parse_args(argv)
    data = measure(a.cache, a.repeats)
    if a.json:
        print(json.dumps(data))
        return 0
    print(
        f"report figures, CPU time, median of {a.repeats}; load average {os.getloadavg()[0]:.2f}, "
        f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}"
    )
    _print("this checkout", data)
    if a.reference is not None:
        cmd = [sys.executable, __file__, "--repeats", str(a.repeats), "--json"]
        if a.reference_cache is not None:
            cmd += ["--cache", str(a.reference_cache)]
        env = {**os.environ, "PYTHONPATH": os.path.abspath(a.reference)}
        out = subprocess.run(cmd, env=env, capture_output=True, text=True, check=True).stdout
        ref = json.loads(out.strip().splitlines()[-1])
        _print(f"reference ({a.reference})", {k: tuple(v) for k, v in ref.items()})
        common = sorted((set(ref) & set(data)) - {MINIMAL})
        now_cost = sum(data[k][0] for k in common)
        ref_cost = sum(ref[k][0] for k in common)
        print(f"\nreference / now, total cost of the {len(common)} common figures: {ref_cost / now_cost:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

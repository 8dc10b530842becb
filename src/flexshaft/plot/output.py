"""Writing figures to files: one at a time (:func:`save_figure`) or a batch, serially or in
worker processes (:func:`render_figures`).

A batch is a list of :class:`FigureJob` (a figure function of :mod:`flexshaft.plot` and its
plain-array arguments), so a worker process receives only picklable data and draws the figure
itself. PNG is always written; SVG only on request (it costs about as much as the PNG again).
"""

from __future__ import annotations

import gc
import io
import math
import sys
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from flexshaft.files import writing
from flexshaft.parallel.pool import worker_pool

if TYPE_CHECKING:
    from concurrent.futures import Executor

    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.transforms import Bbox

__all__ = [
    "FIGURE_MODULES",
    "PNG_DPI",
    "FigureJob",
    "RenderedFigure",
    "one_collection",
    "render_figures",
    "save_figure",
    "start_figures",
    "write_png",
]

#: Resolution of the PNG files [dots per inch]. An 8 in wide report figure is 960 px, shown at
#: 768 CSS px (96 px per inch): text of 8.5 pt is 14 px high, sharp on ordinary and on 1.25×
#: screens; files are 35 % smaller than at 150 dpi (rendering time hardly depends on it).
PNG_DPI = 120
#: zlib compression level of the PNG figures, given to Pillow (:func:`write_png`).
#: Measured on the report's 25 figures (benchmarks/figure_floor.py, 2026-12-02, Pillow 13.0):
#: level 1 14.1 ms and 100 kB a figure, 2 14.3 ms 99 kB, 3 14.6 ms 97 kB, 4 18.0 ms 91 kB,
#: 6 (Pillow's default) 20.3 ms 90 kB.
PNG_COMPRESSION = 1
#: Pixels added beyond what a figure draws past its canvas' edge when the canvas is grown (:func:`write_png`).
PAD_PX = 2
#: What a process that draws figures imports once (a worker of :func:`flexshaft.parallel.pool.worker_pool`).
FIGURE_MODULES = ("matplotlib.figure", "matplotlib.backends.backend_agg", "flexshaft.plot.driveline")


def _check_stem(stem: str) -> None:
    if not isinstance(stem, str) or not stem or Path(stem).name != stem or stem in (".", ".."):
        raise ValueError(f"stem: expected a plain file name without folders, got {stem!r}")


def write_png(fig: Figure, file: Any, dpi: float = PNG_DPI) -> Bbox | None:
    """Draw ``fig`` at ``dpi`` and write it as a PNG to ``file`` (a path or a binary file object).

    Through matplotlib's public API: the Agg canvas draws (``canvas.draw``) and its pixels
    (``buffer_rgba``) go to Pillow's PNG encoder at zlib level :data:`PNG_COMPRESSION`. An
    opaque figure (visible face of alpha 1, as every figure of :mod:`flexshaft.plot`) is
    written as RGB: its alpha channel is 255 everywhere, and Pillow's row-filter search and
    zlib then work on 3 bytes a pixel instead of 4 (15 % less encoding time, 10 % smaller
    files; benchmarks/figure_floor.py). A figure with a transparent face keeps RGBA, and a
    figure on another canvas (an interactive backend's, even one derived from Agg: its window
    must not be resized or redrawn) goes through ``savefig``. The figure's own ``dpi`` is
    restored afterwards. The ``savefig.*`` settings of matplotlib (``savefig.facecolor``,
    ``savefig.transparent``, ``savefig.bbox``) do not apply on the canvas path: the figure is
    written as it is drawn.

    Nothing drawn is cut at the canvas' edge: the margins of :func:`flexshaft.plot.style.new_figure`
    are fixed, and a long tick label (``0.00175``) can push an axis label past them. When the
    drawn canvas has ink in its outermost row or column of pixels, or an axis label, title or
    legend passes its edge (cheap tests on what was just drawn), the figure's drawn extent is
    measured (``get_tightbbox``) and, where it passes the canvas, ``savefig`` draws the canvas
    grown to hold it (the panels keep their size and place; the file is that much larger;
    ``savefig.*`` settings kept out) and Pillow writes it as above. Returns that grown box
    [in], or None when the canvas holds everything (:func:`save_figure` writes the SVG over the
    same box).
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    if type(fig.canvas) is not FigureCanvasAgg:
        fig.savefig(file, dpi=dpi, format="png", pil_kwargs={"compress_level": PNG_COMPRESSION})
        return None
    from matplotlib.colors import to_rgba
    from PIL import Image

    opaque = fig.patch.get_visible() and to_rgba(fig.patch.get_facecolor())[3] == 1.0
    own_dpi = fig.dpi
    fig.dpi = dpi
    try:
        fig.canvas.draw()
        grown = _grown_canvas(fig, fig.canvas)
        if grown is None:
            size = fig.canvas.get_width_height(physical=True)
            image = Image.frombuffer("RGBA", size, fig.canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
    finally:
        fig.dpi = own_dpi
    if grown is not None:
        # savefig draws the grown box; matplotlib's savefig.* settings kept out as on the canvas path
        drawn = io.BytesIO()
        fig.savefig(
            drawn, dpi=dpi, format="png", bbox_inches=grown, facecolor="auto", edgecolor="auto", transparent=False
        )
        image = Image.open(drawn)
    (image.convert("RGB") if opaque else image).save(file, format="png", compress_level=PNG_COMPRESSION, dpi=(dpi, dpi))
    return grown


def _grown_canvas(fig: Figure, canvas: FigureCanvasAgg) -> Bbox | None:
    """The figure's box grown to hold what its last draw put past the canvas' edge [in], by
    that overflow plus :data:`PAD_PX`, in whole pixels, on each side that overflows; None when
    nothing did.

    Measured (``get_tightbbox``, about a third of a draw) only when a cut is likely: ink in the
    canvas' outermost pixels (a glyph or line crossing the edge), or an axis label, axes title,
    legend or figure text whose box passes the edge (one pushed wholly past it leaves no ink).
    """
    import numpy as np
    from matplotlib.colors import to_rgba
    from matplotlib.transforms import Bbox

    renderer = canvas.get_renderer()
    pixels = np.asarray(canvas.buffer_rgba())
    # Agg clears to transparent white: what an invisible face leaves
    face = (
        np.round(255 * np.asarray(to_rgba(fig.patch.get_facecolor())))
        if fig.patch.get_visible()
        else (255, 255, 255, 0)
    )
    edges = np.concatenate([pixels[0], pixels[-1], pixels[:, 0], pixels[:, -1]]).astype(int)
    if np.all(np.abs(edges - np.asarray(face)) <= 8) and not _outermost_past_edge(fig, renderer):
        return None
    page = fig.bbox_inches
    drawn = fig.get_tightbbox(renderer)
    if drawn is None or (drawn.x0 >= page.x0 and drawn.y0 >= page.y0 and drawn.x1 <= page.x1 and drawn.y1 <= page.y1):
        return None
    # whole pixels, rounded outwards: a fractional edge is truncated by Agg, and an extent leaves
    # out half a frame's stroke (a legend past the edge by 6.32 px kept 1 px of it cut)
    dpi = fig.dpi
    return Bbox.from_extents(
        math.floor(drawn.x0 * dpi - PAD_PX) / dpi if drawn.x0 < page.x0 else page.x0,
        math.floor(drawn.y0 * dpi - PAD_PX) / dpi if drawn.y0 < page.y0 else page.y0,
        math.ceil(drawn.x1 * dpi + PAD_PX) / dpi if drawn.x1 > page.x1 else page.x1,
        math.ceil(drawn.y1 * dpi + PAD_PX) / dpi if drawn.y1 > page.y1 else page.y1,
    )


def _outermost_past_edge(fig: Figure, renderer: Any) -> bool:
    """Whether an axis label, an axes' title or text, a legend or a figure text of ``fig`` (as
    last drawn) has a box passing the canvas' edge: what may lie wholly outside it."""
    from matplotlib.text import Text

    outer: list[Any] = [*fig.texts, *fig.legends]
    for ax in fig.axes:  # its titles (centre, left, right), texts and annotations are its Text children
        outer += [ax.xaxis.label, ax.yaxis.label, *(c for c in ax.get_children() if isinstance(c, Text))]
        if ax.get_legend() is not None:
            outer.append(ax.get_legend())
    page = fig.bbox
    for artist in outer:
        if not artist.get_visible() or (hasattr(artist, "get_text") and not artist.get_text()):
            continue
        box = artist.get_window_extent(renderer)
        if box.x0 < page.x0 or box.y0 < page.y0 or box.x1 > page.x1 or box.y1 > page.y1:
            return True
    return False


def save_figure(
    fig: Figure, folder: str | Path, stem: str, *, svg: bool = True, dpi: float = PNG_DPI
) -> dict[str, Path]:
    """Write ``stem.png`` (and ``stem.svg`` when ``svg``) into ``folder``, each atomically
    (:func:`flexshaft.files.writing`); release the figure.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure to save.
    folder : str or Path
        Output folder, created if missing.
    stem : str
        File name without extension; no path separators.
    svg : bool
        Also write the SVG file (reproducible: no date in it).
    dpi : float
        PNG resolution [dots per inch].

    Returns
    -------
    dict
        ``{"png": Path}`` plus ``"svg"`` when written.
    """
    _check_stem(stem)
    out = Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    paths = {"png": out / f"{stem}.png"}
    # the Agg canvas's pixels, Pillow's PNG encoder at zlib level 1 (write_png);
    # each file through a temporary name and a rename (flexshaft.files.writing): a symbolic link
    # at the name is replaced, never written through, and a full disk leaves no half file
    with writing(paths["png"]) as tmp:
        grown = write_png(fig, tmp, dpi)
    if svg:
        paths["svg"] = out / f"{stem}.svg"
        with writing(paths["svg"]) as tmp:
            fig.savefig(
                tmp,
                format="svg",
                metadata={"Date": None},
                # the PNG's box and colours, whatever matplotlib's savefig.* settings say
                bbox_inches=grown if grown is not None else fig.bbox_inches,
                facecolor="auto",
                edgecolor="auto",
                transparent=False,
            )
    if "matplotlib.pyplot" in sys.modules:  # only pyplot keeps a reference to figures
        sys.modules["matplotlib.pyplot"].close(fig)
    return paths


@dataclass(frozen=True)
class FigureJob:
    """One figure to draw and save: ``function(*args, **kwargs)`` returns the Figure.

    ``function`` must be importable by name (a figure function of :mod:`flexshaft.plot`, or a
    result class's ``plot``) and the arguments picklable, so that a worker process can draw it.
    """

    stem: str
    function: Callable[..., Any]
    args: tuple = ()
    kwargs: dict = field(default_factory=dict)

    def __post_init__(self) -> None:
        _check_stem(self.stem)


@dataclass(frozen=True)
class RenderedFigure:
    """Files written for one :class:`FigureJob` and the time it took [s] (draw and save, wall)."""

    stem: str
    paths: dict
    seconds: float


@contextmanager
def one_collection() -> Iterator[None]:
    """Python's cyclic garbage collector paused in the block, then one collection of the
    youngest generation: what a figure drawn and released in the block leaves.

    A figure is some 10^5 objects linked in cycles (artists, transforms, the canvas). With the
    collector running, their allocation starts a young collection every 700 objects, and those
    collections start full ones, each walking every object of the process (the analysis
    results included): 0.5 s of CPU for the report's 25 figures drawn in a row, 12 % of their
    time. Paused, every object of the block stays in the youngest generation, and the one
    collection at the end walks only those, freeing the released figure (0.15 s for the 25;
    both timed with ``gc.callbacks``, 2026-12-03).
    Nothing is done when the collector is already off (a caller's own setting, or a
    surrounding block). Memory: the block's garbage waits for its end (one figure's worth).
    """
    if not gc.isenabled():
        yield
        return
    gc.disable()
    try:
        yield
    finally:
        gc.enable()
        gc.collect(0)


def _render(job: FigureJob, folder: Path, svg: bool, dpi: float) -> RenderedFigure:
    start = time.perf_counter()
    with one_collection():  # the figure is released inside: its objects freed by one young collection
        paths = save_figure(job.function(*job.args, **job.kwargs), folder, job.stem, svg=svg, dpi=dpi)
    return RenderedFigure(job.stem, paths, time.perf_counter() - start)


def _check_jobs(jobs: Sequence[FigureJob]) -> None:
    stems = [job.stem for job in jobs]
    duplicated = sorted({s for s in stems if stems.count(s) > 1})
    if duplicated:
        raise ValueError(f"jobs: figure stems must be unique, repeated: {duplicated}")


def start_figures(
    jobs: Sequence[FigureJob], folder: str | Path, executor: Executor, *, svg: bool = False, dpi: float = PNG_DPI
) -> Callable[[], dict[str, RenderedFigure]]:
    """Submit every job to ``executor`` (e.g. :func:`flexshaft.parallel.pool.worker_pool`) and return
    a function that waits for them and returns ``{stem: RenderedFigure}`` in job order: the
    caller writes its other files while the workers draw."""
    _check_jobs(jobs)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    futures = [executor.submit(_render, job, folder, bool(svg), float(dpi)) for job in jobs]

    def collect() -> dict[str, RenderedFigure]:
        return {r.stem: r for r in (f.result() for f in futures)}

    return collect


def render_figures(
    jobs: Sequence[FigureJob],
    folder: str | Path,
    *,
    svg: bool = False,
    dpi: float = PNG_DPI,
    processes: int = 1,
    executor: Executor | None = None,
) -> dict[str, RenderedFigure]:
    """Draw and save every job into ``folder``; returns ``{stem: RenderedFigure}`` in job order.

    Parameters
    ----------
    jobs : sequence of FigureJob
        Stems must be unique.
    folder : str or Path
        Output folder, created if missing.
    svg : bool
        Also write SVG files.
    dpi : float
        PNG resolution [dots per inch].
    processes : int
        1 draws in this process; more uses that many forked worker processes (POSIX only;
        elsewhere, or for fewer than two jobs, it falls back to drawing here).
    executor : concurrent.futures.Executor, optional
        Draw in this pool's workers instead (``processes`` is then ignored).
    """
    if int(processes) != processes or processes < 1:
        raise ValueError(f"processes must be an integer >= 1 (got {processes!r})")
    if executor is not None:
        return start_figures(jobs, folder, executor, svg=svg, dpi=dpi)()

    with worker_pool(max(1, min(int(processes), len(jobs))), FIGURE_MODULES) as pool:
        if pool is not None:
            return start_figures(jobs, folder, pool, svg=svg, dpi=dpi)()
    _check_jobs(jobs)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    done = [_render(job, folder, bool(svg), float(dpi)) for job in jobs]
    return {r.stem: r for r in done}

"""Nothing a figure draws is cut at the edge of its file.

The margins of :func:`flexshaft.plot.style.new_figure` are fixed in inches; a long tick label
pushes the axis label outwards, and on the tuned design the thermal sweeps' rise of 1.7e-3 K
(tick labels ``0.00175``) put the label "T − T_air [K]" 4 px past the left edge of
shaft_temperature_sweeps.png (and the bearing orbits' "v (vertical) [μm]" 1 px).

References: the label's own box as matplotlib lays it out (``get_window_extent`` at the files'
120 dpi): the file must hold it; and the PNG's pixels: the figures' face is white, a glyph or
line cut by the canvas' edge leaves ink in the file's outermost column or row. The threshold
(a channel 8 levels from the face, of 255) is above PNG rounding (exact) and far below a cut
glyph's core (255 levels). The pixels alone miss a label pushed wholly past the edge: the
label's box catches it.
"""

from __future__ import annotations

import io
import re

import numpy as np
import pytest
from PIL import Image

from flexshaft.plot.output import PNG_DPI, save_figure, write_png
from flexshaft.plot.thermal import temperature_profiles_figure


def edge_ink(png: bytes | Image.Image) -> dict[str, int]:
    """Pixels of each outermost row/column that differ from white by more than 8 levels."""
    image = png if isinstance(png, Image.Image) else Image.open(io.BytesIO(png))
    a = np.asarray(image.convert("RGB")).astype(int)
    edges = {"left": a[:, 0], "right": a[:, -1], "top": a[0], "bottom": a[-1]}
    return {side: int(np.any(np.abs(v - 255) > 8, axis=1).sum()) for side, v in edges.items()}


def _profiles(scale: float):
    x = np.linspace(0.0, 8.05, 33)
    rise = scale * np.sin(np.pi * x / 8.05)
    return temperature_profiles_figure(x, {"wall 5.0 mm": rise}, {"h = 5 W/m²K": 25.0 * rise})


def label_overflow_px(fig) -> tuple[float, float]:
    """(left, right) edges [px] of the first panel's y label, laid out by matplotlib at the
    files' resolution: a negative left edge is that much past the canvas."""
    fig.dpi = PNG_DPI
    fig.canvas.draw()
    box = fig.axes[0].yaxis.label.get_window_extent(fig.canvas.get_renderer())
    return box.x0, box.x1


@pytest.mark.parametrize("scale", [1.7e-3, -1.7e-3], ids=["cut", "wholly-outside"])
def test_a_label_pushed_past_the_margin_is_written_whole(scale):
    """The tuned design's thermal sweeps (peak rise 1.7e-3 K, tick labels of seven characters)
    push the y label about 4 px past the left edge; a negative rise (tick labels of eight) about
    18 px, wholly past it, where no ink reaches the edge to show the loss. References: the
    label's own box as matplotlib lays it out (``get_window_extent``), and the file's pixels.
    The file is wider than the nominal 11 in x 120 dpi = 1320 px by at least the label's
    overflow, and has no ink at any edge."""
    left, right = label_overflow_px(_profiles(scale))
    assert left < 0.0
    if scale < 0:
        assert right < 0.0  # wholly outside: the unfixed file has no ink at its edge
    buffer = io.BytesIO()
    grown = write_png(_profiles(scale), buffer)
    image = Image.open(io.BytesIO(buffer.getvalue()))
    assert edge_ink(image) == {"left": 0, "right": 0, "top": 0, "bottom": 0}
    assert grown is not None and grown.x0 < 0.0
    assert image.size[0] >= round(11.0 * PNG_DPI) - left
    assert image.size[1] == round(4.2 * PNG_DPI)  # nothing passed the top or the bottom: no growth there
    assert image.mode == "RGB"  # an opaque figure, written as RGB as when it fits


def test_a_figure_inside_its_margins_keeps_its_size():
    """Rises of order 1 K (tick labels ``1.50``) fit the margins: the file is the figure's
    nominal 11 x 4.2 in at 120 dpi = 1320 x 504 px, exactly, with no ink at its edges."""
    buffer = io.BytesIO()
    assert write_png(_profiles(1.7), buffer) is None
    image = Image.open(io.BytesIO(buffer.getvalue()))
    assert image.size == (round(11.0 * PNG_DPI), round(4.2 * PNG_DPI))
    assert edge_ink(image) == {"left": 0, "right": 0, "top": 0, "bottom": 0}


def test_the_svg_is_grown_with_the_png(tmp_path):
    """``save_figure``'s SVG covers the same grown box: its width exceeds the nominal
    11 in x 72 pt/in = 792 pt (the figure that fits keeps 792 pt)."""
    widths = []
    for scale in (1.7e-3, 1.7):
        paths = save_figure(_profiles(scale), tmp_path, f"profiles_{scale:g}")
        match = re.search(r'<svg[^>]*\swidth="([0-9.]+)pt"', paths["svg"].read_text(encoding="utf-8"))
        assert match is not None
        widths.append(float(match.group(1)))
        assert edge_ink(paths["png"].read_bytes()) == {"left": 0, "right": 0, "top": 0, "bottom": 0}
    assert widths[0] > 792.0
    assert widths[1] == 792.0


def test_an_axes_text_wholly_past_the_edge_is_kept():
    """An annotation placed at figure fraction x = 1.2 (wholly right of the canvas: no ink
    reaches the edge) is found and the canvas grown to hold it; its own box (matplotlib's
    layout) lies inside the file's width, and the grown side ends on a whole pixel."""
    from flexshaft.plot.style import new_figure

    fig, axes = new_figure(1, 1, (4.0, 3.0))
    note = axes[0, 0].text(1.2, 0.5, "far note", transform=fig.transFigure)
    fig.dpi = PNG_DPI
    fig.canvas.draw()
    box = note.get_window_extent(fig.canvas.get_renderer())
    assert box.x0 > 4.0 * PNG_DPI  # wholly outside
    buffer = io.BytesIO()
    grown = write_png(fig, buffer)
    image = Image.open(io.BytesIO(buffer.getvalue()))
    assert image.size[0] >= box.x1
    assert edge_ink(image) == {"left": 0, "right": 0, "top": 0, "bottom": 0}
    # the grown side ends on a whole pixel, 2 px or more past the text: Agg truncates a
    # fractional canvas, which cut the last pixel of the Jeffcott rotor's Campbell legend
    # (6.32 px past its canvas, review r133)
    assert grown is not None
    right_px = grown.x1 * PNG_DPI
    assert abs(right_px - round(right_px)) < 1e-9 and right_px >= box.x1 + 2.0

"""A text wholly below the canvas is kept, with the pad outside it on the bottom side too.

`write_png`'s docstring (plot/output.py): where the drawn extent passes the canvas, the canvas
is grown "to hold it", and `_grown_canvas` adds "that overflow plus PAD_PX, in whole pixels,
on each side that overflows" (PAD_PX = 2 px, as the sibling test reads it). The sibling test
(tests/test_figure_canvas_edge_reference.py) checks the left and right sides; here the
bottom, the side of x-axis labels and of the legends set in a band below the axes.

References: the text's own box as matplotlib lays it out (``get_window_extent`` at the files'
120 dpi, y upwards from the canvas' bottom edge) and the file's pixels. A figure note at
figure fraction y = -0.2 (76 px below a 3-in canvas, no ink reaches the edge): the grown
bottom edge lies on a whole pixel at least 2 px below the text's box, the file is taller
than the nominal 3 in x 120 dpi = 360 px by at least that depth, and no ink is at any edge.
Integer pixels and matplotlib's own layout: compared exactly (whole-pixel test to 1e-9 px).
"""

from __future__ import annotations

import io

from PIL import Image

from flexshaft.plot.output import PNG_DPI, write_png
from flexshaft.plot.style import new_figure
from tests.test_figure_canvas_edge_reference import edge_ink


def test_a_text_wholly_below_the_canvas_is_kept_with_its_pad():
    fig, axes = new_figure(1, 1, (4.0, 3.0))
    note = axes[0, 0].text(0.5, -0.2, "jgpq [y]", transform=fig.transFigure)  # descenders reach the box's bottom
    fig.dpi = PNG_DPI
    fig.canvas.draw()
    box = note.get_window_extent(fig.canvas.get_renderer())
    assert box.y1 < 0.0  # wholly below the canvas
    buffer = io.BytesIO()
    grown = write_png(fig, buffer)
    image = Image.open(io.BytesIO(buffer.getvalue()))
    assert grown is not None
    bottom_px = grown.y0 * PNG_DPI
    assert abs(bottom_px - round(bottom_px)) < 1e-9 and bottom_px <= box.y0 - 2.0
    assert image.size[1] >= round(3.0 * PNG_DPI) - box.y0 + 2.0
    assert image.size[0] == round(4.0 * PNG_DPI)  # nothing passed the left or right edge
    assert edge_ink(image) == {"left": 0, "right": 0, "top": 0, "bottom": 0}

"""PNG files of the figures in one zlib pass.

Matplotlib hands its Agg buffer to Pillow, whose PNG encoder picks a filter for every row by
trying all five (adaptive filtering), with no option to skip it: on a report figure that search
costs two thirds of the save (44 ms of 60 at zlib level 1; 1 Mpx figures). Plot images are flat
colour and lines, for which the search buys nothing: unfiltered rows compress to the same size
(188 against 191 kB). :func:`write_png` writes the same pixels, resolution and ``Software`` text
with the standard library's zlib and no filter, in a quarter of the time; an opaque figure is
stored as RGB (no alpha channel), a figure with transparency as RGBA.

:func:`fast_png_canvas` is an Agg canvas whose ``print_png`` uses it, so that
``Figure.savefig(..., format="png")`` keeps all of matplotlib's saving logic (dpi, face colour,
bounding box) and only the encoding changes. Nothing here imports matplotlib at module level.
"""

from __future__ import annotations

import functools
import struct
import zlib
from typing import IO, Any

import numpy as np
from numpy.typing import NDArray

__all__ = ["fast_png_canvas", "write_png"]

_SIGNATURE = b"\x89PNG\r\n\x1a\n"
_METRES_PER_INCH = 0.0254


def _chunk(tag: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))


def write_png(
    file: str | IO[bytes] | Any,
    rgba: NDArray[np.uint8],
    dpi: float | None = None,
    text: dict[str, str] | None = None,
    level: int = 1,
) -> None:
    """Write an (height, width, 4) uint8 RGBA image as a PNG file.

    Parameters
    ----------
    file : path or binary file object
        Destination.
    rgba : ndarray of uint8, shape (height, width, 4)
        The pixels, top row first (Agg's ``buffer_rgba``).
    dpi : float, optional
        Resolution stored in the ``pHYs`` chunk [dots per inch].
    text : dict, optional
        ``tEXt`` entries (Latin-1 keys of 1-79 characters and values); None values are skipped.
    level : int
        zlib compression level, 0-9.
    """
    rgba = np.asarray(rgba)
    if rgba.dtype != np.uint8 or rgba.ndim != 3 or rgba.shape[2] != 4 or 0 in rgba.shape[:2]:
        raise ValueError(f"rgba: expected a non-empty (height, width, 4) uint8 array, got {rgba.dtype} {rgba.shape}")
    height, width = rgba.shape[:2]
    opaque = bool(rgba[..., 3].min() == 255)
    pixels = rgba[..., :3] if opaque else rgba
    rows = np.empty((height, 1 + width * pixels.shape[2]), dtype=np.uint8)
    rows[:, 0] = 0  # filter type 0 (none) on every row
    rows[:, 1:] = pixels.reshape(height, -1)
    parts = [_SIGNATURE, _chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2 if opaque else 6, 0, 0, 0))]
    if dpi is not None:
        per_metre = int(float(dpi) / _METRES_PER_INCH + 0.5)
        parts.append(_chunk(b"pHYs", struct.pack(">IIB", per_metre, per_metre, 1)))
    for key, value in (text or {}).items():
        if value is not None:
            parts.append(_chunk(b"tEXt", key.encode("latin-1") + b"\0" + str(value).encode("latin-1", "replace")))
    parts += [_chunk(b"IDAT", zlib.compress(rows.data, level)), _chunk(b"IEND", b"")]
    if hasattr(file, "write"):
        file.write(b"".join(parts))
    else:
        with open(file, "wb") as out:
            out.write(b"".join(parts))


@functools.cache
def fast_png_canvas() -> type:
    """The Agg canvas class whose ``print_png`` writes with :func:`write_png` (compression level
    from ``pil_kwargs["compress_level"]``, default 1). Other ``pil_kwargs`` go to matplotlib's
    own Pillow path, unchanged."""
    import matplotlib
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    class FastPngCanvas(FigureCanvasAgg):
        def print_png(self, filename_or_obj, *, metadata=None, pil_kwargs=None, **applied):
            # ``applied``: dpi, face and edge colour, orientation, bbox_inches_restore, which
            # print_figure passes to a print method outside matplotlib; it has applied them
            # to the figure already (matplotlib's own print_png is not given them)
            options = dict(pil_kwargs or {})
            level = options.pop("compress_level", 1)
            if options:
                return super().print_png(filename_or_obj, metadata=metadata, pil_kwargs=pil_kwargs)
            FigureCanvasAgg.draw(self)
            text = {
                "Software": f"Matplotlib version{matplotlib.__version__}, https://matplotlib.org/",
                **(metadata or {}),
            }
            write_png(filename_or_obj, np.asarray(self.buffer_rgba()), self.figure.dpi, text, int(level))

    return FastPngCanvas

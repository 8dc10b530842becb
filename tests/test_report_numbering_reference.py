"""The report page numbers its tables and figures across the report, not per section.

Reference: API contract (render_report's docstring; no docs page states it): "Report body,
numbered in order; tables and figures are numbered across the report", worked by hand for a
stand-in body: sections 1-4 holding 2, 0, 1 and 1 tables are Tables 1, 2 | - | 3 | 4, and the
one figure of section 3 is Figure 1. The figure is a PNG built here byte by byte (IHDR width and
height at bytes 16-24, pHYs in pixels per metre), so its shown size is also checked against the
published units: the PNG specification (version 1.2, §4.2.4.2 pHYs: pixels per unit, unit
specifier byte 1 = the metre; "one inch is equal to exactly 0.0254 meters", so dpi = ppm ×
0.0254) and CSS Values and Units Level 3 (§5.2, 1 in = 96 px), so a figure is shown pixels ×
96 / dpi CSS px wide (240 px at 3780 px/m ≈ 96.01 dpi → 240 × 96 / 96.012 = 239.97 → 240 CSS px;
120 px → 120). Integers and text only: no tolerance.
"""

from __future__ import annotations

import re
import struct
import zlib
from pathlib import Path

from flexshaft.report import FigureRef, Section, Table, render_report


def _chunk(kind: bytes, payload: bytes) -> bytes:
    return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))


def _png(path: Path, width: int, height: int, per_metre: int) -> Path:
    """A white RGB PNG of ``width`` × ``height`` pixels with a pHYs chunk (unit: metre)."""
    rows = b"".join(b"\x00" + b"\xff" * (3 * width) for _ in range(height))
    data = (
        b"\x89PNG\r\n\x1a\n"
        + _chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
        + _chunk(b"pHYs", struct.pack(">IIB", per_metre, per_metre, 1))
        + _chunk(b"IDAT", zlib.compress(rows))
        + _chunk(b"IEND", b"")
    )
    path.write_bytes(data)
    return path


def test_tables_and_figures_numbered_across_the_report(tmp_path: Path) -> None:
    """Sections with 2, 0, 1, 1 tables: captions Table 1-4 in page order, ids table-1..4, each
    caption with its own table's text; the figure in section 3 is Figure 1 at 240 × 120 CSS px."""
    png = _png(tmp_path / "shape.png", 240, 120, 3780)
    sections = [
        Section("Inputs", tables=[Table("alpha", ["x [m]"], [[1.0]]), Table("beta", ["x [m]"], [[2.0]])]),
        Section("Text only", paragraphs=["no table here"]),
        Section("Modes", tables=[Table("gamma", ["f [Hz]"], [[3.0]])], figures=[FigureRef(png, "a shape")]),
        Section("Strength", tables=[Table("delta", ["SF"], [[4.0]])]),
    ]
    page = render_report("numbering", sections, generated=None)
    captions = re.findall(r"<caption>Table (\d+)\. (\w+)</caption>", page)
    assert captions == [("1", "alpha"), ("2", "beta"), ("3", "gamma"), ("4", "delta")]
    assert re.findall(r'<table id="table-(\d+)">', page) == ["1", "2", "3", "4"]
    assert re.findall(r"<figcaption>Figure (\d+)\. a shape", page) == ["1"]
    assert re.findall(r'<img [^>]*width="(\d+)" height="(\d+)"', page) == [("240", "120")]

"""One self-contained HTML page for ``flexshaft run``: sections of text, tables and figures.

The page needs nothing but itself: inline CSS, no script, no external URL, and every figure
embedded as a base64 PNG (the PNG files, and SVG files when asked for, written by
:mod:`flexshaft.plot.output` stay beside it for other uses). Each image is shown at its
physical size (from the PNG's pHYs resolution, 96 CSS px per inch). A
Content-Security-Policy meta tag forbids any load other than ``data:`` images, so an accidental
external reference fails visibly instead of silently reaching the network. All text is escaped.
"""

from __future__ import annotations

import base64
import datetime as dt
import html
import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft import __version__
from flexshaft.files import atomic_write_text

__all__ = ["Table", "FigureRef", "Preformatted", "Section", "format_cell", "page_head", "render_report", "write_report"]

_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
_DEFAULT_DPI = 150.0  # a PNG without a pHYs chunk is assumed at this resolution; shown at 96 CSS px per inch
_CSP = "default-src 'none'; img-src data:; style-src 'unsafe-inline'"

_CSS = """
:root { --ink: #1b1f24; --muted: #57606a; --rule: #d0d7de; --band: #f6f8fa; --accent: #0b5394; }
* { box-sizing: border-box; }
body { margin: 0; color: var(--ink); background: #fff;
       font: 15px/1.5 -apple-system, "Segoe UI", "DejaVu Sans", Helvetica, Arial, sans-serif; }
main { max-width: 1100px; margin: 0 auto; padding: 0 24px 48px; }
header.report { border-bottom: 3px solid var(--accent); padding: 24px 0 12px; margin-bottom: 16px; }
header.report h1 { margin: 0 0 6px; font-size: 1.8em; }
dl.meta { display: grid; grid-template-columns: max-content 1fr; gap: 2px 16px; margin: 0;
          color: var(--muted); }
dl.meta dt { font-weight: 600; } dl.meta dd { margin: 0; }
nav.toc { background: var(--band); border: 1px solid var(--rule); padding: 8px 20px; }
nav.toc h2 { font-size: 1.05em; margin: 6px 0; border: none; }
nav.toc ol { margin: 0 0 6px; padding-left: 22px; }
nav.toc a { color: var(--accent); text-decoration: none; }
section { margin-top: 28px; }
h2 { font-size: 1.35em; border-bottom: 1px solid var(--rule); padding-bottom: 4px; }
table { border-collapse: collapse; margin: 14px 0 20px; font-size: 0.92em; }
caption { caption-side: top; text-align: left; font-weight: 600; padding-bottom: 4px; }
th, td { border: 1px solid var(--rule); padding: 4px 10px; vertical-align: top; }
th { background: var(--band); text-align: left; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
tbody tr:nth-child(even) { background: #fbfcfd; }
figure { margin: 18px 0 26px; }
figure img { display: block; max-width: 100%; height: auto; border: 1px solid var(--rule); }
figcaption { color: var(--muted); font-size: 0.92em; margin-top: 6px; }
details { margin: 14px 0 20px; border: 1px solid var(--rule); padding: 4px 10px; }
details summary { cursor: pointer; font-weight: 600; }
pre { overflow-x: auto; background: var(--band); padding: 8px; font-size: 0.85em; line-height: 1.35; }
footer { margin-top: 40px; border-top: 1px solid var(--rule); padding-top: 8px;
         color: var(--muted); font-size: 0.85em; }
@media print { main { max-width: none; } figure, table { break-inside: avoid; }
               section { break-before: auto; } nav.toc { break-after: page; } }
"""


@dataclass(frozen=True)
class Table:
    """A table of values.

    Parameters
    ----------
    caption : str
        Caption shown above the table; put units in the column names, e.g. "speed [rpm]".
    columns : sequence of str
        Column headings.
    rows : sequence of sequence
        One sequence of values per row, as many as ``columns``; formatted by
        :func:`format_cell` (floats with ``:.4g``).
    """

    caption: str
    columns: Sequence[str]
    rows: Sequence[Sequence[Any]]

    def __post_init__(self) -> None:
        for index, row in enumerate(self.rows):
            if len(row) != len(self.columns):
                raise ValueError(
                    f"Table {self.caption!r}: row {index} has {len(row)} values, "
                    f"expected {len(self.columns)} (columns {list(self.columns)})"
                )


@dataclass(frozen=True)
class FigureRef:
    """A figure already saved as PNG, to embed in the page.

    Parameters
    ----------
    path_png : str or Path
        The PNG file (e.g. ``save_figure(...)["png"]``).
    caption : str
        Caption below the figure.
    alt : str, optional
        Alternative text; defaults to the caption.
    """

    path_png: str | Path
    caption: str
    alt: str | None = None


@dataclass(frozen=True)
class Preformatted:
    """Verbatim text (a file, a listing) in a collapsible block, closed by default.

    Parameters
    ----------
    summary : str
        The line shown when the block is closed.
    text : str
        The verbatim text (escaped, shown in a monospace font).
    """

    summary: str
    text: str


@dataclass(frozen=True)
class Section:
    """A numbered section of the report: paragraphs, tables, figures, then verbatim blocks.

    Parameters
    ----------
    title : str
        Section heading, also listed in the table of contents.
    paragraphs : sequence of str
        Plain-text paragraphs (escaped, not interpreted as HTML).
    tables : sequence of Table
    figures : sequence of FigureRef
    blocks : sequence of Preformatted
    """

    title: str
    paragraphs: Sequence[str] = ()
    tables: Sequence[Table] = ()
    figures: Sequence[FigureRef] = ()
    blocks: Sequence[Preformatted] = ()


def format_cell(value: Any) -> str:
    """Format one table value as text (not yet escaped).

    Floats use ``:.4g``; integers are exact; None is an em dash; NaN is "NaN" and infinities
    "∞"/"−∞"; booleans "yes"/"no"; complex numbers ``a+bj`` with each part ``:.4g``.
    """
    if value is None:
        return "—"
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)):
        return "yes" if value else "no"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        number = float(value)
        if math.isnan(number):
            return "NaN"
        if math.isinf(number):
            return "∞" if number > 0 else "−∞"
        return f"{number:.4g}"
    if isinstance(value, numbers.Complex):
        z = complex(value)
        return f"{z.real:.4g}{z.imag:+.4g}j"
    return str(value)


def _is_numeric(value: Any) -> bool:
    return isinstance(value, numbers.Number) and not isinstance(value, (bool, np.bool_))


def _png_size(data: bytes) -> tuple[int, int]:
    """Pixel width and height from the IHDR chunk of a PNG."""
    return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


def _png_dpi(data: bytes) -> float:
    """Resolution [dots per inch] from the pHYs chunk (before the image data), else the default."""
    position = 8
    while position + 8 <= len(data):
        length = int.from_bytes(data[position : position + 4], "big")
        kind = data[position + 4 : position + 8]
        if kind == b"pHYs" and length == 9:
            per_metre = int.from_bytes(data[position + 8 : position + 12], "big")
            unit = data[position + 16]
            return per_metre * 0.0254 if unit == 1 and per_metre > 0 else _DEFAULT_DPI
        if kind in (b"IDAT", b"IEND"):
            break
        position += 12 + length
    return _DEFAULT_DPI


def _render_table(table: Table, number: int) -> str:
    e = html.escape
    head = "".join(f'<th scope="col">{e(str(name))}</th>' for name in table.columns)
    body = []
    for row in table.rows:
        cells = "".join(
            f'<td class="num">{e(format_cell(v))}</td>' if _is_numeric(v) else f"<td>{e(format_cell(v))}</td>"
            for v in row
        )
        body.append(f"<tr>{cells}</tr>")
    return (
        f'<table id="table-{number}">\n<caption>Table {number}. {e(table.caption)}</caption>\n'
        f"<thead><tr>{head}</tr></thead>\n<tbody>\n" + "\n".join(body) + "\n</tbody>\n</table>"
    )


def _render_figure(figure: FigureRef, number: int) -> str:
    path = Path(figure.path_png)
    if not path.is_file():
        raise FileNotFoundError(f"FigureRef {figure.caption!r}: PNG file not found: {path}")
    data = path.read_bytes()
    if not data.startswith(_PNG_SIGNATURE):
        raise ValueError(f"FigureRef {figure.caption!r}: {path} is not a PNG file")
    dpi = _png_dpi(data)
    width, height = (round(n * 96.0 / dpi) for n in _png_size(data))
    files = f"{path.stem}.png, .svg" if path.with_suffix(".svg").is_file() else f"{path.stem}.png"
    encoded = base64.b64encode(data).decode("ascii")
    alt = html.escape(figure.alt if figure.alt is not None else figure.caption, quote=True)
    return (
        f'<figure id="figure-{number}">\n'
        f'<img src="data:image/png;base64,{encoded}" alt="{alt}" width="{width}" height="{height}">\n'
        f"<figcaption>Figure {number}. {html.escape(figure.caption)} "
        f'<span class="file">({html.escape(files)})</span></figcaption>\n</figure>'
    )


def render_report(
    title: str,
    sections: Sequence[Section],
    *,
    design_name: str | None = None,
    version: str = __version__,
    generated: dt.datetime | dt.date | None = None,
) -> str:
    """Render the report as one self-contained HTML page.

    Parameters
    ----------
    title : str
        Page title and main heading.
    sections : sequence of Section
        Report body, numbered in order; tables and figures are numbered across the report.
    design_name : str, optional
        Design shown in the header; defaults to ``title``.
    version : str
        flexshaft version shown in the header.
    generated : datetime or date, optional
        Date shown in the header; defaults to now (pass a fixed value for reproducible files).

    Returns
    -------
    str
        The HTML document.
    """
    e = html.escape
    generated = generated if generated is not None else dt.datetime.now().replace(microsecond=0)
    date_text = generated.strftime("%Y-%m-%d %H:%M") if isinstance(generated, dt.datetime) else generated.isoformat()
    toc = "\n".join(f'<li><a href="#section-{i}">{e(section.title)}</a></li>' for i, section in enumerate(sections, 1))
    parts: list[str] = []
    table_number = figure_number = 0
    for i, section in enumerate(sections, 1):
        parts.append(f'<section id="section-{i}">\n<h2>{i}. {e(section.title)}</h2>')
        parts.extend(f"<p>{e(paragraph)}</p>" for paragraph in section.paragraphs)
        for table in section.tables:
            table_number += 1
            parts.append(_render_table(table, table_number))
        for figure in section.figures:
            figure_number += 1
            parts.append(_render_figure(figure, figure_number))
        parts.extend(
            f"<details>\n<summary>{e(block.summary)}</summary>\n<pre>{e(block.text)}</pre>\n</details>"
            for block in section.blocks
        )
        parts.append("</section>")
    body = "\n".join(parts)
    return f"""{page_head(title, _CSS, _CSP, version)}
<body>
<main>
<header class="report">
<h1>{e(title)}</h1>
<dl class="meta">
<dt>Design</dt><dd>{e(design_name if design_name is not None else title)}</dd>
<dt>flexshaft</dt><dd>{e(version)}</dd>
<dt>Date</dt><dd>{e(date_text)}</dd>
</dl>
</header>
<nav class="toc" aria-label="Contents">
<h2>Contents</h2>
<ol>
{toc}
</ol>
</nav>
{body}
<footer>Generated by flexshaft {e(version)} on {e(date_text)}. Figures are also saved as image
files beside this page (named in each caption).</footer>
</main>
</body>
</html>
"""


def page_head(title: str, css: str, csp: str, version: str = __version__, script: str = "") -> str:
    """A flexshaft page's doctype and ``<head>``: its content security policy ``csp``, its
    stylesheet ``css`` and, when given, an inline ``<script>`` (text safe inside the element),
    ending with ``</head>`` (the report's page and the interactive page's)."""
    e = html.escape
    script_line = f"\n<script>{script}</script>" if script else ""
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="{csp}">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="flexshaft {e(version)}">
<title>{e(title)}</title>
<style>{css}</style>{script_line}
</head>"""


def write_report(folder: str | Path, title: str, sections: Sequence[Section], **options: Any) -> Path:
    """Write ``report.html`` into ``folder`` (created if missing) and return its path.

    Parameters
    ----------
    folder : str or Path
        Results folder.
    title : str
        Page title.
    sections : sequence of Section
        Report body.
    **options
        ``design_name``, ``version``, ``generated``: see :func:`render_report`.

    Returns
    -------
    Path
        The written ``report.html``.
    """
    out = Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    path = out / "report.html"
    return atomic_write_text(path, render_report(title, sections, **options))

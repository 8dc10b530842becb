"""The offline page ``interactive.html`` (``flexshaft run --interactive``): the verdict's table
and the interactive figures of :func:`flexshaft.report.interactive.assessment_figures`, with
plotly.js inlined so that the page works offline and alone; and where plotly.js comes from (the
file the ``plotly`` wheel ships, the extra ``flexshaft[explore]``), for the page and for
``flexshaft explore``.
"""

from __future__ import annotations

import html
import json
from importlib import resources
from pathlib import Path

from flexshaft.report.html import page_head
from flexshaft.report.interactive import assessment_figures
from flexshaft.report.verdict import VERDICT_COLUMNS, location_text, verdict_rows
from flexshaft.verdict.assess import Assessment

__all__ = [
    "EXPLORE_EXTRA",
    "INTERACTIVE_PAGE",
    "interactive_page",
    "missing_extra",
    "plotly_js_path",
    "write_interactive_report",
]

#: The page :func:`write_interactive_report` writes.
INTERACTIVE_PAGE = "interactive.html"
#: How to install what the interactive figures and ``flexshaft explore`` need.
EXPLORE_EXTRA = "pip install 'flexshaft[explore]'"


def plotly_js_path() -> Path | None:
    """The ``plotly.min.js`` shipped in the ``plotly`` wheel, or None when it is not installed."""
    try:
        path = resources.files("plotly").joinpath("package_data", "plotly.min.js")
    except ModuleNotFoundError:
        return None
    path = Path(str(path))
    return path if path.is_file() else None


def missing_extra(what: str = "the interactive figures") -> str | None:
    """None when plotly.js is available; else the message saying how to install it."""
    if plotly_js_path() is not None:
        return None
    return (
        f"{what}: the optional package plotly is not installed (its plotly.js draws the figures, offline); "
        f"install it with {EXPLORE_EXTRA}"
    )


_CSP = "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src data: blob:"
_CSS = """
body { margin: 0; font: 15px/1.5 "DejaVu Sans", Helvetica, Arial, sans-serif; color: #1b1f24; }
main { max-width: 1100px; margin: 0 auto; padding: 0 24px 48px; }
h1 { font-size: 1.6em; border-bottom: 3px solid #0b5394; padding: 20px 0 8px; }
table { border-collapse: collapse; font-size: 0.9em; margin: 12px 0 20px; }
th, td { border: 1px solid #d0d7de; padding: 3px 8px; text-align: left; }
tr.pass td.status { color: #2e7d32; font-weight: 600; } tr.fail td.status { color: #c62828; font-weight: 600; }
.figure { width: 100%; height: 460px; margin: 8px 0 24px; border: 1px solid #d0d7de; }
#actuators { height: 620px; }
p.note { color: #57606a; }
"""
_TITLES = {
    "margins": "Requirements margins",
    "campbell": "Campbell diagram",
    "spinup": "Spin-up orbit",
    "actuators": "Actuator excursion and force",
    "stability": "Whirl stability",
}


def _script_text(text: str) -> str:
    """Text safe inside a <script> element (no closing tag can appear)."""
    return text.replace("</", "<\\/")


def interactive_page(a: Assessment, plotly_js: str, title: str | None = None) -> str:
    """The HTML page of :func:`write_interactive_report` (``plotly_js``: the library's text)."""
    e = html.escape
    figures = assessment_figures(a)
    rows = verdict_rows(a.verdict)
    statuses = [c.status.replace(" ", "-") for c in a.verdict.checks]
    head = "".join(f"<th>{e(c)}</th>" for c in VERDICT_COLUMNS)
    body = "\n".join(
        f'<tr class="{s}">'
        + "".join(f'<td class="{"status" if i == 4 else ""}">{e(v)}</td>' for i, v in enumerate(row))
        + "</tr>"
        for s, row in zip(statuses, rows)
    )
    failed = "; ".join(f"{c.title} ({location_text(c.location)})" for c in a.verdict.failed)
    divs = "\n".join(
        f'<h2>{e(_TITLES.get(name, name))}</h2>\n<div class="figure" id="{e(name)}"></div>' for name in figures
    )
    data = _script_text(json.dumps(figures, allow_nan=False, separators=(",", ":")))
    heading = title or f"flexshaft interactive figures: {a.design.name}"
    return f"""{page_head(heading, _CSS, _CSP, script=_script_text(plotly_js))}
<body>
<main>
<h1>{e(heading)}</h1>
<p>Verdict: <b>{"PASS" if a.verdict.passed else "FAIL"}</b> at the {e(a.resolution.name)} resolution.
{e(failed)}</p>
<p class="note">The figures of <a href="report.html">report.html</a> with hover and zoom (drag to zoom,
double-click to reset). plotly.js is inside this page: it needs no network.</p>
<table><thead><tr>{head}</tr></thead><tbody>
{body}
</tbody></table>
{divs}
</main>
<script>
const figures = {data};
for (const [name, figure] of Object.entries(figures)) {{
  Plotly.newPlot(name, figure.data, figure.layout, {{responsive: true, displaylogo: false}});
}}
document.body.dataset.plotted = String(Object.keys(figures).length);
</script>
</body>
</html>
"""


def write_interactive_report(a: Assessment, folder: str | Path) -> Path:
    """Write ``interactive.html`` (the verdict and :func:`assessment_figures`, plotly.js inlined)
    into ``folder``; returns its path.

    Raises
    ------
    ModuleNotFoundError
        When plotly is not installed (:func:`missing_extra` says how to install it).
    """
    js = plotly_js_path()
    if js is None:
        raise ModuleNotFoundError(missing_extra())
    path = Path(folder) / INTERACTIVE_PAGE
    path.write_text(interactive_page(a, js.read_text(encoding="utf-8")), encoding="utf-8")
    return path

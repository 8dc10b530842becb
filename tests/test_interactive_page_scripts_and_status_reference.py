"""``interactive.html`` can run its scripts, holds plotly.js itself, and colours each check's status.

References:

* docs/explorer.md, "The report's interactive figures": ``interactive.html`` holds "the verdict
  table and the explorer's five figures of the run's assessment ..., with plotly.js inlined
  (4.9 MB), so the page works offline and alone; its Content-Security-Policy allows no load."
  The explorer's verdict table (same file) shows "value, limit, margin, pass/fail colour, where,
  note".
* The Content-Security-Policy rules (MDN, read): "script-src-elem ... specifies valid sources for
  JavaScript <script> elements (both script requests and blocks) ... If this directive is absent,
  the user agent will look for the script-src directive, and if both of them are absent, fall
  back to default-src directive"
  (https://developer.mozilla.org/en-US/docs/Web/HTTP/Headers/Content-Security-Policy/script-src-elem);
  "The unsafe-inline Content Security Policy (CSP) keyword allows the execution of inline scripts
  or styles" and without it "That inline script will also be blocked by CSP by default"
  (https://content-security-policy.com/unsafe-inline/). A page whose scripts are all inline
  (plotly.js inlined, the plotting loop) therefore draws only when the effective script source
  list holds 'unsafe-inline'. The nonce/hash exception ('unsafe-inline' ignored when a nonce or
  hash is listed, CSP Level 2) is ruled out by asserting neither is listed.
* HTML's class attribute is a set of space-separated tokens (HTML Living Standard, "classes":
  assumed, not re-read for this test), so a row's status class must hold no space.

The page is built on the stand-in assessment of
tests/test_interactive_page_verdict_line_reference.py (three checks: pass, fail at amb_1, not
evaluated) with no figures, and a stand-in library text in place of plotly.min.js (the page's
handling of the text does not depend on which library it is). Text only: no tolerance.
"""

from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

import flexshaft.report.interactive_page as ip
from tests.test_interactive_page_verdict_line_reference import _stand_in

# a stand-in library: defines Plotly, holds no "</" (so it is inlined verbatim)
_LIBRARY = "var Plotly = {newPlot: function (id, data, layout, config) { return id; }};\n"


class _Page(HTMLParser):
    """The parts of the page the tests read: the CSP, each script's text, the style sheet, the
    verdict table's headings and rows (each row's class and its cells' class and text)."""

    def __init__(self) -> None:
        super().__init__()
        self.csp: str | None = None
        self.scripts: list[tuple[dict, str]] = []
        self.style = ""
        self.headings: list[str] = []
        self.rows: list[tuple[str, list[tuple[str, str]]]] = []
        self._in: str | None = None
        self._attrs: dict = {}
        self._text = ""

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "meta" and (a.get("http-equiv") or "").lower() == "content-security-policy":
            self.csp = a.get("content")
        elif tag in ("script", "style", "th", "td"):
            self._in, self._attrs, self._text = tag, a, ""
        elif tag == "tr":
            self.rows.append((a.get("class") or "", []))

    def handle_data(self, data):
        if self._in is not None:
            self._text += data

    def handle_endtag(self, tag):
        if tag != self._in:
            return
        if tag == "script":
            self.scripts.append((self._attrs, self._text))
        elif tag == "style":
            self.style += self._text
        elif tag == "th":
            self.headings.append(self._text)
        elif tag == "td":
            self.rows[-1][1].append((self._attrs.get("class") or "", self._text))
        self._in = None


def _parse(page: str) -> _Page:
    parsed = _Page()
    parsed.feed(page)
    parsed.close()
    return parsed


@pytest.fixture
def page(monkeypatch: pytest.MonkeyPatch) -> str:
    monkeypatch.setattr(ip, "assessment_figures", lambda a: {})
    return ip.interactive_page(_stand_in(), plotly_js=_LIBRARY)  # type: ignore[arg-type]


def _directives(csp: str) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for part in csp.split(";"):
        words = part.split()
        if words:
            out.setdefault(words[0].lower(), words[1:])  # CSP: a repeated directive is ignored
    return out


def test_the_policy_lets_the_inline_scripts_run_and_allows_no_load(page: str) -> None:
    """Every script of the page is inline (no src), and the effective source list of <script>
    elements (script-src-elem, else script-src, else default-src: MDN) holds 'unsafe-inline' and
    no nonce or hash; no directive lists a host, a network scheme or 'self' (docs/explorer.md:
    "allows no load")."""
    parsed = _parse(page)
    assert parsed.scripts, "the page has no script"
    assert all("src" not in attrs for attrs, _ in parsed.scripts)  # all inline
    assert parsed.csp is not None
    directives = _directives(parsed.csp)
    effective = next(directives[d] for d in ("script-src-elem", "script-src", "default-src") if d in directives)
    assert "'unsafe-inline'" in effective, f"inline scripts blocked by {parsed.csp!r}"
    assert not [s for s in effective if s.startswith(("'nonce-", "'sha"))]
    assert directives.get("default-src") == ["'none'"]  # anything not listed loads nothing
    allowed_load = {"'none'", "'unsafe-inline'", "data:", "blob:"}  # no URL reached over a network
    for name, sources in directives.items():
        assert set(sources) <= allowed_load, f"{name} allows a load: {sources}"


def test_the_written_page_inlines_the_library_text(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """write_interactive_report reads plotly.min.js and inlines its text (docs/explorer.md:
    "plotly.js inlined ... works offline and alone"): the page's first script is the library's
    text verbatim (it holds no "</"), before the plotting script, and no script is a file name."""
    library = tmp_path / "plotly.min.js"
    library.write_text(_LIBRARY, encoding="utf-8")
    monkeypatch.setattr(ip, "plotly_js_path", lambda: library)
    monkeypatch.setattr(ip, "assessment_figures", lambda a: {})
    folder = tmp_path / "results"
    folder.mkdir()
    path = ip.write_interactive_report(_stand_in(), folder)  # type: ignore[arg-type]
    assert path == folder / "interactive.html"
    scripts = [text for _, text in _parse(path.read_text(encoding="utf-8")).scripts]
    assert scripts[0] == _LIBRARY
    assert "Plotly.newPlot" in scripts[-1] and len(scripts) == 2
    assert not any(str(library) in text for text in scripts)


def test_the_status_cell_is_the_status_column_and_the_only_coloured_one(page: str) -> None:
    """Each row of the verdict table: its class is its check's status as one token (pass, fail,
    not-evaluated: the stand-in's statuses, docs/requirements.md's three); the one cell of class
    "status" stands under the heading "status" and reads PASS / FAIL / not evaluated; the page's
    stylesheet (rules ``tr.X td.Y { color: ... }``) colours that cell of the passing and of the
    failing row, in two different colours, and no other cell (docs/explorer.md: "pass/fail
    colour")."""
    parsed = _parse(page)
    column = parsed.headings.index("status")
    rows = [r for r in parsed.rows if r[1]]  # the heading row has no td
    assert [r[0] for r in rows] == ["pass", "fail", "not-evaluated"]
    assert all(" " not in r[0] for r in rows)
    rules = re.findall(r"tr\.([\w-]+) td\.([\w-]+) \{ color: (#[0-9a-fA-F]+)", parsed.style)
    colours = {}
    for row_class, cells in rows:
        assert len(cells) == len(parsed.headings)
        status_cells = [i for i, (cls, _) in enumerate(cells) if "status" in cls.split()]
        assert status_cells == [column]
        coloured = {
            i: colour
            for i, (cls, _) in enumerate(cells)
            for r, c, colour in rules
            if r in row_class.split() and c in cls.split()
        }
        if row_class in ("pass", "fail"):
            assert list(coloured) == [column], f"{row_class}: coloured cells {coloured}"
            colours[row_class] = coloured[column]
    assert [cells[column][1] for _, cells in rows] == ["PASS", "FAIL", "not evaluated"]
    assert colours["pass"] != colours["fail"]

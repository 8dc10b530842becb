"""What a notebook shows: short reprs, HTML tables (``_repr_html_``), ``print(modes)`` as a
table, ``to_dataframe()``, ``.save()`` adding ``.nc`` and a snapped station named.

The tables are formatting, not physics: each is compared with the result's own fields (the
numbers those fields hold are verified by the analyses' own tests), and the HTML is parsed,
checked for escaping and, where Debian's chromium is installed (always in CI), rendered in it.
"""

from __future__ import annotations

import re
import warnings
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pytest
from chromium_probe import chromium_or_skip, run_chromium

import flexshaft as fs
from flexshaft.analyses import campbell, imbalance_response, stability
from flexshaft.analyses.results import StationWarning
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import design_from_dict
from flexshaft.units import format_quantity
from flexshaft.verdict.text import VERDICT_COLUMNS, location_text

#: A name with markup: every table must escape it.
MARKUP_NAME = "<script>alert(1)</script> & <b>co</b>"


class _Cells(HTMLParser):
    """The cells of every table (their text and style) and the text outside tables."""

    def __init__(self) -> None:
        super().__init__()
        self.tables: list[list[list[tuple[str, str]]]] = []
        self.scripts = 0
        self._cell: list[str] | None = None
        self._style = ""

    def handle_starttag(self, tag, attrs):
        if tag == "script":
            self.scripts += 1
        if tag == "table":
            self.tables.append([])
        elif tag == "tr":
            self.tables[-1].append([])
        elif tag in ("td", "th"):
            self._cell, self._style = [], dict(attrs).get("style", "")

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self.tables[-1][-1].append(("".join(self._cell), self._style))
            self._cell = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def _parse(page: str) -> _Cells:
    parser = _Cells()
    parser.feed(page)
    return parser


@pytest.fixture(scope="module")
def baseline_assessment():
    """The Table 3.1 baseline, which fails some of its checks and passes others, at the
    optimizer's coarse resolution, with a name full of markup, over one envelope point, the
    standard day, on a coarse mesh (12 shaft, 6 boom elements) (CPU budget, issue 23: the tables
    are formatting; one point's checks still name their point in every location, four points
    cost four times the assessment, and the coarse mesh fails and passes the same checks as
    the design's own, 36 and 24)."""
    coarse = {"name": MARKUP_NAME, "mesh.shaft_elements": 12, "mesh.boom_elements": 6}
    data = fs.with_overrides(fs.baseline_design(), coarse).model_dump()
    data["envelope"]["points"] = [p for p in data["envelope"]["points"] if p["name"] == "standard_day"]
    return fs.assess(design_from_dict(data), fs.SCREENING)


def test_assessment_renders_the_verdict_table(baseline_assessment):
    a = baseline_assessment
    page = a._repr_html_()
    parsed = _parse(page)
    assert parsed.scripts == 0 and "<script>" not in page and "&lt;script&gt;" in page  # the name is escaped
    (table,) = parsed.tables
    assert [text for text, _ in table[0]] == list(VERDICT_COLUMNS)
    rows = table[1:]
    assert [r[0][0] for r in rows] == [c.title for c in a.verdict.checks]
    assert {c.status for c in a.verdict.checks} >= {"pass", "fail"}
    for row, check in zip(rows, a.verdict.checks):
        status, style = row[4]
        assert status == {"pass": "PASS", "fail": "FAIL", "not evaluated": "not evaluated"}[check.status]
        assert ("#cf222e" in style) == (check.status == "fail") and ("#1a7f37" in style) == (check.status == "pass")
        assert row[3][0].lstrip("> ") == format_quantity(check.kind, check.margin, margin=True)
        assert row[5][0] == location_text(check.location)
    assert all(location_text(c.location).startswith("[standard_day]") for c in a.verdict.checks if c.location)
    failed = [c.title for c in a.verdict.checks if c.status == "fail"]
    assert failed and f"verdict: FAIL — {len(failed)} of {len(a.verdict.checks)} checks fail: {failed[0]} (" in page


def test_assessment_html_renders_in_chromium(baseline_assessment, tmp_path: Path):
    """The table as a browser draws it: its rows, and a failed status in red (rgb of #cf222e)."""
    chromium = chromium_or_skip()
    probe = (
        "<script>window.addEventListener('load', () => { const rows = document.querySelectorAll('tbody tr');"
        " const fail = [...document.querySelectorAll('td')].find(td => td.textContent === 'FAIL');"
        " document.title = rows.length + ':' + getComputedStyle(fail).color; });</script>"
    )
    page = tmp_path / "assessment.html"
    page.write_text(
        f"<!doctype html><html><head><meta charset='utf-8'><title>-</title></head><body>"
        f"{baseline_assessment._repr_html_()}{probe}</body></html>",
        encoding="utf-8",
    )
    dump = run_chromium(chromium, tmp_path, "--virtual-time-budget=5000", "--dump-dom", page.as_uri())
    assert dump.returncode == 0, dump.stderr[-2000:]
    title = re.search(r"<title>(.*?)</title>", dump.stdout, re.DOTALL).group(1)
    assert title == f"{len(baseline_assessment.verdict.checks)}:rgb(207, 34, 46)"


def test_verdict_to_dataframe_holds_every_check_in_si(baseline_assessment):
    v = baseline_assessment.verdict
    frame = baseline_assessment.to_dataframe()
    assert list(frame.index) == [c.key for c in v.checks]
    for c in v.checks:
        row = frame.loc[c.key]
        assert (row["status"], row["margin"], row["limit"]) == (c.status, c.margin, c.limit)
    assert v.headline.startswith(f"FAIL — {len(v.failed)} of {len(v.checks)} checks fail: ")


def test_reprs_are_one_short_line(baseline_assessment):
    """repr(model) dumped the matrices and the design (about 8 kB)."""
    a = baseline_assessment
    for obj in (a, a.model, a.model.dofs, a.spinup, a.modes_at_speed, a.stability, a.verdict):
        text = repr(obj)
        assert "\n" not in text and len(text) < 600, (type(obj).__name__, len(text))
    assert f"{a.model.dofs.size} DOFs ({a.model.dofs.free.size} free)" in repr(a.model)


def test_print_modes_is_the_per_mode_table_and_to_dataframe_its_rows():
    model = fs.build_model(fs.tuned_design())
    m = fs.modes(model, model.speed, 12)
    lines = str(m).splitlines()
    assert lines[1].split() == ["mode", "f", "[Hz]", "f", "[rpm]", "ζ", "[-]", "δ", "[-]", "kind", "whirl", "component"]
    body = lines[3 : 3 + 12]
    assert [int(line.split()[0]) for line in body] == list(range(1, 13))
    assert [line.split()[1] for line in body] == [f"{f:.4g}" for f in m.frequencies]
    frame = m.to_dataframe()
    assert list(frame.index) == list(range(1, 13))
    np.testing.assert_array_equal(frame["frequency_Hz"].to_numpy(), m.frequencies)
    np.testing.assert_array_equal(frame["damping_ratio"].to_numpy(), m.damping_ratios)
    assert len(_parse(m._repr_html_()).tables[0]) == 13


def test_campbell_stability_and_response_show_tables():
    model = fs.build_model(fs.baseline_design())
    c = campbell(model, np.linspace(0.0, 1.3 * model.speed, 12), n_modes=6)
    frame = c.to_dataframe()
    assert list(frame["speed_rpm"]) == [k.speed_rpm for k in c.critical_speeds]
    assert list(frame["mode"]) == [k.mode + 1 for k in c.critical_speeds]
    tables = _parse(c._repr_html_()).tables
    assert len(tables[0]) == 7 and len(tables[1]) == 1 + len(c.critical_speeds)
    s = stability(model, np.linspace(0.0, 1.5 * model.speed, 6), n_modes=6)
    (rows,) = _parse(s._repr_html_()).tables
    assert [float(r[1][0]) for r in rows[1:]] == [float(f"{f:.4g}") for f in s.frequencies[0]]
    q = imbalance_response(model, np.linspace(10.0, model.speed, 8), imbalance_loads(model))
    (rows,) = _parse(q._repr_html_()).tables
    assert ["excitation", "imbalance"] in [[text for text, _ in r] for r in rows]


def test_save_adds_nc_to_a_path_without_suffix(tmp_path: Path):
    m = fs.modes(fs.build_model(fs.baseline_design()), 0.0, 2)
    assert m.save(tmp_path / "modes") == tmp_path / "modes.nc" and (tmp_path / "modes.nc").is_file()
    assert m.save(tmp_path / "modes.cdf") == tmp_path / "modes.cdf"  # a suffix given is kept
    assert not (tmp_path / "modes").exists()


def test_a_station_between_nodes_says_where_it_is_shown():
    model = fs.build_model(fs.baseline_design())
    q = imbalance_response(model, np.linspace(10.0, model.speed, 8), imbalance_loads(model))
    x = model.dofs.shaft_x
    k = int(np.searchsorted(x, 4.42))
    nearest = x[k] if abs(x[k] - 4.42) < abs(x[k - 1] - 4.42) else x[k - 1]
    with pytest.warns(StationWarning, match=rf"station 4.42 m is not a shaft node: .* x = {nearest:g} m"):
        q.plot(kind="bode", station=4.42)
    with warnings.catch_warnings():
        warnings.simplefilter("error", StationWarning)
        q.plot(kind="bode", station=float(x[k]))  # a node: no warning
    import matplotlib.pyplot as plt

    plt.close("all")

"""The tables every result shows (analyses/results.py: ``cell_text``, ``text_table``,
``html_table``) on hand-typed rows.

References (the module's contract, derived by hand): a number has ``digits`` significant
figures (default 4): 55.3219 → "55.32", 0.0123456 → "0.01235"; a yes/no value reads
"true"/"false", not 1/0; every row appears, in order; ``row_styles[k]`` styles row k (the
first row's failure red, the second's pass green). Exact strings; CPU about 1 ms.
"""

from __future__ import annotations

import re

from flexshaft.analyses.results import cell_text, html_table, text_table


def test_cells_have_four_significant_figures_and_words_for_booleans():
    assert cell_text(55.3219) == "55.32"
    assert cell_text(0.0123456) == "0.01235"
    assert cell_text(7200.4) == "7200"
    assert cell_text(55.3219, digits=3) == "55.3"
    assert cell_text(True) == "true" and cell_text(False) == "false"
    assert cell_text(None) == "—" and cell_text(3) == "3"


def test_text_table_keeps_every_row_in_order():
    """Two modes, 55.32 Hz and 120.5 Hz: the header, the rule, then mode 1 and mode 2."""
    text = text_table(["mode", "f [Hz]"], [[1, 55.3219], [2, 120.5]], title="modes", caption="end")
    lines = text.splitlines()
    assert lines[0] == "modes" and lines[-1] == "end"
    body = [line.split() for line in lines[3:-1]]
    assert body == [["1", "55.32"], ["2", "120.5"]]


def test_html_row_styles_belong_to_their_rows():
    rows = [["whirl onset", "FAIL"], ["strength", "PASS"]]
    styles = [{1: "color:red;"}, {1: "color:green;"}]
    html = html_table(["requirement", "status"], rows, row_styles=styles)
    tds = re.findall(r'<td style="([^"]*)">([^<]*)</td>', html)
    assert ("text-align:left;color:red;", "FAIL") in tds
    assert ("text-align:left;color:green;", "PASS") in tds
    assert ("text-align:left;", "whirl onset") in tds

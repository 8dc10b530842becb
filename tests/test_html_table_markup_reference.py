"""The notebook tables of flexshaft.analyses.results.html_table keep their text as text.

Documented rule (html_table's docstring, the contract every result's ``_repr_html_`` relies
on): "every cell escaped" — a header, a cell, the title and the caption may hold any text,
and the markup around them must survive it. The reference is the markup itself: escaped
HTML of a table is well-formed XML, and an XML parser (xml.etree, an independent reader)
gives back each cell's text exactly as written, ``<``, ``>``, ``&`` and quotes included. A
cell left unescaped either breaks the parse or turns its text into elements.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from flexshaft.analyses.results import html_table


def test_cell_header_title_and_caption_text_comes_back_unchanged():
    headers = ["name <id>", "value & unit"]
    rows = [['bearing <B1> & "aft"', 1.5], ["x > y", 'a "quoted" <b>bold</b>']]
    markup = html_table(headers, rows, title="T < 1 & ok", caption="see <ref> & co")
    root = ET.fromstring(f"<div>{markup}</div>")  # escaped HTML of a table is well-formed XML

    cells = [[td.text for td in tr.findall("td")] for tr in root.iter("tr") if tr.findall("td")]
    assert cells == [['bearing <B1> & "aft"', "1.5"], ["x > y", 'a "quoted" <b>bold</b>']]
    assert [th.text for th in root.iter("th")] == headers
    assert root.find("p/b").text == "T < 1 & ok"
    assert list(root.iter("b")) == [root.find("p/b")]  # the title's <b> only: none from a cell
    assert root.findall("p")[-1].text == "see <ref> & co"

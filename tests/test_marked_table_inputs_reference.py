"""The values a design file marks "assumed" or "calibrated" through a table header, and the key
each marked value is listed under, against docs/requirements.md ("The report states its
inputs"): "lists every value whose comment says "assumed" or "calibrated" (a marker on a table
header marks every key of that table)".

References (by hand): a 13-line TOML text written here, its marked keys read off by eye;
the key of a marked value in an array of tables is checked by indexing the file as Python's
own TOML parser (tomllib, independent of flexshaft's line scanner) reads it. Text only: well
under 0.01 s.
"""

from __future__ import annotations

import tomllib

from flexshaft.report.inputs import marked_inputs

TEXT = """\
[shaft]  # assumed from the supplier's data sheet
outer_diameter = 0.06
wall_thickness = 0.004

[operating]
power = 150e3

[[bearings]]
kp = 5e5  # calibrated on the rig
kd = 560.0

[[bearings]]
kp = 7e5
"""


def test_a_header_marker_marks_its_table_only():
    """Lines 2 and 3 inherit the [shaft] header's marker; [operating] (line 6), whose header has
    no marker, and the second bearing (line 13) are not marked; line 9 is marked on its own."""
    marked = marked_inputs(TEXT)
    assert [(m.key, m.value, m.marker, m.line) for m in marked] == [
        ("shaft.outer_diameter", "0.06", "assumed", 2),
        ("shaft.wall_thickness", "0.004", "assumed", 3),
        ("bearings[0].kp", "5e5", "calibrated", 9),
    ]


def test_an_unnamed_array_element_is_listed_under_its_index_in_the_file():
    """The first [[bearings]] element is element 0 of the array as TOML reads it (tomllib):
    the listed key must lead to the value on the marked line (5e5, not the second element's
    7e5). Exact: both are the same decimal literal parsed to the same double."""
    (kp,) = (m for m in marked_inputs(TEXT) if m.marker == "calibrated")
    table, rest = kp.key.split("[", 1)
    index, key = rest.split("].", 1)
    data = tomllib.loads(TEXT)
    assert data[table][int(index)][key] == float(kp.value) == 5e5

"""Which design-file values report/inputs.py's scan lists as marked, for comment-only lines and
named array-of-tables elements.

References (rules written in the module's docstrings, report/inputs.py): "comment-only lines
are ignored" (module docstring), and MarkedInput.key is a "Dotted path, array-of-tables
elements by name (``bearings[amb_1].gap``) or index". The expected keys are read off by eye
from the 8-line TOML text below; the element's name is checked against Python's own TOML
parser (tomllib, independent of flexshaft's line scanner), which reads ``name = "amb_1"`` as
the string amb_1 without its quotes. Text only: well under 0.01 s.
"""

from __future__ import annotations

import tomllib

from flexshaft.report.inputs import marked_inputs

TEXT = """\
[shaft]
outer_diameter = 0.06
# assumed values of the bearings follow (a comment-only line)
wall_thickness = 0.004

[[bearings]]
name = "amb_1"
gap = 0.00025  # assumed: half a typical air gap
"""


def test_a_comment_only_line_marks_nothing():
    """Line 3 is a comment-only line: the measured shaft values on lines 2 and 4 stay unmarked;
    only line 8's gap is listed."""
    assert [(m.key, m.line) for m in marked_inputs(TEXT)] == [("bearings[amb_1].gap", 8)]


def test_a_named_element_is_listed_under_its_name_as_toml_reads_it():
    """The label between the brackets is the element's name as tomllib parses it."""
    (gap,) = marked_inputs(TEXT)
    name = gap.key.split("[", 1)[1].split("]", 1)[0]
    (element,) = [b for b in tomllib.loads(TEXT)["bearings"] if b["name"] == name]
    assert element["gap"] == float(gap.value) == 0.00025

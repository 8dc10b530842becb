"""Comments of a design file placed by hand on known keys: a key under a table header, and a
standalone comment line at column 0 right under a key.

Reference: docs/optimizer.md, the design files keep "every note at the key or table it annotates
(... the indented continuation lines of a long note too)"; the rules of
:mod:`flexshaft.optimize.toml_comments`' module docstring, the code's contract ("a comment after
a key's value ... belongs to that key ..., and so do the indented comment lines right under it";
"comment lines that stand alone belong to the next key or table header"); and TOML v1.0.0
("Table": keys under a ``[table]`` header belong to that table until the next header), so
``wall_thickness`` under ``[shaft]`` is the path ``("shaft", "wall_thickness")``. The texts are
written here; each expected placement is read off them by hand. Text only (CPU: ms).
"""

from __future__ import annotations

from flexshaft.optimize.toml_comments import read_comments

TEXT = """\
wall_thickness = 9.0  # top-level key of the same name

[shaft]
# the tube wall
wall_thickness = 0.003  # m, 8 plies (assumed)
# the tube length, not the wall
length = 2.0  # m
    # continued note on the length
"""


def test_a_key_under_a_table_carries_its_own_comments():
    """``[shaft]`` then ``wall_thickness``: its standalone line and inline note are at
    ``("shaft", "wall_thickness")``, not at the top-level ``wall_thickness`` (which keeps its
    own inline note only)."""
    keys = read_comments(TEXT).keys
    assert ("shaft", "wall_thickness") in keys
    shaft_wall = keys[("shaft", "wall_thickness")]
    assert shaft_wall.before == ["the tube wall"]
    assert shaft_wall.inline == ["m, 8 plies (assumed)"]
    top = keys[("wall_thickness",)]
    assert top.before == [] and top.inline == ["top-level key of the same name"]


def test_a_column_zero_comment_under_a_key_explains_the_next_key():
    """``# the tube length, not the wall`` stands alone at column 0 right under
    ``wall_thickness``: it belongs to ``length`` (before), and ``wall_thickness`` keeps only its
    inline note; the indented line under ``length`` continues ``length``'s note."""
    keys = read_comments(TEXT).keys
    assert keys[("shaft", "wall_thickness")].inline == ["m, 8 plies (assumed)"]
    length = keys[("shaft", "length")]
    assert length.before == ["the tube length, not the wall"]
    assert length.inline == ["m", "continued note on the length"]

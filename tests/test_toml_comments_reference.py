"""Comments of a design file by the key they annotate (flexshaft.optimize.toml_comments), and
carried by the writer to the right key.

Reference: small TOML texts written here, each comment placed on a known key by hand; the rules
are the module's documented ones (an inline comment and its indented continuation belong to its
key, standalone comment lines to the next key or header, lines after the last key are
``trailing``; a path indexes each array-of-tables element from 0, a nested array restarting at
0 in each outer element, as TOML's own array-of-tables semantics nest them, TOML v1.0.0
"Array of Tables"). Where the writer is involved, the file is read back with ``tomllib`` to
find which element a line belongs to. Text only, no analysis (CPU: a few ms).
"""

from __future__ import annotations

import tomllib

from flexshaft.design import loads_design, with_overrides
from flexshaft.optimize.files import design_toml
from flexshaft.optimize.toml_comments import read_comments

TEXT = """\
# preamble one
# preamble two

name = "rotor # one"  # the rotor's name

# about the first outer
[[outer]]
v = 1  # first outer
[[outer.inner]]
w = 10  # outer 0, inner 0
[[outer.inner]]
w = 11  # outer 0, inner 1
[[outer]]
v = 2  # second outer
[[outer.inner]]
w = 20  # outer 1, inner 0
    # its continuation
# trailing one
"""


def test_each_comment_belongs_to_its_key():
    assert tomllib.loads(TEXT)["outer"][1]["inner"][0]["w"] == 20  # the paths below, as TOML nests them
    c = read_comments(TEXT)
    assert c.preamble == ["preamble one", "preamble two"]
    assert c.keys[("name",)].inline == ["the rotor's name"]  # the '#' inside the string is not one
    assert c.keys[("outer", 0)].before == ["about the first outer"]
    assert c.keys[("outer", 0, "v")].inline == ["first outer"]
    assert c.keys[("outer", 0, "inner", 0, "w")].inline == ["outer 0, inner 0"]
    assert c.keys[("outer", 0, "inner", 1, "w")].inline == ["outer 0, inner 1"]
    assert c.keys[("outer", 1, "v")].inline == ["second outer"]
    assert c.keys[("outer", 1, "inner", 0, "w")].inline == ["outer 1, inner 0", "its continuation"]
    assert c.trailing == ["trailing one"]
    assert ("outer", 1, "inner", 2, "w") not in c.keys


SMALL = """\
name = "two-bay rotor"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7850.0
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.05
wall_thickness = 0.005
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "left"
kind = "contact"
x = 0.0                  # m, LEFT NOTE
stiffness = { v = 5e7, w = 5e7 }
[[bearings]]
name = "amb"
kind = "active"
x = 1.0
kp = 2e6                 # N/m, AMB NOTE
kd = 200.0
gap = 1.0e-3
[[bearings]]
name = "right"
kind = "contact"
x = 2.0                  # m, RIGHT NOTE
stiffness = { v = 5e7, w = 5e7 }
[operating]
speed_rpm = 6000.0
power = 0.0
[mesh]
shaft_elements = 6
# END NOTE after the last key
"""


def test_the_writer_puts_each_note_on_its_bearing():
    """Each bearing's note on the line of that bearing's key (the element found by counting
    [[bearings]] headers, the order tomllib gives the elements in), the trailing note kept."""
    base = loads_design(SMALL)
    design = with_overrides(base, {"bearings[1].kp": 3e6})
    text = design_toml(design, base=base, base_text=SMALL)
    names = [b["name"] for b in tomllib.loads(text)["bearings"]]
    element, where = -1, {}
    for line in text.splitlines():
        if line.startswith("[[bearings]]"):
            element += 1
        for note in ("LEFT NOTE", "AMB NOTE", "RIGHT NOTE"):
            if note in line and not line.startswith("#"):
                where[note] = (names[element], line.split("=", 1)[0].strip())
    assert where == {"LEFT NOTE": ("left", "x"), "AMB NOTE": ("amb", "kp"), "RIGHT NOTE": ("right", "x")}
    assert "# END NOTE after the last key" in text.splitlines()

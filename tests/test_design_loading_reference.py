"""Which design is loaded: the embedded designs by name, the default, a file with a byte-order
mark, and overrides on the element they name (flexshaft.design.io).

References:

* the packaged design files themselves, read with ``tomllib`` from the package folder by their
  documented file names (docs/thesis-reproduction.md: ``baseline`` is Table 3.1's study
  configuration, ``tuned`` the (60/-60/60/-60/0/0)s, 3.75 mm re-tuned design that every
  command analyses by default, docs/requirements.md "The embedded tuned design (every
  command's default)");
* a small design written here: a byte-order mark (U+FEFF, which Windows editors put first in a
  UTF-8 file) is not part of the document (Unicode Standard, section 23.8 "Specials": at the
  start of a UTF-8 text it only signals the encoding), so the file loads as the same text
  without it; an override ``bearings[1].kp`` sets the second ``[[bearings]]`` element's value
  (indices from 0, docs/design-reference.md and ``with_overrides``' docstring), every other
  value staying as written.

Loading and validating three small designs and the packaged ones (CPU: well under 0.5 s).
"""

from __future__ import annotations

import tomllib
from importlib import resources

import pytest

from flexshaft.design import baseline_design, embedded_design, load_design, loads_design, tuned_design, with_overrides

FILES = {"baseline": "baseline.toml", "tuned": "tuned.toml", "current": "current_driveline.toml"}


def _packaged(filename: str) -> dict:
    return tomllib.loads(resources.files("flexshaft.design").joinpath(filename).read_text(encoding="utf-8"))


@pytest.mark.parametrize("name", list(FILES))
def test_each_embedded_design_is_its_own_file(name):
    data = _packaged(FILES[name])
    design = embedded_design(name)
    assert design.name == data["name"]
    assert design.shaft.wall_thickness == data["shaft"]["wall_thickness"]
    assert [b.name for b in design.bearings] == [b["name"] for b in data["bearings"]]


def test_the_named_helpers_and_the_default_are_the_documented_designs():
    from flexshaft.cli.common import default_design

    tuned, baseline = _packaged("tuned.toml"), _packaged("baseline.toml")
    assert tuned["name"] != baseline["name"]
    assert tuned_design().name == tuned["name"] and baseline_design().name == baseline["name"]
    default = default_design().design  # what `flexshaft run` analyses without a design file
    assert default.name == tuned["name"]
    assert default.shaft.wall_thickness == 3.75e-3 and default.shaft.layup == "(60/-60/60/-60/0/0)s"


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
kind = "active"
x = 0.0
kp = 1e6
kd = 100.0
gap = 1.0e-3
[[bearings]]
name = "amb"
kind = "active"
x = 1.0
kp = 2e6
kd = 200.0
gap = 1.0e-3
[[bearings]]
name = "right"
kind = "active"
x = 2.0
kp = 4e6
kd = 400.0
gap = 1.0e-3
[operating]
speed_rpm = 6000.0
power = 0.0
[mesh]
shaft_elements = 6
"""


def test_a_file_with_a_byte_order_mark_is_the_same_design(tmp_path):
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + SMALL.encode("utf-8"))
    design = load_design(path)
    assert design == loads_design(SMALL)
    assert design.name == "two-bay rotor" and design.shaft.wall_thickness == 0.005


def test_an_override_sets_the_element_it_names():
    base = loads_design(SMALL)
    written = tomllib.loads(SMALL)["bearings"]
    changed = with_overrides(base, {"bearings[1].kp": 3e6, "bearings[0].kd": 150.0, "shaft.wall_thickness": 0.004})
    assert [b.kp for b in changed.bearings] == [written[0]["kp"], 3e6, written[2]["kp"]]
    assert [b.kd for b in changed.bearings] == [150.0, written[1]["kd"], written[2]["kd"]]
    assert changed.shaft.wall_thickness == 0.004 and base.shaft.wall_thickness == 0.005  # the base untouched

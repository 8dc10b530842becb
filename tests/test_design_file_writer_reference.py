"""The optimizer's design-file writer (flexshaft.optimize.files) against the values a user set.

Reference: a small design written by hand below, every value chosen here. The file the writer
produces is read back with the standard library's ``tomllib`` (not with flexshaft) and compared
key by key with those values: a design file is SI as docs/design-reference.md states (m, Pa,
N/m; ``speed_rpm`` in rpm as its name says), and the writer converts nothing, so each key must
hold exactly the number written in SMALL. TOML floats are IEEE doubles and the writer's text is
the shortest that reads back to the double (its docstring), so the comparison is exact (``==``):
any rounding is a different design.

The verified verdict (``verify_outputs``) is checked with the assessment replaced by a stand-in
whose checks hold values chosen here: each output must be the check its long name in
``VERIFY_OUTPUTS`` names (the verdict's check keys, flexshaft.verdict.checks: ``tsai_wu``,
``buckling``, ``actuator_force``, ``spinup_deflection``). No analysis runs (CPU: a few ms).
"""

from __future__ import annotations

import math
import tomllib
from types import SimpleNamespace

import flexshaft.optimize.files as files
from flexshaft.design import loads_design, with_overrides
from flexshaft.optimize.files import design_toml, write_design_file
from flexshaft.resolution import REPORT

#: A material name with a space and a dot: a bare TOML key would split it into nested tables.
MATERIAL = "steel 4340.q"

SMALL = f"""
name = "two-bay rotor"
[materials."{MATERIAL}"]
kind = "isotropic"
E = 212345000000.0
G = 81234000000.0
density = 7850.0
loss_factor = 0.002
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.05
wall_thickness = 0.005
material = "{MATERIAL}"
fixed_start = ["u", "theta"]
shear_deformation = true
[[bearings]]
name = "left"
kind = "contact"
x = 0.0
stiffness = {{ v = 5e7, w = 5e7 }}
[[bearings]]
name = "amb"
kind = "active"
x = 1.0
kp = 2e6
kd = 200.0
gap = 1.0e-3
[[bearings]]
name = "right"
kind = "contact"
x = 2.0
stiffness = {{ v = 6e7, w = 7e7 }}
[operating]
speed_rpm = 6000.0
power = 0.0
[loads]
eccentricity = 10e-6
[mesh]
shaft_elements = 6
"""

#: The values set in SMALL, by TOML path (units as docs/design-reference.md states them).
SET = {
    ("name",): "two-bay rotor",
    ("materials", MATERIAL, "E"): 212345000000.0,  # Pa: 2.12345e11 has 6 significant digits
    ("materials", MATERIAL, "G"): 81234000000.0,  # Pa
    ("materials", MATERIAL, "density"): 7850.0,  # kg/m^3
    ("shaft", "outer_diameter"): 0.05,  # m
    ("shaft", "wall_thickness"): 0.005,  # m
    ("shaft", "material"): MATERIAL,
    ("shaft", "shear_deformation"): True,
    ("bearings", 0, "name"): "left",
    ("bearings", 0, "x"): 0.0,  # m
    ("bearings", 0, "stiffness", "v"): 5e7,  # N/m
    ("bearings", 1, "name"): "amb",
    ("bearings", 1, "x"): 1.0,
    ("bearings", 1, "kp"): 2e6,  # N/m
    ("bearings", 1, "kd"): 200.0,  # N s/m
    ("bearings", 1, "gap"): 1.0e-3,  # m
    ("bearings", 2, "name"): "right",
    ("bearings", 2, "x"): 2.0,
    ("bearings", 2, "stiffness", "v"): 6e7,
    ("bearings", 2, "stiffness", "w"): 7e7,
    ("operating", "speed_rpm"): 6000.0,  # rpm, as the key says
    ("loads", "eccentricity"): 10e-6,  # m
    ("mesh", "shaft_elements"): 6,
}


def _at(data, path):
    for part in path:
        data = data[part]
    return data


def test_every_value_set_is_in_its_key_unrounded(tmp_path):
    design = loads_design(SMALL)
    path = write_design_file(design, tmp_path / "d.toml")
    with path.open("rb") as handle:
        data = tomllib.load(handle)
    for key, value in SET.items():
        assert _at(data, key) == value and type(_at(data, key)) is type(value), key
    assert list(data["materials"]) == [MATERIAL]  # one material, its name one key
    assert [b["name"] for b in data["bearings"]] == ["left", "amb", "right"]
    assert "kp" not in data["bearings"][0] and "stiffness" not in data["bearings"][1]


def test_a_multi_line_comment_stays_a_comment(tmp_path):
    """A header comment spanning lines (a verdict summary) must not become TOML: every line of
    it is a ``#`` line, and the file's values are the design's."""
    design = loads_design(SMALL)
    summary = 'FAIL: 2 of 9 requirements\nname = "not this design"\n[operating]\nspeed_rpm = 1.0'
    text = design_toml(design, ["written by a test", summary])
    data = tomllib.loads(text)
    assert data["name"] == "two-bay rotor" and data["operating"]["speed_rpm"] == 6000.0
    for line in summary.splitlines():
        assert f"# {line}" in text.splitlines()


def test_the_optimised_value_is_written_and_the_base_value_noted(tmp_path):
    """The base's wall is 0.005 m (SMALL); the optimised one 0.0035 m: the key holds 0.0035 and
    its note says it was 0.005; a key left alone has no note."""
    base = loads_design(SMALL)
    design = with_overrides(base, {"shaft.wall_thickness": 0.0035, "bearings[1].kp": 3.5e6})
    text = design_toml(design, base=base, base_text=SMALL)
    data = tomllib.loads(text)
    assert data["shaft"]["wall_thickness"] == 0.0035 and data["bearings"][1]["kp"] == 3.5e6
    assert data["bearings"][0]["x"] == 0.0 and data["shaft"]["outer_diameter"] == 0.05
    lines = text.splitlines()
    (wall,) = [line for line in lines if line.startswith("wall_thickness")]
    assert wall.split("#", 1)[1].strip().startswith("optimized: was ") and float(wall.split("was", 1)[1]) == 0.005
    (kp,) = [line for line in lines if line.startswith("kp")]
    assert kp.split("#", 1)[1].strip().startswith("optimized: was ") and float(kp.split("was", 1)[1]) == 2e6
    assert not [line for line in lines if line.startswith("outer_diameter") and "#" in line]


def test_the_verified_verdict_takes_each_output_from_its_check(monkeypatch):
    values = {"tsai_wu": 1.7, "buckling": 2.9, "actuator_force": 812.0, "spinup_deflection": 3.1e-4}
    seen = {}

    def check(key):
        return SimpleNamespace(value=values.get(key))

    verdict = SimpleNamespace(passed=False, failed=["a", "b"], not_evaluated=["c"], check=check)

    def fake_assess(design, resolution):
        seen["design"], seen["resolution"] = design, resolution
        return SimpleNamespace(verdict=verdict, model=SimpleNamespace(shaft_mass=4.25))

    monkeypatch.setattr(files, "assess", fake_assess)
    monkeypatch.setattr(files, "load_design", lambda path: f"design of {path}")
    out = files.verify_outputs(SimpleNamespace(axes={"design_file": "p1.toml"}))
    assert seen == {"design": "design of p1.toml", "resolution": REPORT}  # flexshaft run's resolution
    assert out == {
        "passed": 0.0,
        "n_failed": 2.0,
        "n_not_evaluated": 1.0,
        "shaft_mass": 4.25,
        "safety_factor": 1.7,
        "buckling_safety_factor": 2.9,
        "actuator_force": 812.0,
        "spinup_deflection": 3.1e-4,
    }
    assert [name for name, _, _ in files.VERIFY_OUTPUTS] == list(out)
    values.pop("spinup_deflection")  # a check without a value: nan, not 0
    assert math.isnan(files.verify_outputs(SimpleNamespace(axes={"design_file": "p2.toml"}))["spinup_deflection"])


def test_control_characters_in_a_name_are_escaped(tmp_path):
    """TOML v1.0.0 ("String"): a basic string must escape the control characters U+0000-U+0008,
    U+000A-U+001F and U+007F (DEL). A design whose name and material key hold each of them (a
    valid file writes them escaped, as ``\\u007f``) is written to a file that ``tomllib`` reads
    back to the same strings; and a comment may hold none of them either (TOML v1.0.0,
    "Comment"), so the name in the header comment must not make the file invalid. (Was: DEL
    written bare, and every control character bare in the header: an invalid file that
    ``write_design_file`` then failed to read back.)"""
    controls = "".join(chr(c) for c in [*range(1, 0x20), 0x7F])
    material = "steel" + controls
    text = SMALL.replace(MATERIAL, "steel" + "".join(f"\\u{ord(c):04x}" for c in controls))
    design = with_overrides(loads_design(text), {"name": "rotor" + controls})
    assert design.name == "rotor" + controls and list(design.materials) == [material]
    # the optimizer's header names the base design: in a comment, which may not hold them either
    path = write_design_file(design, tmp_path / "d.toml", [f"Base design: {design.name}", "kept"])
    with path.open("rb") as handle:
        data = tomllib.load(handle)
    assert data["name"] == "rotor" + controls and "# kept" in path.read_text(encoding="utf-8").splitlines()
    assert list(data["materials"]) == [material] and data["shaft"]["material"] == material


def test_a_text_that_does_not_load_back_is_never_written(tmp_path, monkeypatch):
    """The writer checks its text before the file exists: a text that is not valid TOML (a bare
    DEL, TOML v1.0.0 "String") or that loads to another design (the baseline's text for the
    tuned design) raises, and the output folder stays empty."""
    import pytest

    from flexshaft.design import DesignError, baseline_text, tuned_design

    target = tmp_path / "pareto_01.toml"
    monkeypatch.setattr(files, "design_toml", lambda *args, **kwargs: 'name = "a\x7fb"\n')
    with pytest.raises(DesignError):
        write_design_file(tuned_design(), target)
    assert not target.exists() and not list(tmp_path.iterdir())
    monkeypatch.setattr(files, "design_toml", lambda *args, **kwargs: baseline_text())
    with pytest.raises(RuntimeError, match="does not load back to the same design"):
        write_design_file(tuned_design(), target)
    assert not list(tmp_path.iterdir())

"""Design-file schema: the baseline loads, and every documented refusal names field and value."""

from __future__ import annotations

import math
import pickle
import re
import tomllib
from pathlib import Path

import pytest
from pydantic import ValidationError

from flexshaft.design import (
    Design,
    DesignError,
    baseline_design,
    baseline_text,
    design_from_dict,
    load_design,
    loads_design,
    with_overrides,
)
from flexshaft.design.schema import ActiveBearing, ContactBearing, Isotropic, Lamina
from flexshaft.units import rpm_to_rad_s

BASELINE = baseline_text()


def refusal(text: str) -> DesignError:
    with pytest.raises(DesignError) as info:
        loads_design(text)
    return info.value


def edit(old: str, new: str, count: int = 1) -> str:
    """The baseline text with one exact fragment replaced (the fragment must exist)."""
    assert old in BASELINE, old
    return BASELINE.replace(old, new, count)


def without_tailboom(text: str = BASELINE) -> str:
    """Drop [tailboom], [tailboom.end_mass] and the point load on the end mass."""
    start = text.index("[tailboom]")
    end = text.index("# ----", start)
    text = text[:start] + text[end:]
    start = text.index("[[loads.point]]")
    end = text.index("# ----", start)
    return text[:start] + text[end:]


# ------------------------------------------------------------------------------------------------
# The baseline


def test_baseline_loads_with_thesis_values() -> None:
    design = baseline_design()
    assert isinstance(design, Design)
    assert design.operating.speed_rad_s == pytest.approx(4800.0 * 2.0 * math.pi / 60.0, rel=1e-15)
    assert design.operating.power == 246.0e3
    assert design.operating.torque == pytest.approx(246.0e3 / (4800.0 * 2.0 * math.pi / 60.0))
    assert design.shaft.ply_angles_deg == (55.0, -55.0, 0.0, 0.0, 0.0, 0.0, -55.0, 55.0)
    assert design.shaft.outer_diameter == 0.1016
    assert design.shaft.wall_thickness == 0.003
    assert design.shaft.inner_diameter == pytest.approx(0.0956)
    assert (design.shaft.x_start, design.shaft.x_end) == (0.0, 8.05)
    assert design.shaft.fixed_start == ("theta",)
    assert design.shaft.fixed_end == ()
    assert design.shaft.shear_deformation is False

    ply = design.shaft_material
    assert isinstance(ply, Lamina)
    assert (ply.E_L, ply.E_T, ply.G_LT, ply.nu_LT) == (115.0e9, 0.10e9, 0.10e9, 0.35)
    assert (ply.loss_E_L, ply.loss_E_T, ply.loss_G_LT) == (3.0e-4, 0.12, 0.12)
    assert (ply.X_t, ply.X_c, ply.Y_t, ply.Y_c, ply.S) == (2185.0e6, 2000.0e6, 5.1e6, 5.5e6, 20.0e6)
    assert ply.F12 is None
    assert isinstance(design.materials["al6061_t6"], Isotropic)

    boom = design.tailboom
    assert boom is not None and boom.end_mass is not None
    assert boom.length == 8.05 and boom.wall_thickness == 0.0045
    assert boom.root_semi_axes == (0.50, 0.40) and boom.tip_semi_axes == (0.25, 0.20)
    assert boom.semi_axes_at(8.05) == pytest.approx((0.25, 0.20))
    assert boom.shaft_offset_at(0.0) == pytest.approx(0.58)
    assert boom.end_mass.mass == 200.0 and boom.end_mass.offset == (0.0, 1.0, 0.0)
    assert design.tailboom_material is design.materials["boom_aluminium"]
    assert design.tailboom_material.density == 5000.0

    assert [b.name for b in design.bearings] == ["hanger_forward", "amb_1", "amb_2", "hanger_aft"]
    assert [b.x for b in design.bearings] == [0.79, 3.21, 5.63, 8.05]
    forward, amb_1, _, aft = design.bearings
    assert isinstance(forward, ContactBearing) and isinstance(amb_1, ActiveBearing)
    assert forward.stiffness == {"u": 1e8, "v": 1e8, "w": 1e8}
    assert aft.stiffness == {"u": 1e8, "v": 1e8, "w": 1e8} and aft.damping is None
    assert aft.stiffness_of("beta") == 0.0 and aft.stiffness_of("w") == 1e8 and aft.damping_of("v") == 0.0
    assert forward.boom_x == 0.79 and forward.offset is None
    assert (amb_1.kp, amb_1.kd, amb_1.controller) == (1.0e7, 0.0, None)
    assert amb_1.transfer_function() == ((0.0, 1.0e7), (1.0,))
    assert design.bearing("amb_2").x == 5.63

    assert design.loads.eccentricity == 18.2e-6
    assert design.loads.imbalance_placement == "mid_bay"
    assert design.loads.load_factor == (0.0, -3.5, 0.0)
    (thrust,) = design.loads.point
    assert (thrust.on, thrust.x, thrust.force, thrust.moment) == ("end_mass", None, (0.0, 0.0, 5000.0), (0.0,) * 3)
    assert (design.mesh.shaft_elements, design.mesh.boom_elements) == (36, 24)
    assert design.disks == ()


def test_baseline_text_is_the_packaged_file(tmp_path: Path) -> None:
    packaged = Path(__file__).parents[1] / "src" / "flexshaft" / "design" / "baseline.toml"
    if packaged.exists():  # running from the source tree
        assert BASELINE == packaged.read_text(encoding="utf-8")
    copy = tmp_path / "design.toml"
    copy.write_text(BASELINE, encoding="utf-8")
    assert load_design(copy) == baseline_design()
    assert load_design(str(copy)) == baseline_design()


def test_models_are_frozen() -> None:
    design = baseline_design()
    with pytest.raises(ValidationError, match="frozen"):
        design.shaft.wall_thickness = 0.002  # type: ignore[misc]


def test_design_without_tailboom_validates() -> None:
    design = loads_design(without_tailboom())
    assert design.tailboom is None and design.tailboom_material is None
    assert len(design.bearings) == 4


def test_aluminium_shaft_without_layup_validates() -> None:
    text = edit('material = "t700_adiprene"', 'material = "al6061_t6"').replace('layup = "(55/-55/0/0)s"', "")
    design = loads_design(text)
    assert design.shaft.ply_angles_deg == ()
    assert isinstance(design.shaft_material, Isotropic)
    assert design.shaft_material.poisson_ratio == pytest.approx(68.9 / 52.0 - 1.0)


def test_controller_replaces_pd_gains() -> None:
    text = edit(
        "kp = 1.0e7                # N/m, thesis Table 3.1\nkd = 0.0                  # N s/m",
        "controller = { numerator = [2.0e4, 1.0e7], denominator = [1.0e-4, 1.0] }",
    )
    bearing = loads_design(text).bearings[1]
    assert isinstance(bearing, ActiveBearing)
    assert (bearing.kp, bearing.kd) == (None, None)
    assert bearing.transfer_function() == ((2.0e4, 1.0e7), (1.0e-4, 1.0))


def test_speed_in_rad_s_and_integers_for_floats() -> None:
    design = loads_design(edit("speed_rpm = 4800.0", "speed = 500"))
    assert design.operating.speed_rad_s == 500.0 and isinstance(design.operating.speed, float)


def test_optional_tables_take_defaults() -> None:
    data = tomllib.loads(BASELINE)
    del data["mesh"], data["loads"]
    design = design_from_dict(data)
    assert (design.mesh.shaft_elements, design.mesh.boom_elements) == (36, 24)
    assert design.loads.eccentricity == 0.0 and design.loads.point == ()


# ------------------------------------------------------------------------------------------------
# Refusals: each names the field path and the offending value

REFUSALS = {
    "unknown top-level key": (lambda: 'colour = "red"\n' + BASELINE, "colour: unknown key", '"red"'),
    "unknown nested key": (
        lambda: edit("fixed_end = []", "fixed_end = []\ncolour = 7"),
        "shaft.colour: unknown key",
        "got 7",
    ),
    "unknown key in an inline table": (
        lambda: edit("w = 1.0e8 }   # axially fixed too", "w = 1.0e8, theta = 5.0 }   # axially fixed too"),
        "bearings[3].stiffness.theta: unknown key",
        "(got 5.0; allowed: u, v, w, beta, gamma)",
    ),
    "unknown key in a material": (
        lambda: edit("G_LT = 0.10e9", "G_LT = 0.10e9\nG_TT = 3.0e7"),
        "materials.t700_adiprene.G_TT: unknown key",
        "got 30000000.0",
    ),
    "negative thickness": (
        lambda: edit("wall_thickness = 0.003 ", "wall_thickness = -0.003 "),
        "shaft.wall_thickness: must be > 0",
        "got -0.003",
    ),
    "wall thicker than the radius": (
        lambda: edit("wall_thickness = 0.003 ", "wall_thickness = 0.06 "),
        "shaft.wall_thickness: must be less than outer_diameter/2 = 0.0508 m",
        "got 0.06",
    ),
    "ply angle 95": (
        lambda: edit('"(55/-55/0/0)s"', '"(95/-55/0/0)s"'),
        "shaft.layup: ply angle 95 deg is outside [-90, 90] deg",
        '"(95/-55/0/0)s"',
    ),
    "bad layup syntax": (
        lambda: edit('"(55/-55/0/0)s"', '"(55/-55/0/0"'),
        "shaft.layup: expected ')'",
        '"(55/-55/0/0"',
    ),
    "bearing off the shaft": (
        lambda: edit("x = 5.63", "x = 9.1"),
        "bearings[2].x: 9.1 is outside the shaft [0, 8.05] m",
        "9.1",
    ),
    "bearing off the boom": (
        lambda: edit("x = 5.63", "x = 5.63\nx_boom = 8.5"),
        "bearings[2].x_boom: boom station 8.5 is outside the tailboom [0, 8.05] m",
        "8.5",
    ),
    "NaN": (
        lambda: edit("E_L = 115.0e9", "E_L = nan"),
        "materials.t700_adiprene.E_L: must be a finite number",
        "got nan",
    ),
    "infinity": (
        lambda: edit("eccentricity = 18.2e-6", "eccentricity = inf"),
        "loads.eccentricity: must be a finite number",
        "got inf",
    ),
    "missing material": (
        lambda: edit('material = "t700_adiprene"', 'material = "t800_epoxy"'),
        "shaft.material: names no material in [materials]",
        '"t800_epoxy"',
    ),
    "speed_rpm and speed both given": (
        lambda: edit("speed_rpm = 4800.0", "speed_rpm = 4800.0\nspeed = 502.0"),
        "operating.speed_rpm: give exactly one of speed_rpm [rev/min] or speed [rad/s]",
        "speed = 502.0",
    ),
    "lamina tailboom": (
        lambda: edit('material = "boom_aluminium"', 'material = "t700_adiprene"'),
        "tailboom.material: must name an isotropic material",
        '"t700_adiprene"',
    ),
    "controller with kp": (
        lambda: edit("kd = 0.0                  # N s/m", "controller = { numerator = [1.0e7], denominator = [1.0] }"),
        "bearings[1].kp: must be omitted when a controller is given",
        "got 10000000.0",
    ),
    "improper controller": (
        lambda: edit(
            "kp = 1.0e7                # N/m, thesis Table 3.1\nkd = 0.0                  # N s/m",
            "controller = { numerator = [1.0, 2.0, 3.0], denominator = [1.0, 1.0] }",
        ),
        "bearings[1].controller.numerator: degree 2 exceeds the denominator degree 1",
        "[1.0, 2.0, 3.0]",
    ),
    "string for a float": (
        lambda: edit("power = 246.0e3", 'power = "3"'),
        "operating.power: must be a number",
        '"3", a string',
    ),
    "boolean for a float": (
        lambda: edit("density = 2700.0", "density = true"),
        "materials.al6061_t6.density: must be a number",
        "true, a boolean",
    ),
    "number for a boolean": (
        lambda: edit("shear_deformation = false", "shear_deformation = 0"),
        "shaft.shear_deformation: must be true or false",
        "got 0",
    ),
    "float for an integer": (
        lambda: edit("shaft_elements = 36", "shaft_elements = 36.5"),
        "mesh.shaft_elements: must be an integer",
        "got 36.5",
    ),
    "unknown bearing kind": (
        lambda: edit('kind = "contact"', 'kind = "roller"'),
        "bearings[0].kind: unknown kind",
        '"roller"',
    ),
    "vector of two": (
        lambda: edit("offset = [0.0, 1.0, 0.0]", "offset = [0.0, 1.0]"),
        "tailboom.end_mass.offset: must have exactly 3 values",
        "[0.0, 1.0]",
    ),
    "unknown imbalance placement": (
        lambda: edit('imbalance_placement = "mid_bay"', 'imbalance_placement = "middle"'),
        "loads.imbalance_placement: unknown value",
        '"middle"',
    ),
    "duplicate bearing name": (
        lambda: edit('name = "amb_2"', 'name = "amb_1"'),
        "bearings[2].name: duplicate name",
        '"amb_1"',
    ),
    "unknown fixed dof": (
        lambda: edit('fixed_start = ["theta"]', 'fixed_start = ["theta", "phi"]'),
        "shaft.fixed_start[1]: unknown value",
        '"phi"',
    ),
    "poisson ratio above one half": (
        lambda: edit("G = 26.0e9", "G = 20.0e9"),
        "materials.al6061_t6.G: gives Poisson ratio E/(2G) - 1 = 0.7225",
        "got 20000000000.0",
    ),
    "shaft ends reversed": (
        lambda: edit("x_end = 8.05 ", "x_end = -0.5 "),
        "shaft.x_end: must be greater than x_start = 0 m",
        "got -0.5",
    ),
    "layup with an isotropic shaft": (
        lambda: edit('material = "t700_adiprene"', 'material = "al6061_t6"'),
        "shaft.layup: must be omitted for the isotropic material",
        '"(55/-55/0/0)s"',
    ),
    "missing required key": (
        lambda: edit("outer_diameter = 0.1016", "# outer_diameter"),
        "shaft.outer_diameter: required key is missing",
        "expected a number",
    ),
    "too many elements": (
        lambda: edit("boom_elements = 24", "boom_elements = 20000"),
        "mesh.boom_elements: must be <= 2000",
        "got 20000",
    ),
    "indefinite transverse shear modulus": (
        lambda: edit("S = 20.0e6 ", "G_23 = 1.0e7\nS = 20.0e6 "),
        "materials.t700_adiprene.G_23: must exceed E_T/(4 (1 - nu_LT nu_TL)) = 2.50027e+07 Pa",
        "got 10000000.0",
    ),
    "shear correction above one": (
        lambda: edit("S = 20.0e6 ", "shear_correction = 1.2\nS = 20.0e6 "),
        "materials.t700_adiprene.shear_correction: must be <= 1",
        "got 1.2",
    ),
    "thermal expansion in ppm": (
        lambda: edit("S = 20.0e6 ", "alpha_T = 110.0\nS = 20.0e6 "),
        "materials.t700_adiprene.alpha_T: must be a thermal expansion coefficient in 1/K",
        "got 110.0",
    ),
}


@pytest.mark.parametrize("case", REFUSALS, ids=list(REFUSALS))
def test_refusal_names_field_and_value(case: str) -> None:
    make_text, expected_start, expected_value = REFUSALS[case]
    error = refusal(make_text())
    lines = str(error).splitlines()
    matching = [line for line in lines if line.startswith(expected_start)]
    assert matching, f"no line starts with {expected_start!r} in:\n{error}"
    assert any(expected_value in line for line in matching), str(error)
    assert all(problem.path and problem.message for problem in error.problems)


def test_every_problem_is_listed_one_per_line() -> None:
    text = edit("wall_thickness = 0.003 ", "wall_thickness = -1.0 ").replace("E_L = 115.0e9", "E_L = nan")
    text = text.replace("power = 246.0e3", 'power = "x"')
    lines = str(refusal(text)).splitlines()
    assert len(lines) == 3
    assert {line.split(":")[0] for line in lines} == {
        "shaft.wall_thickness",
        "materials.t700_adiprene.E_L",
        "operating.power",
    }
    assert all(re.fullmatch(r"\S+: .+ \(got .+\)", line) for line in lines)


def test_end_mass_load_needs_a_tailboom() -> None:
    start = BASELINE.index("[tailboom]")
    end = BASELINE.index("# ----", start)
    error = refusal(BASELINE[:start] + BASELINE[end:])
    assert str(error).startswith('loads.point[0].on: is "end_mass" but the design has no [tailboom.end_mass]')


def test_x_boom_without_tailboom_is_refused() -> None:
    text = without_tailboom(edit("x = 5.63", "x = 5.63\nx_boom = 5.0"))
    assert "bearings[2].x_boom: must be omitted when the design has no [tailboom] (got 5.0)" in str(refusal(text))


def test_at_least_one_bearing() -> None:
    data = tomllib.loads(BASELINE)
    data["bearings"] = []
    with pytest.raises(DesignError, match=r"bearings: must have at least 1 items"):
        design_from_dict(data)


def test_file_problems_are_design_errors(tmp_path: Path) -> None:
    with pytest.raises(DesignError, match="no such design file"):
        load_design(tmp_path / "missing.toml")
    with pytest.raises(DesignError, match="is a directory"):
        load_design(tmp_path)
    binary = tmp_path / "binary.toml"
    binary.write_bytes(b'name = "x"\n\xff\xfe\n')
    with pytest.raises(DesignError, match=r"binary.toml: not UTF-8 text: invalid byte 0xff at line 2"):
        load_design(binary)
    broken = tmp_path / "broken.toml"
    broken.write_text(BASELINE.replace("power = 246.0e3", "power = 246 kW"), encoding="utf-8")
    with pytest.raises(DesignError, match=r"broken.toml: TOML syntax error: .*line \d+, column \d+"):
        load_design(broken)
    with pytest.raises(DesignError, match=r"TOML syntax error"):
        loads_design("[shaft\n")


# ------------------------------------------------------------------------------------------------
# Overrides


def test_with_overrides_returns_a_new_validated_design() -> None:
    design = baseline_design()
    changed = with_overrides(
        design,
        {
            "shaft.wall_thickness": 0.002,
            "bearings[1].kp": 2e6,
            "shaft.layup": "(45/-45)s",
            "materials.t700_adiprene.E_L": 120e9,
            "loads.load_factor[1]": -2.0,
            "operating.speed_rpm": 3000,
        },
    )
    assert isinstance(changed, Design)
    assert changed.shaft.wall_thickness == 0.002
    assert changed.bearings[1].kp == 2e6 and changed.bearings[2].kp == 1e7
    assert changed.shaft.ply_angles_deg == (45.0, -45.0, -45.0, 45.0)
    assert changed.materials["t700_adiprene"].E_L == 120e9  # type: ignore[union-attr]
    assert changed.loads.load_factor == (0.0, -2.0, 0.0)
    assert changed.operating.speed_rad_s == pytest.approx(rpm_to_rad_s(3000.0))
    assert design == baseline_design(), "the original design must be left unchanged"
    assert with_overrides(design, {}) == design


def test_with_overrides_accepts_numpy_values() -> None:
    numpy = pytest.importorskip("numpy")
    changed = with_overrides(
        baseline_design(),
        {
            "shaft.wall_thickness": numpy.float64(0.004),
            "mesh.shaft_elements": numpy.int64(40),
            "loads.load_factor": numpy.array([0.0, -1.0, 0.0]),
        },
    )
    assert (changed.shaft.wall_thickness, changed.mesh.shaft_elements) == (0.004, 40)
    assert changed.loads.load_factor == (0.0, -1.0, 0.0)


def test_with_overrides_can_remove_an_optional_table() -> None:
    changed = with_overrides(baseline_design(), {"tailboom": None, "loads.point": []})
    assert changed.tailboom is None


@pytest.mark.parametrize(
    ("overrides", "expected"),
    [
        ({"shaft.wall_thickness": -0.002}, "shaft.wall_thickness: must be > 0 (got -0.002)"),
        ({"bearings[1].kp": "big"}, 'bearings[1].kp: must be a number (got "big", a string)'),
        ({"shaft.wal_thickness": 0.002}, "shaft.wal_thickness: unknown key (got 0.002; allowed: x_start"),
        ({"shaf.wall_thickness": 0.002}, 'shaf.wall_thickness: no such key "shaf" in the design'),
        ({"bearings[7].kp": 1.0}, "bearings[7].kp: index 7 is out of range (bearings has 4 items)"),
        ({"shaft[0]": 1.0}, "shaft[0]: shaft is not a list"),
        ({"bearings..kp": 1.0}, "bearings..kp: malformed override path"),
        ({"": 1.0}, '"": malformed override path'),
        ({"tailboom.end_mass.mass": float("nan")}, "tailboom.end_mass.mass: must be a finite number (got nan)"),
    ],
)
def test_bad_overrides_name_the_path(overrides: dict[str, object], expected: str) -> None:
    with pytest.raises(DesignError) as info:
        with_overrides(baseline_design(), overrides)
    assert str(info.value).startswith(expected), str(info.value)


def test_override_into_absent_table() -> None:
    no_boom = loads_design(without_tailboom())
    with pytest.raises(DesignError, match=r"tailboom.length: tailboom is not present in this design"):
        with_overrides(no_boom, {"tailboom.length": 9.0})


# ------------------------------------------------------------------------------------------------
# Layup notation


def test_design_error_survives_pickling() -> None:
    error = refusal(edit("wall_thickness = 0.003 ", "wall_thickness = -0.003 "))
    copy = pickle.loads(pickle.dumps(error))
    assert isinstance(copy, DesignError) and isinstance(copy, ValueError)
    assert (copy.problems, copy.source, str(copy)) == (error.problems, error.source, str(error))

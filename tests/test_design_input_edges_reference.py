"""The design file's inputs at the edges the documentation states, as they reach the physics.

Each case edits a packaged design and only validates it (no model is built): milliseconds each.
References, read from the documentation, not from the code's output:

* docs/design-reference.md ``[mesh]`` and ``[analysis]`` rows: ``shaft_elements`` defaults to
  36, ``boom_elements`` to 24, ``internal_damping`` to ``"rotating"``;
* a bearing's boom station ``x_boom`` (default ``x``) lies on the tailboom [0, length], both
  ends included (the packaged baseline's aft hanger sits at the 8.05 m boom's tip); a sensor's
  boom station ``x_boom + sensor_offset`` lies on it too (docs/magnetic-bearings.md), and a
  bearing's ``offset`` needs a tailboom (docs/design-reference.md: "Only with a tailboom"); a
  coupling's station is strictly inside the shaft and no two couplings share one (their order
  in the file is not restricted); a disk, like a bearing, sits on one side of a joint,
  not at its station (docs/segmented-driveline.md);
* a segment without a material of its own inherits the ``[shaft]`` material and may give its
  own layup when that material is a lamina (a metal takes none); a shaft cut by couplings is
  segmented even when it is one tube (``Design.segmented``, docs/segmented-driveline.md);
* ``[materials.<name>.temperature_table]`` (docs/thermal.md): the table must span the matrix
  reference temperature and reach the allowable temperature (its last row may be the
  allowable itself); rows lie in (−273.15, 400] °C and a loss factor in the open (0, 1)
  (docs/design-reference.md, the table's ``temperature_c`` and ``loss_*`` rows);
  the optional ``E_L`` column makes the fibre modulus vary (exact at a row);
* an ``[envelope]`` point with ``material_temperature = "ambient"`` and no ambient of its own
  puts the shaft at ``[thermal] ambient_temperature_c``, which must lie in the tables;
* :func:`~flexshaft.design.with_overrides` accepts numpy scalars, the extended-precision
  ``np.longdouble`` among them, as their float values (its docstring).
"""

from __future__ import annotations

import numpy as np

from flexshaft.design import DesignError, loads_design, tuned_design, with_overrides
from flexshaft.design.io import embedded_text
from flexshaft.thermal.matrix import LaminaTable
from flexshaft.units import celsius_to_kelvin

TUNED = tuned_design()
TABLE = "materials.t700_adiprene.temperature_table"
RIGID = {"angular_stiffness": "rigid", "axial_stiffness": "rigid", "torsional_stiffness": "rigid"}


def _problems(overrides: dict, design=TUNED) -> list[str]:
    """The refusal's lines, or [] when the edited design validates."""
    try:
        with_overrides(design, overrides)
    except DesignError as exc:
        return str(exc).strip().splitlines()
    return []


def _refused_at(overrides: dict, path: str, design=TUNED) -> bool:
    return any(line.startswith(f"{path}:") for line in _problems(overrides, design))


def _without_table(text: str, header: str) -> str:
    """The design text without the table ``[header]`` (up to the next table header)."""
    start = text.index(f"\n[{header}]\n") + 1
    end = text.find("\n[", start + 1)
    return text[:start] + ("" if end < 0 else text[end + 1 :])


def test_defaults_of_mesh_and_analysis_are_the_documented_ones() -> None:
    text = _without_table(_without_table(embedded_text("tuned"), "mesh"), "analysis")
    design = loads_design(text)
    assert (design.mesh.shaft_elements, design.mesh.boom_elements) == (36, 24)
    assert design.analysis.internal_damping == "rotating"


def test_bearing_boom_station_at_the_boom_tip_and_read_from_x_boom() -> None:
    assert TUNED.tailboom is not None and TUNED.tailboom.length == 8.05
    assert _problems({"bearings[3].x_boom": 8.05}) == []  # the tip, end included
    assert _refused_at({"bearings[3].x_boom": 8.06}, "bearings[3].x_boom")
    # a 7 m boom: the aft hanger at shaft station 8.05 is mounted at boom station 7.0 (its tip)
    assert _problems({"tailboom.length": 7.0, "bearings[3].x_boom": 7.0}) == []
    assert _refused_at({"tailboom.length": 7.0}, "bearings[3].x")  # x_boom defaults to x = 8.05


def _coupling(name: str, x: float) -> dict:
    return {"name": name, "x": x, **RIGID}


def test_couplings_in_any_order_but_not_at_one_station() -> None:
    assert _problems({"couplings": [_coupling("aft", 5.0), _coupling("fwd", 2.0)]}) == []
    assert _problems({"couplings": [_coupling("fwd", 2.0), _coupling("aft", 5.0)]}) == []
    assert _refused_at({"couplings": [_coupling("a", 2.0), _coupling("b", 2.0)]}, "couplings[1].x")


def test_disk_at_a_coupling_station_is_refused() -> None:
    disk = {"name": "flange", "x": 2.0, "mass": 1.0}
    assert _refused_at({"couplings": [_coupling("joint", 2.0)], "disks": [disk]}, "disks[0].x")
    assert _problems({"couplings": [_coupling("joint", 2.0)], "disks": [dict(disk, x=2.1)]}) == []


def test_one_tube_cut_by_a_coupling_is_segmented() -> None:
    assert not TUNED.segmented
    cut = with_overrides(TUNED, {"couplings": [_coupling("joint", 4.0)]})
    assert len(cut.shaft.tubes) == 1 and cut.segmented


def test_segment_layup_on_an_inherited_lamina_is_accepted() -> None:
    segments = [
        {"name": "fwd", "x_start": 0.0, "x_end": 4.0},
        {"name": "aft", "x_start": 4.0, "x_end": 8.05, "layup": "(45/-45)s"},
    ]
    design = with_overrides(TUNED, {"shaft.segments": segments})
    assert design.shaft.tubes[1].layup == "(45/-45)s"
    assert design.shaft.tubes[0].layup == TUNED.shaft.layup


def test_temperature_table_must_span_the_reference_and_may_end_at_the_allowable() -> None:
    rows = TUNED.materials["t700_adiprene"].temperature_table.temperature_c
    assert (rows[0], rows[-1]) == (-60.0, 120.0)
    # the reference below the first row: refused, though the allowable (100) lies inside
    assert _refused_at({"thermal.matrix_reference_temperature_c": -70.0}, f"{TABLE}.temperature_c")
    assert _problems({"thermal.allowable_temperature_c": 120.0}) == []  # the last row itself
    assert _refused_at({"thermal.allowable_temperature_c": 120.5}, f"{TABLE}.temperature_c")


def _table_with_row(temperature: float, loss: float = 0.7) -> dict:
    table = TUNED.materials["t700_adiprene"].temperature_table
    return {
        TABLE: {
            "temperature_c": [*table.temperature_c, temperature],
            "E_T": [*table.E_T, 5e6],
            "G_LT": [*table.G_LT, 5e6],
            "loss_E_T": [*table.loss_E_T, loss],
            "loss_G_LT": [*table.loss_G_LT, loss],
        }
    }


def test_table_rows_up_to_400_celsius_and_loss_factors_below_one() -> None:
    assert _problems(_table_with_row(250.0)) == []
    assert _problems(_table_with_row(400.0)) == []
    assert _refused_at(_table_with_row(400.5), f"{TABLE}.temperature_c[10]")
    assert _problems(_table_with_row(250.0, loss=0.999)) == []
    assert _refused_at(_table_with_row(250.0, loss=1.0), f"{TABLE}.loss_E_T[10]")


def test_fibre_modulus_column_varies_with_temperature() -> None:
    """E_L given at each row: LaminaTable returns the row's value exactly at its temperature."""
    rows = TUNED.materials["t700_adiprene"].temperature_table.temperature_c
    e_l = [115e9 * (1.0 - 0.001 * i) for i in range(len(rows))]
    design = with_overrides(TUNED, {f"{TABLE}.E_L": e_l})
    table = LaminaTable.from_schema(design.materials["t700_adiprene"].temperature_table)
    assert table.at(celsius_to_kelvin(120.0))["E_L"] == e_l[-1]


def test_envelope_ambient_point_uses_the_thermal_ambient() -> None:
    point = {"name": "parked", "material_temperature": "ambient"}
    # ambient -70 degC lies below the table's -60: the point is refused (the reference, 20, is inside)
    overrides = {"envelope": {"points": [point]}, "thermal.ambient_temperature_c": -70.0}
    assert _refused_at(overrides, "envelope.points[0].ambient_temperature_c")
    assert _problems({"envelope": {"points": [point]}, "thermal.ambient_temperature_c": -50.0}) == []


def test_longdouble_override_is_its_float_value() -> None:
    design = with_overrides(TUNED, {"shaft.wall_thickness": np.longdouble("0.0025")})
    # decimal -> long double -> double: two roundings, each within half an ulp of 2.5e-3 (4.3e-19)
    assert abs(design.shaft.wall_thickness - 0.0025) <= 1e-18
    # (where np.longdouble is a double, as on Windows or arm64 macOS, the value is a Python float
    # before the override sees it: this still passes, and the mutation it guards is caught on
    # x86-64 Linux, CI's platform)


def test_sensor_boom_station_lies_on_the_boom() -> None:
    """A 5.7 m boom: amb_2 at x = x_boom = 5.63 with its sensor 0.1 m aft reads boom station
    5.73, beyond the tip; 0.05 m aft (5.68) is on the boom (the aft hanger mounted at the tip)."""
    short = {"tailboom.length": 5.7, "bearings[3].x_boom": 5.7}
    assert TUNED.bearings[2].name == "amb_2" and TUNED.bearings[2].x == 5.63
    assert _problems({**short, "bearings[2].sensor_offset": 0.05}) == []
    assert _refused_at({**short, "bearings[2].sensor_offset": 0.1}, "bearings[2].sensor_offset")


def test_bearing_height_needs_a_tailboom() -> None:
    """`offset` is the shaft's height above the boom's neutral axis: without a boom it means
    nothing and is refused (the hanger of a boomless design joins the ground)."""
    boomless = {"tailboom": None, "loads.point": [], "envelope": None}
    assert _problems(boomless) == []
    assert _refused_at({**boomless, "bearings[0].offset": 0.1}, "bearings[0].offset")

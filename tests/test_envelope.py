"""The operating envelope: the ``[envelope]`` schema and the design at each of its points
(flexshaft.thermal.envelope.point_conditions + flexshaft.design.points.design_at_point)."""

from __future__ import annotations

import math

import pytest

from flexshaft.design import DesignError, baseline_design, embedded_design, tuned_design, with_overrides
from flexshaft.design.envelope import DEFAULT_ENVELOPE_POINTS, Envelope, EnvelopePoint
from flexshaft.design.points import design_at_point
from flexshaft.strength import compressive_strength
from flexshaft.thermal.envelope import envelope_conditions, point_conditions
from flexshaft.thermal.options import environment_from, matrix_law_from
from flexshaft.thermal.tailboom import boom_equivalent_diameter, tailboom_temperature
from flexshaft.units import celsius_to_kelvin, kelvin_to_celsius


@pytest.fixture(scope="module")
def design():
    return tuned_design()


def at(design, point):
    conditions = point_conditions(design, point)
    return conditions, design_at_point(design, point, conditions)


# ------------------------------------------------------------------------------------------------
# Schema


def test_default_envelope_and_the_packaged_files_agree(design):
    """An [envelope] without points holds the three documented points (a design without one is
    judged at its own operating point: design.envelope is None); the baseline file spells them
    out; the tuned file adds the hot day at full power and runs the hot-soak start on the ground
    (75 kW, about 30 % of the power; 1 g of the 3.5 g)."""
    assert [p.name for p in Envelope().points] == ["cold_day", "standard_day", "hot_soak_start"]
    assert baseline_design().envelope == Envelope()
    assert [p.name for p in design.envelope.points] == ["cold_day", "standard_day", "hot_day", "hot_soak_start"]
    cold_day, standard_day, hot_day, hot_soak = design.envelope.points
    assert (cold_day, standard_day) == DEFAULT_ENVELOPE_POINTS[:2]
    assert (hot_day.ambient_temperature_c, hot_day.material_temperature, hot_day.power) == (None, "shaft_air", None)
    assert hot_soak.material_temperature == "parked" and hot_soak.power == pytest.approx(
        0.3 * design.operating.power, rel=0.02
    )
    assert hot_soak.load_scale == pytest.approx(1.0 / 3.5, rel=1e-9)
    cold, standard, hot = DEFAULT_ENVELOPE_POINTS
    assert (cold.ambient_temperature_c, cold.material_temperature) == (-40.0, "ambient")
    assert (standard.ambient_temperature_c, standard.material_temperature) == (15.0, "shaft_air")
    assert (hot.ambient_temperature_c, hot.material_temperature) == (None, "parked")


@pytest.mark.parametrize(
    "override, message",
    [
        ({"envelope.points[1].name": "cold_day"}, r"envelope\.points\[1\]\.name: duplicate name"),
        (
            {"envelope.points[0].material_temperature": "given"},
            r"envelope\.points\[0\]\.material_temperature_c: required",
        ),
        ({"envelope.points[0].material_temperature_c": 10.0}, r'must be omitted unless material_temperature = "given"'),
        ({"envelope.points[0].material_temperature": "oven"}, r"envelope\.points\[0\]\.material_temperature"),
        ({"envelope.points[0].load_scale": -1.0}, r"envelope\.points\[0\]\.load_scale"),
        ({"envelope.points": []}, r"envelope\.points"),
    ],
)
def test_bad_points_are_refused_naming_the_field(design, override, message):
    with pytest.raises(DesignError, match=message):
        with_overrides(design, override)


# ------------------------------------------------------------------------------------------------
# The design at a point


def test_reference_conditions_give_the_design_itself(design):
    """The design's own ambient, speed, power, unit load scale and the material at the reference
    temperature: the point design equals the design (exact)."""
    for point in (
        EnvelopePoint(name="ref", material_temperature="given", material_temperature_c=20.0),
        EnvelopePoint(
            name="explicit",
            ambient_temperature_c=25.6,
            material_temperature="given",
            material_temperature_c=20.0,
            speed_rpm=4800.0,
            power=246.0e3,
            load_scale=1.0,
        ),
    ):
        conditions, point_design = at(design, point)
        assert conditions.thermal == {} and conditions.materials == {}
        assert point_design == design


def test_cold_day(design):
    """-40 °C ambient, shaft cold-soaked: the lamina is the table's -40 °C row exactly, the sky
    follows Swinbank's T^1.5 from the file's 285 K at 25.6 °C (closed form, rel 1e-14), and
    the matrix reference temperature moves to -40 °C."""
    conditions, cold = at(design, "cold_day")
    assert conditions.material_temperature == celsius_to_kelvin(-40.0)
    material = cold.shaft_material
    assert (material.E_T, material.G_LT, material.loss_E_T, material.loss_G_LT) == (
        448.169e6,
        448.169e6,
        0.0441455,
        0.0441455,
    )
    sky = (11.85 + 273.15) * ((-40.0 + 273.15) / (25.6 + 273.15)) ** 1.5 - 273.15
    assert cold.thermal.sky_temperature_c == pytest.approx(sky, rel=1e-14)
    assert cold.thermal.ambient_temperature_c == -40.0
    assert cold.thermal.matrix_reference_temperature_c == -40.0
    assert (cold.operating, cold.loads, cold.bearings) == (design.operating, design.loads, design.bearings)


def test_hot_soak_start_is_at_the_parked_boom_temperature(design):
    """The hot-soak point's material temperature is the thermal model's parked boom skin
    temperature (the same function, same environment: exact) -- the thesis's 89 °C, which the
    file's solar_area_fraction is calibrated to (within 0.5 K)."""
    conditions, hot = at(design, "hot_soak_start")
    parked = tailboom_temperature("parked", boom_equivalent_diameter(design.tailboom), environment_from(design.thermal))
    assert conditions.material_temperature == parked.temperature
    assert conditions.boom_temperatures["parked"] == parked.temperature
    assert kelvin_to_celsius(conditions.material_temperature) == pytest.approx(89.0, abs=0.5)
    law = matrix_law_from(design.thermal, design.shaft_material)
    expected = law.material(design.shaft_material, parked.temperature)
    assert hot.shaft_material == expected
    assert hot.thermal.ambient_temperature_c == design.thermal.ambient_temperature_c
    assert hot.thermal.matrix_reference_temperature_c == kelvin_to_celsius(parked.temperature)


def test_standard_day_is_in_the_boom_hover_air(design):
    """15 °C (ISA sea level): the shaft's air is the boom's hover skin temperature in the point's
    environment (ambient 15 °C, sky scaled)."""
    conditions, standard = at(design, "standard_day")
    env = environment_from(standard.thermal)
    hover = tailboom_temperature("hover", boom_equivalent_diameter(design.tailboom), env)
    assert conditions.material_temperature == hover.temperature
    assert conditions.ambient_temperature == celsius_to_kelvin(15.0)


def test_a_night_point_without_sun_leaves_the_boom_at_the_ambient(design):
    """A point with no sun (``solar_fraction = 0``) under a sky at the air's temperature: the
    boom, parked or hovering, takes no net heat from convection or radiation at T = T_ambient (the
    heat balance h A (T − T_a) + ε σ A (T⁴ − T_sky⁴) = α q_sun A_p vanishes there with q_sun = 0
    and T_sky = T_a), so both skin temperatures are the ambient, to the root finder's tolerance
    (1e-6 K asserted; the design's sun parks it some 70 K above). The same point with the design's
    sun (``solar_fraction`` left to [thermal]) is hotter: the point's fraction must reach it."""
    ambient = design.thermal.ambient_temperature_c
    night = EnvelopePoint(
        name="night",
        ambient_temperature_c=ambient,
        sky_temperature_c=ambient,
        solar_fraction=0.0,
        material_temperature="parked",
    )
    conditions = point_conditions(design, night)
    for condition, temperature in conditions.boom_temperatures.items():
        assert temperature == pytest.approx(celsius_to_kelvin(ambient), abs=1e-6), condition
    sunny = point_conditions(design, night.model_copy(update={"solar_fraction": None}))
    assert sunny.boom_temperatures["parked"] > conditions.boom_temperatures["parked"] + 10.0


def test_moved_reference_describes_the_same_curves(design):
    """From the point design (keys at T_m, reference at T_m) the lamina at any other temperature
    is the base design's lamina there: moving the reference does not move the curves (rel 1e-12)."""
    _, hot = at(design, "hot_soak_start")
    for T_c in (-40.0, 20.0, 61.3):
        T = celsius_to_kelvin(T_c)
        base = matrix_law_from(design.thermal, design.shaft_material).material(design.shaft_material, T)
        moved = matrix_law_from(hot.thermal, hot.shaft_material).material(hot.shaft_material, T)
        for name in ("E_T", "G_LT", "loss_E_T", "loss_G_LT"):
            assert getattr(moved, name) == pytest.approx(getattr(base, name), rel=1e-12)
    law_only = with_overrides(design, {"materials.t700_adiprene.temperature_table": None})
    _, hot_law = at(law_only, "hot_soak_start")
    T = celsius_to_kelvin(61.3)
    base = matrix_law_from(law_only.thermal, law_only.shaft_material).material(law_only.shaft_material, T)
    moved = matrix_law_from(hot_law.thermal, hot_law.shaft_material).material(hot_law.shaft_material, T)
    assert moved.E_T == pytest.approx(base.E_T, rel=1e-12)
    assert moved.loss_G_LT == pytest.approx(base.loss_G_LT, rel=1e-12)


def test_given_temperature_between_rows(design):
    """90 °C: the midpoint of the 80 and 100 °C rows, the geometric mean (rel 1e-14)."""
    _, point_design = at(design, EnvelopePoint(name="p", material_temperature="given", material_temperature_c=90.0))
    assert point_design.shaft_material.G_LT == pytest.approx(math.sqrt(22.313e6 * 13.5335e6), rel=1e-14)


def test_speed_power_and_loads_of_a_point(design):
    """speed_rpm replaces the operating speed and the geared main rotor follows; load_scale
    multiplies the manoeuvre load factor and the point loads; the imbalance stays."""
    point = EnvelopePoint(
        name="fast",
        material_temperature="given",
        material_temperature_c=20.0,
        speed_rpm=5000.0,
        power=300e3,
        load_scale=2.0,
    )
    _, fast = at(design, point)
    assert fast.operating.speed_rpm == 5000.0
    assert fast.operating.main_rotor_speed_rpm == pytest.approx(289.0 * 5000.0 / 4800.0, rel=1e-15)
    assert fast.operating.power == 300e3
    assert fast.loads.load_factor == (0.0, -7.0, 0.0)
    assert fast.loads.point[0].force == (0.0, 0.0, 10000.0)
    assert fast.loads.eccentricity == design.loads.eccentricity
    assert fast.materials == design.materials


def test_a_point_at_rest(design):
    """speed_rpm = 0 (ground, rotor stopped; power 0: no torque): the geared main rotor stops
    too, so its excitation speed is dropped rather than scaled to an invalid 0 rev/min."""
    point = EnvelopePoint(
        name="rest", material_temperature="given", material_temperature_c=20.0, speed_rpm=0.0, power=0.0
    )
    _, rest = at(design, point)
    assert (rest.operating.speed_rpm, rest.operating.power, rest.operating.main_rotor_speed_rpm) == (0.0, 0.0, None)


def test_kink_band_strength_follows_the_hot_lamina(design):
    """At the hot-soak point G_LT has fallen to ~18 MPa and the kink-band X_c with it:
    G/(1 + phi G/S) with S = 20 MPa (closed form, rel 1e-14)."""
    _, hot = at(design, "hot_soak_start")
    G = hot.shaft_material.G_LT
    expected = G / (1.0 + math.radians(2.0) * G / 20e6)
    assert compressive_strength(hot.shaft_material).kink_band == pytest.approx(expected, rel=1e-14)
    assert 15e6 < expected < 20e6


def test_no_tailboom_means_the_ambient(design):
    bare = with_overrides(design, {"tailboom": None, "loads.point": []})
    for conditions in envelope_conditions(bare):
        assert conditions.boom_temperatures == {}
        assert conditions.material_temperature == conditions.ambient_temperature


def test_isotropic_shaft_keeps_its_metal():
    """The segmented aluminium driveline has no lamina: a cold day changes [thermal] only."""
    current = embedded_design("current")
    conditions = point_conditions(current, "cold_day")
    assert conditions.materials == {} and "matrix_reference_temperature_c" not in conditions.thermal
    cold = design_at_point(current, "cold_day", conditions)
    assert cold.materials == current.materials and cold.thermal.ambient_temperature_c == -40.0


def test_a_computed_temperature_outside_the_table_is_refused(design):
    """A boom parked at a 45 °C ambient passes the table's 120 °C top only when the table stops
    lower: with the table cut at 100 °C the point is refused, naming the point and lamina."""
    table = design.shaft_material.temperature_table
    short = {
        f"materials.t700_adiprene.temperature_table.{name}": list(values[:-1])
        for name, values in {"temperature_c": table.temperature_c, **table.columns()}.items()
    }
    cut = with_overrides(design, short)
    point = EnvelopePoint(name="desert", ambient_temperature_c=45.0, material_temperature="parked")
    with pytest.raises(ValueError, match=r"envelope point 'desert', lamina 't700_adiprene': temperature 1\d\d"):
        point_conditions(cut, point)

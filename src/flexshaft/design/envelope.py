"""The ``[envelope]`` of the design file: the operating points every check must hold at.

A verdict at one temperature is not a verdict for a driveline whose urethane matrix changes its
moduli and loss factors by large factors between a cold day and a hot-soaked boom. Each
``[[envelope.points]]`` names an operating point: the ambient air, the shaft's speed and power,
a scale on the static loads and where the shaft's material temperature comes from:

* ``"ambient"``: the ambient air (a cold-soaked start);
* ``"shaft_air"``: the air around the running shaft, the tailboom's hover skin temperature
  (thesis §2.8; the ambient without a tailboom) -- the operating condition of the thesis;
* ``"parked"``: the tailboom's skin temperature parked in the sun (a hot-soak start; the
  ambient without a tailboom);
* ``"given"``: ``material_temperature_c``.

Omitted keys take the design's own values (``[thermal] ambient_temperature_c``, ``[operating]``
speed and power). :func:`flexshaft.thermal.envelope.design_at_point` turns a design and a point
into the design at that point (the lamina at the material temperature, the thermal environment
at the ambient, the operating speed, power and loads); this module only validates the numbers.

Default points (an ``[envelope]`` without points; :func:`envelope_point` also finds them by name
for a design without an ``[envelope]``, which the verdict judges at its own operating point
only), assumed values with their grounds:

* ``cold_day``: -40 °C ambient, the shaft cold-soaked at it. -40 °C is an assumed cold limit of a
  rotorcraft envelope (MIL-HDBK-310's climatic design data and MIL-STD-810H's low-temperature
  method are where a program takes its own; their numbers were not read for this default).
* ``standard_day``: 15 °C, the sea-level temperature of the ICAO/ISO 2533 standard atmosphere,
  the shaft in the boom's hover air.
* ``hot_soak_start``: the design's ``[thermal] ambient_temperature_c`` (the hot day the thermal
  model is calibrated to: 25.6 °C with the thesis's 89 °C parked boom), the shaft at the parked
  boom's temperature when the rotor starts.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from flexshaft.design.fields import FrozenModel, Name, Problems, check_unique, format_number, format_value
from flexshaft.design.loads import SpeedRpm
from flexshaft.design.quantities import Power, quantity_field
from flexshaft.units import ZERO_CELSIUS

__all__ = [
    "DEFAULT_ENVELOPE_POINTS",
    "envelope_point",
    "MAX_ENVELOPE_POINTS",
    "Envelope",
    "EnvelopePoint",
    "MaterialTemperatureSource",
    "check_envelope_temperatures",
]

#: Most points of an envelope (each runs every check of the verdict).
MAX_ENVELOPE_POINTS = 20

#: Where the shaft's material temperature at a point comes from (module docstring).
MaterialTemperatureSource = Literal["ambient", "shaft_air", "parked", "given"]

PointCelsius = Annotated[
    float, quantity_field("degC", "temperature above absolute zero and at most 400 °C", gt=-ZERO_CELSIUS, le=400.0)
]
Fraction = Annotated[float, quantity_field("-", "fraction from 0 to 1", ge=0.0, le=1.0)]
LoadScale = Annotated[
    float,
    quantity_field(
        "-", "multiplier of the static loads from 0 to 100 (0: no manoeuvre or point loads)", ge=0.0, le=100.0
    ),
]


class EnvelopePoint(FrozenModel):
    """One operating point of the envelope; omitted keys take the design's own values.

    Attributes
    ----------
    name : str
        Name of the point (unique), e.g. ``"cold_day"``.
    ambient_temperature_c : float or None
        Ambient air temperature [°C]; omitted: ``[thermal] ambient_temperature_c``.
    material_temperature : {"ambient", "shaft_air", "parked", "given"}
        Where the shaft's material temperature comes from: the ambient, the air around the
        running shaft (the boom's hover skin temperature), the boom parked in the sun, or
        ``material_temperature_c``.
    material_temperature_c : float or None
        The shaft's material temperature [°C]; required with ``material_temperature = "given"``,
        refused otherwise.
    speed_rpm : float or None
        Shaft speed [rev/min]; omitted: the ``[operating]`` speed. The main-rotor speed scales
        with it (the two are geared).
    power : float or None
        Transmitted power [W]; omitted: the ``[operating]`` power.
    load_scale : float
        Multiplier of the static loads [-]: the manoeuvre load factor and every point and line
        load of ``[loads]`` (the imbalance is not scaled).
    sky_temperature_c : float or None
        Effective sky temperature [°C]; omitted: ``[thermal] sky_temperature_c`` scaled with the
        ambient as T_sky ∝ T_amb^1.5 in kelvin (Swinbank's clear-sky relation, which the
        baseline's pair 25.6 °C / 285 K follows), unchanged when the ambient is the design's.
    solar_fraction : float or None
        Atmospheric transmission of the sun [-] (0: night or overcast); omitted:
        ``[thermal] solar_fraction``.
    """

    name: Name
    ambient_temperature_c: PointCelsius | None = None
    material_temperature: MaterialTemperatureSource = "ambient"
    material_temperature_c: PointCelsius | None = None
    speed_rpm: SpeedRpm | None = None
    power: Power | None = None
    load_scale: LoadScale = 1.0
    sky_temperature_c: PointCelsius | None = None
    solar_fraction: Fraction | None = None

    @model_validator(mode="after")
    def _check(self) -> EnvelopePoint:
        problems = Problems()
        if self.material_temperature == "given" and self.material_temperature_c is None:
            problems.add(("material_temperature_c",), 'required key is missing (material_temperature = "given")')
        elif self.material_temperature != "given" and self.material_temperature_c is not None:
            problems.add(
                ("material_temperature_c",),
                f'must be omitted unless material_temperature = "given" (got '
                f"{format_value(self.material_temperature_c)} with material_temperature = "
                f"{format_value(self.material_temperature)})",
            )
        problems.raise_if_any()
        return self


#: The envelope of a design without an ``[envelope]`` table (module docstring).
DEFAULT_ENVELOPE_POINTS = (
    EnvelopePoint(name="cold_day", ambient_temperature_c=-40.0, material_temperature="ambient"),
    EnvelopePoint(name="standard_day", ambient_temperature_c=15.0, material_temperature="shaft_air"),
    EnvelopePoint(name="hot_soak_start", material_temperature="parked"),
)


class Envelope(FrozenModel):
    """The operating points every check is evaluated at (``[[envelope.points]]``).

    Attributes
    ----------
    points : tuple of tables
        The operating points, at least one; default: ``cold_day`` (-40 °C, shaft at the
        ambient), ``standard_day`` (15 °C, shaft in the boom's hover air) and
        ``hot_soak_start`` (the design's ambient, shaft at the parked boom's temperature).
    """

    points: tuple[EnvelopePoint, ...] = Field(
        default=DEFAULT_ENVELOPE_POINTS, min_length=1, max_length=MAX_ENVELOPE_POINTS
    )

    @model_validator(mode="after")
    def _check(self) -> Envelope:
        problems = Problems()
        check_unique(problems, ("points",), [point.name for point in self.points])
        problems.raise_if_any()
        return self

    def point(self, name: str) -> EnvelopePoint:
        """The point called ``name``."""
        for point in self.points:
            if point.name == name:
                return point
        raise KeyError(name)


def check_envelope_temperatures(problems: Problems, envelope: Envelope, ambient_c: float, tables: dict) -> None:
    """Report points whose material temperature, known before any analysis, lies outside a table.

    ``tables`` maps a lamina's name to its :class:`~flexshaft.design.temperature_table.TemperatureTable`;
    ``ambient_c`` is ``[thermal] ambient_temperature_c`` [°C]. Only the ``"ambient"`` and
    ``"given"`` sources are known here; the boom temperatures are checked when they are computed.
    """
    for index, point in enumerate(envelope.points):
        if point.material_temperature == "given":
            field, value = "material_temperature_c", point.material_temperature_c
        elif point.material_temperature == "ambient":
            given = point.ambient_temperature_c is not None
            field, value = "ambient_temperature_c", point.ambient_temperature_c if given else ambient_c
        else:
            continue
        assert value is not None  # Point's validator requires material_temperature_c with "given"
        for name, table in tables.items():
            low, high = table.temperature_c[0], table.temperature_c[-1]
            if not low <= value <= high:
                source = (
                    ""
                    if point.ambient_temperature_c is not None or field != "ambient_temperature_c"
                    else (" ([thermal] ambient_temperature_c)")
                )
                problems.add(
                    ("envelope", "points", index, field),
                    f"puts the shaft at {format_number(value)} °C{source}, outside the temperature_table of "
                    f"lamina {format_value(name)} [{format_number(low)}, {format_number(high)}] °C "
                    "(tables are not extrapolated; extend the table)",
                )


def envelope_point(design, name: str) -> EnvelopePoint:
    """The point called ``name`` of ``design``'s ``[envelope]``, or of the default points
    (:data:`DEFAULT_ENVELOPE_POINTS`) for a design without one (KeyError when there is none)."""
    if design.envelope is not None:
        return design.envelope.point(name)
    for point in DEFAULT_ENVELOPE_POINTS:
        if point.name == name:
            return point
    raise KeyError(f"{name!r}: not a point of the default envelope (the design has no [envelope])")

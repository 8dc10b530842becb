"""The conditions at an operating point of a design's envelope: temperatures and laminae.

:func:`point_conditions` evaluates, for a design and one ``[[envelope.points]]`` entry
(:class:`~flexshaft.design.envelope.EnvelopePoint`), everything of the point that needs the
thermal models; :func:`flexshaft.design.points.design_at_point` then applies it, with the point's
speed, power and loads, to give the design at the point (a data operation of the design layer:
this package never makes designs). The one recipe at every point::

    conditions = point_conditions(design, point)
    at_point = design_at_point(design, point, conditions)   # run any check on it

1. **Thermal environment.** ``[thermal] ambient_temperature_c`` becomes the point's ambient; the
   sky temperature the point's, or the design's scaled as T_sky ∝ T_amb^1.5 in kelvin (Swinbank's
   clear-sky relation, which the baseline's 25.6 °C / 285 K pair follows) when the ambient
   changes; the solar transmission the point's when given.
2. **Material temperature** T_m, by the point's source: the ambient; the shaft's air (the
   tailboom's hover skin temperature, thesis §2.8.1, or the ambient without a tailboom, as in
   :func:`~flexshaft.thermal.analysis.shaft_air_temperature`); the tailboom parked in the sun
   (:func:`~flexshaft.thermal.tailboom.tailboom_temperature`, ``"parked"``; the ambient without
   a tailboom); or the given value. The boom temperatures use the point's environment.
3. **Laminae at T_m.** Every lamina of ``[materials]`` gets its storage moduli and loss factors
   at T_m from its temperature table, or from the ``[thermal]`` matrix law without one
   (:meth:`~flexshaft.thermal.matrix.MatrixTemperatureLaw.material`, the one way to a lamina at
   a temperature), and ``[thermal] matrix_reference_temperature_c`` moves to T_m where the new
   values apply (a table gives each property relative to its reference value, so it describes
   the same curves from there): a self-heating analysis of the point design starts at the point.
   Strengths do not vary (the kink-band X_c follows G_LT,
   :func:`flexshaft.strength.compressive_strength`); isotropic metals do not vary.

At the design's own conditions (its ambient, and T_m at the reference temperature) nothing
changes. The thermal residual stress of the strength check takes its temperature as an
argument: pass :attr:`PointConditions.material_temperature`
(:func:`flexshaft.analyses.shaft_strength.shaft_safety_factor`, ``temperature=``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from pydantic import ValidationError

from flexshaft.design.envelope import DEFAULT_ENVELOPE_POINTS, EnvelopePoint, envelope_point
from flexshaft.design.materials import Lamina
from flexshaft.design.schema import Design
from flexshaft.design.thermal_schema import Thermal
from flexshaft.thermal.options import matrix_law_from, thermal_options
from flexshaft.thermal.tailboom import boom_equivalent_diameter, tailboom_temperature
from flexshaft.units import celsius_to_kelvin, kelvin_to_celsius

__all__ = ["SKY_EXPONENT", "PointConditions", "envelope_conditions", "point_conditions", "point_thermal"]

#: Exponent of Swinbank's (1963) clear-sky temperature, T_sky = 0.0552 T_amb^1.5 [K].
SKY_EXPONENT = 1.5


@dataclass(frozen=True)
class PointConditions:
    """What the thermal models say about one operating point of a design.

    Attributes
    ----------
    point : EnvelopePoint
        The point.
    ambient_temperature : float
        Ambient air temperature [K].
    material_temperature : float
        The shaft's material temperature T_m [K]: the laminae's properties are at it, and it is
        the temperature of the thermal residual stress.
    boom_temperatures : dict of str to float
        Tailboom skin temperatures {"hover", "parked"} at the point [K] (empty without a tailboom).
    thermal : dict
        The changed keys of the ``[thermal]`` table, in the file's units (°C).
    materials : dict of str to Lamina
        The laminae of ``[materials]`` whose properties differ at T_m, at T_m.
    """

    point: EnvelopePoint
    ambient_temperature: float
    material_temperature: float
    boom_temperatures: dict[str, float] = field(default_factory=dict)
    thermal: dict[str, float] = field(default_factory=dict)
    materials: dict[str, Lamina] = field(default_factory=dict)

    @property
    def name(self) -> str:
        """The point's name."""
        return self.point.name

    @property
    def material_temperature_c(self) -> float:
        """The shaft's material temperature [°C]."""
        return kelvin_to_celsius(self.material_temperature)

    @property
    def ambient_temperature_c(self) -> float:
        """Ambient air temperature [°C]."""
        return kelvin_to_celsius(self.ambient_temperature)


def point_thermal(design: Design, point: EnvelopePoint) -> dict[str, float]:
    """The keys of ``design``'s ``[thermal]`` table that differ at ``point`` (step 1, file units)."""
    base = design.thermal
    out: dict[str, float] = {}
    ambient_c = base.ambient_temperature_c if point.ambient_temperature_c is None else point.ambient_temperature_c
    if ambient_c != base.ambient_temperature_c:
        out["ambient_temperature_c"] = ambient_c
    if point.sky_temperature_c is not None:
        out["sky_temperature_c"] = point.sky_temperature_c
    elif ambient_c != base.ambient_temperature_c:
        ratio = celsius_to_kelvin(ambient_c) / celsius_to_kelvin(base.ambient_temperature_c)
        out["sky_temperature_c"] = kelvin_to_celsius(celsius_to_kelvin(base.sky_temperature_c) * ratio**SKY_EXPONENT)
    if point.solar_fraction is not None:
        out["solar_fraction"] = point.solar_fraction
    return out


def _material_temperature(point: EnvelopePoint, ambient: float, boom: dict[str, float]) -> float:
    """T_m [K] by the point's source (step 2 of the module)."""
    source = point.material_temperature
    if source == "given":
        assert point.material_temperature_c is not None  # EnvelopePoint requires it with "given"
        return celsius_to_kelvin(point.material_temperature_c)
    if source == "shaft_air":
        return boom.get("hover", ambient)
    if source == "parked":
        return boom.get("parked", ambient)
    return ambient


def point_conditions(design: Design, point: EnvelopePoint | str) -> PointConditions:
    """Temperatures and laminae of ``design`` at one operating point (module docstring).

    Parameters
    ----------
    design : Design
        The design (read only).
    point : EnvelopePoint or str
        A point, or the name of one of ``design.envelope.points`` (of the default points
        without an ``[envelope]``; :func:`~flexshaft.design.envelope.envelope_point`).

    Raises
    ------
    ValueError
        When the material temperature lies outside a lamina's temperature table (the message
        names the point, the lamina, the temperature and the table's range).
    """
    if isinstance(point, str):
        point = envelope_point(design, point)
    changes = point_thermal(design, point)
    thermal = Thermal.model_validate({**design.thermal.model_dump(), **changes})
    options = thermal_options(thermal)
    ambient = options.environment.ambient_temperature
    boom: dict[str, float] = {}
    if design.tailboom is not None:
        diameter = boom_equivalent_diameter(design.tailboom)
        for condition in ("hover", "parked"):
            boom[condition] = tailboom_temperature(
                condition, diameter, options.environment, options.boom_convection
            ).temperature
    T_m = _material_temperature(point, ambient, boom)
    materials = {}
    for name, material in design.materials.items():
        if not isinstance(material, Lamina):
            continue
        try:
            at_T = matrix_law_from(design.thermal, material).material(material, T_m)
        except ValueError as exc:
            raise ValueError(f"envelope point {point.name!r}, lamina {name!r}: {_refusal(exc, T_m)}") from None
        if at_T is not material:
            materials[name] = at_T
    if materials:
        changes["matrix_reference_temperature_c"] = kelvin_to_celsius(T_m)
    return PointConditions(point, ambient, T_m, boom, changes, materials)


def envelope_conditions(design: Design) -> tuple[PointConditions, ...]:
    """:func:`point_conditions` at every point of ``design.envelope``, in order; at the default
    points (:data:`~flexshaft.design.envelope.DEFAULT_ENVELOPE_POINTS`) for a design without an
    ``[envelope]`` (which the verdict judges at its own operating point only)."""
    points = design.envelope.points if design.envelope is not None else DEFAULT_ENVELOPE_POINTS
    return tuple(point_conditions(design, point) for point in points)


def _refusal(exc: ValueError, temperature: float) -> str:
    """One line for a lamina refused at ``temperature`` [K]: a table's message as it is (it names
    the temperature); for the matrix law's lamina out of the schema's bounds (a pydantic
    ValidationError, whose text spans lines and links a web page), the temperature, each field
    with the value it would take and its bound, and the keys that set them."""
    if not isinstance(exc, ValidationError):
        return str(exc)
    fields = [f"at {kelvin_to_celsius(temperature):.4g} °C"]
    for error in exc.errors():
        key = ".".join(str(part) for part in error.get("loc", ())) or "value"
        value = error.get("input")
        shown = f"{value:.6g}" if isinstance(value, float) else repr(value)
        fields.append(f"{key} would be {shown} ({str(error.get('msg', '')).lower()})")
    return (
        fields[0]
        + " "
        + "; ".join(fields[1:])
        + "; the [thermal] matrix law sets it there (matrix_reference_temperature_c, matrix_modulus_decay, "
        "matrix_loss_growth), or a [materials.<name>.temperature_table]"
    )

"""The design-file schema: one pydantic model tree, the single source of truth for inputs.

The annotated example ``baseline.toml`` next to this module defines the file format; every
table of it is a model, every key a field. All models forbid unknown keys and are frozen.
Quantities are SI floats [m, kg, s, N, Pa, W]; the only unit conversions are ``speed_rpm``
[rev/min] and the layup angles [deg], exposed as :attr:`Operating.speed_rad_s` and
:attr:`Shaft.ply_angles_deg`.

The models of the tables live in topic modules and are re-exported here, so that every public
name of the schema is importable from this module:

* :mod:`flexshaft.design.fields`: shared field types, message formatting, the problem collector;
* :mod:`flexshaft.design.materials`: :class:`Lamina`, :class:`Isotropic`;
* :mod:`flexshaft.design.components`: :class:`Shaft`, :class:`Tailboom`, bearings, :class:`Disk`;
* :mod:`flexshaft.design.segments`: :class:`ShaftSegment`, :class:`Coupling` (segmented shafts);
* :mod:`flexshaft.design.loads`: :class:`Operating`, :class:`Loads` and its point and line loads;
* :mod:`flexshaft.design.requirements`: :class:`Requirements`, the limits the results must meet;
* :mod:`flexshaft.design.envelope`: :class:`Envelope`, the operating points of the verdict;
* :mod:`flexshaft.design.temperature_table`: :class:`TemperatureTable` of a lamina;
* :mod:`flexshaft.design.drivetrain`: :class:`TailRotor`, :class:`MainGearbox` (the torsional ends);
* this module: :class:`Mesh` and :class:`Design` with the cross-table checks.

Constraints that involve several fields are checked in ``model_validator(mode="after")``
hooks that report every problem at once through :class:`~flexshaft.design.fields.Problems`;
the error carries the sub-paths so that :mod:`flexshaft.design.io` can name each offending
field. Cross-table checks on :class:`Design` (material references, bearings on the shaft, ...)
run only once every table validates on its own.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from flexshaft.design.components import (
    ActiveBearing,
    Bearing,
    ContactBearing,
    Controller,
    Disk,
    EndMass,
    Shaft,
    Tailboom,
)
from flexshaft.design.drivetrain import MainGearbox, TailRotor
from flexshaft.design.envelope import Envelope, EnvelopePoint, check_envelope_temperatures
from flexshaft.design.fields import (
    LAYUP_ERROR_TYPE,
    PROBLEMS_ERROR_TYPE,
    BearingDirection,
    DesignName,
    DofName,
    ElementCount,
    FieldPath,
    FrozenModel,
    ImbalancePlacement,
    Name,
    Problems,
    check_unique,
    format_number,
    format_value,
)
from flexshaft.design.loads import MAX_SPEED_RPM, LineLoad, Loads, Operating, PointLoad
from flexshaft.design.materials import Isotropic, Lamina, Material
from flexshaft.design.quantities import MAX_BEARINGS, MAX_DISKS, MAX_MATERIALS
from flexshaft.design.requirements import Requirements
from flexshaft.design.segments import MAX_COUPLINGS, Coupling, ShaftSegment, Tube
from flexshaft.design.temperature_table import TemperatureTable, check_table_range
from flexshaft.design.thermal_schema import Thermal

__all__ = [
    "Analysis",
    "InternalDamping",
    "Thermal",
    "ActiveBearing",
    "Bearing",
    "BearingDirection",
    "ContactBearing",
    "Controller",
    "Coupling",
    "Design",
    "Disk",
    "DofName",
    "Envelope",
    "EnvelopePoint",
    "EndMass",
    "ImbalancePlacement",
    "Isotropic",
    "Lamina",
    "LineLoad",
    "Loads",
    "MainGearbox",
    "Material",
    "Mesh",
    "Operating",
    "PointLoad",
    "Requirements",
    "Shaft",
    "ShaftSegment",
    "TailRotor",
    "Tailboom",
    "TemperatureTable",
    "Tube",
    "PROBLEMS_ERROR_TYPE",
    "LAYUP_ERROR_TYPE",
    "MAX_SPEED_RPM",
    "format_value",
]


class Mesh(FrozenModel):
    """Approximate element counts; nodes are always placed at bearings and disks.

    Attributes
    ----------
    shaft_elements : int
        Approximate number of shaft elements, shared among the segments between nodes in
        proportion to their length (at least one each).
    boom_elements : int
        Approximate number of tailboom elements, shared the same way.
    """

    shaft_elements: ElementCount = 36
    boom_elements: ElementCount = 24


#: How the shaft's hysteretic (internal) loss acts; one choice for every analysis of a model.
InternalDamping = Literal["rotating", "thesis"]


class Analysis(FrozenModel):
    """Model-wide physics choices shared by every analysis.

    ``internal_damping``: ``"rotating"`` (default) applies the shaft's hysteretic loss in the
    rotating frame, where the material is cycled at the whirl frequency relative to the spin
    (exact for an axisymmetric shaft: synchronous forward whirl is not damped by it);
    ``"thesis"`` applies it as a fixed-frame complex stiffness (thesis eqs. 2.39-2.40).

    Attributes
    ----------
    internal_damping : {"rotating", "thesis"}
        How the shaft's hysteretic loss acts, the same in every analysis of the model.
    """

    internal_damping: InternalDamping = "rotating"


# ------------------------------------------------------------------------------------------------
# The design


class Design(FrozenModel):
    """A complete driveline design, as read from a TOML design file.

    Attributes
    ----------
    name : str
        Title of the design (reports and output folders show it).
    materials : dict of str to table
        Materials by name (``[materials.<name>]``), referenced by the shaft and the tailboom.
    shaft : table
        The drive shaft (``[shaft]``).
    tailboom : table or None
        The flexible tailboom the bearings are mounted on (``[tailboom]``); omitted: the
        bearings join the shaft to the ground.
    bearings : tuple of tables
        Contact (hanger) and active magnetic bearings (``[[bearings]]``), at least one.
    disks : tuple of tables
        Rigid disks on the shaft (``[[disks]]``).
    couplings : tuple of tables
        Flexible couplings that cut the shaft into pieces (``[[couplings]]``;
        docs/segmented-driveline.md).
    tail_rotor : table or None
        The tail rotor driven by the shaft's aft end (``[tail_rotor]``); omitted: the aft end is
        free in twist unless ``shaft.fixed_end`` holds it.
    main_gearbox : table or None
        The gearbox driving the shaft's forward end (``[main_gearbox]``); omitted: the forward
        twist is as ``shaft.fixed_start`` says.
    operating : table
        The operating point (``[operating]``).
    loads : table
        Imbalance and static loads (``[loads]``).
    mesh : table
        Element counts (``[mesh]``).
    analysis : table
        Model-wide physics choices (``[analysis]``).
    thermal : table
        Thermal environment and matrix temperature law (``[thermal]``).
    requirements : table
        Limits of the requirements verdict (``[requirements]``).
    envelope : table or None
        Operating points every check is evaluated at (``[envelope]``); omitted: the design is
        judged at its own operating point only (``[envelope]`` without points holds the three
        default points, :data:`~flexshaft.design.envelope.DEFAULT_ENVELOPE_POINTS`).
    """

    name: DesignName
    materials: dict[Name, Material] = Field(max_length=MAX_MATERIALS)
    shaft: Shaft
    tailboom: Tailboom | None = None
    bearings: tuple[Bearing, ...] = Field(min_length=1, max_length=MAX_BEARINGS)
    disks: tuple[Disk, ...] = Field(default=(), max_length=MAX_DISKS)
    couplings: tuple[Coupling, ...] = Field(default=(), max_length=MAX_COUPLINGS)
    tail_rotor: TailRotor | None = None
    main_gearbox: MainGearbox | None = None
    operating: Operating
    loads: Loads = Loads()
    mesh: Mesh = Mesh()
    analysis: Analysis = Analysis()
    thermal: Thermal = Thermal()
    requirements: Requirements = Requirements()
    envelope: Envelope | None = None

    @model_validator(mode="after")
    def _check(self) -> Design:
        problems = Problems()
        self._check_materials(problems)
        self._check_segment_materials(problems)
        self._check_couplings(problems)
        self._check_bearings(problems)
        self._check_disks(problems)
        self._check_loads(problems)
        self._check_temperature_tables(problems)
        self._check_drive_ends(problems)
        problems.raise_if_any()
        return self

    # -- cross-table checks ----------------------------------------------------------------------

    def _material_reference(self, problems: Problems, path: FieldPath, name: str) -> Lamina | Isotropic | None:
        material = self.materials.get(name)
        if material is None:
            allowed = ", ".join(format_value(key) for key in self.materials) or "none defined"
            message = f"names no material in [materials] (got {format_value(name)}; allowed: {allowed})"
            problems.add(path, message)
        return material

    def _check_materials(self, problems: Problems) -> None:
        shaft_material = self._material_reference(problems, ("shaft", "material"), self.shaft.material)
        if isinstance(shaft_material, Lamina) and self.shaft.layup is None:
            problems.add(
                ("shaft", "layup"),
                f"required key is missing (the shaft material {format_value(self.shaft.material)} is a lamina)",
            )
        elif isinstance(shaft_material, Isotropic) and self.shaft.layup is not None:
            problems.add(
                ("shaft", "layup"),
                f"must be omitted for the isotropic material {format_value(self.shaft.material)} "
                f"(got {format_value(self.shaft.layup)})",
            )
        if self.tailboom is not None:
            boom_material = self._material_reference(problems, ("tailboom", "material"), self.tailboom.material)
            if isinstance(boom_material, Lamina):
                problems.add(
                    ("tailboom", "material"),
                    f'must name an isotropic material (got {format_value(self.tailboom.material)}, kind = "lamina")',
                )

    def _check_segment_materials(self, problems: Problems) -> None:
        """Each segment's material exists; a lamina needs a layup, a metal refuses one."""
        for index, (segment, tube) in enumerate(zip(self.shaft.segments, self.shaft.tubes)):
            if segment.material is None:
                continue  # inherits [shaft] material and layup, checked above
            path: FieldPath = ("shaft", "segments", index)
            material = self._material_reference(problems, path + ("material",), segment.material)
            if isinstance(material, Lamina) and tube.layup is None:
                problems.add(
                    path + ("layup",),
                    f"required key is missing (the segment material {format_value(segment.material)} is a lamina)",
                )
            elif isinstance(material, Isotropic) and tube.layup is not None:
                problems.add(
                    path + ("layup",),
                    f"must be omitted for the isotropic material "
                    f"{format_value(segment.material)} (got {format_value(tube.layup)})",
                )
        for index, segment in enumerate(self.shaft.segments):
            inherited = self.materials.get(self.shaft.material)
            if segment.material is None and segment.layup is not None and isinstance(inherited, Isotropic):
                problems.add(
                    ("shaft", "segments", index, "layup"),
                    f"must be omitted for the isotropic material {format_value(self.shaft.material)} "
                    f"(got {format_value(segment.layup)})",
                )

    def _check_temperature_tables(self, problems: Problems) -> None:
        """Each lamina's table spans the reference temperature and reaches the allowable; the
        envelope's known material temperatures lie inside the tables."""
        tables = {}
        for name, material in self.materials.items():
            if isinstance(material, Lamina) and material.temperature_table is not None:
                tables[name] = material.temperature_table
                check_table_range(
                    problems,
                    ("materials", name, "temperature_table"),
                    material.temperature_table,
                    self.thermal.matrix_reference_temperature_c,
                    self.thermal.allowable_temperature_c,
                )
        if self.envelope is not None:
            check_envelope_temperatures(problems, self.envelope, self.thermal.ambient_temperature_c, tables)

    def _check_couplings(self, problems: Problems) -> None:
        """Couplings strictly inside the shaft, at distinct stations."""
        check_unique(problems, ("couplings",), [coupling.name for coupling in self.couplings])
        tol = self._station_tolerance()
        seen: list[float] = []
        for index, coupling in enumerate(self.couplings):
            if not self.shaft.x_start + tol < coupling.x < self.shaft.x_end - tol:
                problems.add(
                    ("couplings", index, "x"),
                    f"{format_value(coupling.x)} is not strictly inside the "
                    f"shaft {self._shaft_range()} (a coupling joins two pieces)",
                )
            elif any(abs(coupling.x - other) <= tol for other in seen):
                problems.add(
                    ("couplings", index, "x"), f"{format_value(coupling.x)} repeats the station of another coupling"
                )
            seen.append(coupling.x)

    def _station_tolerance(self) -> float:
        return 1e-9 * max(1.0, abs(self.shaft.x_end - self.shaft.x_start))

    def _at_coupling(self, problems: Problems, path: FieldPath, x: float) -> None:
        """A bearing, sensor or disk must sit on one side of a coupling, not at its station."""
        tol = self._station_tolerance()
        for coupling in self.couplings:
            if abs(x - coupling.x) <= tol:
                problems.add(
                    path,
                    f"{format_value(x)} is the station of coupling {format_value(coupling.name)}; "
                    "put it on one side of the joint",
                )

    def _shaft_range(self) -> str:
        return f"[{format_number(self.shaft.x_start)}, {format_number(self.shaft.x_end)}] m"

    def _on_shaft(self, x: float) -> bool:
        return self.shaft.x_start <= x <= self.shaft.x_end

    def _on_boom(self, x: float) -> bool:
        return self.tailboom is not None and 0.0 <= x <= self.tailboom.length

    def _boom_range(self) -> str:
        assert self.tailboom is not None
        return f"[0, {format_number(self.tailboom.length)}] m"

    def _check_bearings(self, problems: Problems) -> None:
        check_unique(problems, ("bearings",), [bearing.name for bearing in self.bearings])
        for index, bearing in enumerate(self.bearings):
            if not self._on_shaft(bearing.x):
                problems.add(
                    ("bearings", index, "x"), f"{format_value(bearing.x)} is outside the shaft {self._shaft_range()}"
                )
            if self.tailboom is None:
                for field in ("x_boom", "offset"):
                    value = getattr(bearing, field)
                    if value is not None:
                        problems.add(
                            ("bearings", index, field),
                            f"must be omitted when the design has no [tailboom] (got {format_value(value)})",
                        )
            elif not self._on_boom(bearing.boom_x) and (
                bearing.x_boom is not None or self._on_shaft(bearing.x)  # else reported as off the shaft
            ):
                field = "x" if bearing.x_boom is None else "x_boom"
                note = "" if bearing.x_boom is not None else " (x_boom defaults to x; give x_boom)"
                problems.add(
                    ("bearings", index, field),
                    f"boom station {format_value(bearing.boom_x)} is outside the tailboom {self._boom_range()}{note}",
                )
            if isinstance(bearing, ActiveBearing) and bearing.sensor_offset != 0.0:
                self._check_sensor(problems, index, bearing)
                self._at_coupling(problems, ("bearings", index, "sensor_offset"), bearing.sensor_x)
            self._at_coupling(problems, ("bearings", index, "x"), bearing.x)

    def _check_sensor(self, problems: Problems, index: int, bearing: ActiveBearing) -> None:
        """The displacement sensor at x + sensor_offset must lie on the shaft (and on the boom)."""
        path: FieldPath = ("bearings", index, "sensor_offset")
        if self._on_shaft(bearing.x) and not self._on_shaft(bearing.sensor_x):
            problems.add(
                path,
                f"puts the sensor at x = {format_number(bearing.sensor_x)} m, outside the shaft "
                f"{self._shaft_range()} (got {format_value(bearing.sensor_offset)})",
            )
        elif self.tailboom is not None and self._on_boom(bearing.boom_x) and not self._on_boom(bearing.sensor_boom_x):
            problems.add(
                path,
                f"puts the sensor's boom station at {format_number(bearing.sensor_boom_x)} m, outside the "
                f"tailboom {self._boom_range()} (got {format_value(bearing.sensor_offset)})",
            )

    def _check_disks(self, problems: Problems) -> None:
        check_unique(problems, ("disks",), [disk.name for disk in self.disks])
        for index, disk in enumerate(self.disks):
            if not self._on_shaft(disk.x):
                problems.add(
                    ("disks", index, "x"), f"{format_value(disk.x)} is outside the shaft {self._shaft_range()}"
                )
            self._at_coupling(problems, ("disks", index, "x"), disk.x)

    def _check_station(self, problems: Problems, path: FieldPath, on: str, x: float) -> None:
        if on == "shaft" and not self._on_shaft(x):
            problems.add(path, f"{format_value(x)} is outside the shaft {self._shaft_range()}")
        elif on == "boom" and self.tailboom is not None and not self._on_boom(x):
            problems.add(path, f"{format_value(x)} is outside the tailboom {self._boom_range()}")

    def _check_loads(self, problems: Problems) -> None:
        check_unique(problems, ("loads", "point"), [load.name for load in self.loads.point])
        check_unique(problems, ("loads", "line"), [load.name for load in self.loads.line])
        for index, point in enumerate(self.loads.point):
            path: FieldPath = ("loads", "point", index)
            if point.on == "end_mass" and (self.tailboom is None or self.tailboom.end_mass is None):
                problems.add(path + ("on",), 'is "end_mass" but the design has no [tailboom.end_mass]')
            elif point.on == "boom" and self.tailboom is None:
                problems.add(path + ("on",), 'is "boom" but the design has no [tailboom]')
            elif point.x is not None:
                self._check_station(problems, path + ("x",), point.on, point.x)
        for index, line in enumerate(self.loads.line):
            path = ("loads", "line", index)
            if line.on == "boom" and self.tailboom is None:
                problems.add(path + ("on",), 'is "boom" but the design has no [tailboom]')
                continue
            self._check_station(problems, path + ("x_start",), line.on, line.x_start)
            self._check_station(problems, path + ("x_end",), line.on, line.x_end)

    def _check_drive_ends(self, problems: Problems) -> None:
        """An elastic gearbox or a tail rotor drives an end's twist: the end must not hold it."""
        if self.main_gearbox is not None and not self.main_gearbox.rigid and "theta" in self.shaft.fixed_start:
            problems.add(
                ("shaft", "fixed_start"),
                f"holds the twist (theta), but [main_gearbox] stiffness = "
                f"{format_value(self.main_gearbox.stiffness)} makes the forward end elastic in twist; "
                f'remove "theta" from fixed_start (got {format_value(list(self.shaft.fixed_start))})',
            )
        if self.tail_rotor is not None and "theta" in self.shaft.fixed_end:
            problems.add(
                ("shaft", "fixed_end"),
                'holds the twist (theta) of the aft end that drives the [tail_rotor]; remove "theta" '
                f"from fixed_end (got {format_value(list(self.shaft.fixed_end))})",
            )

    # -- convenience -----------------------------------------------------------------------------

    @property
    def shaft_material(self) -> Lamina | Isotropic:
        """The material the shaft is made of."""
        return self.materials[self.shaft.material]

    @property
    def segmented(self) -> bool:
        """True when the shaft has more than one zone or any coupling (not one uniform tube)."""
        return len(self.shaft.tubes) > 1 or bool(self.couplings)

    def tube_material(self, tube: Tube) -> Lamina | Isotropic:
        """The material of one resolved shaft zone (:attr:`Shaft.tubes`)."""
        return self.materials[tube.material]

    @property
    def tailboom_material(self) -> Isotropic | None:
        """The (isotropic) tailboom material, or None without a tailboom."""
        if self.tailboom is None:
            return None
        material = self.materials[self.tailboom.material]
        assert isinstance(material, Isotropic)
        return material

    def bearing(self, name: str) -> ContactBearing | ActiveBearing:
        """The bearing called ``name``."""
        for bearing in self.bearings:
            if bearing.name == name:
                return bearing
        raise KeyError(name)

"""The design variables the explorer offers, with their bounds read from the design schema.

:func:`design_controls` lists, for a design, the variables that move a driveline's verdict: the
layup's ply-angle pairs, the wall thickness and outer diameter, each active bearing's station and
gains (K_p, K_d), each hanger's and damper's station, the balance grade and the operating speed. Each
:class:`Control` writes one or more design paths (:func:`control_overrides`); its bounds are the
schema's (``minimum``/``maximum`` of the design's JSON Schema,
:func:`flexshaft.design.reference.design_json_schema`), converted to the display unit. Every
value is then validated by the schema itself (:func:`flexshaft.design.with_overrides`), whose
message names the field.

Display units are the engineer's (mm, rpm, degrees) and are converted here through
:mod:`flexshaft.units`; the design paths take SI, as design files do (``speed_rpm`` and the
balance grade keep their file units, rpm and mm/s). The layup is a string: its angle pairs are
numbers in it (e.g. ``a`` and ``b`` of ``(a/-a/b/-b)s``), rewritten in place, and their range
[-90, 90] deg is the layup grammar's (:func:`flexshaft.design.layup.parse_layup`, whose message
the page shows for an angle outside it).
"""

from __future__ import annotations

import functools
import math
import re
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from flexshaft.assembly.balance import design_eccentricity, permissible_eccentricity
from flexshaft.design import Design, DesignError, Problem
from flexshaft.design.reference import design_json_schema
from flexshaft.units import m_to_mm, rad_s_to_rpm

__all__ = [
    "Control",
    "LayupAngle",
    "advanced_overrides",
    "control_overrides",
    "design_controls",
    "layup_angles",
    "schema_property",
]


@dataclass(frozen=True)
class Control:
    """One variable of the page.

    Attributes
    ----------
    key : str
        Identifier on the page (the design path for a plain variable).
    label, group : str
        What it is and the panel it belongs to.
    unit : str
        Display unit.
    value : float
        The design's value in the display unit.
    paths : tuple of str
        Design paths it writes (a schema problem on one of them is shown at this control).
    scale : float
        Display value per design-file value (1000 for metres shown in mm).
    minimum, maximum : float or None
        The schema's bounds, in the display unit (None: none given).
    exclusive_minimum, exclusive_maximum : bool
        Whether the bound itself is refused.
    step : float
        Step of the arrow keys in the display unit (``log``: a factor).
    log : bool
        The variable spans decades (gains): its steps multiply.
    help : str
        The schema's description of the field.
    """

    key: str
    label: str
    group: str
    unit: str
    value: float
    paths: tuple[str, ...]
    scale: float = 1.0
    minimum: float | None = None
    maximum: float | None = None
    exclusive_minimum: bool = False
    exclusive_maximum: bool = False
    step: float = 1.0
    log: bool = False
    help: str = ""
    extra: Mapping[str, Any] = field(default_factory=dict)  # fixed overrides written with it

    def to_dict(self) -> dict:
        return {
            "key": self.key,
            "label": self.label,
            "group": self.group,
            "unit": self.unit,
            "value": self.value,
            "paths": list(self.paths),
            "minimum": self.minimum,
            "maximum": self.maximum,
            "exclusive_minimum": self.exclusive_minimum,
            "exclusive_maximum": self.exclusive_maximum,
            "step": self.step,
            "log": self.log,
            "help": self.help,
        }


# ------------------------------------------------------------------------------------------------
# The schema's bounds


@functools.lru_cache(maxsize=1)
def _schema() -> dict:
    return design_json_schema()


def _number_schema(prop: Mapping[str, Any]) -> Mapping[str, Any]:
    """The numeric alternative of a property (``anyOf: [number, null]`` for optional ones)."""
    for option in prop.get("anyOf", ()):
        if option.get("type") in ("number", "integer"):
            return {**option, "description": prop.get("description", option.get("description", ""))}
    return prop


def schema_property(model: Any, name: str) -> Mapping[str, Any]:
    """The JSON Schema of field ``name`` of the schema model instance ``model`` (its numeric
    alternative when optional): ``minimum``/``maximum`` or ``exclusiveMinimum``/``exclusiveMaximum``,
    ``unit`` and ``description``."""
    schema = _schema()
    node = schema if isinstance(model, Design) else schema["$defs"][type(model).__name__]
    return _number_schema(node["properties"][name])


def _bounded(key: str, label: str, group: str, model: Any, name: str, path: str, value: float, **kw: Any) -> Control:
    """A control of field ``name`` of ``model`` (at design ``path``) with the schema's bounds."""
    prop = schema_property(model, name)
    scale = kw.pop("scale", 1.0)

    def shown(bound: Any) -> float | None:
        return None if bound is None else float(bound) * scale

    low = prop.get("minimum", prop.get("exclusiveMinimum"))
    high = prop.get("maximum", prop.get("exclusiveMaximum"))
    return Control(
        key,
        label,
        group,
        value=float(value) * scale,
        paths=(path,),
        scale=scale,
        minimum=shown(low),
        maximum=shown(high),
        exclusive_minimum="exclusiveMinimum" in prop,
        exclusive_maximum="exclusiveMaximum" in prop,
        help=str(prop.get("description", "")),
        **kw,
    )


# ------------------------------------------------------------------------------------------------
# The layup's angles

# an angle of the stacking notation: optional sign or sign pair, then the number; a number
# after ")", "]" or "_" is a repeat count, not an angle (handled by the caller)
_ANGLE = re.compile(r"(?P<sign>±|∓|\+/-|-/\+|\+-|-\+|[+-])?\s*(?P<number>[0-9]+(?:\.[0-9]*)?|\.[0-9]+)")
_PAIR_SIGNS = ("±", "∓", "+/-", "-/+", "+-", "-+")


@dataclass(frozen=True)
class LayupAngle:
    """One control of the layup: the angle tokens it writes (start, end, sign factor)."""

    value: float  # [deg], of the first token
    tokens: tuple[tuple[int, int, float], ...]  # (start, end, factor): token = factor × value
    pair_symbol: bool = False  # one "±a" token


def layup_angles(layup: str) -> list[LayupAngle]:
    """The angle controls of a layup string: each ``a/-a`` (or ``a/a``, ``0/0``) pair of
    neighbouring angles is one control, a ``±a`` token one, any other angle its own.

    >>> [a.value for a in layup_angles("(55/-55/0/0)s")]
    [55.0, 0.0]
    """
    found: list[tuple[int, int, float, bool]] = []  # start, end, signed value, pair symbol
    for match in _ANGLE.finditer(layup):
        before = layup[: match.start()].rstrip()
        if before.endswith((")", "]", "_")):
            continue  # a repeat count
        sign = match.group("sign") or ""
        value = float(match.group("number"))
        if sign in ("-", "∓", "-/+", "-+"):
            value = -value
        found.append((match.start(), match.end(), value, sign in _PAIR_SIGNS))
    out: list[LayupAngle] = []
    i = 0
    while i < len(found):
        start, end, value, pair = found[i]
        if pair:
            out.append(LayupAngle(value, ((start, end, 1.0),), pair_symbol=True))
            i += 1
            continue
        if i + 1 < len(found) and not found[i + 1][3]:
            start2, end2, value2, _ = found[i + 1]
            between = layup[end:start2].strip()
            if between in ("/", ",") and abs(value2) == abs(value):
                # a ± pair (0/0 counts as one: the thesis's (a/-a/b/-b) family), or an equal pair
                factor = 1.0 if (value2 == value and value != 0.0) else -1.0
                out.append(LayupAngle(value, ((start, end, 1.0), (start2, end2, factor))))
                i += 2
                continue
        out.append(LayupAngle(value, ((start, end, 1.0),)))
        i += 1
    return out


def _angle_text(value: float) -> str:
    text = f"{value:.6g}"
    return "0" if text in ("-0", "0") else text


def _layup_with(layup: str, angles: list[LayupAngle], values: Mapping[int, float]) -> str:
    """``layup`` with the angles of ``values`` (control index -> degrees) rewritten in place."""
    edits = []
    for index, angle in enumerate(angles):
        if index not in values:
            continue
        new = float(values[index])
        for start, end, factor in angle.tokens:
            if angle.pair_symbol:  # "±a" is a/-a, "∓a" is -a/a (the layup grammar): the first ply's sign
                text = f"{'∓' if new < 0 else '±'}{_angle_text(abs(new))}"
            else:
                text = _angle_text(factor * new)
            edits.append((start, end, text))
    for start, end, text in sorted(edits, reverse=True):
        layup = layup[:start] + text + layup[end:]
    return layup


# ------------------------------------------------------------------------------------------------
# The controls of a design


def design_controls(design: Design) -> list[Control]:
    """The explorer's controls of ``design`` (see the module docstring), in page order."""
    controls: list[Control] = []
    shaft = design.shaft
    mm = m_to_mm(1.0)
    if shaft.layup is not None:
        layup_help = str(schema_property(shaft, "layup").get("description", ""))
        for k, angle in enumerate(layup_angles(shaft.layup)):
            signs = "±" if len(angle.tokens) == 2 and angle.tokens[1][2] < 0 or angle.pair_symbol else ""
            controls.append(
                Control(
                    f"layup.{k}",
                    f"ply angle {signs}a{k + 1} ({shaft.layup})",
                    "shaft",
                    "deg",
                    angle.value,
                    ("shaft.layup",),
                    help=layup_help,
                )
            )
    controls.append(
        _bounded(
            "shaft.wall_thickness",
            "wall thickness",
            "shaft",
            shaft,
            "wall_thickness",
            "shaft.wall_thickness",
            shaft.wall_thickness,
            unit="mm",
            scale=mm,
            step=0.1,
        )
    )
    controls.append(
        _bounded(
            "shaft.outer_diameter",
            "outer diameter",
            "shaft",
            shaft,
            "outer_diameter",
            "shaft.outer_diameter",
            shaft.outer_diameter,
            unit="mm",
            scale=mm,
            step=1.0,
        )
    )
    for i, b in enumerate(design.bearings):
        path = f"bearings[{i}]"
        if b.kind == "active":
            group = f"actuator {b.name}"
            controls.append(_bounded(f"{path}.x", "station x", group, b, "x", f"{path}.x", b.x, unit="m", step=0.05))
            if b.kp is not None:
                controls.append(
                    _bounded(f"{path}.kp", "K_p", group, b, "kp", f"{path}.kp", b.kp, unit="N/m", step=1.1, log=True)
                )
            if b.kd is not None:
                controls.append(
                    _bounded(f"{path}.kd", "K_d", group, b, "kd", f"{path}.kd", b.kd, unit="N s/m", step=10)
                )
        elif (role := getattr(b, "role", "hanger")) in ("hanger", "damper"):  # a gearbox's bearing stays
            controls.append(
                _bounded(f"{path}.x", f"{b.name} station x", f"{role}s", b, "x", f"{path}.x", b.x, unit="m", step=0.05)
            )
    operating = design.operating
    if operating.speed_rpm is not None:
        controls.append(
            _bounded(
                "operating.speed_rpm",
                "operating speed",
                "operating",
                operating,
                "speed_rpm",
                "operating.speed_rpm",
                operating.speed_rpm,
                unit="rpm",
                step=50.0,
            )
        )
    else:
        controls.append(
            _bounded(
                "operating.speed",
                "operating speed",
                "operating",
                operating,
                "speed",
                "operating.speed",
                operating.speed_rad_s,
                unit="rpm",
                scale=rad_s_to_rpm(1.0),
                step=50.0,
            )
        )
    controls.append(_balance_grade(design))
    return controls


def _balance_grade(design: Design) -> Control:
    """The balance grade G [mm/s]: the design's, or the grade of its eccentricity at the highest
    operating speed (ISO 21940-11, e = G/Ω_max); setting it sets the eccentricity to 0."""
    loads = design.loads
    grade = loads.balance_grade
    if grade is None:
        per_grade = permissible_eccentricity(1.0, design.operating.speed_limits[1])  # [m] per (mm/s)
        grade = design_eccentricity(design) / per_grade if per_grade > 0 else 0.0
    control = _bounded(
        "loads.balance_grade",
        "balance grade G",
        "operating",
        loads,
        "balance_grade",
        "loads.balance_grade",
        grade,
        unit="mm/s",
        step=1.1,
        log=True,
    )
    return Control(**{**vars(control), "paths": ("loads.balance_grade", "loads.eccentricity")})


# ------------------------------------------------------------------------------------------------
# Values to design overrides


def control_overrides(design: Design, values: Mapping[str, Any]) -> dict[str, Any]:
    """Design overrides (path -> design-file value) of control values in display units.

    Parameters
    ----------
    design : Design
        The design the controls were listed for (its layup is rewritten in place).
    values : mapping
        Control key -> value in the control's display unit.

    Raises
    ------
    DesignError
        For an unknown control or a value that is not a finite number (naming the field).
    """
    controls = {c.key: c for c in design_controls(design)}
    overrides: dict[str, Any] = {}
    angles: dict[int, float] = {}
    problems = []
    for key, raw in values.items():
        control = controls.get(key)
        if control is None:
            problems.append(Problem(str(key), f"no such control (allowed: {', '.join(controls)})"))
            continue
        if isinstance(raw, bool) or not isinstance(raw, (int, float)) or not math.isfinite(raw):
            problems.append(Problem(control.paths[0], f"{control.label}: expected a finite number, got {raw!r}"))
            continue
        if key.startswith("layup."):
            angles[int(key.split(".", 1)[1])] = float(raw)
        elif key == "loads.balance_grade":
            overrides["loads.balance_grade"] = float(raw)
            overrides["loads.eccentricity"] = 0.0
        else:
            overrides[control.paths[0]] = float(raw) / control.scale
    if problems:
        raise DesignError(problems, "<explorer>")
    if angles:
        layup = design.shaft.layup or ""
        overrides["shaft.layup"] = _layup_with(layup, layup_angles(layup), angles)
    return overrides


def advanced_overrides(entries: Mapping[str, str]) -> dict[str, Any]:
    """Overrides of the advanced field: dotted design path -> a TOML value as text (SI, as in
    a design file: ``0.0025``, ``"(45/-45)s"``, ``[0.0, -3.5, 0.0]``).

    Raises
    ------
    DesignError
        When a value is not a TOML value (naming the path).
    """
    out: dict[str, Any] = {}
    problems = []
    for path, text in entries.items():
        try:
            out[str(path)] = tomllib.loads(f"value = {text}")["value"]
        except (tomllib.TOMLDecodeError, TypeError):
            problems.append(
                Problem(str(path), f'not a TOML value (got {str(text)[:60]!r}; e.g. 0.0025, "(45/-45)s", [1, 2])')
            )
    if problems:
        raise DesignError(problems, "<explorer>")
    return out

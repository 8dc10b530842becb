"""What the optimizer varies and what it seeks: design variables with bounds, and objectives.

A :class:`DesignVariable` names one or more design-file paths (``"shaft.wall_thickness"``,
``"bearings[1].kp"``; several paths share one value, e.g. the gain of both active bearings) or a
placeholder of the problem's **layup template** (``"layup.a"`` fills ``{a}`` and ``{-a}`` in
``"({a}/{-a}/{b}/{-b})s"``). Values are in the design file's units: SI, ply angles in degrees.
``integer=True`` rounds the value (ply counts: a placeholder used as a repeat count, e.g.
``"(55/-55/0_{n})s"``; with ``ply_thickness`` the wall thickness then follows the ply count);
``log=True`` searches the logarithm (gains spanning decades). :func:`default_variables` is the
default search of ``flexshaft optimize``.

An :class:`Objective` is an output with a sense: for the driveline (:data:`DESIGN_OBJECTIVES`)
``driveline_mass`` (tubes, couplings, bearings and actuators) is minimised and ``min_margin``
(the smallest normalised margin of the constraints: the requirement that limits the design)
maximised, the default pair; ``shaft_mass``, ``safety_factor`` (the minimum Tsai-Wu safety
factor) and the others are there too.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

from flexshaft.design.bearings import ActiveBearing
from flexshaft.design.layup import AngleToken, angle_tokens, parse_layup

if TYPE_CHECKING:
    from flexshaft.design import Design

__all__ = [
    "DEFAULT_OBJECTIVES",
    "DESIGN_OBJECTIVES",
    "LAYUP_PLACEHOLDER",
    "LAYUP_PREFIX",
    "MOST_PLY_ANGLES",
    "PLY_ANGLE_SPREAD",
    "DesignVariable",
    "Objective",
    "OptimizeError",
    "TWO_ANGLE_BOUNDS",
    "TWO_ANGLE_TEMPLATE",
    "default_variables",
    "layup_template",
    "match_layup",
]


#: Prefix of a variable that fills a placeholder of the layup template.
LAYUP_PREFIX = "layup."
#: A placeholder of a layup template: ``{a}`` (the value) or ``{-a}`` (its negative).
LAYUP_PLACEHOLDER = re.compile(r"\{(-?)([A-Za-z_][A-Za-z0-9_]*)\}")


class OptimizeError(ValueError):
    """An optimization that cannot run: bad variable, objective, constraint or run folder."""


#: A variable's name: an identifier (letters, digits, _).
_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def _name_of(path: str) -> str:
    return re.sub(r"[^A-Za-z0-9_]+", "_", path).strip("_")


@dataclass(frozen=True, init=False)
class DesignVariable:
    """One search variable.

    Parameters
    ----------
    path : str or sequence of str
        Design path(s) set to the value, or ``"layup.<placeholder>"``.
    lower, upper : float
        Bounds, in the design file's unit of the path (SI; degrees for ply angles).
    integer : bool
        Round to integers (bounds must be integers).
    log : bool
        Search log10 of the value (bounds must be positive).
    name : str, optional
        Name in the results (default: the first path with non-identifier characters as ``_``).
    units : str
        Unit of the value for the results' attributes.
    significant_digits : int or None
        Values are rounded to this many significant digits (clean design files, and candidates
        that differ below it are one design); None: exact.
    """

    path: str | tuple[str, ...]
    lower: float
    upper: float
    integer: bool
    log: bool
    name: str  # resolved: the default is made from the path
    units: str
    significant_digits: int | None

    def __init__(
        self,
        path: str | Sequence[str],
        lower: float,
        upper: float,
        integer: bool = False,
        log: bool = False,
        name: str | None = None,
        units: str = "",
        significant_digits: int | None = 4,
    ) -> None:
        for field_name, value in (
            ("lower", lower),
            ("upper", upper),
            ("integer", integer),
            ("log", log),
            ("units", units),
            ("significant_digits", significant_digits),
        ):
            object.__setattr__(self, field_name, value)  # a frozen dataclass
        paths = (path,) if isinstance(path, str) else tuple(path)
        if not paths or not all(isinstance(p, str) and p.strip() for p in paths):
            raise OptimizeError(f"variable path: give one or more design paths (got {path!r})")
        paths = tuple(p.strip() for p in paths)
        object.__setattr__(self, "path", paths if len(paths) > 1 else paths[0])
        where = f"variable {paths[0]!r}"
        for label, value in (("lower", self.lower), ("upper", self.upper)):
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                raise OptimizeError(f"{where}: {label} bound must be a finite number (got {value!r})")
        if not self.lower < self.upper:
            raise OptimizeError(f"{where}: lower bound {self.lower!r} must be less than upper bound {self.upper!r}")
        if self.log and self.lower <= 0:
            raise OptimizeError(f"{where}: a log-scale variable needs a positive lower bound (got {self.lower!r})")
        if self.integer and (self.lower != int(self.lower) or self.upper != int(self.upper)):
            raise OptimizeError(
                f"{where}: an integer variable needs integer bounds (got {self.lower!r}, {self.upper!r})"
            )
        if self.integer and self.log:
            raise OptimizeError(f"{where}: a variable is either integer or log-scale, not both")
        if self.significant_digits is not None and not (
            isinstance(self.significant_digits, int) and 1 <= self.significant_digits <= 17
        ):
            raise OptimizeError(
                f"{where}: significant_digits must be an integer from 1 to 17 or None (got {self.significant_digits!r})"
            )
        if any(p.startswith(LAYUP_PREFIX) for p in paths) and len(paths) > 1:
            raise OptimizeError(f"{where}: a layup placeholder cannot share a variable with other paths")
        name = name if name is not None else _name_of(paths[0])
        if not _IDENTIFIER.fullmatch(name or ""):
            raise OptimizeError(f"{where}: name must be an identifier (letters, digits, _), got {name!r}")
        object.__setattr__(self, "name", name)

    @property
    def paths(self) -> tuple[str, ...]:
        return (self.path,) if isinstance(self.path, str) else tuple(self.path)

    @property
    def placeholder(self) -> str | None:
        """The layup placeholder this variable fills, or None."""
        p = self.paths[0]
        return p[len(LAYUP_PREFIX) :] if p.startswith(LAYUP_PREFIX) else None

    @property
    def search_bounds(self) -> tuple[float, float]:
        """Bounds in the search space (log10 for log-scale variables)."""
        if self.log:
            return math.log10(self.lower), math.log10(self.upper)
        return float(self.lower), float(self.upper)

    def decode(self, x: float) -> float | int:
        """The value of search coordinate ``x`` (clipped to the bounds, rounded if integer)."""
        value = 10.0 ** float(x) if self.log else float(x)
        value = min(max(value, float(self.lower)), float(self.upper))
        if self.integer:
            return int(round(value))
        if self.significant_digits is not None and value != 0.0:
            value = float(f"{value:.{self.significant_digits}g}")
            value = min(max(value, float(self.lower)), float(self.upper))
        return value

    def encode(self, value: float) -> float:
        """The search coordinate of ``value``."""
        return math.log10(value) if self.log else float(value)

    def spec(self) -> dict:
        return {
            "path": list(self.paths),
            "lower": self.lower,
            "upper": self.upper,
            "integer": self.integer,
            "log": self.log,
            "name": self.name,
            "units": self.units,
            "significant_digits": self.significant_digits,
        }


@dataclass(frozen=True)
class Objective:
    """An output to minimise (``sense="min"``) or maximise (``"max"``), with a label for figures."""

    output: str
    sense: Literal["min", "max"] = "min"
    label: str = ""

    def __post_init__(self) -> None:
        if self.sense not in ("min", "max"):
            raise OptimizeError(f"objective {self.output!r}: sense must be 'min' or 'max' (got {self.sense!r})")


#: The driveline's objectives by name (outputs of :func:`~flexshaft.optimize.evaluate.design_metrics`).
DESIGN_OBJECTIVES = {
    "driveline_mass": Objective("driveline_mass", "min", "driveline mass, actuators included [kg]"),
    "min_margin": Objective("min_margin", "max", "smallest normalised margin of the requirements [-]"),
    "shaft_mass": Objective("shaft_mass", "min", "shaft mass [kg]"),
    "safety_factor": Objective("safety_factor", "max", "minimum Tsai-Wu safety factor [-]"),
    "buckling_safety_factor": Objective("buckling_safety_factor", "max", "torsional-buckling safety factor [-]"),
    "actuator_force": Objective("actuator_force", "min", "peak actuator force [N]"),
    "actuator_orbit": Objective("actuator_orbit", "min", "peak actuator excursion [m]"),
    "spinup_deflection": Objective("spinup_deflection", "min", "peak spin-up shaft orbit [m]"),
    "max_temperature": Objective("max_temperature", "min", "maximum shaft temperature [K]"),
    "min_log_decrement": Objective("min_log_decrement", "max", "smallest whirl log decrement [-]"),
}


#: An angle as a layup writes it, captured (with an optional sign and exponent).
_ANGLE_TEXT = r"\s*([-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)\s*"


def match_layup(template: str, layup: str) -> dict[str, float] | None:
    """Placeholder values that turn ``template`` into ``layup`` (None if it does not fit); a
    placeholder read as 90° in one place and −90° in another is 90° (the same ply)."""
    pattern, groups, position = "", [], 0
    for m in LAYUP_PLACEHOLDER.finditer(template):
        pattern += re.escape(template[position : m.start()]) + _ANGLE_TEXT
        groups.append((m.group(1) == "-", m.group(2)))
        position = m.end()
    pattern += re.escape(template[position:])
    found = re.fullmatch(pattern.replace(r"\ ", r"\s*"), layup.replace(" ", ""))
    if found is None:
        return None
    out: dict[str, float] = {}
    for (negated, name), text in zip(groups, found.groups()):
        value = -float(text) if negated else float(text)
        if name in out and not math.isclose(out[name], value, abs_tol=1e-9):
            if abs(out[name]) == abs(value) == 90.0:
                continue
            return None
        out[name] = value + 0.0  # -0.0 -> 0.0
    return out


#: The default objectives of ``flexshaft optimize``: total mass against the margin that limits.
DEFAULT_OBJECTIVES = ("driveline_mass", "min_margin")


#: The thesis's two-angle layup family: the default search of a design whose layup is in it.
TWO_ANGLE_TEMPLATE = "({a}/{-a}/{b}/{-b})s"
#: Bounds of the two-angle family's ply angles a and b [deg].
TWO_ANGLE_BOUNDS = {"a": (30.0, 75.0), "b": (0.0, 30.0)}
#: How far a derived template's ply angle may move from the design's own [deg] (:func:`layup_template`).
PLY_ANGLE_SPREAD = 15.0
#: Most distinct ply angles a derived template varies (more: the two-angle family instead).
MOST_PLY_ANGLES = 4
#: A ply angle no layup is expected to hold [deg]: turned to it, a 0° or 90° group shows
#: whether turning keeps the laminate balanced (:func:`layup_template`).
_PROBE_TURN = 7.123456789


def _balanced_when_turned(tokens: Sequence[AngleToken], letters: dict[float, str], layup: str, turned: float) -> bool:
    """Whether the plies of magnitude ``turned`` (0 or 90), turned by a small angle with their
    signs alternating as :func:`layup_template` writes them, pair off as +θ/−θ."""
    probe = _PROBE_TURN if turned == 0.0 else 90.0 - _PROBE_TURN
    values = {letter: (probe if magnitude == turned else magnitude) for magnitude, letter in letters.items()}
    plies = parse_layup(_render(tokens, letters, layup, values, frozenset()))
    return plies.count(probe) == plies.count(-probe)


def _render(
    tokens: Sequence[AngleToken],
    letters: dict[float, str],
    layup: str,
    values: dict[str, float] | None,
    held: frozenset[float],
) -> str:
    """``layup`` with each angle token replaced: by its placeholder (``values`` None) or by a
    value; the magnitudes in ``held`` stay as written. Unsigned 0° and 90° tokens alternate
    in sign, the first positive."""
    pieces, position, seen = [], 0, dict.fromkeys(letters, 0)
    for token in tokens:
        pieces.append(layup[position : token.start])
        position = token.end
        if token.magnitude in held:
            pieces.append(layup[token.start : token.end])
            continue
        letter = letters[token.magnitude]
        negate = False
        if not token.signed and token.magnitude in (0.0, 90.0):
            seen[token.magnitude] += 1
            negate = seen[token.magnitude] % 2 == 0
        if values is None:
            pieces.append(("{-" if negate else "{") + letter + "}")
        else:
            pieces.append(repr(-values[letter] if negate else values[letter]))
    pieces.append(layup[position:])
    return "".join(pieces)


def layup_template(layup: str, spread: float = PLY_ANGLE_SPREAD) -> tuple[str, tuple[DesignVariable, ...]] | None:
    """A layup template that writes ``layup`` in its own notation with one placeholder per
    distinct ply-angle magnitude, and its ply-angle variables, each within ``spread`` degrees of
    the design's own angle (and within [0, 90]); None with more than :data:`MOST_PLY_ANGLES`
    magnitudes.

    ``"(60/-60/60/-60/0/0)s"`` gives ``"({a}/-{a}/{a}/-{a}/{b}/{-b})s"`` with a in [45, 75]°
    and b in [0, 15]°: a sign written stays in front of its placeholder, and the unsigned 0°
    (and 90°) plies alternate in sign, so that turning them keeps the laminate balanced. Where
    they cannot pair off (an odd number, a ply count ``0_3``, a repeated group ``(0/90)2s``:
    checked on the plies the template expands to) they stay as written, not searched. Filled
    with the design's own angles the template is the design's layup string.
    """
    tokens = angle_tokens(layup)
    letters: dict[float, str] = {}
    for token in tokens:
        if token.magnitude not in letters:
            if len(letters) == MOST_PLY_ANGLES:
                return None
            letters[token.magnitude] = "abcd"[len(letters)]
    held = frozenset(m for m in (0.0, 90.0) if m in letters and not _balanced_when_turned(tokens, letters, layup, m))
    # letters in order of first appearance among the searched magnitudes: a, b, ...
    searched = {m: "abcd"[k] for k, m in enumerate(m for m in letters if m not in held)}
    template = _render(tokens, {**searched, **dict.fromkeys(held, "")}, layup, None, held)
    variables = tuple(
        DesignVariable(
            f"{LAYUP_PREFIX}{letter}",
            max(0.0, magnitude - spread),
            min(90.0, magnitude + spread),
            name=f"ply_angle_{letter}",
            units="degree",
        )
        for magnitude, letter in searched.items()
    )
    return template, variables


def _in_two_angle_family(layup: str) -> bool:
    """Whether ``layup`` expands to (a/−a/b/−b)s with a and b within :data:`TWO_ANGLE_BOUNDS`."""
    plies = parse_layup(layup)
    if len(plies) != 8:
        return False
    a, b = plies[0], plies[2]
    family = (a, -a, b, -b, -b, b, -a, a)
    (a_low, a_high), (b_low, b_high) = TWO_ANGLE_BOUNDS["a"], TWO_ANGLE_BOUNDS["b"]
    return all(p == q or abs(p) == abs(q) == 90.0 for p, q in zip(plies, family)) and (
        a_low <= a <= a_high and b_low <= b <= b_high
    )


def _two_angle_variables() -> list[DesignVariable]:
    return [
        DesignVariable(f"{LAYUP_PREFIX}{k}", lower, upper, name=f"ply_angle_{k}", units="degree")
        for k, (lower, upper) in TWO_ANGLE_BOUNDS.items()
    ]


def _gain_groups(magnets: dict[int, ActiveBearing], key: str) -> list[tuple[tuple[int, ...], str]]:
    """The active bearings that share one gain variable ``key`` ("kp" or "kd"), with its name:
    all of them (``key``) when they have the same gain, else each its own (``<name>_<key>``),
    so that the search holds the design either way."""
    if len({getattr(b, key) for b in magnets.values()}) <= 1:
        return [(tuple(magnets), key)]
    return [((i,), _own_name(b.name, i, key)) for i, b in magnets.items()]


def _own_name(bearing: str, index: int, key: str) -> str:
    """``<bearing>_<key>`` as an identifier, or ``bearings_<index>_<key>`` for a bearing whose
    name does not start one (e.g. "1")."""
    name = _name_of(f"{bearing}_{key}")
    return name if _IDENTIFIER.fullmatch(name) else f"bearings_{index}_{key}"


def default_variables(design: Design, layup: str | None = None) -> tuple[tuple[DesignVariable, ...], str | None]:
    """The default search of ``flexshaft optimize`` on a design, and its layup template.

    Built to hold the design it starts from (the optimizer seeds its first generation with it):

    * ply angles: with a template ``layup`` given, its placeholders a and b within the bounds
      of the thesis's two-angle family ``(a/−a/b/−b)s``, a in [30, 75]°, b in [0, 30]°
      (optimum (55/−55/0/0)s). Else the family itself when the design's layup is in it with its
      angles in those bounds (written as the family's template when the text fits it, else in
      the design's own notation); else the design's own layup, each distinct angle within ±15°
      of its own (:func:`layup_template`; more than four angles: the family);
    * wall thickness from 1 mm to 4 mm (or to the design's own), at the design's outer diameter;
    * the active bearings' K_p (log scale, 1e5 to 1e7 N/m, or to the design's own) and K_d (0 to
      3000 N s/m, or to the design's own), each one variable shared by every active bearing when
      their gains are equal, else one a bearing (``<name>_kp``, ``<name>_kd``);
    * each active bearing's station within ±1 m of its own, at least 0.3 m from its neighbours.

    The design is not held when a K_p is 0 (a log scale), a bearing stands within 0.3 m of its
    neighbour, or an active bearing has a controller transfer function instead of K_p and K_d.
    """
    variables: list[DesignVariable] = []
    template = None
    own = design.shaft.layup
    if layup is not None:
        template = layup
        variables += _two_angle_variables()
    elif own is not None:
        in_family = _in_two_angle_family(own)
        derived = layup_template(own)
        if (in_family and match_layup(TWO_ANGLE_TEMPLATE, own) is not None) or derived is None:
            template = TWO_ANGLE_TEMPLATE
            variables += _two_angle_variables()
        elif in_family and [v.placeholder for v in derived[1]] == ["a", "b"]:
            template = derived[0]
            variables += _two_angle_variables()
        elif derived[1]:
            template, angles = derived
            variables += angles
    wall = design.shaft.wall_thickness
    variables.append(
        DesignVariable("shaft.wall_thickness", min(0.001, wall), max(0.004, wall), name="wall_thickness", units="m")
    )
    bearings = list(design.bearings)
    magnets = {i: b for i, b in enumerate(bearings) if isinstance(b, ActiveBearing)}
    active = list(magnets)
    if active:
        gains = [float(b.kp) for b in magnets.values() if b.kp is not None and b.kp > 0]
        damping = [float(b.kd) for b in magnets.values() if b.kd is not None]
        for group, name in _gain_groups(magnets, "kp"):
            variables.append(
                DesignVariable(
                    tuple(f"bearings[{i}].kp" for i in group),
                    min([1e5, *gains]),
                    max([1e7, *gains]),
                    log=True,
                    name=name,
                    units="N m-1",
                )
            )
        for group, name in _gain_groups(magnets, "kd"):
            variables.append(
                DesignVariable(
                    tuple(f"bearings[{i}].kd" for i in group), 0.0, max([3000.0, *damping]), name=name, units="N s m-1"
                )
            )
        stations = sorted(b.x for b in bearings)
        for i in active:
            x = bearings[i].x
            k = stations.index(x)
            below = stations[k - 1] + 0.3 if k > 0 else design.shaft.x_start + 0.3
            above = stations[k + 1] - 0.3 if k + 1 < len(stations) else design.shaft.x_end - 0.3
            lower, upper = max(x - 1.0, below), min(x + 1.0, above)
            if lower < upper:
                variables.append(
                    DesignVariable(
                        f"bearings[{i}].x",
                        round(lower, 3),
                        round(upper, 3),
                        name=_own_name(bearings[i].name, i, "x"),
                        units="m",
                    )
                )
    return tuple(variables), template

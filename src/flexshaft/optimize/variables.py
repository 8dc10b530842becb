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
from typing import Literal

__all__ = [
    "DEFAULT_OBJECTIVES",
    "DESIGN_OBJECTIVES",
    "DesignVariable",
    "LAYUP_PREFIX",
    "Objective",
    "OptimizeError",
    "default_variables",
]


#: Prefix of a variable that fills a placeholder of the layup template.
LAYUP_PREFIX = "layup."


class OptimizeError(ValueError):
    """An optimization that cannot run: bad variable, objective, constraint or run folder."""


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
        if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name or ""):
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


#: The default objectives of ``flexshaft optimize``: total mass against the margin that limits.
DEFAULT_OBJECTIVES = ("driveline_mass", "min_margin")


def default_variables(design) -> tuple[tuple[DesignVariable, ...], str | None]:
    """The default search of ``flexshaft optimize`` on a design, and its layup template.

    * ply angles of a ``(a/−a/b/−b)s`` laminate: a in [30, 75]°, b in [0, 30]° (the thesis's
      two-angle family, optimum (55/−55/0/0)s);
    * wall thickness from 1 mm to 4 mm at the design's outer diameter;
    * the active bearings' K_p (shared, log scale, 1e5 to 1e7 N/m) and K_d (shared, 0 to
      3000 N s/m);
    * each active bearing's station within ±1 m of its own, at least 0.3 m from its neighbours.
    """
    variables = []
    template = None
    if design.shaft.layup is not None:
        template = "({a}/{-a}/{b}/{-b})s"
        variables += [
            DesignVariable("layup.a", 30.0, 75.0, name="ply_angle_a", units="degree"),
            DesignVariable("layup.b", 0.0, 30.0, name="ply_angle_b", units="degree"),
        ]
    variables.append(DesignVariable("shaft.wall_thickness", 0.001, 0.004, name="wall_thickness", units="m"))
    bearings = list(design.bearings)
    active = [i for i, b in enumerate(bearings) if b.kind == "active"]
    if active:
        variables.append(
            DesignVariable(tuple(f"bearings[{i}].kp" for i in active), 1e5, 1e7, log=True, name="kp", units="N m-1")
        )
        variables.append(
            DesignVariable(tuple(f"bearings[{i}].kd" for i in active), 0.0, 3000.0, name="kd", units="N s m-1")
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
                        name=_name_of(f"{bearings[i].name}_x"),
                        units="m",
                    )
                )
    return tuple(variables), template

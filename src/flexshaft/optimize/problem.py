"""What the optimizer searches: a :class:`DesignProblem` of design variables with bounds
(:mod:`flexshaft.optimize.variables`), objectives and constraints on a base design.

Constraints are outputs that must be ``>= 0``: the verdict checks' normalised margins
(:func:`~flexshaft.verdict.result.normalised_margin`).

A check that is **not evaluated** (its margin is NaN) is a violated constraint, never a
satisfied one: it counts as a violation of :data:`NOT_EVALUATED_VIOLATION` (the margin of a
design that fails by its whole limit). A requirement the design never evaluates (e.g. no
``max_spinup_deflection``) must be left out of ``constraints`` explicitly. A design the schema
refuses (a bearing moved past its neighbour) or whose evaluation fails is infeasible through one
more constraint, ``valid``.
"""

from __future__ import annotations

import hashlib
import json
import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from flexshaft import __version__
from flexshaft.design import Design, DesignError, baseline_design, embedded_text, with_overrides
from flexshaft.design.io import path_replaces, paths_overlap, value_at_path
from flexshaft.design.layup import parse_layup
from flexshaft.optimize.evaluate import CHECK_KEYS, FIDELITIES, applicable_checks, design_outputs, metric_outputs
from flexshaft.optimize.variables import (
    DEFAULT_OBJECTIVES,
    DESIGN_OBJECTIVES,
    LAYUP_PLACEHOLDER,
    DesignVariable,
    Objective,
    OptimizeError,
    match_layup,
)

__all__ = ["DERIVED_OUTPUTS", "DesignProblem", "NOT_EVALUATED_VIOLATION", "objectives_and_constraints"]

#: Constraint violation of a check that was not evaluated (a failure by the whole limit).
NOT_EVALUATED_VIOLATION = 1.0

#: Outputs a problem derives from its constraints (not computed by the evaluation), by name:
#: (unit, long name). ``min_margin`` is the smallest normalised margin of the problem's
#: constraints (a check not evaluated counts as −:data:`NOT_EVALUATED_VIOLATION`): the
#: requirement that limits the design, whichever it is; ignored checks do not count.
DERIVED_OUTPUTS = {
    "min_margin": (
        "1",
        "smallest normalised margin of the constraints (the requirement that limits; not evaluated: -1)",
    )
}
#: Objective value given to a design without a result (never compared: it is infeasible).
_NO_RESULT = 1e30


def _output_triple(output: Sequence[str]) -> tuple[str, str, str]:
    """``(name, unit, long name)`` of an evaluation output."""
    name, unit, long_name = output
    return name, unit, long_name


def _qualname(func: Callable) -> str:
    return f"{getattr(func, '__module__', '?')}.{getattr(func, '__qualname__', repr(func))}"


def _format_angle(value: float) -> str:
    # the decoded value as is (4 significant digits by default): the layup written is the design evaluated
    text = f"{float(value):.6g}"
    return "0" if text == "-0" else text


@dataclass(frozen=True, init=False)
class DesignProblem:
    """A design optimization: variables, objectives and constraints on a base design.

    Parameters
    ----------
    variables : sequence of DesignVariable
    base : Design, optional
        The design every candidate starts from (default: the embedded Table 3.1 baseline).
    objectives : sequence of str or Objective
        Names of :data:`DESIGN_OBJECTIVES` or :class:`Objective` on any output (or on
        ``min_margin``, :data:`DERIVED_OUTPUTS`). Default :data:`DEFAULT_OBJECTIVES`: the
        driveline mass and the smallest normalised margin.
    constraints : sequence of str, optional
        Outputs that must be >= 0; a verdict check key (``"tsai_wu"``) stands for its margin
        output ``margin_<key>``. Default: every verdict check.
    layup : str, optional
        Layup template with ``{name}`` / ``{-name}`` placeholders filled by ``layup.<name>``
        variables, e.g. ``"({a}/{-a}/{b}/{-b})s"`` (degrees; a placeholder after ``_`` is a ply
        repeat count and its variable must be integer).
    ply_thickness : float, optional
        Cured ply thickness [m]: the wall thickness becomes plies × ply_thickness.
    fixed : mapping, optional
        Design overrides applied to every candidate.
    fidelity : {"verdict", "screening"}
        Resolution of the evaluation (:data:`~flexshaft.optimize.evaluate.FIDELITIES`).
    evaluate : callable, optional
        Sweep output function ``evaluate(point) -> {output: float}`` (module level, for worker
        processes); default the driveline evaluation.
    outputs : sequence of (name, unit, long name), optional
        What ``evaluate`` returns (default: the driveline metrics and checks).
    name : str
        Title of the results.
    base_text : str, optional
        The base design file's text (TOML): the design files written keep its comments
        (:func:`~flexshaft.optimize.files.design_toml`). Default: the embedded baseline's text
        when ``base`` is omitted, else none. Not part of the search's identity.
    """

    # the resolved values (the constructor takes names and sequences: see Parameters)
    variables: tuple[DesignVariable, ...]
    base: Design
    objectives: tuple[Objective, ...]
    constraints: tuple[str, ...]
    layup: str | None
    ply_thickness: float | None
    fixed: Mapping[str, Any]
    fidelity: str
    evaluate: Callable
    outputs: tuple[tuple[str, str, str], ...]
    name: str
    base_text: str | None = field(compare=False, repr=False)

    def __init__(
        self,
        variables: Sequence[DesignVariable],
        base: Design | None = None,
        objectives: Sequence[str | Objective] = DEFAULT_OBJECTIVES,
        constraints: Sequence[str] | None = None,
        layup: str | None = None,
        ply_thickness: float | None = None,
        fixed: Mapping[str, Any] | None = None,
        fidelity: str = "verdict",
        evaluate: Callable = design_outputs,
        outputs: Sequence[Sequence[str]] | None = None,
        name: str = "design optimization",
        base_text: str | None = None,
    ) -> None:
        def set_field(field_name: str, value: Any) -> None:
            object.__setattr__(self, field_name, value)  # a frozen dataclass

        if base is None:
            base = baseline_design()
            if base_text is None:
                base_text = embedded_text("baseline")
        set_field("base", base)
        set_field("base_text", base_text)
        resolved = tuple(variables)
        if not resolved:
            raise OptimizeError("an optimization needs at least one variable")
        if not all(isinstance(v, DesignVariable) for v in resolved):
            raise OptimizeError("variables must be DesignVariable objects")
        set_field("variables", resolved)
        names = [v.name for v in resolved]
        if len(set(names)) != len(names):
            raise OptimizeError(f"variable names must be unique, got {names}")
        paths = [p for v in resolved for p in v.paths]
        shared = [
            (p, q)
            for i, v in enumerate(resolved)
            for w in resolved[i + 1 :]
            for p in v.paths
            for q in w.paths
            if paths_overlap(p, q)
        ]
        if len(set(paths)) != len(paths) or shared:
            raise OptimizeError(f"a design path may belong to one variable only, got {paths}")
        set_field("layup", layup)
        set_field("ply_thickness", ply_thickness)
        set_field("fixed", dict(fixed or {}))
        searched = [(p, f) for p in paths for f in self.fixed if path_replaces(p, f)]
        if searched:  # overrides() applies fixed first: every candidate would take the variable's value
            path, fixed_path = searched[0]
            same = "" if path == fixed_path else f" (over the fixed {fixed_path})"
            raise OptimizeError(
                f"{path} is both fixed and a variable's path{same}, and the variable would win in every "
                "candidate: fix it or search it, not both"
            )
        set_field("evaluate", evaluate)
        set_field("name", name)
        if fidelity not in FIDELITIES:
            raise OptimizeError(f"fidelity: must be one of {', '.join(FIDELITIES)} (got {fidelity!r})")
        set_field("fidelity", fidelity)
        set_field("outputs", tuple(_output_triple(o) for o in (outputs if outputs is not None else metric_outputs())))
        set_field("constraints", self._resolve_constraints(constraints))
        set_field("objectives", self._resolve_objectives(objectives))
        if self.ply_thickness is not None and not (math.isfinite(self.ply_thickness) and self.ply_thickness > 0):
            raise OptimizeError(f"ply_thickness: must be a positive thickness [m] (got {self.ply_thickness!r})")
        self._check_layup()

    # -- resolution and checks -----------------------------------------------------------------
    @property
    def output_names(self) -> tuple[str, ...]:
        """The evaluation's outputs, in the order of its records."""
        return tuple(o[0] for o in self.outputs)

    @property
    def derived_outputs(self) -> tuple[tuple[str, str, str], ...]:
        """``(name, unit, long name)`` of the outputs derived from the constraints
        (:data:`DERIVED_OUTPUTS`; none without constraints, or when the evaluation has one of
        that name)."""
        if not self.constraints:
            return ()
        return tuple((k, u, t) for k, (u, t) in DERIVED_OUTPUTS.items() if k not in self.output_names)

    @property
    def all_output_names(self) -> tuple[str, ...]:
        """The evaluation's outputs, then the derived ones."""
        return self.output_names + tuple(o[0] for o in self.derived_outputs)

    def with_derived(self, outputs: ArrayLike) -> np.ndarray:
        """Outputs (n, n_outputs) in the order of :attr:`output_names`, with the derived
        columns appended (the order of :attr:`all_output_names`)."""
        outputs = np.atleast_2d(np.asarray(outputs, dtype=float))
        if not self.derived_outputs:
            return outputs
        return np.column_stack([outputs, self.constraint_margins(outputs).min(axis=1)])

    def limiting(self, outputs: ArrayLike) -> list[str]:
        """The constraint with the smallest margin of each row (its check key: ``tsai_wu``,
        not ``margin_tsai_wu``); empty strings without constraints."""
        outputs = np.atleast_2d(np.asarray(outputs, dtype=float))
        if not self.constraints:
            return [""] * outputs.shape[0]
        margins = self.constraint_margins(outputs)
        return [self.constraints[k].removeprefix("margin_") for k in np.argmin(margins, axis=1)]

    def constraint_margins(self, outputs: ArrayLike) -> np.ndarray:
        """Margins (n, n_constraints) of the constraints, a not-evaluated (NaN) one as
        −:data:`NOT_EVALUATED_VIOLATION`."""
        outputs = np.atleast_2d(np.asarray(outputs, dtype=float))
        index = {name: i for i, name in enumerate(self.output_names)}
        margins = outputs[:, [index[c] for c in self.constraints]].reshape(outputs.shape[0], len(self.constraints))
        return np.where(np.isnan(margins), -NOT_EVALUATED_VIOLATION, margins)

    def _resolve_objectives(self, objectives: Sequence[str | Objective]) -> tuple[Objective, ...]:
        out = []
        for item in objectives:
            if isinstance(item, Objective):
                objective = item
            elif isinstance(item, str) and item in DESIGN_OBJECTIVES:
                objective = DESIGN_OBJECTIVES[item]
            else:
                raise OptimizeError(
                    f"objective: unknown name {item!r} (allowed: {', '.join(DESIGN_OBJECTIVES)}, "
                    "or an Objective on an output)"
                )
            if objective.output not in self.all_output_names:
                raise OptimizeError(
                    f"objective {objective.output!r}: not an output of the evaluation "
                    f"(outputs: {', '.join(self.all_output_names)})"
                )
            out.append(objective)
        if not out:
            raise OptimizeError("an optimization needs at least one objective")
        if len({o.output for o in out}) != len(out):
            raise OptimizeError(f"objectives must differ, got {[o.output for o in out]}")
        return tuple(out)

    def _resolve_constraints(self, constraints: Sequence[str] | None) -> tuple[str, ...]:
        given: Sequence[str]
        if constraints is None and "margin_tsai_wu" in self.output_names:
            given = applicable_checks(self.base)  # the base design's verdict: its parts decide which checks apply
        else:
            given = constraints or ()
        out = []
        for name in given:
            output = f"margin_{name}" if name in CHECK_KEYS else name
            if output not in self.output_names:
                allowed = ", ".join(k for k in CHECK_KEYS if f"margin_{k}" in self.output_names) or ", ".join(
                    self.output_names
                )
                raise OptimizeError(f"constraint: unknown check or output {name!r} (allowed: {allowed})")
            out.append(output)
        if len(set(out)) != len(out):
            raise OptimizeError(f"constraints must differ, got {out}")
        return tuple(out)

    def _check_layup(self) -> None:
        layup_vars = {v.placeholder: v for v in self.variables if v.placeholder is not None}
        if self.layup is None:
            if layup_vars:
                raise OptimizeError(
                    f"variables {sorted('layup.' + k for k in layup_vars)} need a layup template "
                    '(e.g. layup = "({a}/{-a}/{b}/{-b})s")'
                )
            if self.ply_thickness is not None:
                raise OptimizeError("ply_thickness needs a layup template (the ply count comes from it)")
            return
        used = {m.group(2) for m in LAYUP_PLACEHOLDER.finditer(self.layup)}
        if used != set(layup_vars):
            raise OptimizeError(
                f"layup template {self.layup!r}: placeholders {sorted(used)} must match the layup "
                f"variables {sorted(layup_vars)} (paths layup.<name>)"
            )
        for m in LAYUP_PLACEHOLDER.finditer(self.layup):
            if self.layup[: m.start()].endswith("_") and not layup_vars[m.group(2)].integer:
                raise OptimizeError(
                    f"layup template {self.layup!r}: {{{m.group(2)}}} is a ply count, its variable must be integer"
                )
        # the template's layup (and wall) are written last: a path it would replace, however
        # written, would be set for nothing (a [shaft] table is refined, not replaced)
        given = [*self.fixed, *(p for v in self.variables for p in v.paths)]
        if any(path_replaces("shaft.layup", p) for p in given):
            raise OptimizeError("give the layup either as a template or through shaft.layup, not both")
        if self.ply_thickness is not None and any(path_replaces("shaft.wall_thickness", p) for p in given):
            raise OptimizeError(
                "with ply_thickness the wall thickness follows the ply count; do not set shaft.wall_thickness too"
            )

    def validate(self) -> None:
        """Check every path and both bounds of every variable against the design schema.

        Each variable is set to its lower and its upper bound with the others at the middle of
        their range; raises :class:`OptimizeError` naming the variable and the schema's message.
        """
        middle = {v.name: v.decode(sum(v.search_bounds) / 2) for v in self.variables}
        for v in self.variables:
            for bound in (v.lower, v.upper):
                values = {**middle, v.name: int(bound) if v.integer else float(bound)}
                try:
                    with_overrides(self.base, self.overrides(values))
                except DesignError as exc:
                    raise OptimizeError(
                        f"variable {v.name!r} = {bound!r} (others mid-range) gives an invalid design:\n{exc}"
                    ) from None

    # -- candidates ----------------------------------------------------------------------------
    @property
    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower and upper bounds of the search space (log10 for log-scale variables)."""
        b = np.array([v.search_bounds for v in self.variables], dtype=float)
        return b[:, 0], b[:, 1]

    @property
    def integer_mask(self) -> np.ndarray:
        return np.array([v.integer for v in self.variables])

    def values(self, x: Sequence[float]) -> dict[str, float | int]:
        """Variable values by name of one search point."""
        return {v.name: v.decode(xi) for v, xi in zip(self.variables, x)}

    def overrides(self, values: Mapping[str, float | int]) -> dict[str, Any]:
        """Design overrides (``fixed`` first) of a candidate's variable values."""
        out = dict(self.fixed)
        for v in self.variables:
            if v.placeholder is None:
                out.update(dict.fromkeys(v.paths, values[v.name]))
        if self.layup is not None:
            layup = self.layup_of(values)
            out["shaft.layup"] = layup
            if self.ply_thickness is not None:
                out["shaft.wall_thickness"] = len(parse_layup(layup)) * float(self.ply_thickness)
        return out

    def layup_of(self, values: Mapping[str, float | int]) -> str:
        """The layup string of a candidate (placeholders filled, degrees)."""
        by_placeholder = {v.placeholder: values[v.name] for v in self.variables if v.placeholder is not None}

        def fill(m: re.Match) -> str:
            value = by_placeholder[m.group(2)]
            if isinstance(value, int):
                return str(-value if m.group(1) else value)
            return _format_angle(-value if m.group(1) else value)

        return LAYUP_PLACEHOLDER.sub(fill, self.layup or "")

    def base_values(self) -> dict[str, float | int] | None:
        """The base design's variable values (to seed the search), or None when a variable
        cannot be read back from it or lies outside its bounds."""
        data = json.loads(self.base.model_dump_json())
        values: dict[str, float | int] = {}
        for v in self.variables:
            if v.placeholder is not None:
                continue
            found = {value_at_path(data, p) for p in v.paths}
            if len(found) != 1 or None in found:
                return None
            values[v.name] = found.pop()
        if self.layup is not None:
            from_layup = match_layup(self.layup, self.base.shaft.layup or "")
            if from_layup is None:
                return None
            for v in self.variables:
                if v.placeholder is not None:
                    values[v.name] = from_layup[v.placeholder]
        for v in self.variables:
            value = values[v.name]
            if not isinstance(value, (int, float)) or not v.lower <= value <= v.upper:
                return None
            if v.integer and value != int(value):
                return None
            values[v.name] = int(value) if v.integer else float(value)
        return values

    # -- identity ------------------------------------------------------------------------------
    def evaluation_spec(self) -> dict:
        """What an evaluation's result depends on besides the design itself (keys the cache)."""
        return {
            "evaluate": _qualname(self.evaluate),
            "outputs": [list(o) for o in self.outputs],
            "fidelity": self.fidelity,
            "flexshaft": __version__,
        }

    def evaluation_fingerprint(self) -> str:
        text = json.dumps(self.evaluation_spec(), sort_keys=True, default=repr)
        return hashlib.sha256(text.encode()).hexdigest()

    def spec(self) -> dict:
        """JSON-able description of the search (what the run folder belongs to)."""
        return {
            "name": self.name,
            "variables": [v.spec() for v in self.variables],
            "objectives": [[o.output, o.sense] for o in self.objectives],
            "constraints": list(self.constraints),
            "layup": self.layup,
            "ply_thickness": self.ply_thickness,
            "fixed": dict(self.fixed.items()),
            "base": json.loads(self.base.model_dump_json()),
            "evaluation": self.evaluation_fingerprint(),
        }


def objectives_and_constraints(
    problem: DesignProblem, outputs: ArrayLike, valid: ArrayLike
) -> tuple[np.ndarray, np.ndarray]:
    """The minimisation objectives F and constraints G (<= 0 feasible) of evaluated candidates.

    Parameters
    ----------
    outputs : ndarray
        (n, n_outputs) in the order of ``problem.outputs``.
    valid : ndarray of bool
        (n,) False for a design the schema refused.

    Returns
    -------
    F : ndarray
        (n, n_objectives): the objective, negated when maximised.
    G : ndarray
        (n, n_constraints + 1): −margin of each constraint (:data:`NOT_EVALUATED_VIOLATION`
        where the margin is NaN, i.e. not evaluated, or −inf, a failure with no finite margin),
        then 0 for a valid design with a finite
        value of every objective and 1 otherwise.
    """
    outputs = np.atleast_2d(np.asarray(outputs, dtype=float))
    index = {name: i for i, name in enumerate(problem.all_output_names)}
    full = problem.with_derived(outputs)
    F = np.column_stack([full[:, index[o.output]] * (-1.0 if o.sense == "max" else 1.0) for o in problem.objectives])
    ok = np.asarray(valid, dtype=bool) & np.all(np.isfinite(F), axis=1)
    F[~ok] = _NO_RESULT
    columns = []
    for name in problem.constraints:
        margin = outputs[:, index[name]]
        columns.append(np.where(np.isnan(margin) | np.isneginf(margin), NOT_EVALUATED_VIOLATION, -margin))
    columns.append(np.where(ok, 0.0, 1.0))
    G = np.column_stack(columns)
    G[~ok, :-1] = np.where(np.isnan(G[~ok, :-1]), NOT_EVALUATED_VIOLATION, G[~ok, :-1])
    return F, G

"""One optimizer evaluation: the assessment of a design at the optimizer's fidelity, as floats.

An evaluation is :func:`flexshaft.verdict.assess.assess` (the recipe ``flexshaft run`` uses) at
the :class:`~flexshaft.resolution.Resolution` of its fidelity (:data:`FIDELITIES`):

* ``"verdict"``: :data:`~flexshaft.resolution.VERDICT`, the report's grids (651 scan speeds, 41
  whirl speeds) without what only the report shows (Campbell diagram, modes at rest, load
  shares, classical-shell buckling, thermal sweeps): two thirds of the CPU time of the full
  analysis (benchmarks/optimizer.py), the same verdict as ``flexshaft run``
  (tests/test_optimize.py compares every check);
* ``"screening"``: :data:`~flexshaft.resolution.SCREENING`, 261 scan speeds (0.5 % of the
  operating speed apart, the critical-speed peaks still refined) and 21 whirl speeds (the onset
  is still solved between them). Its margins differ from the full run's by the tolerances stated
  in the test; the optimizer's final designs are re-verified at the report's resolution.

:func:`design_metrics` turns a design into flat floats (objectives, check values and
normalised margins, check status codes); :func:`design_outputs` is the same as a sweep output
function. The checks are those of :data:`flexshaft.verdict.checks.CHECKS`, in its order.
"""

from __future__ import annotations

import numpy as np

from flexshaft.assembly import build_model
from flexshaft.optimize.mass import driveline_mass
from flexshaft.resolution import SCREENING, VERDICT, Resolution
from flexshaft.verdict.assess import Assessment, assess
from flexshaft.verdict.checks import CHECK_KEYS, CHECKS
from flexshaft.verdict.result import FAILED_WITHOUT_MARGIN, Check, normalised_margin

__all__ = [
    "CHECK_KEYS",
    "CHECK_STATUS_CODES",
    "FIDELITIES",
    "METRICS",
    "applicable_checks",
    "check_outputs",
    "design_metrics",
    "assessment_metrics",
    "design_outputs",
    "evaluate_design",
    "metric_outputs",
    "normalised_margin",
]

#: Status of a check as a float output: pass, fail, not evaluated, and not applicable (the design
#: has no part the check concerns: ``metal_strength`` without an isotropic segment,
#: ``coupling_angle`` without couplings).
CHECK_STATUS_CODES = {"pass": 1.0, "fail": 0.0, "not evaluated": -1.0, "not applicable": -2.0}

#: Metrics every evaluation returns besides the checks: name -> (SI unit, description).
METRICS = {
    "driveline_mass": (
        "kg",
        "driveline mass: tubes, couplings, hangers, dampers and actuators (design mass fields; an "
        "actuator without one estimated from its force capacity, flexshaft.optimize.mass)",
    ),
    "shaft_mass": ("kg", "shaft mass"),
    "safety_factor": (
        "1",
        "minimum strength safety factor (static + imbalance at the operating speed): ply "
        "Tsai-Wu of a laminated shaft, the smaller of it and the metal segments' fatigue/yield",
    ),
    "buckling_safety_factor": ("1", "torsional-buckling safety factor"),
    "actuator_force": ("N", "largest static + spin-up actuator force over the active bearings"),
    "actuator_orbit": ("m", "largest static offset + spin-up orbit over the active bearings"),
    "spinup_deflection": ("m", "peak shaft orbit during spin-up"),
    "max_temperature": ("K", "maximum shaft temperature (self-heating equilibrium)"),
    "min_log_decrement": ("1", "smallest log decrement of the shaft's lateral modes at the operating speed"),
}

#: The evaluation fidelities by name (module docstring).
FIDELITIES: dict[str, Resolution] = {"verdict": VERDICT, "screening": SCREENING}


def _resolution(fidelity: str | Resolution) -> Resolution:
    if isinstance(fidelity, Resolution):
        return fidelity
    try:
        return FIDELITIES[fidelity]
    except KeyError:
        raise ValueError(f"fidelity: no such fidelity (got {fidelity!r}; allowed: {', '.join(FIDELITIES)})") from None


def evaluate_design(design, fidelity: str | Resolution = "screening") -> Assessment:
    """The assessment of ``design`` at the resolution of ``fidelity`` (:data:`FIDELITIES`, or a
    :class:`~flexshaft.resolution.Resolution`)."""
    return assess(design, _resolution(fidelity))


def check_outputs() -> list[tuple[str, str, str]]:
    """``(name, unit, long name)`` of the per-check outputs: normalised margin and status."""
    out = []
    for key in CHECK_KEYS:
        out.append(
            (f"margin_{key}", "1", f"normalised margin of the {key} check (negative: fails; NaN: not evaluated)")
        )
        out.append(
            (f"status_{key}", "1", f"status of the {key} check: 1 pass, 0 fail, -1 not evaluated, -2 not applicable")
        )
    return out


def metric_outputs() -> list[tuple[str, str, str]]:
    """``(name, unit, long name)`` of every output of :func:`design_metrics`."""
    return [(name, unit, text) for name, (unit, text) in METRICS.items()] + check_outputs()


def design_metrics(design, fidelity: str | Resolution = "screening") -> dict[str, float]:
    """Objectives and constraints of one design, as floats (NaN where a result does not exist).

    Returns
    -------
    dict
        Every name of :data:`METRICS` and, per check key, ``margin_<key>``
        (:func:`normalised_margin`) and ``status_<key>`` (:data:`CHECK_STATUS_CODES`).
    """
    return assessment_metrics(evaluate_design(design, fidelity))


def _constraint_margin(check: Check) -> float:
    """The check's normalised margin as a constraint: a failure without a negative margin (a
    thermal runaway below the allowable, :data:`~flexshaft.verdict.result.FAILED_WITHOUT_MARGIN`
    in the figures) is −inf, a violation by the whole limit
    (:data:`~flexshaft.optimize.problem.NOT_EVALUATED_VIOLATION`), not by 1e-300."""
    margin = normalised_margin(check)
    return float("-inf") if check.status == "fail" and margin == FAILED_WITHOUT_MARGIN else margin


def assessment_metrics(assessment: Assessment) -> dict[str, float]:
    """:func:`design_metrics` of an assessment already computed."""
    verdict = assessment.verdict
    present = {c.key: c for c in verdict.checks}

    def value(key: str) -> float:
        c = present.get(key)
        return float("nan") if c is None or c.value is None else float(c.value)

    strength = [v for v in (value("tsai_wu"), value("metal_strength")) if np.isfinite(v)]
    out = {
        "driveline_mass": driveline_mass(assessment.model),
        "shaft_mass": float(assessment.model.shaft_mass),
        "safety_factor": min(strength) if strength else float("nan"),
        "buckling_safety_factor": value("buckling"),
        "actuator_force": value("actuator_force"),
        "actuator_orbit": value("actuator_orbit"),
        "spinup_deflection": value("spinup_deflection"),
        "max_temperature": value("temperature"),
        "min_log_decrement": value("whirl_damping"),
    }
    for key in CHECK_KEYS:
        c = present.get(key)
        out[f"margin_{key}"] = float("nan") if c is None else _constraint_margin(c)
        out[f"status_{key}"] = CHECK_STATUS_CODES["not applicable" if c is None else c.status]
    return out


def applicable_checks(design) -> tuple[str, ...]:
    """The verdict's checks that can apply to ``design``'s kind of driveline: those of
    :data:`~flexshaft.verdict.checks.CHECKS` whose ``applies`` accepts its model (``tsai_wu``
    and ``temperature`` need a one-piece laminated shaft, ``metal_strength`` an isotropic
    segment, the actuator checks active bearings, ``coupling_angle`` couplings). A check that
    applies but cannot be evaluated for a candidate stays a violated constraint."""
    model = build_model(design)
    return tuple(rule.key for rule in CHECKS if rule.applies(model))


def design_outputs(point) -> dict[str, float]:
    """Sweep output function: :func:`design_metrics` of the point's design at the fidelity of
    its special axis ``fidelity``."""
    return design_metrics(point.design, point.axes.get("fidelity", "screening"))

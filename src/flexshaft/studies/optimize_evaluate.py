"""One optimizer evaluation: the verdict of a design, computed with only what its checks need.

``flexshaft run`` computes everything a report shows (Campbell diagram, thermal design sweeps,
the modes at rest, leave-one-out load shares, thesis studies): about 5 s a design on one core.
The optimizer needs only the verdict's nine checks and the objectives, so
:func:`verdict_run` builds the same :class:`~flexshaft.studies.run.RunResults` fields that
:func:`~flexshaft.studies.verdict_evidence.evidence_from_run` reads, with the same analysis
functions, and leaves the rest out:

* no Campbell diagram (it only labels the critical speeds), no modes at rest;
* the Tsai-Wu safety factor without the leave-one-out shares (the minimum is the same);
* the torsional buckling of the shear-deformable shell only (the classical shell is the run's
  comparison, not the verdict's number);
* the thermal check from the self-heating equilibrium alone (no wall/convection sweeps);
* the whirl stability and the unbalance scan at the resolution of the :class:`Fidelity`.

Two fidelities (:data:`FIDELITIES`):

* ``"verdict"``: the run's resolutions (651 scan speeds, 41 whirl speeds): the same checks as
  ``flexshaft run`` (tests/test_optimize.py compares every margin);
* ``"screening"``: 261 scan speeds (0.5 % of the operating speed apart, the critical-speed
  peaks still refined by :func:`~flexshaft.analyses.separation.resolve_peak`) and 21 whirl
  speeds (the onset is still solved between them). Its margins differ from the full run's
  by the tolerances stated in the test; the optimizer's final designs are re-verified with the
  full run.

:func:`design_metrics` turns a design into flat floats (objectives, check values and
normalised margins, check status codes); :func:`design_outputs` is the same as a sweep output
function.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "CHECK_KEYS",
    "CHECK_STATUS_CODES",
    "FIDELITIES",
    "Fidelity",
    "METRICS",
    "applicable_checks",
    "check_outputs",
    "design_metrics",
    "design_outputs",
    "metric_outputs",
    "normalised_margin",
    "verdict_run",
]

#: The verdict's checks, in report order (:mod:`flexshaft.studies.verdict`).
CHECK_KEYS = (
    "tsai_wu",
    "metal_strength",
    "buckling",
    "whirl_onset",
    "whirl_damping",
    "separation",
    "actuator_orbit",
    "actuator_force",
    "temperature",
    "spinup_deflection",
    "coupling_angle",
)
#: Status of a check as a float output: pass, fail, not evaluated, and not applicable (the design
#: has no part the check concerns: ``metal_strength`` without an isotropic segment,
#: ``coupling_angle`` without couplings).
CHECK_STATUS_CODES = {"pass": 1.0, "fail": 0.0, "not evaluated": -1.0, "not applicable": -2.0}

#: Metrics every evaluation returns besides the checks: name -> (SI unit, description).
METRICS = {
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


@dataclass(frozen=True)
class Fidelity:
    """Resolution of one evaluation.

    Attributes
    ----------
    name : str
    n_speeds : int
        Spin speeds of the unbalance scan from 2 % to 130 % of the operating speed.
    n_whirl_speeds : int
        Speeds of the whirl-stability analysis from rest to 1.5 × the operating speed.
    """

    name: str
    n_speeds: int
    n_whirl_speeds: int


#: The evaluation fidelities by name (module docstring).
FIDELITIES = {"verdict": Fidelity("verdict", 651, 41), "screening": Fidelity("screening", 261, 21)}


def _fidelity(fidelity: str | Fidelity) -> Fidelity:
    if isinstance(fidelity, Fidelity):
        return fidelity
    try:
        return FIDELITIES[fidelity]
    except KeyError:
        raise ValueError(f"fidelity: no such fidelity (got {fidelity!r}; allowed: {', '.join(FIDELITIES)})") from None


def verdict_run(design, fidelity: str | Fidelity = "screening"):
    """The fields of :class:`~flexshaft.studies.run.RunResults` the verdict reads, and the verdict.

    Parameters
    ----------
    design : Design
        A validated design.
    fidelity : str or Fidelity
        ``"screening"`` or ``"verdict"`` (:data:`FIDELITIES`).

    Returns
    -------
    RunResults
        With ``campbell``, ``modes_at_rest``, the thesis studies and the thermal design sweeps
        left empty; ``verdict`` set.
    """
    from flexshaft.analyses import imbalance_response, modes
    from flexshaft.analyses.metal_strength import metal_strength
    from flexshaft.analyses.misalignment import coupling_misalignment
    from flexshaft.analyses.response import actuator_response, bearing_reactions, worst_case_orbits
    from flexshaft.analyses.shaft_buckling import shaft_buckling
    from flexshaft.analyses.shaft_strength import shaft_safety_factor, static_load_parts
    from flexshaft.analyses.stability import stability
    from flexshaft.analyses.summary import model_summary
    from flexshaft.assembly import build_model
    from flexshaft.assembly.loads import imbalance_loads
    from flexshaft.studies.run import SCAN_BOTTOM, SCAN_TOP, RunResults
    from flexshaft.studies.verdict import evaluate
    from flexshaft.studies.verdict_evidence import evidence_from_run

    fid = _fidelity(fidelity)
    model = build_model(design)
    speed = model.speed
    top = max(speed, 1.0)
    at_speed = modes(model, speed, 10)
    speeds = np.linspace(SCAN_BOTTOM, SCAN_TOP, fid.n_speeds) * top
    loads = imbalance_loads(model)
    q = imbalance_response(model, speeds, loads)
    amp, case = worst_case_orbits(model, q)
    idx = np.arange(speeds.size)
    envelope = amp[:, case, idx]
    disp, force = actuator_response(model, q[:, case, idx], speeds)
    parts = static_load_parts(model)
    q_at_speed = (
        imbalance_response(model, [speed], loads)[:, :, 0] if speed > 0 else np.zeros((model.dofs.size, 1), complex)
    )
    strength_static = strength_total = buckling = thermal = None
    if model.shaft.laminate is not None:
        strength_static = shaft_safety_factor(model, parts)
        strength_total = min(
            (shaft_safety_factor(model, parts, q_at_speed[:, c]) for c in range(q_at_speed.shape[1])),
            key=lambda r: r.safety_factor,
        )
        buckling = shaft_buckling(model, compare_classical=False).to_dict()  # the verdict reads the shear shell only
        thermal = _self_heating(design, model)
    q_static = parts["external"] + parts["torque"]
    metal = misalignment = None
    if any(design.materials[seg.material].kind == "isotropic" for seg in model.segments):
        metal = metal_strength(model, q_static, q_at_speed)
    if model.couplings:
        misalignment = coupling_misalignment(model, q_static, q_at_speed)
    whirl = np.linspace(0.0, 1.5 * top, fid.n_whirl_speeds)
    results = RunResults(
        model=model,
        summary=model_summary(model),
        modes_at_rest=[],
        modes_at_speed=[],
        mode_shapes=at_speed,
        campbell=None,
        speeds=speeds,
        shaft_peak=envelope.max(axis=0),
        shaft_envelope=envelope,
        actuator_displacement=disp,
        actuator_force=force,
        static_displacement=q_static,
        strength_static=strength_static,
        strength_total=strength_total,
        imbalance_at_speed=q_at_speed,
        buckling=buckling,
        stability=stability(model, whirl, n_modes=10),
        thermal=thermal,
        shaft_orbits=amp,
        metal_strength=metal,
        coupling_misalignment=misalignment,
        bearing_reactions=bearing_reactions(model, q_static, q_at_speed),
    )
    results.verdict = evaluate(evidence_from_run(results), design.requirements)
    return results


def _self_heating(design, model):
    """The part of :func:`flexshaft.thermal.study.thermal_results` the temperature check reads."""
    from flexshaft.thermal.study import thermal_results

    return thermal_results(design, model, self_heat=True, detail=False)


def normalised_margin(check, operating_speed: float) -> float:
    """A check's margin as a dimensionless number (negative: fails; NaN: not evaluated).

    Scales: the limit for safety factors, log decrements, lengths, forces and temperatures
    [K]; the operating speed for speeds; none for separation (its margin is already a fraction
    of the operating speed).
    """
    if check.status == "not evaluated" or check.margin is None:
        return float("nan")
    if check.kind == "fraction":
        scale = 1.0
    elif check.kind == "speed":
        scale = operating_speed
    else:
        scale = abs(check.limit) if check.limit else 1.0
    return float(check.margin) / scale


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


def design_metrics(design, fidelity: str | Fidelity = "screening") -> dict[str, float]:
    """Objectives and constraints of one design, as floats (NaN where a result does not exist).

    Returns
    -------
    dict
        Every name of :data:`METRICS` and, per check key, ``margin_<key>``
        (:func:`normalised_margin`) and ``status_<key>`` (:data:`CHECK_STATUS_CODES`).
    """
    res = verdict_run(design, fidelity)
    verdict = res.verdict
    speed = float(res.model.speed)

    present = {c.key: c for c in verdict.checks}

    def value(key: str) -> float:
        c = present.get(key)
        return float("nan") if c is None or c.value is None else float(c.value)

    strength = [v for v in (value("tsai_wu"), value("metal_strength")) if np.isfinite(v)]
    out = {
        "shaft_mass": float(res.model.shaft_mass),
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
        out[f"margin_{key}"] = float("nan") if c is None else normalised_margin(c, speed)
        out[f"status_{key}"] = CHECK_STATUS_CODES["not applicable" if c is None else c.status]
    return out


def applicable_checks(design) -> tuple[str, ...]:
    """The verdict's checks that can apply to ``design``'s kind of driveline: every key of
    :data:`CHECK_KEYS` but those its parts rule out (as :func:`flexshaft.studies.run.run_analysis`
    decides): ``tsai_wu`` and ``temperature`` without a one-piece laminated shaft,
    ``metal_strength`` without an isotropic segment, the actuator checks without active
    bearings, ``coupling_angle`` without couplings. A check that applies but cannot be
    evaluated for a candidate stays a violated constraint."""
    from flexshaft.assembly import build_model

    model = build_model(design)
    skip = set()
    if model.shaft.laminate is None:
        skip |= {"tsai_wu", "temperature"}
    if not any(design.materials[seg.material].kind == "isotropic" for seg in model.segments):
        skip.add("metal_strength")
    if not model.actuators:
        skip |= {"actuator_orbit", "actuator_force"}
    if not model.couplings:
        skip.add("coupling_angle")
    return tuple(k for k in CHECK_KEYS if k not in skip)


def design_outputs(point) -> dict[str, float]:
    """Sweep output function: :func:`design_metrics` of the point's design at the fidelity of
    its special axis ``fidelity``."""
    return design_metrics(point.design, point.axes.get("fidelity", "screening"))

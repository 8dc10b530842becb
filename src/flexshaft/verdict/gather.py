"""The evidence of an operating point: the numbers each requirement needs, read from its analyses.

:func:`gather_evidence` reads a :class:`~flexshaft.verdict.operating_point.PointAnalyses` (typed
results; nothing is computed here) and returns the plain
:class:`~flexshaft.verdict.evidence.Evidence` the checks of :mod:`flexshaft.verdict.checks` judge.
:func:`actuator_limits` gives each active bearing's limits as the actuator checks read them (the
Monte-Carlo exceedances use the same).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.assembly.model import Model
from flexshaft.units import celsius_to_kelvin
from flexshaft.verdict.evidence import ActuatorEvidence, CouplingEvidence, Evidence, MetalEvidence, ModeDamping
from flexshaft.verdict.operating_point import PointAnalyses

__all__ = ["WHIRL_DAMPING_SHAFT_SHARE", "ActuatorLimits", "actuator_limits", "gather_evidence"]

#: Smallest share of a mode's kinetic energy in the shaft for the whirl-damping requirement.
WHIRL_DAMPING_SHAFT_SHARE = 0.1


@dataclass(frozen=True)
class ActuatorLimits:
    """The limits of one active bearing the actuator checks hold its peaks against: the
    auxiliary-bearing radial clearance ``gap`` [m] and the ``force_capacity`` [N] (the design's,
    else the magnet's saturation force when its geometry is given); None: not given."""

    gap: float | None
    force_capacity: float | None


def actuator_limits(model: Model) -> dict[str, ActuatorLimits]:
    """:class:`ActuatorLimits` of each active bearing of ``model``, by name."""
    out = {}
    for a in model.actuators:
        bearing = model.design.bearing(a.name) if model.design is not None else None
        gap = bearing.gap if bearing is not None else None
        capacity = bearing.force_capacity if bearing is not None else None
        if capacity is None:
            capacity = a.saturation_force  # the magnet's saturation force when its geometry is given
        out[a.name] = ActuatorLimits(gap, capacity)
    return out


def _modes_at_operating(p: PointAnalyses) -> tuple[ModeDamping, ...]:
    """Log decrements at the operating speed of the lateral modes the shaft takes part in.

    From the damped modes at the operating speed (the model's damping physics). Only lateral
    modes with at least :data:`WHIRL_DAMPING_SHAFT_SHARE` of their kinetic energy in the shaft
    count: API 617's log-decrement criterion concerns the rotor's whirl modes; boom-only modes
    (damped by the structure, η/2) and torsional or axial modes cannot whirl and are excluded.
    """
    m = p.modes_at_speed
    out = []
    for k in range(m.eigenvalues.size):
        if m.kind[k] != "lateral" or m.shaft_fractions[k] < WHIRL_DAMPING_SHAFT_SHARE:
            continue
        label = f"{k + 1} ({m.whirl[k]}, {m.component[k]})"
        out.append(ModeDamping(label, float(abs(m.eigenvalues[k].imag)), float(m.log_decrements[k])))
    return tuple(out)


def _strength(p: PointAnalyses, notes: dict) -> dict:
    results = [r for r in (p.strength_static, p.strength_total) if r is not None]
    if not results:
        notes["tsai_wu"] = "ply strength needs a lamina shaft material"
        return {}
    r = min(results, key=lambda r: r.safety_factor)
    case = "static + imbalance" if r is p.strength_total else "static"
    return {
        "safety_factor": float(r.safety_factor),
        "safety_factor_location": {
            "station": float(r.x),
            "ply": f"{r.ply + 1} ({r.ply_angle_deg:+.0f}°)",
            "case": case,
            "detail": f"φ = {r.phase_deg:.0f}°, {r.dominant_stress} dominates",
        },
    }


def _metal(p: PointAnalyses, notes: dict) -> dict:
    """Fatigue and yield safety factors of each isotropic segment (no check without one)."""
    metal = p.metal_strength
    if metal is None:
        return {}
    if not metal.evaluated:
        notes["metal_strength"] = "; ".join(metal.notes) or "no isotropic segment gives its strengths"
        return {"metal_strength": ()}
    findings = []
    for segment in metal.segments:
        for criterion, label in (("fatigue", "fatigue (modified Goodman)"), ("yield", "yield (von Mises)")):
            worst = metal.worst(criterion, segment)
            findings.append(MetalEvidence(segment, label, worst["safety_factor"], worst["station"]))
    return {"metal_strength": tuple(findings)}


def _couplings(p: PointAnalyses) -> dict:
    angles = p.coupling_misalignment
    if angles is None:
        return {}
    return {
        "coupling_angles": tuple(
            CouplingEvidence(name, float(x), float(a), float(d), None if np.isnan(limit) else float(limit))
            for name, x, a, d, limit in zip(
                angles.names, angles.stations, angles.static_angle, angles.dynamic_angle, angles.allowable_angle
            )
        )
    }


def _metal_buckling(p: PointAnalyses, notes: dict) -> dict:
    """Torsional buckling of the metal segments (isotropic classical shell), the weakest one."""
    metal = p.metal_strength
    if metal is None or not metal.buckling:
        notes["buckling"] = "laminated-shell buckling needs a lamina shaft material"
        return {}
    covered = {b.segment for b in metal.buckling}
    uncovered = [seg.name for seg in p.model.segments if seg.name not in covered]
    if uncovered:  # the metal tubes alone must not pass the check for the whole shaft
        notes["buckling"] = (
            f"segment(s) {', '.join(uncovered)} are laminated: the buckling of a laminated segment of "
            "a segmented shaft is not modelled"
        )
        return {}
    b = min(metal.buckling, key=lambda b: b.safety_factor)
    return {
        "buckling_safety_factor": float(b.safety_factor),
        "buckling_location": {
            "case": f"segment {b.segment}, n = {b.wave_number}",
            "detail": f"applied {b.torque:.0f} N m, T_cr = {b.critical_torque:.0f} N m, isotropic classical (Sanders) "
            f"shell over {b.length:.2f} m",
        },
    }


def _buckling(p: PointAnalyses, notes: dict) -> dict:
    if p.buckling is None:
        return _metal_buckling(p, notes)
    r = p.buckling.result
    positive = r.torque_positive <= r.torque_negative
    sense, n = ("positive", r.n_positive) if positive else ("negative", r.n_negative)
    n = "∞ (shear crimping)" if n is None else n
    critical = float(min(r.torque_positive, r.torque_negative))
    return {
        "buckling_safety_factor": float(p.buckling.safety_factor),
        "buckling_location": {
            "case": f"{sense} torque, n = {n}",
            "detail": f"applied {p.buckling.torque:.0f} N m, T_cr = {critical:.0f} N m, {r.theory} shell",
        },
    }


def _whirl(p: PointAnalyses) -> dict:
    st = p.stability
    out = {"stability_max_speed": float(st.speeds[-1]), "modes_at_operating": _modes_at_operating(p)}
    if st.onset_speed is not None:
        m = st.unstable_mode
        k = int(np.argmin(np.abs(np.asarray(st.speeds) - st.onset_speed)))
        out["onset_speed"] = float(st.onset_speed)
        out["onset_location"] = {
            "mode": f"{m + 1} ({st.whirl[k, m]})",
            "frequency": float(abs(st.eigenvalues[k, m].imag)),
            "detail": f"{st.damping_model} internal-damping model",
        }
    return out


def _actuators(p: PointAnalyses) -> tuple[ActuatorEvidence, ...]:
    """The spin-up peaks (to the operating speed) of each active bearing, its static offset and
    force (the run's static reaction: the constraint force of an integrating law too), limits."""
    model = p.model
    spinup = p.spinup
    limits = actuator_limits(model)
    up = spinup.up_to(model.speed)
    out = []
    for a in model.actuators:
        d = np.asarray(spinup.actuator_displacement[a.name])
        f = np.asarray(spinup.actuator_force[a.name])
        i, j = int(up[np.argmax(d[up])]), int(up[np.argmax(f[up])])
        static = float(np.hypot(*np.real(a.lateral_rows @ p.static_displacement)))
        out.append(
            ActuatorEvidence(
                a.name,
                float(d[i]),
                float(spinup.speeds[i]),
                float(f[j]),
                float(spinup.speeds[j]),
                static_offset=static,
                static_force=float(p.bearing_reactions[a.name].static_lateral),
                gap=limits[a.name].gap,
                force_capacity=limits[a.name].force_capacity,
            )
        )
    return tuple(out)


def _temperature(p: PointAnalyses, notes: dict) -> dict:
    th = p.thermal
    if th is None:
        notes["temperature"] = "no shaft thermal result (the thermal model needs a laminated shaft)"
        return {}
    sh = th.self_heating
    temperature = th.shaft_temperature
    i = int(np.argmax(temperature.temperature))
    detail = (
        f"self-heating equilibrium ({sh.status}), {th.loss_model} loss model"
        if sh is not None
        else f"{th.loss_model} loss model, constant properties"
    )
    return {
        "max_temperature": float(temperature.temperature[i]),
        "temperature_location": {"station": float(temperature.x[i]), "detail": detail},
        "thermal_runaway": sh is not None and sh.status == "runaway",
    }


def _spinup_peak(p: PointAnalyses, criticals) -> dict:
    """The largest shaft orbit of the spin-up to the operating speed and where; a sharp resonance
    falls between the sampled speeds: its refined peak when that is larger."""
    spinup = p.spinup
    speed = p.operating_speed
    up = spinup.up_to(speed)
    peaks = spinup.shaft_peak
    if not up.size:
        return {}
    k = int(up[np.argmax(peaks[up])])
    node = int(np.argmax(spinup.envelope[:, k]))
    out = {
        "spinup_peak": float(peaks[k]),
        "spinup_location": {"station": float(p.model.dofs.shaft_x[node]), "speed": float(spinup.speeds[k])},
    }
    for c in criticals or ():
        refined = c.location.get("peak_orbit")
        if refined is not None and c.speed <= speed and np.isfinite(refined) and refined > out["spinup_peak"]:
            out["spinup_peak"] = float(refined)
            out["spinup_location"] = {
                "station": c.location["station"],
                "speed": float(c.speed),
                "detail": "peak refined between the sampled speeds",
            }
    return out


def gather_evidence(p: PointAnalyses) -> Evidence:
    """The verdict's evidence from the analyses of an operating point (every number is read
    from ``p``; notes say why a check's evidence is missing)."""
    notes: dict[str, str] = {}
    values: dict = {}
    values.update(_strength(p, notes))
    values.update(_metal(p, notes))
    values.update(_couplings(p))
    values.update(_buckling(p, notes))
    values.update(_whirl(p))
    found = p.criticals
    if found.criticals is not None:
        values["critical_speeds"] = found.criticals
        values["critical_search_max_speed"] = found.search_top
    else:
        notes["separation"] = found.note
    values.update(_temperature(p, notes))
    values["allowable_temperature"] = celsius_to_kelvin(p.design.thermal.allowable_temperature_c)
    values.update(_spinup_peak(p, found.criticals))
    return Evidence(operating_speed=p.operating_speed, actuators=_actuators(p), notes=notes, **values)

"""The one adapter from a ``flexshaft run`` result to the verdict's :class:`Evidence`.

:func:`evidence_from_run` reads :class:`flexshaft.studies.run.RunResults`; everything else of
the verdict works on the plain :class:`~flexshaft.studies.verdict.Evidence`.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.criticals import scan_critical_speeds
from flexshaft.studies.evidence import ActuatorEvidence, CouplingEvidence, Evidence, MetalEvidence, ModeDamping
from flexshaft.units import celsius_to_kelvin

__all__ = ["evidence_from_run"]

# ------------------------------------------------------------------------------------------------
# Whirl stability at the operating speed


#: Smallest share of a mode's kinetic energy in the shaft for the whirl-damping requirement.
WHIRL_DAMPING_SHAFT_SHARE = 0.1


def _modes_at_operating(res, speed: float) -> tuple[ModeDamping, ...] | None:
    """Log decrements at the operating speed of the lateral modes the shaft takes part in.

    From the damped modes at the operating speed (``res.mode_shapes``, the model's damping
    physics). Only lateral modes with at least :data:`WHIRL_DAMPING_SHAFT_SHARE` of their
    kinetic energy in the shaft count: API 617's log-decrement criterion concerns the
    rotor's whirl modes; boom-only modes (damped by the structure, η/2) and torsional or axial
    modes cannot whirl and are excluded.
    """
    m = res.mode_shapes
    if m is None or not np.isclose(m.speed, speed, rtol=1e-9, atol=1e-9):
        return None
    out = []
    for k in range(m.eigenvalues.size):
        if m.kind[k] != "lateral" or m.shaft_fractions[k] < WHIRL_DAMPING_SHAFT_SHARE:
            continue
        label = f"{k + 1} ({m.whirl[k]}, {m.component[k]})"
        out.append(ModeDamping(label, float(abs(m.eigenvalues[k].imag)), float(m.log_decrements[k])))
    return tuple(out)


# ------------------------------------------------------------------------------------------------
# The adapter


def _strength(res, notes: dict) -> dict:
    results = [r for r in (res.strength_static, res.strength_total) if r is not None]
    if not results:
        notes["tsai_wu"] = "ply strength needs a lamina shaft material"
        return {}
    r = min(results, key=lambda r: r.safety_factor)
    case = "static + imbalance" if r is res.strength_total else "static"
    return {
        "safety_factor": float(r.safety_factor),
        "safety_factor_location": {
            "station": float(r.x),
            "ply": f"{r.ply + 1} ({r.ply_angle_deg:+.0f}°)",
            "case": case,
            "detail": f"φ = {r.phase_deg:.0f}°, {r.dominant_stress} dominates",
        },
    }


def _metal(res, notes: dict) -> dict:
    """Fatigue and yield safety factors of each isotropic segment (no check without one)."""
    metal = getattr(res, "metal_strength", None)
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


def _couplings(res) -> dict:
    angles = getattr(res, "coupling_misalignment", None)
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


def _metal_buckling(res, notes: dict) -> dict:
    """Torsional buckling of the metal segments (isotropic classical shell), the weakest one."""
    metal = getattr(res, "metal_strength", None)
    if metal is None or not metal.buckling:
        notes["buckling"] = "laminated-shell buckling needs a lamina shaft material"
        return {}
    covered = {b.segment for b in metal.buckling}
    uncovered = [seg.name for seg in getattr(res.model, "segments", ()) if seg.name not in covered]
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


def _buckling(res, notes: dict) -> dict:
    b = res.buckling
    if b is None:
        return _metal_buckling(res, notes)
    positive = b["critical_torque_positive_Nm"] <= b["critical_torque_negative_Nm"]
    sense, n = ("positive", b["wave_number_positive"]) if positive else ("negative", b["wave_number_negative"])
    n = "∞ (shear crimping)" if n is None else n
    critical = min(b["critical_torque_positive_Nm"], b["critical_torque_negative_Nm"])
    return {
        "buckling_safety_factor": float(b["safety_factor"]),
        "buckling_location": {
            "case": f"{sense} torque, n = {n}",
            "detail": f"applied {b['torque_Nm']:.0f} N m, T_cr = {critical:.0f} N m, {b['theory']} shell",
        },
    }


def _whirl(res, speed: float, notes: dict) -> dict:
    st = res.stability
    if st is None:
        notes["whirl_onset"] = notes["whirl_damping"] = "no whirl stability analysis (it needs PD actuators)"
        return {}
    out = {"stability_max_speed": float(st.speeds[-1]), "modes_at_operating": _modes_at_operating(res, speed)}
    if out["modes_at_operating"] is None:
        notes["whirl_damping"] = "no damped modes at the operating speed"
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


def _spinup_indices(res) -> np.ndarray:
    """Indices of the run's speeds up to the operating speed (the spin-up proper)."""
    return np.flatnonzero(np.asarray(res.speeds) <= res.model.speed * (1 + 1e-9))


def _actuators(res) -> tuple[ActuatorEvidence, ...]:
    model = res.model
    design = model.design
    out = []
    up = _spinup_indices(res)
    for a in model.actuators:
        d = np.asarray(res.actuator_displacement[a.name])[up]
        f = np.asarray(res.actuator_force[a.name])[up]
        i, j = int(up[np.argmax(d)]), int(up[np.argmax(f)])
        d, f = np.asarray(res.actuator_displacement[a.name]), np.asarray(res.actuator_force[a.name])
        static = float(np.hypot(*np.real(a.lateral_rows @ res.static_displacement)))
        bearing = design.bearing(a.name) if design is not None else None
        capacity = getattr(bearing, "force_capacity", None)
        if capacity is None:
            capacity = a.saturation_force  # the magnet's saturation force when its geometry is given
        reactions = getattr(res, "bearing_reactions", None) or {}
        if a.name in reactions:  # the run's static reaction: the constraint force of an integrating law too
            static_force = float(reactions[a.name].static_lateral)
        elif a.integrates:  # C(0) infinite: the static force is not law × offset; left to the dynamic part
            static_force = 0.0
        else:
            static_force = float(abs(a.law(0j))) * static
        out.append(
            ActuatorEvidence(
                a.name,
                float(d[i]),
                float(res.speeds[i]),
                float(f[j]),
                float(res.speeds[j]),
                static_offset=static,
                static_force=static_force,
                gap=getattr(bearing, "gap", None),
                force_capacity=capacity,
            )
        )
    return tuple(out)


def _temperature(res, notes: dict) -> dict:
    th = res.thermal
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


def evidence_from_run(res: object) -> Evidence:
    """Build the verdict's evidence from a :class:`flexshaft.studies.run.RunResults`.

    Computes the lateral critical speeds and their amplification factors
    (:func:`flexshaft.analyses.criticals.scan_critical_speeds`) unless ``res.critical_speeds`` holds them; every other
    number is read from ``res``.
    """
    model = res.model
    design = model.design
    speed = float(model.speed)
    notes: dict[str, str] = {}
    values: dict = {}
    values.update(_strength(res, notes))
    values.update(_metal(res, notes))
    values.update(_couplings(res))
    values.update(_buckling(res, notes))
    values.update(_whirl(res, speed, notes))
    found = getattr(res, "critical_speeds", None)  # computed with the spin-up scan
    if found is None:
        found = scan_critical_speeds(model, np.asarray(res.speeds), getattr(res, "shaft_orbits", None))
    found = found.labelled(res.campbell)
    if found.criticals is not None:
        values["critical_speeds"] = found.criticals
        values["critical_search_max_speed"] = found.search_top
    else:
        notes["separation"] = found.note
    values.update(_temperature(res, notes))
    if design is not None:
        values["allowable_temperature"] = celsius_to_kelvin(design.thermal.allowable_temperature_c)
    up = _spinup_indices(res)
    peak = np.asarray(res.shaft_peak)[up]
    if peak.size:
        k = int(up[np.argmax(peak)])
        peak = np.asarray(res.shaft_peak)
        node = int(np.argmax(np.asarray(res.shaft_envelope)[:, k]))
        values["spinup_peak"] = float(peak[k])
        values["spinup_location"] = {"station": float(model.dofs.shaft_x[node]), "speed": float(res.speeds[k])}
        # a sharp resonance falls between grid speeds: take its refined peak when it is larger
        for c in values.get("critical_speeds") or ():
            refined = c.location.get("peak_orbit")
            if refined is not None and c.speed <= speed and np.isfinite(refined) and refined > values["spinup_peak"]:
                values["spinup_peak"] = float(refined)
                values["spinup_location"] = {
                    "station": c.location["station"],
                    "speed": float(c.speed),
                    "detail": "peak refined between the sampled speeds",
                }
    return Evidence(operating_speed=speed, actuators=_actuators(res), notes=notes, **values)

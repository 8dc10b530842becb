"""The evidence of an operating point: the numbers each requirement needs, read from its analyses.

:func:`gather_evidence` reads a :class:`~flexshaft.verdict.operating_point.PointAnalyses` (typed
results; nothing is computed here) and returns the plain
:class:`~flexshaft.verdict.evidence.Evidence` the checks of :mod:`flexshaft.verdict.checks` judge.
:func:`actuator_limits` gives each active bearing's limits as the actuator checks read them (the
Monte-Carlo exceedances use the same).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from flexshaft.assembly.model import Model
from flexshaft.strength import compressive_strength_note
from flexshaft.units import celsius_to_kelvin, kelvin_to_celsius, rad_s_to_rpm
from flexshaft.verdict.evidence import (
    ActuatorEvidence,
    CouplingEvidence,
    Evidence,
    LoopEvidence,
    MetalEvidence,
    ModeDamping,
    TorsionalEvidence,
)
from flexshaft.verdict.operating_point import PointAnalyses, whirl_modes
from flexshaft.verdict.point_tasks import required_onset_speed

__all__ = ["WHIRL_DAMPING_SHAFT_SHARE", "ActuatorLimits", "actuator_limits", "gather_evidence", "judged_whirl_modes"]

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


def judged_whirl_modes(m) -> np.ndarray:
    """Mask of the modes of ``m`` (:class:`~flexshaft.analyses.modal.Modes`) the whirl-damping
    requirement judges: the lateral whirl modes (:func:`~flexshaft.verdict.operating_point.whirl_modes`)
    with Im s > 0 and at least :data:`WHIRL_DAMPING_SHAFT_SHARE` of their kinetic energy in the shaft."""
    s = np.asarray(m.eigenvalues)
    return whirl_modes(m) & (np.asarray(m.shaft_fractions) >= WHIRL_DAMPING_SHAFT_SHARE) & (s.imag > 0)


def _modes_at_operating(p: PointAnalyses) -> tuple[ModeDamping, ...]:
    """Log decrements at the operating speed of the lateral modes the shaft takes part in.

    From the damped modes at the operating speed (the model's damping physics). Only lateral
    modes with at least :data:`WHIRL_DAMPING_SHAFT_SHARE` of their kinetic energy in the shaft
    count: API 617's log-decrement criterion concerns the rotor's whirl modes; boom-only modes
    (damped by the structure, η/2) and torsional or axial modes cannot whirl and are excluded, as
    are real and overdamped roots (:func:`~flexshaft.verdict.operating_point.whirl_modes`: the
    controllers' states; a divergent root fails the onset check).
    """
    m = p.modes_at_speed
    out = []
    for k in np.flatnonzero(judged_whirl_modes(m)):
        label = f"{k + 1} ({m.whirl[k]}, {m.component[k]})"
        out.append(ModeDamping(label, float(abs(m.eigenvalues[k].imag)), float(m.log_decrements[k])))
    return tuple(out)


def _whirl_modes_top(p: PointAnalyses) -> float | None:
    """Frequency [rad/s] of the highest lateral whirl mode computed at the operating speed,
    whatever its shaft share (None without one): where the whirl-damping check's scope ends."""
    m = p.modes_at_speed
    frequencies = np.abs(m.eigenvalues.imag)[whirl_modes(m) & (m.eigenvalues.imag > 0)]
    return float(frequencies.max()) if frequencies.size else None


def _strength(p: PointAnalyses, notes: dict) -> dict:
    results = [r for r in (p.strength_static, p.strength_total) if r is not None]
    if not results:
        notes["tsai_wu"] = "ply strength needs a lamina shaft material"
        return {}
    r = min(results, key=lambda r: r.safety_factor)
    case = "static + imbalance" if r is p.strength_total else "static"
    parts = []
    c = p.compressive_strength
    if c is not None:
        note = compressive_strength_note(c, p.design.shaft.material)
        parts.append(
            note
            if note is not None
            else f"X_c = {c.datasheet * 1e-6:.4g} MPa (below its kink band {c.kink_band * 1e-6:.3g} MPa)"
        )
    if p.torque_factor != 1.0:
        parts.append(f"steady torque × {p.torque_factor:.4g} (tail-rotor torque oscillation)")
    if p.residual_temperature is not None:
        parts.append(
            f"thermal residual at {kelvin_to_celsius(p.residual_temperature):.1f} °C, integrated over the cool-down"
        )
    return {
        "safety_factor": float(r.safety_factor),
        "safety_factor_location": {
            "station": float(r.x),
            "ply": f"{r.ply + 1} ({r.ply_angle_deg:+.0f}°)",
            "case": case,
            "detail": f"φ = {r.phase_deg:.0f}°, {r.dominant_stress} dominates",
        },
        "strength_note": "; ".join(parts),
        "torque_factor": p.torque_factor,
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
        "buckling_safety_factor": float(b.safety_factor) / p.torque_factor,
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
    n: int | str | None  # the wave number, or a word when there is none
    sense, n = ("positive", r.n_positive) if positive else ("negative", r.n_negative)
    n = "∞ (shear crimping)" if n is None else n
    critical = float(min(r.torque_positive, r.torque_negative))
    peak = f" × {p.torque_factor:.4g} (torsional response)" if p.torque_factor != 1.0 else ""
    return {
        "buckling_safety_factor": float(p.buckling.safety_factor) / p.torque_factor,
        "buckling_location": {
            "case": f"{sense} torque, n = {n}",
            "detail": f"applied {p.buckling.torque:.0f} N m{peak}, T_cr = {critical:.0f} N m, {r.theory} shell",
        },
    }


def _whirl(p: PointAnalyses) -> dict:
    """The lowest onset of the tracked modes (an oscillatory mode or a divergence) and of the
    every-root check, whichever is lower."""
    st = p.stability
    out = {
        "stability_max_speed": float(st.speeds[-1]),
        "modes_at_operating": _modes_at_operating(p),
        "whirl_modes_top": _whirl_modes_top(p),
        "whirl_scope": required_onset_speed(p.model),
    }
    location: dict[str, Any]
    onset, location = None, {}
    if st.onset_speed is not None:
        onset = float(st.onset_speed)
        k = min(st.at_speed(onset), st.speeds.size - 1)
        m = st.unstable_mode
        if m is None or st.onset_kind == "divergence":
            root = st.divergence[k] if st.divergence is not None else float("nan")
            location = {"mode": "divergence (real root)", "detail": f"s = {root:.4g} 1/s, {st.damping_model} model"}
        else:
            location = {
                "mode": f"{m + 1} ({st.onset_whirl})",
                "frequency": float(abs(st.eigenvalues[k, m].imag)),
                "detail": f"{st.damping_model} internal-damping model",
            }
    roots = p.roots
    first = roots.onset_speed
    if first is not None and (onset is None or first < onset):
        worst = roots.worst_at(first)
        assert worst is not None  # first is the speed of an unstable root (RootStability.onset_speed)
        kind = "divergence (real root)" if worst.kind == "divergence" else "untracked root"
        solved = "" if worst.refined or worst.kind == "divergence" else " (first-order loss estimate)"
        n = sum(r.speed == first for r in roots.unstable)
        # the onset lies above the last speed solved stable and at or below `first`: held to the
        # lower end, so an unstable root at the required speed itself fails (margin < 0)
        below = roots.speeds[roots.speeds < first]
        onset = float(below.max()) if below.size else first
        bracket = f"between {rad_s_to_rpm(onset):.0f} and " if below.size else "at or below "
        location = {
            "mode": kind,
            "frequency": worst.frequency,
            "detail": f"{n} unstable root(s) of the closed loop at {rad_s_to_rpm(first):.0f} rpm (onset {bracket}"
            f"{rad_s_to_rpm(first):.0f} rpm), worst s = {worst.root.real:.4g} {worst.root.imag:+.4g}j 1/s, "
            f"ζ = {worst.damping_ratio:.3g}{solved}",
        }
    if onset is not None:
        out["onset_speed"] = onset
        out["onset_location"] = location
    return out


def _actuators(p: PointAnalyses) -> tuple[ActuatorEvidence, ...]:
    """The spin-up peaks (to the highest operating speed) of each active bearing, its static offset and
    force (the run's static reaction: the constraint force of an integrating law too), limits."""
    model = p.model
    spinup = p.spinup
    limits = actuator_limits(model)
    up = spinup.up_to(_highest_speed(p))
    out = []
    for a in model.actuators:
        d = np.asarray(spinup.actuator_displacement[a.name])
        f = np.asarray(spinup.actuator_force[a.name])
        static = float(np.hypot(*np.real(a.lateral_rows @ p.static_displacement)))
        if up.size:
            i, j = int(up[np.argmax(d[up])]), int(up[np.argmax(f[up])])
            peaks = (float(d[i]), float(spinup.speeds[i]), float(f[j]), float(spinup.speeds[j]))
        else:  # at rest: no spin-up, the static offset and force alone
            peaks = (0.0, 0.0, 0.0, 0.0)
        out.append(
            ActuatorEvidence(
                a.name,
                *peaks,
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
    out: dict[str, Any] = {
        "max_temperature": float(temperature.temperature[i]),
        "temperature_location": {"station": float(temperature.x[i]), "detail": detail},
        "thermal_runaway": sh is not None and sh.status == "runaway",
        "self_heating_status": None if sh is None else sh.status,
    }
    c = p.conditions
    if c is not None and c.material_temperature > out["max_temperature"]:
        # a hot-soaked start: the shaft starts hotter than its running equilibrium
        out["max_temperature"] = float(c.material_temperature)
        out["temperature_location"] = {
            "detail": f"the shaft's material temperature at the point ({c.point.material_temperature}), "
            f"above its self-heating equilibrium {kelvin_to_celsius(float(temperature.temperature[i])):.1f} °C"
        }
    return out


def _spinup_peak(p: PointAnalyses, criticals) -> dict:
    """The largest shaft orbit of the spin-up to the highest operating speed and where; a sharp resonance
    falls between the sampled speeds: its refined peak when that is larger."""
    spinup = p.spinup
    speed = _highest_speed(p)
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


def _torsional(p: PointAnalyses, notes: dict) -> dict:
    """Each torsional mode against its nearest excitation (not evaluated at rest or without a
    free twist)."""
    if p.torsional_separation is None:
        notes["torsional_separation"] = (
            "the model has no free twist (no torsional modes)"
            if p.torsional_modes is None
            else "the point is at rest: no excitation sweeps the torsional modes"
        )
        return {}
    hz = 2.0 * np.pi
    return {
        "torsional_modes": tuple(
            TorsionalEvidence(
                f"T{s.mode + 1}",
                hz * s.natural_frequency,
                float(s.margin),
                s.excitation,
                (hz * s.band[0], hz * s.band[1]),
            )
            for s in p.torsional_separation
        )
    }


def _loops(p: PointAnalyses) -> dict:
    if p.bearing_loops is None:
        return {}

    def finite(x: float, scale: float = 1.0) -> float | None:
        return float(x) * scale if np.isfinite(x) else None

    out = []
    for loop in p.bearing_loops:
        m = loop.margins
        crossing = None if m.phase_margin_frequency is None else 2.0 * np.pi * m.phase_margin_frequency
        out.append(
            LoopEvidence(
                loop.actuator,
                loop.axis,
                float(loop.speed),
                float(m.peak_sensitivity),
                float(2.0 * np.pi * m.peak_frequency),
                finite(m.gain_margin_upper_db),
                finite(m.gain_margin_lower_db),
                finite(m.phase_margin_deg, np.pi / 180.0),
                crossing,
            )
        )
    return {"loops": tuple(out)}


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
    values.update(_torsional(p, notes))
    values.update(_loops(p))
    return Evidence(
        operating_speed=p.operating_speed,
        operating_range=operating_range(p),
        actuators=_actuators(p),
        notes=notes,
        **values,
    )


def _highest_speed(p: PointAnalyses) -> float:
    """Where the spin-up checks end [rad/s]: the highest operating speed (the operating speed
    without a ``speed_range``)."""
    found = operating_range(p)
    return p.operating_speed if found is None else found[1]


def operating_range(p: PointAnalyses) -> tuple[float, float] | None:
    """The lowest and highest operating speeds of the point [rad/s] (``[operating] speed_range``
    of the design at the point); None at rest or without a range."""
    operating = p.design.operating
    if operating.speed_range is None or not p.operating_speed > 0.0:
        return None
    low, high = operating.speed_limits
    return float(low), float(high)

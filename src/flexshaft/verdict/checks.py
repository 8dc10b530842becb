"""The requirements a design is judged against: one check each, in one table (:data:`CHECKS`).

Each check is a function of the :class:`~flexshaft.verdict.evidence.Evidence` (the few numbers
it needs, SI, with where they occur) and the design's
:class:`~flexshaft.design.requirements.Requirements`, returning a
:class:`~flexshaft.verdict.result.Check`, or None when the driveline has no part it concerns
(the check is then not listed). :func:`evaluate` runs the table in order; the optimizer's
constraints, the comparison and the report read the same table, so a new requirement is a new
entry here (with its evidence in :mod:`flexshaft.verdict.evidence` and
:mod:`flexshaft.verdict.gather`), and nothing else (docs/architecture.md).

Checks, in report order (key: requirement):

* ``tsai_wu``: minimum ply Tsai-Wu safety factor (static loads, the steady torque times the
  torsional response's torque factor, + imbalance at the operating speed), with the effective
  compressive strength min(X_c, kink band); its note says which governs;
* ``metal_strength`` (when the shaft has an isotropic segment): the smaller of the von Mises
  yield and modified-Goodman fatigue safety factors of the metal segments
  (:mod:`flexshaft.analyses.metal_strength`) against ``min_safety_factor``;
* ``buckling``: torsional-buckling safety factor;
* ``whirl_onset``: no whirl instability below (1 + margin) × the operating speed: neither a
  tracked mode nor any root of the closed loop at rest, the operating speed and that speed;
* ``whirl_damping``: log decrement of the lateral whirl modes (shaft share ≥ 10 %) at the operating speed;
* ``separation``: API 684 separation margin of every lateral critical speed
  (:mod:`flexshaft.analyses.separation`);
* ``torsional_separation``: every torsional mode at least ``min_torsional_separation`` from
  every excitation (1/rev, tail-rotor N/rev, main-rotor harmonics) over the speed range;
* ``actuator_orbit``: static offset + spin-up orbit at each actuator within its auxiliary-bearing gap;
* ``actuator_force``: static + spin-up force of each actuator within its capacity;
* ``loop_sensitivity``, ``loop_gain_margin``, ``loop_phase_margin`` (when the design has
  active bearings): sensitivity peak (ISO 14839-3), gain and phase margins of every loop;
* ``temperature``: maximum shaft temperature within the matrix allowable;
* ``spinup_deflection``: peak shaft orbit during spin-up within the limit;
* ``coupling_angle`` (when the design has couplings): the static plus whirling misalignment
  angle of each coupling within its ``allowable_angle_deg``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Literal

from flexshaft.analyses.separation import api684_separation
from flexshaft.assembly.model import Model
from flexshaft.design.requirements import Requirements
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict.evidence import Evidence, Location
from flexshaft.verdict.result import Check, Finding, Kind, Status, Verdict

__all__ = [
    "CHECKS",
    "CHECK_KEYS",
    "CheckRule",
    "actuator_force",
    "actuator_orbit",
    "buckling",
    "coupling_angle",
    "evaluate",
    "metal_strength",
    "separation",
    "spinup_deflection",
    "loop_gain_margin",
    "loop_phase_margin",
    "loop_sensitivity",
    "temperature",
    "torsional_separation",
    "tsai_wu",
    "whirl_damping",
    "whirl_onset",
    "whirl_onset_check",
]


# ------------------------------------------------------------------------------------------------
# Findings

_Sense = Literal["at least", "at most"]  # Check.sense
_Args = tuple[str, str, Kind, _Sense]  # key, title, kind, sense: the leading arguments of a Check


def _not_evaluated(key: str, title: str, kind: Kind, sense: _Sense, note: str) -> Check:
    return Check(key, title, kind, sense, "not evaluated", note=note)


def _from_findings(key: str, title: str, kind: Kind, sense: _Sense, findings: list[Finding], note: str = "") -> Check:
    worst = min(findings, key=lambda f: f.margin)
    status: Status = "pass" if worst.passed else "fail"
    n_failed = sum(not f.passed for f in findings)
    if len(findings) > 1:
        count = f"{n_failed} of {len(findings)} fail" if n_failed else f"all {len(findings)} pass"
        note = f"{count}; {note}" if note else count
    return Check(
        key,
        title,
        kind,
        sense,
        status,
        worst.value,
        worst.limit,
        worst.margin,
        worst.location,
        note,
        tuple(findings),
        worst.lower_bound,
    )


def _at_least(value: float, limit: float, location: Location) -> Finding:
    return Finding(float(value), float(limit), float(value - limit), dict(location))


def _at_most(value: float, limit: float, location: Location) -> Finding:
    return Finding(float(value), float(limit), float(limit - value), dict(location))


# ------------------------------------------------------------------------------------------------
# The requirements


def tsai_wu(ev: Evidence, req: Requirements) -> Check:
    """The smallest ply Tsai-Wu safety factor at least ``min_safety_factor`` (the note says which
    compressive strength governs and the torque factor applied)."""
    args: _Args = ("tsai_wu", "Tsai-Wu safety factor", "ratio", "at least")
    if ev.safety_factor is None:
        return _not_evaluated(*args, ev.notes.get("tsai_wu", "no ply strength result"))
    finding = _at_least(ev.safety_factor, req.min_safety_factor, ev.safety_factor_location)
    return _from_findings(*args, [finding], ev.strength_note)


def buckling(ev: Evidence, req: Requirements) -> Check:
    """The torsional-buckling safety factor at least ``min_buckling_safety_factor``."""
    args: _Args = ("buckling", "buckling safety factor", "ratio", "at least")
    if ev.buckling_safety_factor is None:
        return _not_evaluated(*args, ev.notes.get("buckling", "no torsional buckling result"))
    finding = _at_least(ev.buckling_safety_factor, req.min_buckling_safety_factor, ev.buckling_location)
    return _from_findings(*args, [finding])


def whirl_onset_check(
    onset_speed: float | None,
    max_speed: float | None,
    operating_speed: float,
    min_margin: float,
    location: Location | None = None,
    note: str = "",
) -> Check:
    """The whirl-onset requirement: no instability below (1 + ``min_margin``) × Ω_op.

    Parameters
    ----------
    onset_speed : float or None
        Lowest onset speed of whirl instability [rad/s]; None: stable up to ``max_speed``.
    max_speed : float or None
        Highest speed analysed [rad/s]; None: no stability analysis (``note`` says why).
    operating_speed : float
        Ω_op [rad/s].
    min_margin : float
        Required margin above the operating speed [fraction].
    location : mapping, optional
        The unstable mode.
    """
    args: _Args = ("whirl_onset", "whirl onset speed", "speed", "at least")
    if max_speed is None:
        return _not_evaluated(*args, note or "no whirl stability result")
    required = (1.0 + min_margin) * operating_speed
    if onset_speed is not None:
        return _from_findings(*args, [_at_least(onset_speed, required, location or {})])
    if max_speed >= required:
        finding = Finding(float(max_speed), float(required), float(max_speed - required), {}, lower_bound=True)
        return _from_findings(*args, [finding], "no onset up to the highest speed analysed")
    return _not_evaluated(
        *args,
        f"stable up to {max_speed:.6g} rad/s only, the requirement needs "
        f"{required:.6g} rad/s; analyse to a higher speed",
    )


def whirl_damping(ev: Evidence, req: Requirements) -> Check:
    """The log decrement of every lateral whirl mode at the operating speed at least the required one."""
    args: _Args = ("whirl_damping", "whirl log decrement", "log_decrement", "at least")
    if not ev.modes_at_operating:
        return _not_evaluated(*args, ev.notes.get("whirl_damping", "no eigenvalues at the operating speed"))
    limit = req.required_log_decrement
    findings = [
        _at_least(m.log_decrement, limit, {"mode": m.label, "frequency": m.frequency}) for m in ev.modes_at_operating
    ]
    note = "lateral modes with ≥ 10 % of their kinetic energy in the shaft, at the operating speed"
    if ev.whirl_modes_top is not None:
        held = "the resolution's lowest modes"
        if ev.whirl_scope:  # every one below the onset requirement's speed, and the count
            held = f"every one below {ev.whirl_scope / (2 * math.pi):.3g} Hz and at least the resolution's lowest"
        note += f", to {ev.whirl_modes_top / (2 * math.pi):.3g} Hz ({held}; none above is held)"
    if req.min_damping_ratio is not None:
        note += f"; damping ratio ≥ {req.min_damping_ratio:g} as a log decrement"
    return _from_findings(*args, findings, note)


def separation(ev: Evidence, req: Requirements) -> Check:
    """Every lateral critical speed separated from the operating speed by API 684's margin for its AF."""
    args: _Args = ("separation", "critical-speed separation", "fraction", "at least")
    if req.separation == "off":
        return _not_evaluated(*args, 'separation = "off" in [requirements]')
    if ev.critical_speeds is None:
        return _not_evaluated(*args, ev.notes.get("separation", "no unbalance response to find critical speeds"))
    if not ev.critical_speeds:
        return Check(
            *args,
            "pass",
            note="no resonance peak in the unbalance response"
            + (f" up to {rad_s_to_rpm(ev.critical_search_max_speed):.0f} rpm" if ev.critical_search_max_speed else ""),
        )
    findings = []
    for critical in ev.critical_speeds:
        sep = api684_separation(critical.speed, critical.amplification_factor, ev.operating_speed, ev.operating_range)
        location = {
            **critical.location,
            "speed": critical.speed,
            "amplification_factor": sep.amplification_factor,
            "position": sep.position,
            "reference_speed": sep.reference_speed,
        }
        findings.append(_at_least(sep.margin, sep.required_margin, location))
    within = ev.operating_range is not None and ev.operating_range[0] < ev.operating_range[1]
    return _from_findings(
        *args,
        findings,
        "margin from the nearest end of the operating speed range (API: the minimum operating speed below "
        "it, the maximum continuous speed above)"
        if within
        else "margin as a fraction of the operating speed",
    )


def _actuator_check(ev: Evidence, key: str) -> Check:
    orbit = key == "actuator_orbit"
    args: _Args = (key, "actuator excursion" if orbit else "actuator force", "length" if orbit else "force", "at most")
    if not ev.actuators:
        return _not_evaluated(*args, ev.notes.get(key, "the design has no active bearings"))
    limit_field = "gap" if orbit else "force_capacity"
    findings, missing = [], []
    for a in ev.actuators:
        limit = a.gap if orbit else a.force_capacity
        if limit is None:
            missing.append(a.name)
            continue
        value = a.static_offset + a.peak_orbit if orbit else a.static_force + a.peak_force
        speed = a.orbit_speed if orbit else a.force_speed
        findings.append(_at_most(value, limit, {"actuator": a.name, "speed": speed}))
    if not findings:
        return _not_evaluated(*args, f"no {limit_field} given on the active bearings ({', '.join(missing)})")
    note = "static + spin-up peak"
    if missing:
        note += f"; not evaluated for {', '.join(missing)} (no {limit_field} given)"
    return _from_findings(*args, findings, note)


#: The ISA standard day at sea level (ISO 2533: 15 °C) [K]: the temperature check's margin is
#: compared with other checks' as a share of the allowable's rise above it.
STANDARD_DAY = 288.15


def temperature(ev: Evidence, req: Requirements) -> Check:
    """The largest shaft temperature at most the matrix allowable; a thermal runaway fails, and so
    does a self-heating iteration that did not converge: from the air's temperature the iterates
    of a heating that grows with temperature rise toward the equilibrium, so the last one is no
    equilibrium but a value below it (one whose equilibrium lies above the allowable can stop
    below it, still rising)."""
    args: _Args = ("temperature", "shaft temperature", "temperature", "at most")
    if ev.max_temperature is None:
        return _not_evaluated(*args, ev.notes.get("temperature", "no shaft thermal result"))
    if ev.allowable_temperature is None:
        return _not_evaluated(*args, "no allowable temperature given")
    check = _from_findings(*args, [_at_most(ev.max_temperature, ev.allowable_temperature, ev.temperature_location)])
    # compared with other checks as a share of the allowable's rise above the ISA standard day
    # (11 K below 100 °C is 13 % of its 85 K, not 3 % of 373 K), the same at every point
    rise = ev.allowable_temperature - STANDARD_DAY
    check = replace(check, scale=rise if rise > 0.0 else None)
    if ev.thermal_runaway:
        return replace(
            check, status="fail", note="thermal runaway: no self-heating equilibrium below the allowable temperature"
        )
    if ev.self_heating_status == "not_converged":
        return replace(
            check,
            status="fail",
            note="the self-heating iteration did not converge: its last temperature is no equilibrium "
            "(the iterates still rose toward one that may lie above the allowable)",
        )
    return check


def spinup_deflection(ev: Evidence, req: Requirements) -> Check:
    """The largest shaft orbit during the spin-up at most ``max_spinup_deflection``."""
    args: _Args = ("spinup_deflection", "spin-up shaft orbit", "length", "at most")
    if req.max_spinup_deflection is None:
        return _not_evaluated(*args, "no limit given ([requirements] max_spinup_deflection)")
    if ev.spinup_peak is None:
        return _not_evaluated(*args, ev.notes.get("spinup_deflection", "no spin-up response"))
    return _from_findings(*args, [_at_most(ev.spinup_peak, req.max_spinup_deflection, ev.spinup_location)])


def metal_strength(ev: Evidence, req: Requirements) -> Check | None:
    """Listed only when the shaft has an isotropic segment (``ev.metal_strength`` not None)."""
    if ev.metal_strength is None:
        return None
    args: _Args = ("metal_strength", "metal safety factor", "ratio", "at least")
    if not ev.metal_strength:
        return _not_evaluated(*args, ev.notes.get("metal_strength", "no isotropic segment gives its strengths"))
    findings = [
        _at_least(
            m.safety_factor,
            req.min_safety_factor,
            {"station": m.station, "case": f"segment {m.segment}, {m.criterion}"},
        )
        for m in ev.metal_strength
    ]
    return _from_findings(
        *args, findings, "isotropic segments, yield and fatigue (Shigley DE-Goodman); limit min_safety_factor"
    )


def coupling_angle(ev: Evidence, req: Requirements) -> Check | None:
    """Listed only when the design has couplings (``ev.coupling_angles`` not None)."""
    if ev.coupling_angles is None:
        return None
    args: _Args = ("coupling_angle", "coupling misalignment", "angle", "at most")
    findings, missing = [], []
    for c in ev.coupling_angles:
        if c.allowable_angle is None:
            missing.append(c.name)
            continue
        findings.append(
            _at_most(
                c.static_angle + c.dynamic_angle,
                c.allowable_angle,
                {
                    "station": c.station,
                    "case": f"coupling {c.name}",
                    "detail": f"static {math.degrees(c.static_angle):.3g}° + whirl "
                    f"{math.degrees(c.dynamic_angle):.3g}°",
                },
            )
        )
    if not findings:
        return _not_evaluated(
            *args,
            f"no allowable_angle_deg given on the couplings ({', '.join(missing)})"
            if missing
            else "the design has no couplings",
        )
    note = "static + whirling angle at the operating speed"
    if missing:
        note += f"; not evaluated for {', '.join(missing)} (no allowable_angle_deg given)"
    return _from_findings(*args, findings, note)


def whirl_onset(ev: Evidence, req: Requirements) -> Check:
    """:func:`whirl_onset_check` of the evidence's stability analysis."""
    return whirl_onset_check(
        ev.onset_speed,
        ev.stability_max_speed,
        ev.operating_speed,
        req.min_onset_margin,
        ev.onset_location if ev.onset_speed is not None else None,
        ev.notes.get("whirl_onset", ""),
    )


def actuator_orbit(ev: Evidence, req: Requirements) -> Check:
    """Static offset + spin-up orbit of each active bearing within its auxiliary-bearing gap."""
    return _actuator_check(ev, "actuator_orbit")


def actuator_force(ev: Evidence, req: Requirements) -> Check:
    """Static + spin-up force of each active bearing within its force capacity."""
    return _actuator_check(ev, "actuator_force")


def torsional_separation(ev: Evidence, req: Requirements) -> Check:
    """Every torsional natural frequency at least ``min_torsional_separation`` from every
    excitation frequency over the operating speed range (its nearest one per mode)."""
    args: _Args = ("torsional_separation", "torsional separation", "fraction", "at least")
    if ev.torsional_modes is None:
        return _not_evaluated(*args, ev.notes.get("torsional_separation", "no torsional modes"))
    if not ev.torsional_modes:
        return Check(*args, "pass", note="no flexible torsional mode below twice the highest excitation")
    findings = [
        _at_least(
            m.margin,
            req.min_torsional_separation,
            {
                "mode": m.label,
                "frequency": m.frequency,
                "case": m.excitation,
                "detail": f"excitation {m.band[0] / (2 * math.pi):.4g}-{m.band[1] / (2 * math.pi):.4g} Hz "
                "over the speed range",
            },
        )
        for m in ev.torsional_modes
    ]
    return _from_findings(*args, findings, "margin |f_n − f_e|/f_e to the nearest excitation over the speed range")


def _loop_location(loop, frequency: float | None) -> dict:
    location = {"actuator": f"{loop.actuator} ({loop.axis})", "speed": loop.speed}
    if frequency is not None:
        location["frequency"] = frequency
    return location


def loop_sensitivity(ev: Evidence, req: Requirements) -> Check | None:
    """The sensitivity peak |S|max of every magnetic-bearing loop at most ``max_sensitivity_peak``
    (ISO 14839-3's zone limits; listed only with active bearings)."""
    args: _Args = ("loop_sensitivity", "loop sensitivity peak", "ratio", "at most")
    if ev.loops is None:
        return None
    if not ev.loops:
        return _not_evaluated(*args, ev.notes.get("loop_sensitivity", "no loop robustness result"))
    findings = [
        _at_most(lp.peak_sensitivity, req.max_sensitivity_peak, _loop_location(lp, lp.peak_frequency))
        for lp in ev.loops
    ]
    return _from_findings(
        *args, findings, "ISO 14839-3 zones A < 3, B < 4, C < 5, D above; each axis, other loops closed"
    )


def loop_gain_margin(ev: Evidence, req: Requirements) -> Check | None:
    """The gain margin of every magnetic-bearing loop, for a gain rise and for a gain fall, at
    least ``min_gain_margin_db`` (a loop without a phase crossover of a kind has no such limit)."""
    args: _Args = ("loop_gain_margin", "loop gain margin", "decibel", "at least")
    if ev.loops is None:
        return None
    if not ev.loops:
        return _not_evaluated(*args, ev.notes.get("loop_gain_margin", "no loop robustness result"))
    findings = []
    for lp in ev.loops:
        for value, direction in ((lp.gain_margin_upper, "gain rise"), (lp.gain_margin_lower, "gain fall")):
            if value is not None:
                location = {**_loop_location(lp, None), "case": direction}
                findings.append(_at_least(abs(value), req.min_gain_margin_db, location))
    if not findings:
        return Check(  # the requirement is shown; there is no finite margin to measure against it
            *args,
            "pass",
            limit=float(req.min_gain_margin_db),
            note="no phase crossover of any loop in the frequency range: no finite gain margin",
        )
    return _from_findings(*args, findings, "either way: the gain rise or fall that puts the loop on −1")


def loop_phase_margin(ev: Evidence, req: Requirements) -> Check | None:
    """The smallest phase margin over the gain crossovers of every magnetic-bearing loop at least
    ``min_phase_margin_deg``."""
    args: _Args = ("loop_phase_margin", "loop phase margin", "angle", "at least")
    if ev.loops is None:
        return None
    if not ev.loops:
        return _not_evaluated(*args, ev.notes.get("loop_phase_margin", "no loop robustness result"))
    limit = math.radians(req.min_phase_margin_deg)
    findings = [
        _at_least(lp.phase_margin, limit, _loop_location(lp, lp.phase_margin_frequency))
        for lp in ev.loops
        if lp.phase_margin is not None
    ]
    if not findings:
        return Check(*args, "pass", limit=limit, note="no gain crossover of any loop in the frequency range")
    return _from_findings(*args, findings, "smallest over each loop's gain crossovers")


# ------------------------------------------------------------------------------------------------
# The table


def _always(model: Model) -> bool:
    return True


def _laminated(model: Model) -> bool:
    return model.shaft.laminate is not None


def _metal_segment(model: Model) -> bool:
    return any(model.design.materials[seg.material].kind == "isotropic" for seg in model.segments)


def _active_bearings(model: Model) -> bool:
    return bool(model.actuators)


def _couplings(model: Model) -> bool:
    return bool(model.couplings)


@dataclass(frozen=True)
class CheckRule:
    """One requirement of the verdict.

    Attributes
    ----------
    key : str
        The check's key (its :attr:`Check.key`).
    check : callable
        ``check(evidence, requirements) -> Check | None`` (None: not listed).
    applies : callable
        ``applies(model) -> bool``: whether the kind of driveline has the parts the check
        concerns (a one-piece laminated shaft, a metal segment, active bearings, couplings); a
        check that does not apply is never evaluated for it, and the optimizer does not
        constrain it.
    """

    key: str
    check: Callable[[Evidence, Requirements], Check | None]
    applies: Callable[[Model], bool] = _always


#: Every requirement, in report order.
CHECKS: tuple[CheckRule, ...] = (
    CheckRule("tsai_wu", tsai_wu, _laminated),
    CheckRule("metal_strength", metal_strength, _metal_segment),
    CheckRule("buckling", buckling),
    CheckRule("whirl_onset", whirl_onset),
    CheckRule("whirl_damping", whirl_damping),
    CheckRule("separation", separation),
    CheckRule("torsional_separation", torsional_separation),
    CheckRule("actuator_orbit", actuator_orbit, _active_bearings),
    CheckRule("actuator_force", actuator_force, _active_bearings),
    CheckRule("loop_sensitivity", loop_sensitivity, _active_bearings),
    CheckRule("loop_gain_margin", loop_gain_margin, _active_bearings),
    CheckRule("loop_phase_margin", loop_phase_margin, _active_bearings),
    CheckRule("temperature", temperature, _laminated),
    CheckRule("spinup_deflection", spinup_deflection),
    CheckRule("coupling_angle", coupling_angle, _couplings),
)
#: Their keys, in report order.
CHECK_KEYS: tuple[str, ...] = tuple(rule.key for rule in CHECKS)


def evaluate(evidence: Evidence, requirements: Requirements | None = None) -> Verdict:
    """Check the evidence against the requirements (default: the schema defaults).

    Parameters
    ----------
    evidence : Evidence
        Results in SI units, see :class:`~flexshaft.verdict.evidence.Evidence`.
    requirements : Requirements, optional
        The design's ``[requirements]``.

    Returns
    -------
    Verdict
        One check per requirement of :data:`CHECKS` that is listed, in its order.
    """
    req = requirements if requirements is not None else Requirements()
    checks = (rule.check(evidence, req) for rule in CHECKS)
    return Verdict(tuple(c for c in checks if c is not None))

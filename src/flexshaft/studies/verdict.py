"""The requirements verdict: a design's results checked against its ``[requirements]``.

:func:`evaluate` takes plain :class:`Evidence` (the few numbers each requirement needs, in SI,
with where they occur) and the design's :class:`~flexshaft.design.requirements.Requirements`,
and returns a frozen :class:`Verdict`: one :class:`Check` per requirement with its value, limit,
margin (signed, in the value's unit: positive means room to the limit), pass/fail and location.
A requirement that cannot be evaluated (no limit given, no result to check) says why instead of
passing. :func:`flexshaft.studies.verdict_evidence.evidence_from_run` builds the evidence from a
``flexshaft run`` result.

Checks, in report order (key: requirement):

* ``tsai_wu``: minimum ply Tsai-Wu safety factor (static loads + imbalance at the operating speed);
* ``buckling``: torsional-buckling safety factor;
* ``whirl_onset``: no whirl instability below (1 + margin) × the operating speed;
* ``whirl_damping``: log decrement of the lateral whirl modes (shaft share ≥ 10 %) at the operating speed;
* ``separation``: API 684 separation margin of every lateral critical speed
  (:mod:`flexshaft.analyses.separation`);
* ``actuator_orbit``: static offset + spin-up orbit at each actuator within its auxiliary-bearing gap;
* ``actuator_force``: static + spin-up force of each actuator within its capacity;
* ``temperature``: maximum shaft temperature within the matrix allowable;
* ``spinup_deflection``: peak shaft orbit during spin-up within the limit.

Two checks appear only where the driveline has the parts they concern:

* ``metal_strength`` (after ``tsai_wu``; when the shaft has an isotropic segment): the smaller of
  the von Mises yield and modified-Goodman fatigue safety factors of the metal segments
  (:mod:`flexshaft.analyses.metal_strength`) against ``min_safety_factor``;
* ``coupling_angle`` (last; when the design has couplings): the static plus whirling
  misalignment angle of each coupling within its ``allowable_angle_deg``.

Locations are small mappings with SI values (``station`` [m], ``speed`` [rad/s], ``frequency``
[rad/s]) and labels (``actuator``, ``mode``, ``ply``, ``case``, ``detail``); the report
(:mod:`flexshaft.report.verdict`) converts and prints them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal

from flexshaft.analyses.results import ResultMixin, coded, new_dataset
from flexshaft.analyses.separation import api684_separation
from flexshaft.design.requirements import Requirements
from flexshaft.studies.evidence import (  # re-exported: the verdict's input types
    ActuatorEvidence,
    CouplingEvidence,
    Evidence,
    LateralCritical,
    Location,
    MetalEvidence,
    ModeDamping,
)
from flexshaft.units import format_quantity

__all__ = [
    "ActuatorEvidence",
    "Check",
    "CouplingEvidence",
    "Evidence",
    "Finding",
    "Kind",
    "LateralCritical",
    "MetalEvidence",
    "ModeDamping",
    "Status",
    "Verdict",
    "evaluate",
    "whirl_onset_check",
]

#: Outcome of one check.
Status = Literal["pass", "fail", "not evaluated"]
#: Physical kind of a check's value, limit and margin (sets the display unit).
Kind = Literal["ratio", "speed", "length", "force", "temperature", "fraction", "log_decrement", "angle"]
#: SI unit of each kind.
SI_UNITS: dict[str, str] = {
    "ratio": "-",
    "speed": "rad/s",
    "length": "m",
    "force": "N",
    "temperature": "K",
    "fraction": "-",
    "log_decrement": "-",
    "angle": "rad",
}


# ------------------------------------------------------------------------------------------------
# Checks and the verdict


@dataclass(frozen=True)
class Finding:
    """One instance of a requirement (one mode, one critical, one actuator...).

    ``margin`` is in the unit of ``value``: value − limit for "at least" requirements, limit −
    value for "at most" ones, so that a negative margin fails. ``lower_bound``: the true value
    (and margin) is at least this large.
    """

    value: float
    limit: float
    margin: float
    location: Location = field(default_factory=dict)
    lower_bound: bool = False  # the true value is larger (e.g. no whirl onset up to the speed analysed)

    @property
    def passed(self) -> bool:
        return self.margin >= 0.0

    def to_dict(self) -> dict:
        return {
            "value": self.value,
            "limit": self.limit,
            "margin": self.margin,
            "passed": self.passed,
            "lower_bound": self.lower_bound,
            "location": dict(self.location),
        }


@dataclass(frozen=True)
class Check:
    """One requirement: status, the governing (worst) finding and every finding.

    Attributes
    ----------
    key, title : str
        Identifier and human name of the requirement.
    kind : Kind
        Physical kind of value, limit and margin (SI unit in :data:`SI_UNITS`).
    sense : {"at least", "at most"}
        The value must be at least / at most the limit.
    status : {"pass", "fail", "not evaluated"}
    value, limit, margin : float or None
        Of the governing finding (None when not evaluated); with ``lower_bound`` the value and
        margin are lower bounds.
    location : mapping
        Where the governing finding occurs.
    note : str
        Why the check was not evaluated, or a remark on how it was.
    findings : tuple of Finding
        Every instance checked; the governing one has the smallest margin (for separation the
        margins are fractions of the operating speed, so they compare across criticals).
    """

    key: str
    title: str
    kind: Kind
    sense: Literal["at least", "at most"]
    status: Status
    value: float | None = None
    limit: float | None = None
    margin: float | None = None
    location: Location = field(default_factory=dict)
    note: str = ""
    findings: tuple[Finding, ...] = ()
    lower_bound: bool = False

    @property
    def passed(self) -> bool | None:
        """True, False, or None when not evaluated."""
        return None if self.status == "not evaluated" else self.status == "pass"

    @property
    def n_failed(self) -> int:
        return sum(not f.passed for f in self.findings)

    def to_dict(self) -> dict:
        return {
            "key": self.key,
            "title": self.title,
            "status": self.status,
            "sense": self.sense,
            "kind": self.kind,
            "unit": SI_UNITS[self.kind],
            "value": self.value,
            "limit": self.limit,
            "margin": self.margin,
            "lower_bound": self.lower_bound,
            "location": dict(self.location),
            "note": self.note,
            "findings": [f.to_dict() for f in self.findings],
        }


@dataclass(frozen=True)
class Verdict(ResultMixin):
    """Every requirement check of one design; ``passed`` when none fails."""

    checks: tuple[Check, ...]

    plots = {"margins": "plot_margins"}

    def plot_margins(self, ax=None, **kwargs):
        """Bar chart of every check's margin divided by its limit, green pass, red fail, grey
        not evaluated, with the margin in engineering units beside each bar (keywords to
        :func:`flexshaft.plot.verdict.margins_figure`)."""
        from flexshaft.plot.verdict import margins_figure

        normalised = [float("nan") if c.margin is None or not c.limit else c.margin / abs(c.limit) for c in self.checks]
        return margins_figure(
            [c.title for c in self.checks],
            normalised,
            [c.status for c in self.checks],
            ["" if c.margin is None else format_quantity(c.kind, c.margin, margin=True) for c in self.checks],
            [c.lower_bound for c in self.checks],
            ax=ax,
            **{
                "title": f"Requirements verdict: {'PASS' if self.passed else 'FAIL'} (margin / limit of each)",
                **kwargs,
            },
        )

    def to_dataset(self):
        """One row per check: value, limit, margin (SI, the unit of each check in ``units``),
        status coded pass/fail/not_evaluated (xarray)."""
        import numpy as np

        def number(x):
            return float("nan") if x is None else float(x)

        status, status_attrs = coded(
            [c.status.replace(" ", "_") for c in self.checks], ("pass", "fail", "not_evaluated"), "requirement status"
        )
        units = [SI_UNITS.get(c.kind, "-").replace("-", "1") for c in self.checks]
        return new_dataset(
            {
                "value": (
                    "check",
                    np.array([number(c.value) for c in self.checks]),
                    {"long_name": "worst value of the check (unit per check: see check_units)"},
                ),
                "limit": ("check", np.array([number(c.limit) for c in self.checks]), {"long_name": "required limit"}),
                "margin": (
                    "check",
                    np.array([number(c.margin) for c in self.checks]),
                    {"long_name": "signed margin (negative: fails)"},
                ),
                "status": ("check", status, status_attrs),
            },
            {
                "check": ("check", [c.key for c in self.checks], {"long_name": "requirement"}),
                "check_title": ("check", [c.title for c in self.checks], {"long_name": "requirement title"}),
                "check_units": ("check", units, {"long_name": "SI unit of value, limit and margin"}),
            },
            "requirements verdict",
            verdict="PASS" if self.passed else "FAIL",
            summary=self.summary,
        )

    @property
    def passed(self) -> bool:
        """No check fails (checks that could not be evaluated do not fail)."""
        return not self.failed

    @property
    def failed(self) -> tuple[Check, ...]:
        return tuple(c for c in self.checks if c.status == "fail")

    @property
    def not_evaluated(self) -> tuple[Check, ...]:
        return tuple(c for c in self.checks if c.status == "not evaluated")

    def check(self, key: str) -> Check:
        """The check called ``key``."""
        for c in self.checks:
            if c.key == key:
                return c
        raise KeyError(key)

    @property
    def summary(self) -> str:
        """One line: PASS/FAIL, the failed requirements and the count not evaluated."""
        n_pass = sum(c.status == "pass" for c in self.checks)
        head = "PASS" if self.passed else "FAIL"
        parts = []
        if self.failed:
            parts.append(
                f"{len(self.failed)} of {len(self.checks)} requirements fail: "
                + ", ".join(c.title for c in self.failed)
            )
        parts.append(f"{n_pass} pass")
        if self.not_evaluated:
            parts.append(f"{len(self.not_evaluated)} not evaluated: " + ", ".join(c.title for c in self.not_evaluated))
        return f"{head}: " + "; ".join(parts)

    def __repr__(self) -> str:
        return f"Verdict({self.summary})"

    def to_dict(self) -> dict:
        return {"passed": self.passed, "summary": self.summary, "checks": [c.to_dict() for c in self.checks]}


def _not_evaluated(key: str, title: str, kind: Kind, sense, note: str) -> Check:
    return Check(key, title, kind, sense, "not evaluated", note=note)


def _from_findings(key: str, title: str, kind: Kind, sense, findings: list[Finding], note: str = "") -> Check:
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


def _tsai_wu(ev: Evidence, req: Requirements) -> Check:
    args = ("tsai_wu", "Tsai-Wu safety factor", "ratio", "at least")
    if ev.safety_factor is None:
        return _not_evaluated(*args, ev.notes.get("tsai_wu", "no ply strength result"))
    return _from_findings(*args, [_at_least(ev.safety_factor, req.min_safety_factor, ev.safety_factor_location)])


def _buckling(ev: Evidence, req: Requirements) -> Check:
    args = ("buckling", "buckling safety factor", "ratio", "at least")
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
    args = ("whirl_onset", "whirl onset speed", "speed", "at least")
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


def _whirl_damping(ev: Evidence, req: Requirements) -> Check:
    args = ("whirl_damping", "whirl log decrement", "log_decrement", "at least")
    if not ev.modes_at_operating:
        return _not_evaluated(*args, ev.notes.get("whirl_damping", "no eigenvalues at the operating speed"))
    limit = req.required_log_decrement
    findings = [
        _at_least(m.log_decrement, limit, {"mode": m.label, "frequency": m.frequency}) for m in ev.modes_at_operating
    ]
    note = "lateral modes with ≥ 10 % of their kinetic energy in the shaft, at the operating speed"
    if req.min_damping_ratio is not None:
        note += f"; damping ratio ≥ {req.min_damping_ratio:g} as a log decrement"
    return _from_findings(*args, findings, note)


def _separation(ev: Evidence, req: Requirements) -> Check:
    args = ("separation", "critical-speed separation", "fraction", "at least")
    if req.separation == "off":
        return _not_evaluated(*args, 'separation = "off" in [requirements]')
    if ev.critical_speeds is None:
        return _not_evaluated(*args, ev.notes.get("separation", "no unbalance response to find critical speeds"))
    if not ev.critical_speeds:
        return Check(
            *args,
            "pass",
            note="no resonance peak in the unbalance response"
            + (f" up to {ev.critical_search_max_speed:.6g} rad/s" if ev.critical_search_max_speed else ""),
        )
    findings = []
    for critical in ev.critical_speeds:
        sep = api684_separation(critical.speed, critical.amplification_factor, ev.operating_speed)
        location = {
            **critical.location,
            "speed": critical.speed,
            "amplification_factor": sep.amplification_factor,
            "position": sep.position,
        }
        findings.append(_at_least(sep.margin, sep.required_margin, location))
    return _from_findings(*args, findings, "margin as a fraction of the operating speed")


def _actuators(ev: Evidence, key: str) -> Check:
    orbit = key == "actuator_orbit"
    args = (key, "actuator excursion" if orbit else "actuator force", "length" if orbit else "force", "at most")
    if not ev.actuators:
        return _not_evaluated(*args, ev.notes.get(key, "the design has no active bearings"))
    limit_field = "gap" if orbit else "force_capacity"
    findings, missing = [], []
    for a in ev.actuators:
        limit = getattr(a, limit_field)
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


def _temperature(ev: Evidence, req: Requirements) -> Check:
    args = ("temperature", "shaft temperature", "temperature", "at most")
    if ev.max_temperature is None:
        return _not_evaluated(*args, ev.notes.get("temperature", "no shaft thermal result"))
    if ev.allowable_temperature is None:
        return _not_evaluated(*args, "no allowable temperature given")
    check = _from_findings(*args, [_at_most(ev.max_temperature, ev.allowable_temperature, ev.temperature_location)])
    if ev.thermal_runaway:
        return Check(
            *args,
            "fail",
            check.value,
            check.limit,
            check.margin,
            check.location,
            "thermal runaway: no self-heating equilibrium below the allowable temperature",
            check.findings,
        )
    return check


def _spinup(ev: Evidence, req: Requirements) -> Check:
    args = ("spinup_deflection", "spin-up shaft orbit", "length", "at most")
    if req.max_spinup_deflection is None:
        return _not_evaluated(*args, "no limit given ([requirements] max_spinup_deflection)")
    if ev.spinup_peak is None:
        return _not_evaluated(*args, ev.notes.get("spinup_deflection", "no spin-up response"))
    return _from_findings(*args, [_at_most(ev.spinup_peak, req.max_spinup_deflection, ev.spinup_location)])


def _metal_strength(ev: Evidence, req: Requirements) -> Check:
    args = ("metal_strength", "metal safety factor", "ratio", "at least")
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


def _coupling_angle(ev: Evidence) -> Check:
    args = ("coupling_angle", "coupling misalignment", "angle", "at most")
    findings, missing = [], []
    for c in ev.coupling_angles or ():
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


def evaluate(evidence: Evidence, requirements: Requirements | None = None) -> Verdict:
    """Check the evidence against the requirements (default: the schema defaults).

    Parameters
    ----------
    evidence : Evidence
        Results in SI units, see :class:`Evidence`.
    requirements : Requirements, optional
        The design's ``[requirements]``.

    Returns
    -------
    Verdict
        One check per requirement, in the order of the module docstring.
    """
    req = requirements if requirements is not None else Requirements()
    ev = evidence
    onset_location = ev.onset_location if ev.onset_speed is not None else None
    metal = (_metal_strength(ev, req),) if ev.metal_strength is not None else ()
    couplings = (_coupling_angle(ev),) if ev.coupling_angles is not None else ()
    return Verdict(
        (
            _tsai_wu(ev, req),
            *metal,
            _buckling(ev, req),
            whirl_onset_check(
                ev.onset_speed,
                ev.stability_max_speed,
                ev.operating_speed,
                req.min_onset_margin,
                onset_location,
                ev.notes.get("whirl_onset", ""),
            ),
            _whirl_damping(ev, req),
            _separation(ev, req),
            _actuators(ev, "actuator_orbit"),
            _actuators(ev, "actuator_force"),
            _temperature(ev, req),
            _spinup(ev, req),
            *couplings,
        )
    )

"""What a requirements verdict says: one :class:`Check` per requirement with its value, limit,
margin (signed, in the value's unit: positive means room to the limit), pass/fail and location,
and the :class:`Verdict` of a design.

A requirement that cannot be evaluated (no limit given, no result to check) says why instead of
passing. Locations are small mappings with SI values (``station`` [m], ``speed`` [rad/s],
``frequency`` [rad/s]) and labels (``actuator``, ``mode``, ``ply``, ``case``, ``detail``); the
report (:mod:`flexshaft.report.verdict`) converts and prints them.
"""

from __future__ import annotations

import html
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np

from flexshaft.analyses.results import ResultMixin, coded, dataframe, html_table, new_dataset
from flexshaft.plot.verdict import margins_figure
from flexshaft.units import format_quantity
from flexshaft.verdict.evidence import Location
from flexshaft.verdict.text import VERDICT_COLUMNS, location_text, verdict_headline, verdict_rows

__all__ = [
    "Check",
    "Finding",
    "Kind",
    "LOCATION_UNITS",
    "SI_UNITS",
    "Status",
    "Verdict",
    "location_with_units",
    "normalised_margin",
    "FAILED_WITHOUT_MARGIN",
]


#: Outcome of one check.
Status = Literal["pass", "fail", "not evaluated"]

#: Physical kind of a check's value, limit and margin (sets the display unit).
Kind = Literal["ratio", "speed", "length", "force", "temperature", "fraction", "log_decrement", "angle", "decibel"]

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
    "decibel": "dB",
}


#: CSS of each status in a notebook's verdict table.
_STATUS_STYLE = {
    "pass": "color:#1a7f37;font-weight:bold;",
    "fail": "color:#cf222e;font-weight:bold;",
    "not evaluated": "color:#9a6700;",
}


#: The SI unit of each numeric key of a location, written into its key in a results file
#: (``speed_rad_s``; the CLI's ``--json`` promises each unit in its key).
LOCATION_UNITS = {"speed": "rad_s", "frequency": "rad_s", "station": "m", "peak_orbit": "m", "reference_speed": "rad_s"}


def location_with_units(location: Mapping[str, Any]) -> dict:
    """``location`` for a results file: each key of :data:`LOCATION_UNITS` with its unit."""
    return {(f"{k}_{LOCATION_UNITS[k]}" if k in LOCATION_UNITS else k): v for k, v in location.items()}


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
            "location": location_with_units(self.location),
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
    scale : float or None
        What the margin is measured against when checks are compared
        (:func:`normalised_margin`): each finding's |limit| when None; the temperature check's
        is the allowable's rise above the ISA standard day (15 °C).
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
    scale: float | None = None

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
            "normalised_margin": _finite_or_none(normalised_margin(self)),
            "location": location_with_units(self.location),
            "note": self.note,
            "findings": [f.to_dict() for f in self.findings],
        }


#: The normalised margin of a check that fails with a margin that is not negative (a thermal
#: runaway keeps the margin of its last temperature): the largest number below zero a figure
#: draws; the optimizer reads it as a whole-limit violation.
FAILED_WITHOUT_MARGIN = -1e-300


def normalised_margin(check: Check) -> float:
    """A check's margin as a dimensionless number, the one measure by which checks of different
    kinds are compared: the governing point of an envelope, the margins figures, the optimizer's
    constraints and the explorer.

    The smallest margin / scale of the check's findings (of every point, for an envelope's
    check), the scale being the check's :attr:`Check.scale` when given (the temperature's: the
    allowable's rise above 15 °C, so 11 K below a 100 °C allowable reads 13 %, not the 3 % of
    373 K), else each finding's own |limit| (a separation's required margin depends on its
    critical's AF; a finding with a zero limit, a critically damped peak, cannot approach it:
    ±inf). A failing check never reads as positive (a thermal runaway fails with the margin of
    the last temperature computed): −1e-300 then. +inf: passed with nothing to measure (no
    critical speed, no phase crossover); NaN: not evaluated.
    """
    if check.status == "not evaluated":
        return float("nan")
    if check.margin is None:
        return float("-inf") if check.status == "fail" else float("inf")
    pairs: list[tuple[float, float | None]] = [(f.margin, f.limit) for f in check.findings]
    pairs = pairs or [(check.margin, check.limit)]
    relative = min(_share(margin, check.scale if check.scale else abs(limit or 0.0)) for margin, limit in pairs)
    return min(relative, FAILED_WITHOUT_MARGIN) if check.status == "fail" and relative >= 0 else relative


def _finite_or_none(x: float) -> float | None:
    """``x``, or None when it is not finite (strict JSON has no NaN or infinity; the status says
    whether a check without a finite normalised margin passed, failed or was not evaluated)."""
    return x if math.isfinite(x) else None


def _share(margin: float, scale: float) -> float:
    if scale:
        return float(margin) / scale
    return float("inf") if margin >= 0 else float("-inf")


@dataclass(frozen=True)
class Verdict(ResultMixin):
    """Every requirement check of one design; ``passed`` when none fails."""

    checks: tuple[Check, ...]

    plots = {"margins": "plot_margins"}

    def plot_margins(self, ax=None, **kwargs):
        """Bar chart of every check's normalised margin (:func:`normalised_margin`: its margin
        divided by its limit, the temperature's by the allowable's rise above 15 °C), green pass (to the
        axis end when it passed with no finite margin), red fail, grey not evaluated, with the
        margin in engineering units beside each bar (keywords to
        :func:`flexshaft.plot.verdict.margins_figure`)."""
        normalised = [normalised_margin(c) for c in self.checks]
        scaled = sorted({c.title for c in self.checks if c.scale and c.status != "not evaluated"})
        if scaled:
            kwargs.setdefault("xlabel", f"margin / limit [%]; {', '.join(scaled)}: margin / (limit − 15 °C); < 0 fails")
        return margins_figure(
            [c.title for c in self.checks],
            normalised,
            [c.status for c in self.checks],
            ["" if c.margin is None else format_quantity(c.kind, c.margin, margin=True) for c in self.checks],
            [c.lower_bound for c in self.checks],
            ax=ax,
            **{
                "title": f"Requirements verdict: {'PASS' if self.passed else 'FAIL'} (normalised margin of each)",
                **kwargs,
            },
        )

    def to_dataset(self):
        """One row per check: value, limit, margin (SI, the unit of each check in ``units``),
        status coded pass/fail/not_evaluated (xarray)."""

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

    @property
    def headline(self) -> str:
        """One line: ``FAIL — 2 of 9 checks fail: whirl onset speed (3125 rpm; required ≥ 5520
        rpm), …`` or ``PASS — 9 checks pass`` (what ``flexshaft run`` prints first)."""
        return verdict_headline(self)

    def _repr_html_(self) -> str:
        """The verdict table of the report: value, limit, margin, status (green pass, red fail,
        amber not evaluated) and where, in engineering units, under the headline."""
        rows = verdict_rows(self)
        numbers = "white-space:nowrap;text-align:right;"
        styles = [
            {1: numbers, 2: numbers, 3: numbers, 4: "white-space:nowrap;" + _STATUS_STYLE[c.status]}
            for c in self.checks
        ]
        colour = _STATUS_STYLE["pass" if self.passed else "fail"]
        title = f'<p style="{colour}">verdict: {html.escape(self.headline)}</p>'
        return title + html_table(VERDICT_COLUMNS, rows, row_styles=styles)

    def to_dataframe(self):
        """One row per check, indexed by its key: title, status, value, limit and margin in SI
        (the unit in ``unit``), the sense of the limit, whether value and margin are lower bounds,
        and where (text, engineering units). pandas is imported here (xarray brings it)."""
        return dataframe(
            {
                "check": [c.key for c in self.checks],
                "title": [c.title for c in self.checks],
                "status": [c.status for c in self.checks],
                "value": [c.value for c in self.checks],
                "limit": [c.limit for c in self.checks],
                "margin": [c.margin for c in self.checks],
                "unit": [SI_UNITS[c.kind] for c in self.checks],
                "sense": [c.sense for c in self.checks],
                "lower_bound": [c.lower_bound for c in self.checks],
                "where": [location_text(c.location) for c in self.checks],
            },
            index="check",
        )

    def to_dict(self) -> dict:
        return {"passed": self.passed, "summary": self.summary, "checks": [c.to_dict() for c in self.checks]}

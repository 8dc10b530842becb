"""The requirements verdict as text: where a finding occurs and one row per check, in
engineering units (rpm, mm, °C, %), for every reader of a verdict (the HTML report, the terminal,
a notebook's ``Verdict._repr_html_``).

Duck-typed on :class:`flexshaft.verdict.result.Verdict` (checks with SI values, a ``kind``
and a location mapping); converts to engineering units here, at the edge.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from flexshaft.units import format_quantity, rad_s_to_rpm

__all__ = ["VERDICT_COLUMNS", "limit_text", "location_text", "verdict_headline", "verdict_rows"]

#: Columns of the verdict table.
VERDICT_COLUMNS = ("requirement", "value", "limit", "margin", "status", "where", "note")
_STATUS = {"pass": "PASS", "fail": "FAIL", "not evaluated": "not evaluated"}


def location_text(location: Mapping[str, Any], compact: bool = False) -> str:
    """Where a finding occurs, e.g. ``amb_1, 4084 rpm`` or ``mode 6 (forward), 55.32 Hz``.

    Keys (all optional): point (the envelope point, shown first in brackets), actuator, mode,
    station [m], ply, case, speed [rad/s], frequency [rad/s], amplification_factor with
    af_method, position, detail.

    ``compact`` leaves out the free-text detail, the AF method and the position (terminal).
    """
    parts = []
    if "point" in location:
        parts.append(f"[{location['point']}]")
    if "actuator" in location:
        parts.append(str(location["actuator"]))
    if "mode" in location:
        parts.append(f"mode {location['mode']}")
    if "station" in location:
        parts.append(f"x = {location['station']:.2f} m")
    if "ply" in location:
        parts.append(f"ply {location['ply']}")
    if "case" in location:
        parts.append(str(location["case"]))
    if "speed" in location:
        parts.append(f"{rad_s_to_rpm(location['speed']):.0f} rpm")
    if "frequency" in location:
        parts.append(f"{location['frequency'] / (2 * math.pi):.2f} Hz")
    if "amplification_factor" in location:
        method = f", {location['af_method']}" if "af_method" in location and not compact else ""
        parts.append(f"AF {location['amplification_factor']:.3g}{method}")
    if "position" in location and not compact:
        parts.append(f"{location['position']} the operating speed")
    if "detail" in location and not compact:
        parts.append(str(location["detail"]))
    return ", ".join(parts)


def limit_text(check) -> str:
    """The limit of a check with its sense, e.g. ``≥ 1.5`` or ``≤ 0.25 mm`` (— when it has none)."""
    if check.limit is None:
        return "—"
    return ("≥ " if check.sense == "at least" else "≤ ") + format_quantity(check.kind, check.limit)


def verdict_rows(verdict, compact: bool = False) -> list[list[str]]:
    """One row of text per check, in :data:`VERDICT_COLUMNS` order (``compact``: see
    :func:`location_text`)."""
    rows = []
    for c in verdict.checks:
        bound = "> " if c.lower_bound else ""
        rows.append(
            [
                c.title,
                bound + format_quantity(c.kind, c.value),
                limit_text(c),
                bound + format_quantity(c.kind, c.margin, margin=True),
                _STATUS[c.status],
                location_text(c.location, compact),
                c.note,
            ]
        )
    return rows


def verdict_headline(verdict) -> str:
    """The verdict in one line: ``FAIL — 2 of 9 checks fail: whirl onset speed (3125 rpm;
    required ≥ 5520 rpm), …`` or ``PASS — 9 checks pass``, and the checks not evaluated."""

    def finding(check) -> str:
        bound = "> " if check.lower_bound else ""
        return f"{check.title} ({bound}{format_quantity(check.kind, check.value)}; required {limit_text(check)})"

    n = len(verdict.checks)
    failed, skipped = verdict.failed, verdict.not_evaluated
    if failed:
        text = f"FAIL — {len(failed)} of {n} checks fail: " + ", ".join(finding(c) for c in failed)
    elif skipped:
        text = f"PASS — {n - len(skipped)} of {n} checks pass"
    else:
        text = f"PASS — {n} checks pass"
    if skipped:
        text += f"; {len(skipped)} not evaluated: " + ", ".join(c.title for c in skipped)
    return text

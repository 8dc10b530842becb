"""The requirements verdict as text: table rows for the HTML report and the terminal.

Duck-typed on :class:`flexshaft.verdict.result.Verdict` (checks with SI values, a ``kind``
and a location mapping); converts to engineering units (rpm, mm, °C, %) here, at the edge.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from flexshaft.report.html import Section, Table
from flexshaft.units import format_quantity, rad_s_to_rpm  # format_quantity re-exported

__all__ = ["VERDICT_COLUMNS", "format_quantity", "location_text", "verdict_rows", "verdict_section"]

#: Columns of the verdict table.
VERDICT_COLUMNS = ("requirement", "value", "limit", "margin", "status", "where", "note")
_STATUS = {"pass": "PASS", "fail": "FAIL", "not evaluated": "not evaluated"}


def location_text(location: Mapping[str, Any], compact: bool = False) -> str:
    """Where a finding occurs, e.g. ``amb_1, 4084 rpm`` or ``mode 6 (forward), 55.32 Hz``.

    Keys (all optional): point (the envelope point), actuator, mode, station [m], ply, case, speed [rad/s], frequency
    [rad/s], amplification_factor with af_method, position, detail.

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


def _limit_text(check) -> str:
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
                _limit_text(c),
                bound + format_quantity(c.kind, c.margin, margin=True),
                _STATUS[c.status],
                location_text(c.location, compact),
                c.note,
            ]
        )
    return rows


def verdict_section(verdict, operating_rpm: float) -> Section:
    """The report's first section: the overall verdict and the table of requirements."""
    failed = [f"{c.title} ({location_text(c.location)})" for c in verdict.failed]
    lead = f"Verdict: {'PASS' if verdict.passed else 'FAIL'}. " + verdict.summary.split(": ", 1)[1] + "."
    paragraphs = [lead]
    if failed:
        paragraphs.append("Failed, worst case of each: " + "; ".join(failed) + ".")
    paragraphs.append(
        f"Each requirement of the design's [requirements] table (and the gap, force capacity and allowable "
        f"temperature of its components) checked at the operating speed {operating_rpm:.0f} rpm; the margin is "
        "value − limit for a minimum and limit − value for a maximum, negative when failed. A requirement "
        "that could not be evaluated is marked so and does not pass. Separation margins follow API 684: the "
        "amplification factor AF = N_c/(N_2 − N_1) from the half-power points of the unbalance response at the "
        "shaft station where each peak is largest; AF < 2.5 needs no margin, otherwise 17(1 − 1/(AF − 1.5)) % "
        "(at most 16 %) below and 10 + 17(1 − 1/(AF − 1.5)) % (at most 26 %) above the operating speed."
    )
    return Section(
        "Verdict against the requirements",
        paragraphs=paragraphs,
        tables=[
            Table("Requirements verdict (worst case of each requirement)", list(VERDICT_COLUMNS), verdict_rows(verdict))
        ],
    )

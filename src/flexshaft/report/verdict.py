"""The requirements verdict in the HTML report: its first section.

The rows and locations as text (:mod:`flexshaft.verdict.text`, re-exported here) are shared with
the terminal and the notebook display of a verdict.
"""

from __future__ import annotations

from flexshaft.analyses.separation import api684_separation
from flexshaft.report.html import Section, Table
from flexshaft.units import format_quantity, rad_s_to_rpm  # format_quantity re-exported
from flexshaft.verdict.envelope_text import (
    ENVELOPE_COLUMNS,
    envelope_line,
    envelope_rows,
    governing_text,
)  # re-exported
from flexshaft.verdict.text import VERDICT_COLUMNS, location_text, verdict_rows  # re-exported

__all__ = [
    "ENVELOPE_COLUMNS",
    "VERDICT_COLUMNS",
    "envelope_line",
    "every_root_onset",
    "envelope_rows",
    "format_quantity",
    "governing_text",
    "location_text",
    "separation_readings",
    "verdict_rows",
    "verdict_section",
]


def verdict_section(verdict, operating_rpm: float, assessment=None) -> Section:
    """The report's first section: the overall verdict and the table of requirements; with the
    ``assessment`` of a design with an ``[envelope]``, its points and which one governs."""
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
    tables = [
        Table("Requirements verdict (worst case of each requirement)", list(VERDICT_COLUMNS), verdict_rows(verdict))
    ]
    points = envelope_rows(assessment) if assessment is not None else []
    if points:
        paragraphs.append(
            f"Every check is evaluated at each of the {len(points)} points of the design's [envelope] "
            "(each point's material temperature sets the laminae's properties and the thermal residual stress; "
            "its speed, power and load scale the loads); the table above gives each check's worst point in "
            "brackets. The governing point has the tightest check (a failing one first, then the smallest "
            f"normalised margin, as in the margins figure): {governing_text(assessment)}. The analyses and "
            "figures below are at it unless their caption names another point."
        )
        tables.append(Table("Envelope points (each point's own verdict)", list(ENVELOPE_COLUMNS), points))
    return Section("Verdict against the requirements", paragraphs=paragraphs, tables=tables)


def separation_readings(evidence, criticals) -> list[tuple[float, float, float, float]]:
    """What the separation check reads for each of ``criticals`` (the verdict's lateral critical
    speeds), for the Campbell diagrams: the speed its margin is measured from and the nearest
    speed the critical may have [rpm] (that speed moved by the required margin toward the
    critical's side), its margin and API 684's required margin [-]
    (:func:`~flexshaft.analyses.separation.api684_separation`, as
    :func:`flexshaft.verdict.checks.separation` calls it)."""
    out = []
    for c in criticals:
        sep = api684_separation(c.speed, c.amplification_factor, evidence.operating_speed, evidence.operating_range)
        reference = evidence.operating_speed if sep.reference_speed is None else sep.reference_speed
        bound = reference * (1.0 - sep.required_margin if sep.position == "below" else 1.0 + sep.required_margin)
        out.append((rad_s_to_rpm(reference), rad_s_to_rpm(bound), sep.margin, sep.required_margin))
    return out


def every_root_onset(verdict, tracked: float | None) -> str:
    """ "; every root: N rpm (kind)" when the whirl-onset check reads an unstable root of the
    closed loop below the tracked modes' onset ``tracked`` [rad/s] (docs/requirements.md: the
    lowest of rest, the operating speed and (1 + margin) × it where any root is unstable), else
    empty: the onset table's "stable to 7200" stood beside a verdict failing at rest (audit a2)."""
    try:
        c = verdict.check("whirl_onset")
    except KeyError:
        return ""
    kind = c.location.get("mode")
    if c.value is None or kind not in ("untracked root", "divergence (real root)"):
        return ""
    if tracked is not None and c.value >= tracked:
        return ""
    return f"; every root: {rad_s_to_rpm(c.value):.0f} ({kind})"

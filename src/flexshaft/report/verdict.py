"""The requirements verdict in the HTML report: its first section.

The rows and locations as text (:mod:`flexshaft.verdict.text`, re-exported here) are shared with
the terminal and the notebook display of a verdict.
"""

from __future__ import annotations

from flexshaft.report.html import Section, Table
from flexshaft.units import format_quantity  # re-exported
from flexshaft.verdict.text import VERDICT_COLUMNS, location_text, verdict_rows  # re-exported

__all__ = ["VERDICT_COLUMNS", "format_quantity", "location_text", "verdict_rows", "verdict_section"]


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

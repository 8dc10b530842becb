"""The envelope's points as text: one row per point (its conditions, its own verdict, its
tightest check) and the governing point in one line, for the HTML report and the terminal
(:mod:`flexshaft.verdict.text` has the verdict's rows)."""

from __future__ import annotations

from flexshaft.units import format_quantity
from flexshaft.verdict.envelope import tightest_check
from flexshaft.verdict.text import limit_text

__all__ = ["ENVELOPE_COLUMNS", "envelope_line", "envelope_rows", "governing_text"]


#: Columns of the envelope table (one row per operating point).
ENVELOPE_COLUMNS = (
    "point",
    "ambient [°C]",
    "shaft material [°C]",
    "speed [rpm]",
    "power [kW]",
    "load scale",
    "verdict",
    "tightest check",
)


def _tightest_text(check) -> str:
    if check is None:
        return "—"
    bound = "> " if check.lower_bound else ""
    value = "" if check.value is None else f" {bound}{format_quantity(check.kind, check.value)}"
    return f"{check.title}{value}, {limit_text(check)}"


def envelope_rows(assessment) -> list[list[str]]:
    """One row of text per envelope point of an :class:`~flexshaft.verdict.assess.Assessment`,
    in :data:`ENVELOPE_COLUMNS` order: its conditions, its own verdict and its tightest check
    (failing first, then the smallest normalised margin); empty for a design judged at
    its own operating point."""
    if assessment.design.envelope is None:
        return []
    rows = []
    for p in assessment.points:
        operating, conditions = p.analyses.design.operating, p.analyses.conditions
        failed = len(p.verdict.failed)
        rows.append(
            [
                p.name + (" (governs)" if p.name == assessment.governing_point else ""),
                f"{conditions.ambient_temperature_c:.1f}",
                f"{conditions.material_temperature_c:.1f}",
                f"{operating.rpm:.0f}",
                f"{operating.power / 1e3:.1f}",
                f"{conditions.point.load_scale:.3g}",
                f"FAIL {failed}/{len(p.verdict.checks)}" if failed else "PASS",
                _tightest_text(tightest_check(p.verdict)),
            ]
        )
    return rows


def envelope_line(assessment) -> str:
    """The envelope in one line: its points and the governing one with its tightest check, e.g.
    ``envelope: 4 points (cold_day, …); governed by hot_soak_start (loop phase margin 36.5°,
    ≥ 30°): the analyses shown are at it, …``; empty for a design judged at its own operating
    point."""
    if assessment.design.envelope is None:
        return ""
    names = ", ".join(p.name for p in assessment.points)
    return (
        f"envelope: {len(assessment.points)} points ({names}); governed by {governing_text(assessment)}: "
        "the analyses shown are at it, the verdict is each check's worst point"
    )


def governing_text(assessment) -> str:
    """The governing point and its tightest check, e.g. ``hot_soak_start (loop phase margin
    36.5°, ≥ 30°)``."""
    check = tightest_check(assessment.point(assessment.governing_point).verdict)
    return f"{assessment.governing_point} ({_tightest_text(check)})"

"""The verdict over an operating envelope: every check at every point, the worst one and where.

Each point of a design's ``[envelope]`` is judged on its own (:class:`PointAssessment`: the point's
analyses, evidence and verdict). :func:`envelope_verdict` combines them check by check: a check
fails when it fails at some point, passes when it passes at every point where it could be
evaluated, and is not evaluated when it could be evaluated nowhere. Its value, limit, margin and
location are the worst point's (a failing point first, then the smallest normalised margin,
:func:`~flexshaft.verdict.result.normalised_margin`), its location says the point
(``"point"``), and its findings are every point's, each with its point. :func:`governing_point`
names the point of the tightest check (the smallest normalised margin,
:func:`~flexshaft.verdict.result.normalised_margin`), whose analyses the report's figures show.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from flexshaft.verdict.evidence import Evidence
from flexshaft.verdict.operating_point import PointAnalyses
from flexshaft.verdict.result import Check, Finding, Verdict, normalised_margin

__all__ = ["PointAssessment", "envelope_verdict", "governing_point", "tightest_check"]


@dataclass(frozen=True, kw_only=True)
class PointAssessment:
    """One operating point judged: its ``name``, ``analyses``, ``evidence`` and ``verdict``."""

    name: str
    analyses: PointAnalyses
    evidence: Evidence
    verdict: Verdict


def _severity(check: Check) -> tuple[int, float]:
    """Sort key of the tightest check of a verdict, and of one check's worst point: failing
    first, then the smallest normalised margin."""
    return (0 if check.status == "fail" else 1, normalised_margin(check))


def _at_point(finding: Finding, name: str) -> Finding:
    return replace(finding, location={"point": name, **dict(finding.location)})


def envelope_verdict(points: Sequence[PointAssessment]) -> Verdict:
    """Every check's worst point (module docstring), in the order of the first point's checks
    (a check listed at some point only follows them)."""
    keys: list[str] = []
    for p in points:
        keys += [c.key for c in p.verdict.checks if c.key not in keys]
    combined = []
    for key in keys:
        checks = [(p.name, c) for p in points for c in p.verdict.checks if c.key == key]
        evaluated = [(name, c) for name, c in checks if c.status != "not evaluated"]
        if not evaluated:
            name, c = checks[0]
            notes = sorted({c.note for _, c in checks if c.note})
            combined.append(replace(c, note="; ".join(notes) + f" (at every point: {', '.join(n for n, _ in checks)})"))
            continue
        name, worst = min(evaluated, key=lambda item: _severity(item[1]))
        findings = tuple(_at_point(f, n) for n, c in evaluated for f in c.findings)
        skipped = [n for n, c in checks if c.status == "not evaluated"]
        if worst.value is None and worst.status == "pass":  # passed without a number everywhere: no worst point
            note = f"at each of {len(evaluated)} points" + (f": {worst.note}" if worst.note else "")
        else:
            note = f"worst of {len(evaluated)} points: {name}" + (f"; {worst.note}" if worst.note else "")
        if skipped:
            note += f"; not evaluated at {', '.join(skipped)}"
        # (a check passed without a number, e.g. no phase crossover anywhere, has no worst point)
        location = {"point": name, **dict(worst.location)} if worst.value is not None else dict(worst.location)
        combined.append(replace(worst, location=location, findings=findings, note=note))
    return Verdict(tuple(combined))


def tightest_check(verdict: Verdict) -> Check | None:
    """The verdict's tightest evaluated check: failing first, then the smallest margin relative to
    its scale (:func:`~flexshaft.verdict.result.normalised_margin`); None when no check was
    evaluated."""
    evaluated = [c for c in verdict.checks if c.status != "not evaluated"]
    return min(evaluated, key=_severity, default=None)


def governing_point(points: Sequence[PointAssessment]) -> str:
    """The point of the tightest evaluated check (:func:`tightest_check`, the first such point on
    a tie); the first point when no check was evaluated."""
    best = None
    for p in points:
        check = tightest_check(p.verdict)
        if check is not None and (best is None or _severity(check) < best[0]):
            best = (_severity(check), p.name)
    return points[0].name if best is None else best[1]

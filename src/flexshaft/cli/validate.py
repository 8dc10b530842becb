"""``flexshaft validate``: every validation case against its published result.

Prints one table (each compared value: published, flexshaft, relative difference, the case's
tolerance and verdict) and the sources cited, or with ``--json`` the same as JSON. Exits 3, as
``flexshaft run --strict`` on a failed requirement, when a case leaves its tolerance: the check
ran and its answer is "no", which scripts and CI must tell apart from a user error (2) and an
internal fault (4). The cases, their sources and the tolerance of each are in
docs/validation.md (:mod:`flexshaft.validation`).
"""

from __future__ import annotations

from typing import Annotated

import typer

from flexshaft.cli.common import EXIT_REQUIREMENT_FAILED, guarded, print_json
from flexshaft.cli.options import JsonOption

__all__ = ["validate"]


@guarded
def validate(
    case: Annotated[
        list[str] | None,
        typer.Option(
            "--case", help="Run only this case (repeat for several); default: every case.", show_default=False
        ),
    ] = None,
    list_cases: Annotated[bool, typer.Option("--list", help="List the cases and their sources, run nothing.")] = False,
    as_json: JsonOption = False,
) -> None:
    """Compare flexshaft with published results (textbook examples, worked examples, closed
    forms); exit 3 when a case leaves its tolerance."""
    from flexshaft.cli.common import fail
    from flexshaft.validation import CASES, SOURCES, run_validation

    known = {c.id for c in CASES}
    unknown = [c for c in case or () if c not in known]
    if unknown:
        fail(f"--case: no validation case {', '.join(map(repr, unknown))}; cases: {', '.join(c.id for c in CASES)}")
    if list_cases:
        _list(CASES, SOURCES, as_json)
        return
    report = run_validation(case or None)
    if as_json:
        from flexshaft.validation import report_json

        print_json(report_json(report))
    else:
        _print(report)
    if not report.passed:
        raise typer.Exit(EXIT_REQUIREMENT_FAILED)


def _list(cases, sources, as_json: bool) -> None:
    if as_json:
        print_json(
            {
                "cases": [
                    {"id": c.id, "title": c.title, "source": c.source, "where": c.where, "design": c.design}
                    for c in cases
                ],
                "sources": {k: s.citation for k, s in sources.items()},
            }
        )
        return
    from flexshaft.cli.tables import stdout_console, table

    console = stdout_console()
    console.print(
        table(
            "validation cases",
            ["case", "title", "source", "where"],
            [[c.id, c.title, c.source, c.where] for c in cases],
        )
    )


def _print(report) -> None:
    from rich.text import Text

    from flexshaft.cli.tables import print_line, sig, stdout_console, table
    from flexshaft.validation import SOURCES

    rows = []
    for r in report.results:
        c = r.case
        verdict = Text("PASS", style="green") if r.passed else Text("FAIL", style="bold red")
        for i, (label, p, v, d) in enumerate(zip(c.labels, c.published, r.computed, r.differences)):
            first = i == 0
            rows.append(
                [
                    c.id if first else "",
                    f"{label} [{c.unit}]",
                    sig(p, 6),
                    sig(v, 6),
                    sig(100.0 * d, 2),
                    sig(100.0 * c.tolerance, 2) if first else "",
                    verdict if first else "",
                ]
            )
    console = stdout_console()
    console.print(
        table(
            "validation against published results",
            ["case", "value", "published", "flexshaft", "difference [%]", "tolerance [%]", "result"],
            rows,
            numeric={2, 3, 4, 5},
            caption="difference = flexshaft / published − 1; the sources and tolerances are in docs/validation.md",
        )
    )
    for key in report.sources:
        print_line(console, f"{key}: {SOURCES[key].citation}")
    n_failed = len(report.failed)
    summary = (
        f"{len(report.results)} cases from {len(report.sources)} sources: "
        + ("all within their tolerance" if not n_failed else f"{n_failed} outside their tolerance")
        + f" ({report.cpu_seconds:.1f} s CPU)"
    )
    print_line(console, summary, style="bold" if not n_failed else "bold red")

"""Run the validation cases and format their comparison (terminal, JSON, docs/validation.md).

:func:`run_validation` computes every case's quantity from its design file and compares it
with the published values; a case passes when every value lies within the case's relative
tolerance. :func:`markdown` writes the table of docs/validation.md from the same results
(flexshaft's values to five significant figures, differences to 0.001 %, so that the page does
not depend on machine round-off; ``tests/test_validation.py`` keeps the page current).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from importlib import resources

import numpy as np

from flexshaft.design import Design, loads_design
from flexshaft.validation.cases import CASES, SOURCES, Case, case_by_id
from flexshaft.validation.quantities import quantity

__all__ = [
    "DESIGN_PACKAGE",
    "UNITS",
    "CaseResult",
    "ValidationReport",
    "case_design",
    "design_names",
    "design_text",
    "markdown",
    "report_json",
    "run_case",
    "run_validation",
    "update_document",
]

#: Package holding the cases' design files.
DESIGN_PACKAGE = "flexshaft.validation.designs"

#: Display unit of a case -> factor from the quantity's SI value (rad/s, kg m).
UNITS: dict[str, float] = {
    "rad/s": 1.0,
    "Hz": 1.0 / (2.0 * math.pi),
    "rpm": 30.0 / math.pi,
    "g mm": 1.0e6,
    "N/m": 1.0,
    "-": 1.0,
}

#: Unit suffix of a JSON key, per display unit (the CLI's convention: ``frequency_Hz``).
_JSON_SUFFIX = {"rad/s": "rad_per_s", "Hz": "Hz", "rpm": "rpm", "g mm": "g_mm", "N/m": "N_per_m", "-": ""}


def design_names() -> tuple[str, ...]:
    """The design files shipped for the cases, sorted."""
    folder = resources.files(DESIGN_PACKAGE)
    return tuple(sorted(p.name for p in folder.iterdir() if p.name.endswith(".toml")))


def design_text(name: str) -> str:
    """The TOML text of a case's design file ``name`` (e.g. ``"friswell_5_9_1.toml"``)."""
    if name not in design_names():
        raise ValueError(f"no validation design {name!r}; designs: {', '.join(design_names())}")
    return resources.files(DESIGN_PACKAGE).joinpath(name).read_text(encoding="utf-8")


def case_design(case: Case) -> Design | None:
    """The validated design of ``case`` (None for a case on plain numbers)."""
    if case.design is None:
        return None
    return loads_design(design_text(case.design), source=f"validation/{case.design}")


@dataclass(frozen=True)
class CaseResult:
    """A case's comparison: flexshaft's values and their relative differences.

    Attributes
    ----------
    case : Case
        The case.
    computed : tuple of float
        flexshaft's values, in ``case.unit``.
    differences : tuple of float
        flexshaft / published − 1 per value [-].
    cpu_seconds : float
        Process CPU time of the case [s].
    """

    case: Case
    computed: tuple[float, ...]
    differences: tuple[float, ...]
    cpu_seconds: float

    @property
    def worst(self) -> float:
        """The largest |relative difference| [-]."""
        return max(abs(d) for d in self.differences)

    @property
    def passed(self) -> bool:
        """Every value within the case's tolerance."""
        return self.worst <= self.case.tolerance


@dataclass(frozen=True)
class ValidationReport:
    """Every case's result and the CPU time of the whole run [s]."""

    results: tuple[CaseResult, ...]
    cpu_seconds: float

    @property
    def failed(self) -> tuple[CaseResult, ...]:
        """The cases outside their tolerance."""
        return tuple(r for r in self.results if not r.passed)

    @property
    def passed(self) -> bool:
        """Every case within its tolerance."""
        return not self.failed

    @property
    def sources(self) -> tuple[str, ...]:
        """The keys of the sources the cases cite, in order of first use."""
        return tuple(dict.fromkeys(r.case.source for r in self.results))


def run_case(case: Case) -> CaseResult:
    """Compute ``case``'s quantity with flexshaft and compare it with the published values."""
    start = time.process_time()
    values = np.asarray(quantity(case.quantity)(case_design(case), **case.arguments), dtype=float) * UNITS[case.unit]
    if values.shape != (len(case.published),):
        raise ValueError(f"case {case.id}: {values.size} values computed, {len(case.published)} published")
    if not np.all(np.isfinite(values)):
        raise ValueError(f"case {case.id}: flexshaft's values are not finite ({values})")
    published = np.asarray(case.published, dtype=float)
    return CaseResult(
        case,
        tuple(float(v) for v in values),
        tuple(float(d) for d in values / published - 1.0),
        time.process_time() - start,
    )


def run_validation(case_ids: tuple[str, ...] | list[str] | None = None) -> ValidationReport:
    """Run the cases called ``case_ids`` (default: every case of
    :data:`~flexshaft.validation.cases.CASES`, in order)."""
    cases = CASES if case_ids is None else tuple(case_by_id(i) for i in case_ids)
    start = time.process_time()
    results = tuple(run_case(c) for c in cases)
    return ValidationReport(results, time.process_time() - start)


# ------------------------------------------------------------------------------------------------
# Formatting


def significant(value: float, digits: int) -> str:
    """``value`` to ``digits`` significant figures, fixed-point (``716.79``, ``11338``, ``0.01235``;
    at five, 123456.7 is ``123460`` and 9.99997 is ``10.000``)."""
    if value == 0.0 or not math.isfinite(value):
        return str(value)
    exponent = math.floor(math.log10(abs(value)))
    if abs(round(value, digits - 1 - exponent)) >= 10.0 ** (exponent + 1):
        exponent += 1  # the rounding carried into a new leading digit
    decimals = max(digits - 1 - exponent, 0)
    return f"{round(value, digits - 1 - exponent):.{decimals}f}"


def published_text(value: float) -> str:
    """A published value as printed (up to six significant figures, trailing zeros dropped)."""
    return f"{value:.6g}"


def percent(difference: float) -> str:
    """A relative difference in percent to 0.001 % (``+0.012 %``, ``< 0.001 %``)."""
    if abs(difference) < 5e-6:
        return "< 0.001 %"
    return f"{100.0 * difference:+.3f} %"


def _plain(value) -> str:
    return f"{value:g}" if isinstance(value, float) else repr(value) if isinstance(value, str) else str(value)


def report_json(report: ValidationReport) -> dict:
    """The report as JSON-ready data: every case with its source, values and verdict."""
    cases = []
    for r in report.results:
        c = r.case
        suffix = _JSON_SUFFIX[c.unit]
        published_key, flexshaft_key = (
            (f"published_{suffix}", f"flexshaft_{suffix}") if suffix else ("published", "flexshaft")
        )
        cases.append(
            {
                "id": c.id,
                "title": c.title,
                "part": c.part,
                "source": c.source,
                "citation": SOURCES[c.source].citation,
                "where": c.where,
                "via": c.via,
                "reference_kind": c.reference_kind,
                "design": c.design,
                "tolerance": c.tolerance,
                "tolerance_basis": c.tolerance_basis,
                "passed": r.passed,
                "worst_relative_difference": r.worst,
                "cpu_s": r.cpu_seconds,
                "values": [
                    {"label": label, published_key: p, flexshaft_key: v, "relative_difference": d}
                    for label, p, v, d in zip(c.labels, c.published, r.computed, r.differences)
                ],
            }
        )
    return {
        "passed": report.passed,
        "n_cases": len(report.results),
        "n_failed": len(report.failed),
        "n_sources": len(report.sources),
        "cpu_s": report.cpu_seconds,
        "cases": cases,
    }


def markdown(report: ValidationReport) -> str:
    """The results table and the case notes of docs/validation.md (Markdown), generated."""
    lines = [
        "| case | value | published | flexshaft | difference | tolerance | result |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in report.results:
        c = r.case
        for i, (label, p, v, d) in enumerate(zip(c.labels, c.published, r.computed, r.differences)):
            first = i == 0
            lines.append(
                "| "
                + " | ".join(
                    [
                        f"[`{c.id}`](#{c.id.replace('.', '')})" if first else "",
                        f"{label} [{c.unit}]".replace("|", "\\|"),  # |s| in a table cell
                        published_text(p),
                        significant(v, 5),
                        percent(d),
                        f"{100.0 * c.tolerance:g} %" if first else "",
                        ("pass" if r.passed else "**FAIL**") if first else "",
                    ]
                )
                + " |"
            )
    lines += ["", "### Cases", ""]
    for r in report.results:
        c = r.case
        lines += [
            f'<a id="{c.id.replace(".", "")}"></a>',
            "",
            f"**`{c.id}`: {c.title}.** {c.part[0].upper()}{c.part[1:]}.",
            "",
            f"* Source: {SOURCES[c.source].citation}",
            f"* Where: {c.where}." + (f" Read {c.via}." if c.via else "") + f" Kind: {c.reference_kind}.",
            (
                f"* Inputs: [`validation/designs/{c.design}`](../src/flexshaft/validation/designs/{c.design})"
                if c.design
                else "* Inputs (no design file): " + ", ".join(f"`{k} = {_plain(v)}`" for k, v in c.arguments.items())
            )
            + f"; flexshaft's quantity `{c.quantity}`.",
            f"* Tolerance {100.0 * c.tolerance:g} %: {c.tolerance_basis}.",
        ]
        if c.note:
            lines.append(f"* Note: {c.note}")
        lines.append("")
    return "\n".join(lines).rstrip() + "\n"


#: Markers of the generated table in docs/validation.md.
TABLE_START, TABLE_END = "<!-- validation-table:start -->", "<!-- validation-table:end -->"


def update_document(text: str, report: ValidationReport) -> str:
    """``text`` (docs/validation.md) with the block between its markers replaced by
    :func:`markdown` of ``report`` (ValueError when the markers are missing)."""
    if TABLE_START not in text or TABLE_END not in text:
        raise ValueError(f"the page has no {TABLE_START} ... {TABLE_END} block")
    head, rest = text.split(TABLE_START, 1)
    _, tail = rest.split(TABLE_END, 1)
    return f"{head}{TABLE_START}\n\n{markdown(report)}\n{TABLE_END}{tail}"

"""Validation against published results: the cases, their design files and the runner.

>>> from flexshaft.validation import run_validation
>>> report = run_validation(["iso21940-balance-tolerance"])
>>> report.passed, round(report.results[0].computed[0], 2)  # U_per [g mm]; published: 12
(True, 12.03)

The case table is data (:mod:`flexshaft.validation.cases`), each case's inputs a design file
shipped with the package (``flexshaft/validation/designs/``), each compared quantity a function
of flexshaft's public API (:mod:`flexshaft.validation.quantities`). ``flexshaft validate``
runs them all; docs/validation.md holds the table with the sources.
"""

from flexshaft.validation.cases import CASES, SOURCES, Case, Source, case_by_id
from flexshaft.validation.runner import (
    CaseResult,
    ValidationReport,
    case_design,
    design_names,
    design_text,
    markdown,
    report_json,
    run_case,
    run_validation,
)

__all__ = [
    "CASES",
    "SOURCES",
    "Case",
    "CaseResult",
    "Source",
    "ValidationReport",
    "case_by_id",
    "case_design",
    "design_names",
    "design_text",
    "markdown",
    "report_json",
    "run_case",
    "run_validation",
]

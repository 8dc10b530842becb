"""What the explorer computes for a design, as JSON for the page: run in its worker processes.

:func:`design_update` is one update of the page: :func:`flexshaft.verdict.assess.assess` at
:data:`EXPLORE` (the :data:`~flexshaft.resolution.SCREENING` grids, plus a coarse Campbell
diagram to draw; the Campbell diagram only names the critical speeds' modes, so the verdict is
the screening verdict, ``tests/test_explore.py``), the verdict table, the interactive figures
(:mod:`flexshaft.report.interactive`), the masses and the stability numbers. :func:`sweep_point`
is one point of a one-variable sweep: every check's normalised margin
(:func:`flexshaft.optimize.evaluate.assessment_metrics`, the optimizer's constraints) at
:data:`~flexshaft.resolution.SCREENING`.

The functions take and return plain picklable data, so that they run in a worker process. A
design with several envelope points is updated by :func:`update_on`: its points in the
explorer's workers side by side (:func:`point_update`, one point each), then the verdict over
them and the figures at the governing point (:func:`envelope_update`); the payload is
:func:`design_update`'s (``tests/test_explore.py``), its wall time about the points' count
divided by the workers'.
"""

from __future__ import annotations

import asyncio
import math
import time
from dataclasses import replace
from typing import Any, Protocol

from flexshaft.comparison import driveline_inventory
from flexshaft.design import Design, DesignError, with_overrides
from flexshaft.optimize.evaluate import assessment_metrics
from flexshaft.report.interactive import assessment_figures
from flexshaft.report.verdict import VERDICT_COLUMNS, verdict_rows
from flexshaft.resolution import SCREENING
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict.assess import Assessment, PointAssessment, assess, assess_point, combine_points
from flexshaft.verdict.checks import CHECK_KEYS
from flexshaft.verdict.result import normalised_margin

__all__ = [
    "EXPLORE",
    "SWEEP",
    "design_update",
    "envelope_update",
    "point_update",
    "sweep_point",
    "update_on",
    "update_payload",
]

#: Campbell speeds drawn by the explorer: 25, every 5 % of the scan to 130 % of the operating
#: speed (about 0.04 s of CPU on the tuned design, a seventh of the screening assessment).
_CAMPBELL_SPEEDS = 25
#: The explorer's resolution: the screening grids with a Campbell diagram to draw.
EXPLORE = replace(SCREENING, name="explore", campbell_speeds=_CAMPBELL_SPEEDS)
#: The resolution of a sweep's points: the screening itself (no figure is drawn).
SWEEP = SCREENING


def _number(x: float | None) -> float | None:
    return None if x is None or not math.isfinite(x) else float(x)


def update_payload(a: Assessment) -> dict[str, Any]:
    """The page's results of an assessment: verdict table, figures, masses, stability."""
    verdict = a.verdict
    rows = verdict_rows(verdict)
    checks = []
    for c, row in zip(verdict.checks, rows):
        checks.append(
            {
                "key": c.key,
                "status": c.status,
                "normalised_margin": _number(normalised_margin(c)),
                "cells": dict(zip(VERDICT_COLUMNS, row)),
            }
        )
    inventory = driveline_inventory(a.model)
    damping = verdict.check("whirl_damping") if "whirl_damping" in {c.key for c in verdict.checks} else None
    stability = a.stability
    return {
        "design_name": a.design.name,
        "resolution": a.resolution.name,
        "passed": verdict.passed,
        "summary": verdict.summary,
        "columns": list(VERDICT_COLUMNS),
        "checks": checks,
        "numbers": {
            "shaft_mass_kg": float(a.model.shaft_mass),
            "driveline_mass_kg": inventory.total_mass,
            "mass_by_part_kg": {k: float(v) for k, v in inventory.mass.items() if v},
            "min_log_decrement": _number(damping.value) if damping is not None else None,
            "whirl_onset_rpm": None if stability.onset_speed is None else float(rad_s_to_rpm(stability.onset_speed)),
            "stable_to_rpm": float(rad_s_to_rpm(stability.speeds[-1])),
            "operating_speed_rpm": float(rad_s_to_rpm(a.operating_speed)),
        },
        "figures": assessment_figures(a),
    }


def design_update(design: Design) -> dict[str, Any]:
    """One update of the page: the assessment of ``design`` at :data:`EXPLORE` and its payload
    (:func:`update_payload`), with the CPU time it took [s] (``cpu_s``)."""
    start = time.process_time()
    a = assess(design, EXPLORE)
    payload = update_payload(a)
    payload["cpu_s"] = time.process_time() - start
    return payload


def point_update(design: Design, index: int) -> tuple[PointAssessment, float]:
    """Point ``index`` of the design's envelope judged at :data:`EXPLORE`
    (:func:`~flexshaft.verdict.assess.assess_point`), with the CPU time it took [s]."""
    start = time.process_time()
    judged = assess_point(design, index, EXPLORE)
    return judged, time.process_time() - start


def envelope_update(design: Design, judged: list[PointAssessment], cpu_s: float = 0.0) -> dict[str, Any]:
    """The payload of :func:`design_update` from the envelope's points judged by
    :func:`point_update` (in order; their CPU time ``cpu_s`` [s] is added to this step's)."""
    start = time.process_time()
    payload = update_payload(combine_points(design, judged, EXPLORE))
    payload["cpu_s"] = cpu_s + time.process_time() - start
    return payload


class _Workers(Protocol):  # flexshaft.explore.workers.Workers
    processes: int

    async def run(self, function: Any, *args: Any) -> Any: ...


async def update_on(workers: _Workers, design: Design) -> dict[str, Any]:
    """:func:`design_update` of ``design`` computed in ``workers``: an envelope's points side by
    side when there are several points and workers, else the whole update in one worker."""
    points = 0 if design.envelope is None else len(design.envelope.points)
    if points < 2 or workers.processes < 2:
        return await workers.run(design_update, design)
    results = await asyncio.gather(*(workers.run(point_update, design, k) for k in range(points)))
    return await workers.run(envelope_update, design, [j for j, _ in results], sum(c for _, c in results))


def sweep_point(base: Design, overrides: dict[str, Any]) -> dict[str, Any]:
    """One point of a sweep: the normalised margin of every check (NaN → None where not
    evaluated or not applicable) and the shaft mass, or the message when the design is invalid
    or refused there (the schema's, or what the assessment refuses: a size, a "worst"
    placement's bays), so that one refused point leaves the others' results."""
    try:
        design = with_overrides(base, overrides)
        a = assess(design, SWEEP)
    except DesignError as exc:
        return {"error": str(exc)}
    metrics = assessment_metrics(a)
    return {
        "titles": {c.key: c.title for c in a.verdict.checks},
        "margins": {key: _number(metrics[f"margin_{key}"]) for key in CHECK_KEYS},
        "status": {key: metrics[f"status_{key}"] for key in CHECK_KEYS},
        "shaft_mass_kg": metrics["shaft_mass"],
    }

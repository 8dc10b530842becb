"""A full-resolution run of the explored design: ``flexshaft run``'s own pipeline, in a worker.

:func:`full_run` calls :func:`flexshaft.cli.run.run_pipeline` (the assessment at
:data:`~flexshaft.resolution.REPORT` with the thesis studies, and the usual report folder) with a
:class:`RelayProgress` that sends each stage's label to the server through the queue the worker
processes inherit (:func:`set_relay`), so that the page shows the run's progress.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

from flexshaft.cli.common import LoadedDesign
from flexshaft.cli.options import Studies
from flexshaft.cli.progress import StageProgress
from flexshaft.cli.run import run_pipeline
from flexshaft.design import Design
from flexshaft.report.interactive_page import missing_extra

__all__ = ["RelayProgress", "full_run", "relay", "set_relay"]

_RELAY: Any = None  # the queue to the server; set in the server before the workers fork


def set_relay(queue: Any) -> None:
    """Set the queue (``put((job, label, seconds))``) that the workers will inherit."""
    global _RELAY
    _RELAY = queue


def relay() -> Any:
    """The queue set by :func:`set_relay` (None before)."""
    return _RELAY


class RelayProgress(StageProgress):
    """A :class:`~flexshaft.cli.progress.StageProgress` without a display that also sends each
    stage's label, with the seconds since the run started, to the server."""

    def __init__(self, job: str) -> None:
        super().__init__(enabled=False)
        self.job = job
        self._started = time.perf_counter()

    def step(self, label: str) -> None:
        super().step(label)
        if _RELAY is not None:
            _RELAY.put((self.job, label, time.perf_counter() - self._started))


def full_run(job: str, design: Design, text: str | None, source: str, folder: str, studies: str) -> dict[str, Any]:
    """Run ``design`` as ``flexshaft run`` does into the prepared ``folder`` (with
    ``interactive.html`` when plotly is installed); returns the verdict and the page's path."""
    progress = RelayProgress(job)
    assessment, page, _ = run_pipeline(
        LoadedDesign(design, text, source),
        Path(folder),
        progress,
        studies=Studies(studies),
        interactive=missing_extra() is None,
    )
    verdict = assessment.verdict
    return {
        "folder": str(folder),
        "page": Path(page).name,
        "passed": verdict.passed,
        "summary": verdict.summary,
        "status": {c.key: c.status for c in verdict.checks},
        "seconds": progress.elapsed,
    }

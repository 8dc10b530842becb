"""Progress of the long commands on stderr: one line per stage with its elapsed time.

:class:`StageProgress` takes the step labels of :func:`flexshaft.verdict.assess.assess`
(or of :func:`flexshaft.thesis.design_studies.design_studies`) through :meth:`StageProgress.step`.
Each label starts a stage: the previous one is ticked off with its time, the new one shows a
spinner and a running clock. Labels that start with a sub-step prefix (``"design studies: "``)
are shown indented under their stage, each with its own time.

The display is drawn only on a terminal (stderr a TTY), so piped or captured output (and JSON
on stdout) stays clean; the times are recorded either way (:attr:`StageProgress.timings`,
:attr:`StageProgress.sub_timings`; ``flexshaft run`` writes them to ``timings.json``).
"""

from __future__ import annotations

import time
from typing import Any

__all__ = ["StageProgress"]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).


class StageProgress:
    """Stage-by-stage progress (a context manager).

    Parameters
    ----------
    enabled : bool or None
        Draw the display; None: when the console is a terminal.
    transient : bool
        Remove the display when done (keep it as a log otherwise).
    console : rich.console.Console, optional
        Where to draw (default: stderr).
    sub_prefix : str
        Labels starting with it are sub-steps of the current stage.
    """

    def __init__(
        self,
        enabled: bool | None = None,
        transient: bool = False,
        console: Any = None,
        sub_prefix: str = "design studies: ",
    ) -> None:
        self.sub_prefix = sub_prefix
        self.timings: dict[str, float] = {}  # stage -> seconds
        self.sub_timings: dict[str, dict[str, float]] = {}  # stage -> {sub-step: seconds}
        self._start: float | None = None
        self._end: float | None = None
        self._console = console
        self._enabled = enabled
        self._transient = transient
        self._progress: Any = None
        self._stage: tuple[str, float, Any] | None = None  # (label, start, task)
        self._sub: tuple[str, float, Any] | None = None

    def __enter__(self) -> StageProgress:
        from rich.progress import Progress, ProgressColumn, SpinnerColumn, TextColumn
        from rich.text import Text

        class Seconds(ProgressColumn):
            """Elapsed time of the task (frozen when it finished) [s]."""

            def render(self, task: Any) -> Text:
                return Text(f"{task.elapsed or 0.0:6.1f} s", style="progress.elapsed")

        from flexshaft.cli.tables import stderr_console

        self._start = time.perf_counter()
        console = self._console if self._console is not None else stderr_console()
        enabled = console.is_terminal if self._enabled is None else self._enabled
        if enabled:
            self._progress = Progress(
                SpinnerColumn(finished_text="[green]✓"),
                TextColumn("{task.fields[label]}"),
                Seconds(),
                console=console,
                transient=self._transient,
            )
            self._progress.start()
        return self

    def __exit__(self, *exc: Any) -> None:
        self._close_sub()
        self._close_stage()
        self._end = time.perf_counter()
        if self._progress is not None:
            self._progress.stop()

    @property
    def elapsed(self) -> float:
        """Time since the display started (to its end once closed) [s]."""
        if self._start is None:
            return 0.0
        return (self._end if self._end is not None else time.perf_counter()) - self._start

    @property
    def stage(self) -> str | None:
        """The label of the stage running now."""
        return self._stage[0] if self._stage else None

    def step(self, label: str) -> None:
        """Start a stage, or a sub-step of the current stage (label with the sub-step prefix)."""
        from flexshaft.cli.common import plain

        if label.startswith(self.sub_prefix) and self._stage is not None:
            self._close_sub()
            sub = label[len(self.sub_prefix) :]
            self._sub = (sub, time.perf_counter(), self._add(f"  · {plain(sub)}"))
            return
        self._close_sub()
        self._close_stage()
        self._stage = (label, time.perf_counter(), self._add(plain(label)))

    def _add(self, text: str) -> Any:
        if self._progress is None:
            return None
        from rich.markup import escape

        return self._progress.add_task("", total=1, label=escape(text))

    def _finish(self, entry: tuple[str, float, Any], times: dict[str, float]) -> None:
        label, start, task = entry
        times[label] = time.perf_counter() - start
        if self._progress is not None and task is not None:
            self._progress.update(task, completed=1)
            self._progress.stop_task(task)

    def _close_sub(self) -> None:
        if self._sub is not None and self._stage is not None:
            self._finish(self._sub, self.sub_timings.setdefault(self._stage[0], {}))
        self._sub = None

    def _close_stage(self) -> None:
        if self._stage is not None:
            self._finish(self._stage, self.timings)
        self._stage = None

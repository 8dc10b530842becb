"""Independent pieces of a study run, in this process or on a pool of worker processes.

A :class:`Task` is a module-level function and picklable arguments. :func:`start_tasks`
submits a list of them to an executor, longest first (the pool then finishes them at about the
same time), or, without an executor, keeps them for :func:`TaskRun.results` to run in order
here. The results are the same either way; only where and when they are computed changes.
Each task is timed where it runs (wall seconds of the task itself).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from concurrent.futures import Executor, Future
from dataclasses import dataclass, field
from typing import Any

from flexshaft.parallel.threads import one_blas_thread

__all__ = ["Task", "TaskOutcome", "TaskRun", "start_tasks"]


@dataclass(frozen=True)
class Task:
    """``function(*args, **kwargs)``, named ``key``, shown as ``label``; ``cost`` is its
    expected relative run time (it only orders the submission)."""

    key: str
    label: str
    function: Callable[..., Any]
    args: tuple = ()
    kwargs: dict = field(default_factory=dict)
    cost: float = 1.0


@dataclass(frozen=True)
class TaskOutcome:
    """What a task returned, or the error it raised (``error`` is then not None)."""

    key: str
    value: Any
    seconds: float
    error: BaseException | None = None


def _execute(task: Task) -> TaskOutcome:
    start = time.perf_counter()
    with one_blas_thread():
        value = task.function(*task.args, **task.kwargs)
    return TaskOutcome(task.key, value, time.perf_counter() - start)


class TaskRun:
    """Tasks started by :func:`start_tasks`; :meth:`results` waits for them, in task order."""

    def __init__(
        self, tasks: Sequence[Task], futures: dict[str, Future] | None, errors: tuple[type[BaseException], ...]
    ) -> None:
        self.tasks = list(tasks)
        self._futures = futures
        self._errors = errors

    def results(self, progress: Callable[[str], None] | None = None) -> dict[str, TaskOutcome]:
        """``{key: TaskOutcome}`` in task order. An error of one of the ``errors`` types is
        kept in its outcome; any other error is raised. ``progress`` is called with each
        task's label before it runs here (or before its result is awaited)."""
        step = progress or (lambda label: None)
        out = {}
        for task in self.tasks:
            step(task.label)
            start = time.perf_counter()
            try:
                out[task.key] = self._futures[task.key].result() if self._futures is not None else _execute(task)
            except self._errors as exc:
                out[task.key] = TaskOutcome(task.key, None, time.perf_counter() - start, exc)
        return out

    def part(self, keys) -> TaskRun:
        """The tasks of ``keys`` (in this run's order), sharing this run's submissions."""
        keys = set(keys)
        return TaskRun([t for t in self.tasks if t.key in keys], self._futures, self._errors)


def start_tasks(
    tasks: Sequence[Task], executor: Executor | None = None, errors: tuple[type[BaseException], ...] = ()
) -> TaskRun:
    """Submit ``tasks`` to ``executor``, the most costly first; None runs them later, here.

    Keys must be unique. ``errors`` are the exception types that :meth:`TaskRun.results`
    returns in the outcome instead of raising (a study that does not apply to the design).
    """
    keys = [t.key for t in tasks]
    if len(set(keys)) != len(keys):
        raise ValueError(f"task keys must be unique, got {keys}")
    futures = None
    if executor is not None:
        futures = {t.key: executor.submit(_execute, t) for t in sorted(tasks, key=lambda t: -t.cost)}
    return TaskRun(tasks, futures, tuple(errors))

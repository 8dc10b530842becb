"""One pool of forked worker processes for the stages of a command (``flexshaft run``).

The run's independent pieces of work (the thesis studies, then the report's figures) go to the
same few workers, started once at the beginning. The workers fork from a parent that has
already imported numpy, scipy and flexshaft, and import what they will need (matplotlib,
xarray) themselves at start, while the parent computes the main analyses: that import time
and the studies overlap the parent's work instead of following it
(benchmarks/studies_timing.py).

Without ``fork`` (Windows), or for one process, :func:`worker_pool` gives ``None`` and the
callers work in this process, with the same results.
"""

from __future__ import annotations

import importlib
import os
from collections.abc import Iterator, Sequence
from concurrent.futures import Executor
from contextlib import contextmanager

__all__ = ["available_cpus", "worker_pool"]


def available_cpus() -> int:
    """CPUs this process may run on (its affinity mask where the system has one)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def _warm(modules: tuple[str, ...]) -> None:
    """Worker initializer: import ``modules`` once (matplotlib with the Agg backend)."""
    for name in modules:
        if name.startswith("matplotlib"):
            import matplotlib

            matplotlib.use("Agg")
        importlib.import_module(name)


def _ready() -> int:
    return os.getpid()


@contextmanager
def worker_pool(processes: int, warm: Sequence[str] = ()) -> Iterator[Executor | None]:
    """A process pool of ``processes`` forked workers, started now, each importing ``warm``.

    Yields None when ``processes`` < 2 or the platform cannot fork. On leaving the block the
    pool is shut down: queued work is cancelled when an exception (Ctrl-C included) ends it.
    """
    if int(processes) != processes or processes < 1:
        raise ValueError(f"processes must be an integer >= 1 (got {processes!r})")
    if processes < 2 or not hasattr(os, "fork"):
        yield None
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    pool = ProcessPoolExecutor(max_workers=int(processes), mp_context=multiprocessing.get_context("fork"),
                               initializer=_warm, initargs=(tuple(warm),))
    pool.submit(_ready)  # the first submission forks every worker: they warm up while we go on
    try:
        yield pool
    except BaseException:
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    pool.shutdown(wait=True)

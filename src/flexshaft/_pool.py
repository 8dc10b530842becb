"""One pool of forked worker processes for the stages of a command (``flexshaft run``).

The run's independent pieces of work (the thesis studies, then the report's figures) go to the
same few workers, started once at the beginning. The workers fork from a parent that has
already imported numpy, scipy, xarray and flexshaft, and import what else they will need
(matplotlib, for the figures) themselves at start, while the parent computes the main
analyses: that import time and the studies overlap the parent's work instead of following it
(benchmarks/studies_timing.py).

Without ``fork`` (Windows), or for one process, :func:`worker_pool` gives ``None`` and the
callers work in this process, with the same results.

A worker never outlives the command: it ignores Ctrl-C (the parent handles it and ends the
pool at once), and :func:`die_with_parent` ends it when the parent dies, even by SIGKILL.
"""

from __future__ import annotations

import gc
import importlib
import os
import signal
import sys
import threading
import time
from collections.abc import Iterator, Sequence
from concurrent.futures import Executor
from contextlib import contextmanager

__all__ = ["available_cpus", "die_with_parent", "prepare_worker", "worker_pool"]

_PR_SET_PDEATHSIG = 1  # <linux/prctl.h>
#: How often the portable watchdog thread looks at the parent [s].
WATCHDOG_INTERVAL = 0.5


def available_cpus() -> int:
    """CPUs this process may run on (its affinity mask where the system has one)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def _set_parent_death_signal(sig: int) -> bool:
    """Ask Linux to send ``sig`` to this process when its parent dies; False if unavailable."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        prctl = libc.prctl
    except (OSError, AttributeError):  # no libc symbol table (unusual builds)
        return False
    prctl.argtypes = [ctypes.c_int, ctypes.c_ulong, ctypes.c_ulong, ctypes.c_ulong, ctypes.c_ulong]
    prctl.restype = ctypes.c_int
    return prctl(_PR_SET_PDEATHSIG, int(sig), 0, 0, 0) == 0


def _watch_parent(parent_pid: int, interval: float) -> None:
    while os.getppid() == parent_pid:
        time.sleep(interval)
    os._exit(1)  # the parent is gone: end the whole worker now, without cleanup


def die_with_parent(parent_pid: int, pdeathsig: bool = True) -> str:
    """Make this worker process end when its parent ``parent_pid`` ends, however.

    Returns the mechanism used: ``"pdeathsig"`` (Linux: the kernel sends SIGKILL when the
    parent dies, ``prctl(PR_SET_PDEATHSIG)``) or ``"watchdog"`` (elsewhere, or ``pdeathsig``
    False: a daemon thread that exits the process within :data:`WATCHDOG_INTERVAL` of the
    parent's death). The worker must be a direct child of ``parent_pid`` (fork or spawn, not
    a forkserver).
    """
    if pdeathsig and _set_parent_death_signal(signal.SIGKILL):
        # The parent may have died between the fork and the prctl call; then no signal comes.
        if os.getppid() != parent_pid:
            os._exit(1)
        return "pdeathsig"
    threading.Thread(
        target=_watch_parent, args=(parent_pid, WATCHDOG_INTERVAL), daemon=True, name="flexshaft-parent-watch"
    ).start()
    return "watchdog"


def prepare_worker(parent_pid: int, pdeathsig: bool = True) -> str:
    """Set up a worker process of ``parent_pid``: Ctrl-C is left to the parent (which ends
    the pool), SIGTERM gets its default action (not the parent's handler, inherited by fork),
    and the worker ends with the parent (:func:`die_with_parent`, whose result is returned)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    return die_with_parent(parent_pid, pdeathsig)


def _warm(parent_pid: int, modules: tuple[str, ...]) -> None:
    """Worker initializer: :func:`prepare_worker`, then import ``modules`` once (matplotlib
    with the Agg backend)."""
    prepare_worker(parent_pid)
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

    pool = ProcessPoolExecutor(
        max_workers=int(processes),
        mp_context=multiprocessing.get_context("fork"),
        initializer=_warm,
        initargs=(os.getpid(), tuple(warm)),
    )
    # The first submission forks every worker: they warm up while we go on. The objects this
    # process holds by then (the imported modules: ~150,000) are frozen for the fork, so that the
    # workers' full garbage collections skip them (a figure worker spent 0.45 s of CPU in the
    # collector, 0.23 s without them) and do not copy their pages by touching them.
    gc.freeze()
    try:
        pool.submit(_ready)
    finally:
        gc.unfreeze()  # this process collects them as before
    try:
        yield pool
    except BaseException:  # Ctrl-C or an error: the queued work is not wanted, stop the workers now
        _terminate(pool)
        raise
    pool.shutdown(wait=True)


def _terminate(pool) -> None:
    """Cancel the queued work and end the workers without waiting for their current task
    (an interrupted run writes no report; a figure being drawn is lost with it)."""
    workers = dict(getattr(pool, "_processes", None) or {})  # the stdlib's record of them (no public API before 3.14)
    pool.shutdown(wait=False, cancel_futures=True)
    for process in workers.values():  # SIGKILL: a task's own SIGTERM handler (a sweep's) must not delay it
        if process.is_alive():
            process.kill()
    for process in workers.values():
        process.join(timeout=5)

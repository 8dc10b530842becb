"""The package's process pools: one builder (:func:`new_pool`) for the run's pool of forked
workers (:func:`worker_pool`) and the sweep engine's (:mod:`flexshaft.sweep.run`).

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
import multiprocessing
import os
import signal
import sys
import threading
import time
from collections.abc import Iterator, Sequence
from concurrent.futures import Executor, ProcessPoolExecutor
from contextlib import contextmanager
from multiprocessing.context import BaseContext

from flexshaft.parallel import MAX_JOBS

__all__ = ["available_cpus", "die_with_parent", "max_jobs", "new_pool", "prepare_worker", "stop_pool", "worker_pool"]

_PR_SET_PDEATHSIG = 1  # <linux/prctl.h>
#: How often the portable watchdog thread looks at the parent [s].
WATCHDOG_INTERVAL = 0.5


def available_cpus() -> int:
    """CPUs this process may run on (its affinity mask where the system has one)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def max_jobs() -> int:
    """Most local worker processes a sweep of the Python API starts: the machine's CPUs, at least
    :data:`~flexshaft.parallel.MAX_JOBS` (the CLI's ``--jobs`` limit); ``jobs=100000`` used to
    start that many processes."""
    return max(MAX_JOBS, os.cpu_count() or 1)


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


#: Environment of a worker that must not start more than one BLAS thread.
ONE_THREAD_ENVIRONMENT = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def _start_worker(parent_pid: int, modules: tuple[str, ...], pdeathsig: bool, one_thread_env: bool) -> None:
    """Worker initializer: :func:`prepare_worker`, one BLAS thread in the environment when
    asked, then import ``modules`` once (matplotlib with the Agg backend) and freeze what the
    worker holds then, as :func:`new_pool` freezes the parent's objects for the fork: the
    collector's full passes skip the ~44,000 objects of matplotlib and the plot modules too (a
    ``flexshaft run --studies report`` worker spent 0.20 s of CPU in the collector, 0.15 s with
    them frozen)."""
    if one_thread_env:
        for var in ONE_THREAD_ENVIRONMENT:
            os.environ[var] = "1"
    prepare_worker(parent_pid, pdeathsig)
    for name in modules:
        if name.startswith("matplotlib"):
            import matplotlib  # noqa: PLC0415 - only a worker that draws figures needs it (0.4 s)

            matplotlib.use("Agg")
        importlib.import_module(name)
    gc.freeze()


def _ready() -> int:
    return os.getpid()


def new_pool(
    processes: int,
    context: BaseContext,
    *,
    warm: Sequence[str] = (),
    pdeathsig: bool = True,
    one_thread_env: bool = False,
) -> ProcessPoolExecutor:
    """A :class:`~concurrent.futures.ProcessPoolExecutor` of ``processes`` workers of this
    process, started now (a first submission), each set up by :func:`prepare_worker` (Ctrl-C
    left to the parent, ends with it; ``pdeathsig`` as there), with ``OMP/OPENBLAS/MKL_NUM_THREADS``
    = 1 when ``one_thread_env``, and importing ``warm`` once.

    The objects this process holds when the workers fork (the imported modules: ~150,000) are
    frozen for the fork, so that the workers' full garbage collections skip them (a figure
    worker spent 0.45 s of CPU in the collector, 0.23 s without them) and do not copy their pages
    by touching them.
    """
    pool = ProcessPoolExecutor(
        max_workers=int(processes),
        mp_context=context,
        initializer=_start_worker,
        initargs=(os.getpid(), tuple(warm), bool(pdeathsig), bool(one_thread_env)),
    )
    gc.freeze()
    try:
        pool.submit(_ready)
    finally:
        gc.unfreeze()  # this process collects them as before
    return pool


def stop_pool(pool: ProcessPoolExecutor, *, now: bool) -> None:
    """Shut ``pool`` down: wait for its work, or with ``now`` cancel the queued work and end the
    workers without waiting for their current task (SIGKILL: a task's own SIGTERM handler, a
    sweep's, must not delay it)."""
    if not now:
        pool.shutdown(wait=True)
        return
    workers = dict(getattr(pool, "_processes", None) or {})  # the stdlib's record of them (no public API before 3.14)
    pool.shutdown(wait=False, cancel_futures=True)
    for process in workers.values():
        if process.is_alive():
            process.kill()
    for process in workers.values():
        process.join(timeout=5)


@contextmanager
def worker_pool(processes: int, warm: Sequence[str] = ()) -> Iterator[Executor | None]:
    """A pool of ``processes`` forked workers, started now, each importing ``warm``
    (:func:`new_pool`).

    Yields None when ``processes`` < 2 or the platform cannot fork. On leaving the block the
    pool is shut down: queued work is cancelled when an exception (Ctrl-C included) ends it.
    """
    if int(processes) != processes or processes < 1:
        raise ValueError(f"processes must be an integer >= 1 (got {processes!r})")
    if processes < 2 or not hasattr(os, "fork"):
        yield None
        return
    pool = new_pool(processes, multiprocessing.get_context("fork"), warm=warm)
    try:
        yield pool
    except BaseException:  # Ctrl-C or an error: the queued work is not wanted, stop the workers now
        stop_pool(pool, now=True)
        raise
    stop_pool(pool, now=False)

"""Running a study: chunks, local processes or Dask, a run folder that survives interruption.

The grid is cut into fixed chunks of consecutive points. Workers compute chunks; the calling
process writes each finished chunk to ``RUN/chunks/chunk_NNNNNN.npz`` atomically (temporary file
then ``os.replace``), with the study fingerprint, the chunk's point range and a SHA-256 checksum
(:mod:`flexshaft.sweep.store`), so an interrupted run (Ctrl-C, SIGTERM, SIGKILL, a lost node)
leaves only complete chunks. ``RUN/manifest.json`` holds the study's specification and
fingerprint; running the same study on the same folder again verifies every stored chunk,
recomputes the missing and the damaged or foreign ones (with a warning naming each) and writes
``RUN/results.nc``, identical to an uninterrupted run's (the values are stored bit for bit and
the file carries no time stamp).

Backends:

* ``jobs=1``: in this process;
* ``jobs=N``: a pool of N worker processes, one BLAS thread each, started by fork or spawn (the
  default start method, with spawn replacing a forkserver). The workers end with the calling
  process even when it is killed with SIGKILL: on Linux each worker asks the kernel for SIGKILL
  when its parent dies (``prctl(PR_SET_PDEATHSIG)``); elsewhere a thread in each worker watches
  the parent and exits the worker within a second of its death;
* ``client=``: a ``dask.distributed.Client`` or a scheduler address (``"tcp://host:8786"``;
  its form is checked before anything is prepared, and the connection gives up after
  :data:`flexshaft.sweep.dask.CONNECT_TIMEOUT`).
  On SLURM, make the client from ``dask_jobqueue.SLURMCluster``. Dask is imported only then.
"""

from __future__ import annotations

import json
import os
import signal
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft import __version__
from flexshaft.analyses.labelled import LabelledArrays
from flexshaft.netcdf import write_netcdf
from flexshaft.parallel.pool import die_with_parent, max_jobs, new_pool, stop_pool
from flexshaft.sweep.dask import check_scheduler_address, connect, evaluate_chunk_on_worker
from flexshaft.sweep.store import chunk_path, finished_chunks, load_chunks, open_run, write_chunk
from flexshaft.sweep.study import Study, SweepError, evaluate_chunk

__all__ = ["chunk_bounds", "finished_chunks", "run_sweep", "to_arrays", "to_dataset", "write_netcdf"]

RESULTS = "results.nc"


def chunk_bounds(size: int, chunk_size: int) -> list[tuple[int, int]]:
    """``(start, stop)`` of each chunk of a grid of ``size`` points."""
    return [(s, min(s + chunk_size, size)) for s in range(0, size, chunk_size)]


def _default_chunk_size(size: int, workers: int) -> int:
    """About 8 chunks per worker, at most 256 points each (a few seconds of work)."""
    return int(max(1, min(256, -(-size // (8 * max(workers, 1))))))


# ---------------------------------------------------------------------------------------------
# Backends: each yields (chunk index, values) as chunks finish.


def _run_serial(study: Study, todo, on_error) -> Iterator[tuple[int, np.ndarray]]:
    for k, (a, b) in todo:
        yield k, evaluate_chunk(study, a, b, on_error)


# A worker must not outlive the sweep process: orphaned workers would compute forever and hold
# its stdout. Set to False to use the portable watchdog thread on Linux too (tests use this).
_USE_PDEATHSIG = True


def _die_with_parent(parent_pid: int) -> str:
    """Make this worker end when its parent, the sweep process ``parent_pid``, ends, however
    (:func:`flexshaft.parallel.pool.die_with_parent`); returns ``"pdeathsig"`` or ``"watchdog"``."""
    return die_with_parent(parent_pid, pdeathsig=_USE_PDEATHSIG)


def _pool_context():
    """The default multiprocessing context, but spawn instead of a forkserver.

    A forkserver's children are not ours: it outlives a SIGKILLed sweep with its workers
    (seen on Python 3.11), so their deaths cannot be tied to this process.
    """
    import multiprocessing

    context: multiprocessing.context.BaseContext = multiprocessing.get_context()
    if context.get_start_method() == "forkserver":
        context = multiprocessing.get_context("spawn")
    return context


def _run_processes(study: Study, todo, on_error, jobs: int) -> Iterator[tuple[int, np.ndarray]]:
    from concurrent.futures import FIRST_COMPLETED, wait

    # one BLAS thread per worker; Ctrl-C left to this process; each worker ends with it
    pool = new_pool(jobs, _pool_context(), pdeathsig=_USE_PDEATHSIG, one_thread_env=True)
    pending: dict = {}
    queue = list(todo)
    try:
        while queue or pending:
            while queue and len(pending) < 2 * jobs:
                k, (a, b) = queue.pop(0)
                pending[pool.submit(evaluate_chunk, study, a, b, on_error)] = k
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for fut in done:
                yield pending.pop(fut), fut.result()
    finally:
        stop_pool(pool, now=bool(pending))  # chunks still running: stop the workers now


def _run_dask(study: Study, todo, on_error, client) -> Iterator[tuple[int, np.ndarray]]:
    try:
        from distributed import as_completed
    except ImportError as exc:  # pragma: no cover - depends on the extra
        raise SweepError("the Dask backend needs the extra: pip install 'flexshaft[dask]'") from exc
    own = isinstance(client, str)
    client = connect(client) if own else client  # checked address, short connect timeout
    try:
        # the study (design, outputs, evaluation function) goes to every worker once, not with
        # every chunk: chunks then carry two integers (benchmarks/dask_scaling.py)
        shared = client.scatter(study, broadcast=True, hash=False) if todo else study
        futures = {
            client.submit(
                evaluate_chunk_on_worker,
                shared,
                a,
                b,
                on_error,
                pure=False,
                key=f"flexshaft-chunk-{k}-{os.urandom(4).hex()}",
            ): k
            for k, (a, b) in todo
        }
        for fut in as_completed(futures):
            yield futures[fut], fut.result()
    finally:
        if own:
            client.close()


# ---------------------------------------------------------------------------------------------


class _Interrupted(KeyboardInterrupt):
    """SIGTERM turned into an exception so the pool and the progress bar shut down cleanly."""


def _sigterm_to_exception():
    if threading.current_thread() is not threading.main_thread():
        return None
    if signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL:
        return None

    def handler(signum, frame):
        raise _Interrupted(f"signal {signum}")

    return signal.signal(signal.SIGTERM, handler)


def to_dataset(study: Study, values: np.ndarray):
    """Results as an :class:`xarray.Dataset`: one variable per output over the study's dims."""
    return to_arrays(study, values).to_dataset()


def to_arrays(study: Study, values: np.ndarray) -> LabelledArrays:
    """The content of :func:`to_dataset` as plain labelled arrays (no xarray import)."""
    dims = tuple(v.name for v in study.variables)
    grid = values.reshape(study.shape + (len(study.outputs),))
    coords = {}
    for v in study.variables:
        attrs = {"units": v.units, "long_name": v.long_name or v.name}
        if v.path:
            attrs["design_path"] = v.path
        attrs["kind"] = "design variable" if v.is_design else "axis"
        coords[v.name] = (v.name, np.asarray(v.values), attrs)
    data = {
        o.name: (
            dims,
            grid[..., i],
            {"units": o.units, "long_name": o.long_name or o.name, **_nan_comment(grid[..., i])},
        )
        for i, o in enumerate(study.outputs)
    }
    attrs = {
        "title": study.name,
        "design": str(getattr(study.base, "name", "")),
        "fixed_overrides": json.dumps(dict(study.fixed.items()), default=repr),
        "flexshaft_version": __version__,
        "study_fingerprint": study.fingerprint(),
    }
    return LabelledArrays(data, coords, attrs)


def _nan_comment(values: np.ndarray) -> dict[str, str]:
    """A ``comment`` (CF) on an output with NaN points saying what the NaN stands for: a
    study's output that does not apply to the design (the Tsai-Wu factors of `study wall` on a
    metal shaft, its spin-up peak without an active bearing) used to be a bare NaN column."""
    missing = int(np.count_nonzero(np.isnan(values)))
    if not missing:
        return {}
    return {
        "comment": (
            f"NaN at {missing} of {values.size} points: the output does not apply to the design there "
            "(e.g. a Tsai-Wu factor of a metal shaft, an actuator output without an active bearing) "
            "or its evaluation failed"
        )
    }


def run_sweep(
    study: Study,
    run_dir: str | os.PathLike | None = None,
    *,
    jobs: int = 1,
    client: Any = None,
    chunk_size: int | None = None,
    progress: bool = True,
    on_error: str = "raise",
    as_arrays: bool = False,
):
    """Compute a study and return its results as an :class:`xarray.Dataset`.

    Parameters
    ----------
    study : Study
        What to compute. Validated (every design path and value) before anything runs.
    run_dir : path, optional
        Run folder: finished chunks are stored as they come, an interrupted run resumes from
        the ones that pass their checks (:mod:`flexshaft.sweep.store`), and ``results.nc`` is
        written at the end. ``None`` keeps everything in memory.
    jobs : int
        Local worker processes (1: in this process). Each uses one BLAS thread.
    client : dask.distributed.Client or str, optional
        Run the chunks on a Dask cluster instead (a client or a scheduler address).
    chunk_size : int, optional
        Points per chunk (default: ~8 chunks per worker, at most 256 points). A resumed run
        keeps the chunk size it was started with.
    progress : bool
        Show a progress bar (rich) on stderr.
    on_error : {"raise", "nan"}
        What a point whose evaluation raises becomes: stop the run, or NaN outputs.
    as_arrays : bool
        Return the Dataset's content as :class:`~flexshaft.analyses.labelled.LabelledArrays`
        (plain arrays; ``.to_dataset()`` gives the Dataset): no xarray import without
        ``run_dir`` (the studies of ``flexshaft run`` travel between processes as these).

    Raises
    ------
    SweepError
        Bad variable path or value (naming the field), undeclared outputs, or a run folder
        that belongs to another study.

    Warns
    -----
    SweepWarning
        Stored chunks that are not reused (unreadable, edited, of another study or chunk) and
        are recomputed, stray files in ``chunks/``, or a missing or broken manifest (the old
        chunks are then moved to ``chunks.discarded-N/`` and everything is recomputed).
    """
    if on_error not in ("raise", "nan"):
        raise SweepError(f"on_error must be 'raise' or 'nan', got {on_error!r}")
    if not _whole(jobs) or not 1 <= jobs <= max_jobs():
        raise SweepError(f"jobs must be a whole number from 1 to {max_jobs()} (the CPUs, at least 64), got {jobs!r}")
    if chunk_size is not None and (not _whole(chunk_size) or chunk_size < 1):
        raise SweepError(f"chunk_size must be a whole number >= 1, got {chunk_size!r}")
    if isinstance(client, str):
        check_scheduler_address(client)  # before anything is prepared (flexshaft.sweep.dask)
    study.validate()
    workers = jobs if client is None else _dask_workers(client)
    default_chunk_size = _default_chunk_size(study.size, workers)
    run_path = Path(run_dir) if run_dir is not None else None
    fingerprint = study.fingerprint() if run_path is not None else ""
    if run_path is not None:
        run_path.mkdir(parents=True, exist_ok=True)
        chunk_size = open_run(run_path, study, fingerprint, chunk_size, default_chunk_size)
    chunk_size = int(chunk_size or default_chunk_size)
    bounds = chunk_bounds(study.size, chunk_size)
    values = np.full((study.size, len(study.outputs)), np.nan)
    done = set()
    if run_path is not None:
        stored = load_chunks(run_path, bounds, fingerprint=fingerprint, n_outputs=len(study.outputs))
        for k, chunk in stored.items():
            a, b = bounds[k]
            values[a:b] = chunk
            done.add(k)
    todo = [(k, ab) for k, ab in enumerate(bounds) if k not in done]
    if client is not None:
        stream = _run_dask(study, todo, on_error, client)
    elif jobs > 1 and len(todo) > 1:
        stream = _run_processes(study, todo, on_error, jobs)
    else:
        stream = _run_serial(study, todo, on_error)
    previous = _sigterm_to_exception()
    bar = _progress_bar(progress, study, len(bounds), len(done))
    try:
        for k, chunk in stream:
            a, b = bounds[k]
            values[a:b] = chunk
            if run_path is not None:
                write_chunk(chunk_path(run_path, k), chunk, fingerprint=fingerprint, index=k, start=a, stop=b)
                done.add(k)
            bar.advance()
    except KeyboardInterrupt as exc:  # Ctrl-C or SIGTERM: say what is kept (the CLI prints the note)
        if run_path is not None:
            exc.add_note(
                f"{len(done)} of {len(bounds)} chunks are stored in {run_path}: "
                "the same command with the same options resumes from them"
            )
        raise
    finally:
        close = getattr(stream, "close", None)
        if close is not None:
            close()
        bar.stop()
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)
    arrays = to_arrays(study, values)
    if run_path is not None:
        write_netcdf(arrays.to_dataset(), run_path / RESULTS)
    return arrays if as_arrays else arrays.to_dataset()


def _whole(value: Any) -> bool:
    """An integer (not a bool, not 2.5: a count given as 2.5 used to run as 2)."""
    return isinstance(value, (int, np.integer)) and not isinstance(value, bool)


def _dask_workers(client) -> int:
    if isinstance(client, str):
        return 8
    try:
        return max(1, sum(client.nthreads().values()))
    except Exception:  # any client-like object without the call
        return 8


class _progress_bar:
    """A rich progress bar over chunks, or nothing."""

    def __init__(self, enabled: bool, study: Study, total: int, completed: int):
        self.progress = None
        if enabled:
            from rich.console import Console
            from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

            self.progress = Progress(  # on stderr, like every progress display: stdout holds results
                TextColumn("[bold]{task.description}"),
                BarColumn(),
                MofNCompleteColumn(),
                TextColumn("chunks"),
                TimeRemainingColumn(),
                transient=False,
                console=Console(stderr=True),
            )
            self.task = self.progress.add_task(study.name, total=total, completed=completed)
            self.progress.start()

    def advance(self) -> None:
        if self.progress is not None:
            self.progress.advance(self.task)

    def stop(self) -> None:
        if self.progress is not None:
            self.progress.stop()

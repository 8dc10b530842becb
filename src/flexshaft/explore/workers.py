"""The explorer's worker processes: assessments off the server's event loop, one at a time per
page, a newer request superseding an older one; sweeps and full runs on the same workers.

:class:`Workers` forks its processes when it is made, before the web server starts its threads
(:func:`flexshaft.parallel.pool.new_pool`: they end with the server, Ctrl-C is the server's). A
:class:`Session` (one open page) runs one update at a time: a request that is still waiting
when a newer one of the same page arrives is answered "superseded" without being computed, so a
page whose user types faster than the updates only ever waits for the latest value. Full runs
report their stages through the queue the workers inherit (:mod:`flexshaft.explore.fullrun`).
"""

from __future__ import annotations

import asyncio
import multiprocessing
import threading
import time
from collections import OrderedDict
from collections.abc import Awaitable, Callable
from concurrent.futures import Future
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field
from typing import Any

from flexshaft.explore.fullrun import relay, set_relay
from flexshaft.parallel.pool import available_cpus, new_pool, stop_pool

__all__ = ["Job", "Session", "Workers", "default_processes"]

#: Pages kept at once (the oldest is forgotten beyond it).
MAX_SESSIONS = 32


def default_processes() -> int:
    """Worker processes: the CPUs this process may use, at least 2 (an update beside a sweep
    or a full run) and at most 4."""
    return max(2, min(4, available_cpus()))


@dataclass
class Job:
    """A full run: its stages as they come ``(label, seconds)`` and its outcome."""

    id: str
    folder: str
    steps: list = field(default_factory=list)
    state: str = "running"  # "running", "done", "failed"
    result: dict | None = None
    error: str | None = None

    def to_dict(self) -> dict:
        return {
            "id": self.id,
            "folder": self.folder,
            "state": self.state,
            "steps": [{"label": label, "seconds": seconds} for label, seconds in self.steps],
            "result": self.result,
            "error": self.error,
        }


class Workers:
    """The process pool of the explorer and the progress of its full runs."""

    def __init__(self, processes: int | None = None) -> None:
        context = multiprocessing.get_context("fork")
        set_relay(context.SimpleQueue())  # inherited by the workers forked next
        self.processes = int(processes or default_processes())
        self._context = context
        self.pool = new_pool(self.processes, context)
        self.jobs: dict[str, Job] = {}
        self._reader = threading.Thread(target=self._read_progress, daemon=True, name="flexshaft-explore-progress")
        self._reader.start()

    def _read_progress(self) -> None:
        queue = relay()
        while True:
            message = queue.get()
            if message is None:
                return
            job, label, seconds = message
            if job in self.jobs:
                self.jobs[job].steps.append((label, seconds))

    def submit(self, function: Callable, *args: Any) -> Future:
        """Run ``function(*args)`` in a worker (a new pool when a worker died)."""
        try:
            return self.pool.submit(function, *args)
        except BrokenProcessPool:
            self.pool = new_pool(self.processes, self._context)
            return self.pool.submit(function, *args)

    async def run(self, function: Callable, *args: Any) -> Any:
        """Await ``function(*args)`` computed in a worker."""
        return await asyncio.wrap_future(self.submit(function, *args))

    def start_job(self, job: Job, function: Callable, *args: Any) -> None:
        """Start a full run; its stages and outcome go to ``job``."""
        self.jobs[job.id] = job
        future = self.submit(function, *args)

        def finished(done: Future) -> None:
            try:
                job.result = done.result()
                job.state = "done"
            except Exception as exc:  # noqa: BLE001 - reported to the page, which shows it
                job.error = str(exc) or type(exc).__name__
                job.state = "failed"

        future.add_done_callback(finished)

    def close(self) -> None:
        """End the workers now (the server is stopping)."""
        relay().put(None)
        stop_pool(self.pool, now=True)


class Session:
    """One open page: its updates, one at a time, the newest winning."""

    def __init__(self, workers: Workers) -> None:
        self.workers = workers
        self.latest = -1
        self._lock = asyncio.Lock()

    async def update(self, seq: int, compute: Callable[[], Awaitable[Any]]) -> tuple[Any, float] | None:
        """``await compute()`` (its work in the workers), or None when a newer request of this
        page came while this one waited (it is then not computed); with the seconds it waited."""
        self.latest = max(self.latest, seq)
        arrived = time.perf_counter()
        async with self._lock:  # FIFO: the waiting requests go in order, the stale ones skip
            if seq < self.latest:
                return None
            waited = time.perf_counter() - arrived
            return await compute(), waited


class Sessions:
    """The open pages by id (the oldest forgotten beyond :data:`MAX_SESSIONS`)."""

    def __init__(self, workers: Workers) -> None:
        self.workers = workers
        self._sessions: OrderedDict[str, Session] = OrderedDict()

    def get(self, key: str) -> Session:
        session = self._sessions.pop(key, None) or Session(self.workers)
        self._sessions[key] = session
        while len(self._sessions) > MAX_SESSIONS:
            self._sessions.popitem(last=False)
        return session

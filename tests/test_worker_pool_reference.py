"""The forked worker pool: as many workers as asked, and queued work cancelled on Ctrl-C.

References (the docstrings of :mod:`flexshaft.parallel.pool`, API contract):

* :func:`~flexshaft.parallel.pool.worker_pool`: "A pool of ``processes`` forked workers, started
  now" and "queued work is cancelled when an exception (Ctrl-C included) ends it";
* the module docstring: "it ignores Ctrl-C (the parent handles it and ends the pool at once)".

Hand-built tasks whose outcome is known without the code under test:

* two tasks that each wait at a two-party barrier can only both return when two workers run at
  once; with one worker the first waits alone and the barrier times out (``BrokenBarrierError``);
* tasks that each leave a "start" file, sleep 5 s and then leave an "end" file, four submitted
  to two workers; once both workers have started one (their start files, waited for with a
  20 s bound) a ``KeyboardInterrupt``: the workers are killed when the block is left, so no
  "end" file exists then. A pool that is only shut down lets the started tasks run on: the
  parent's ``join(timeout=5)`` of each worker waits for them, and they leave their "end" files
  (started before the joins, they end within them). The files, not ``Future.cancelled()``:
  CPython cancels the pending futures in the executor's manager thread, racing with the
  workers' deaths.

Two pools of two forked workers; about 0.1 s of CPU in this process.
"""

from __future__ import annotations

import multiprocessing
import os
import time
from multiprocessing.synchronize import Barrier

import pytest

from flexshaft.parallel.pool import worker_pool

pytestmark = pytest.mark.skipif(not hasattr(os, "fork"), reason="worker_pool forks")

_barrier: Barrier | None = None  # set before the pool forks: its workers inherit it


def _meet() -> int:
    assert _barrier is not None
    _barrier.wait(timeout=20)  # generous: a loaded 2-core machine still forks within it
    return os.getpid()


def _mark_nap_mark(folder: str, k: int) -> None:
    with open(os.path.join(folder, f"start-{k}"), "w"):
        pass
    time.sleep(5.0)
    with open(os.path.join(folder, f"end-{k}"), "w"):
        pass


def test_two_processes_run_two_tasks_at_once():
    global _barrier
    _barrier = multiprocessing.get_context("fork").Barrier(2)
    try:
        with worker_pool(2) as pool:
            assert pool is not None
            futures = [pool.submit(_meet) for _ in range(2)]
            pids = [f.result(timeout=60) for f in futures]
    finally:
        _barrier = None
    assert len(set(pids)) == 2 and os.getpid() not in pids


def test_interrupt_ends_the_queued_work(tmp_path):
    with pytest.raises(KeyboardInterrupt), worker_pool(2) as pool:
        assert pool is not None
        for k in range(4):
            pool.submit(_mark_nap_mark, str(tmp_path), k)
        deadline = time.monotonic() + 20  # generous: a loaded 2-core machine still forks within it
        while len(list(tmp_path.glob("start-*"))) < 2:
            assert time.monotonic() < deadline, "the two workers did not start a task within 20 s"
            time.sleep(0.01)
        raise KeyboardInterrupt  # as Ctrl-C in the parent, both workers 5 s from their "end" files
    # the workers are killed (and joined) when the block is left: no started task has finished
    assert sorted(p.name for p in tmp_path.glob("end-*")) == []

"""The forked worker pool: as many workers as asked, and queued work cancelled on Ctrl-C.

References (the docstrings of :mod:`flexshaft.parallel.pool`, a code contract):

* :func:`~flexshaft.parallel.pool.worker_pool`: "A pool of ``processes`` forked workers, started
  now" and "queued work is cancelled when an exception (Ctrl-C included) ends it";
* the module docstring: "it ignores Ctrl-C (the parent handles it and ends the pool at once)".

Hand-built tasks whose outcome is known without the code under test:

* two tasks that each wait at a two-party barrier can only both return when two workers run at
  once; with one worker the first waits alone and the barrier times out (``BrokenBarrierError``);
* twelve tasks that each sleep 0.5 s and then leave a file, submitted to two workers, then a
  ``KeyboardInterrupt`` at once: the workers are ended with the queued work, so fewer than
  twelve files exist when the block has been left (none, unless this process stalled for more
  than 0.5 s between submitting and interrupting); a pool that waits for its queued work runs
  all twelve (12 x 0.5 / 2 = 3 s). The files, not ``Future.cancelled()``: CPython cancels the
  pending futures in the executor's manager thread, racing with the workers' deaths.

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


def _nap_then_mark(path: str) -> None:
    time.sleep(0.5)
    with open(path, "w"):
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
        for k in range(12):
            pool.submit(_nap_then_mark, str(tmp_path / f"task-{k}"))
        raise KeyboardInterrupt  # as Ctrl-C in the parent
    # the workers are ended (killed and joined) when the block is left: no task finishes later
    assert len(list(tmp_path.iterdir())) < 12

"""A forked worker leaves Ctrl-C to its parent and dies of SIGTERM whatever the parent set;
the CPUs counted for the workers are those this process may run on.

References:

* :func:`flexshaft.parallel.pool.prepare_worker` (API contract, verbatim): "Ctrl-C is left to
  the parent (which ends the pool), SIGTERM gets its default action (not the parent's handler,
  inherited by fork)", and the module docstring: "it ignores Ctrl-C (the parent handles it and
  ends the pool at once)".
* signal(7), Linux man-pages (assumed): the default action of SIGTERM is to terminate the
  process; a process that ignores SIGINT is not interrupted by it.

Hand-built tasks whose outcome follows from those rules alone:

* a task that sends SIGINT to its own process (as the terminal's Ctrl-C reaches every process
  of the foreground group), waits 0.05 s and returns "kept": a worker that ignores SIGINT
  returns it; one that does not gets a ``KeyboardInterrupt`` in the middle of its task;
* with the parent ignoring SIGTERM (``SIG_IGN``, inherited through fork like any disposition), a
  task that sends SIGTERM to its own process and then sleeps 1 s: a worker with SIGTERM's
  default action dies at once, which the pool reports as ``BrokenProcessPool``; one that kept
  the parent's disposition returns.

Two pools of two forked workers (:func:`~flexshaft.parallel.pool.worker_pool`, the run's pool),
and this process pinned to one CPU for a moment; about 0.05 s of CPU in this process.
"""

from __future__ import annotations

import os
import signal
import time
from concurrent.futures.process import BrokenProcessPool

import pytest

from flexshaft.parallel.pool import worker_pool

pytestmark = pytest.mark.skipif(not hasattr(os, "fork"), reason="worker_pool forks")


def _interrupt_self() -> str:
    os.kill(os.getpid(), signal.SIGINT)
    time.sleep(0.05)
    return "kept"


def _terminate_self() -> str:
    os.kill(os.getpid(), signal.SIGTERM)
    time.sleep(1.0)
    return "still running"


def test_a_worker_leaves_ctrl_c_to_the_parent():
    with worker_pool(2) as pool:
        assert pool is not None
        future = pool.submit(_interrupt_self)
        try:
            outcome = future.result(timeout=60)
        except KeyboardInterrupt:  # the worker's, re-raised here: must not end the test session
            outcome = "KeyboardInterrupt in the worker's task"
        assert outcome == "kept"


def test_a_worker_dies_of_sigterm_although_the_parent_ignores_it():
    previous = signal.signal(signal.SIGTERM, signal.SIG_IGN)
    try:
        with worker_pool(2) as pool:
            assert pool is not None
            future = pool.submit(_terminate_self)
            with pytest.raises(BrokenProcessPool):
                future.result(timeout=60)
    finally:
        signal.signal(signal.SIGTERM, previous)


@pytest.mark.skipif(not hasattr(os, "sched_setaffinity"), reason="no CPU affinity on this platform")
@pytest.mark.skipif((os.cpu_count() or 1) < 2, reason="one CPU: the affinity cannot be narrower than the machine")
def test_the_cpus_counted_are_those_this_process_may_run_on():
    """:func:`~flexshaft.parallel.pool.available_cpus` (API contract, verbatim): "CPUs this
    process may run on (its affinity mask where the system has one)", and
    :func:`flexshaft.cli.bounds.workers_of`: "``--jobs`` up to the CPUs this process may run
    on". Pinned to one CPU (sched_setaffinity(2): the calling thread may then run on that CPU only) while the
    machine has at least two, the count is 1 and ``--jobs 4`` gets one worker."""
    from flexshaft.cli.bounds import workers_of
    from flexshaft.parallel.pool import available_cpus

    mask = os.sched_getaffinity(0)
    if len(mask) < 2:
        pytest.skip("this process may run on one CPU only: no narrower affinity to set")
    try:
        os.sched_setaffinity(0, {min(mask)})
    except OSError as exc:  # a sandbox that refuses it (review r137)
        pytest.skip(f"the CPU affinity cannot be set here: {exc}")
    try:
        assert (available_cpus(), workers_of(4, None)) == (1, 1)
    finally:
        os.sched_setaffinity(0, mask)

"""The BLAS thread limit looks for the loaded libraries again from the main thread only.

Seen on a fresh clone's CI (2026-12-07, under load): a Dask sweep on a threaded LocalCluster
(``processes=False``, tests/test_sweep_dask.py) stopped for good. gdb showed one worker thread
inside threadpoolctl's search of the loaded libraries (``dl_iterate_phdr``, which holds the
dynamic loader's lock while its callback runs Python and so waits for the GIL) and the other
worker thread building a model, holding the GIL: a deadlock. The search ran in a worker thread
because the count of imported modules, which triggers it, changes while threads import lazily.

So (flexshaft.parallel.threads): a thread other than the main one reuses the controller found
before, whatever the count; the main thread looks again when the count changed. Checked with a
stand-in controller that records where it is built: no libraries are read. Exact counts.
"""

from __future__ import annotations

import threading

import threadpoolctl

from flexshaft.parallel import threads


def test_only_the_main_thread_looks_for_the_libraries_again(monkeypatch):
    built: list[str] = []

    class _Controller:
        def __init__(self) -> None:
            built.append(threading.current_thread().name)

    monkeypatch.setattr(threadpoolctl, "ThreadpoolController", _Controller)
    monkeypatch.setattr(threads, "_CONTROLLER", [])
    first = threads._controller(10)
    assert threads._controller(10) is first  # the same modules: found once
    seen = []
    worker = threading.Thread(target=lambda: seen.append(threads._controller(11)), name="worker")
    worker.start()
    worker.join()
    assert seen == [first] and built == [threading.main_thread().name]  # reused, not searched
    assert threads._controller(11) is not first  # the main thread looks again
    assert built == [threading.main_thread().name] * 2


def test_a_thread_finds_the_libraries_when_none_were_found_before(monkeypatch):
    built: list[str] = []

    class _Controller:
        def __init__(self) -> None:
            built.append(threading.current_thread().name)

    monkeypatch.setattr(threadpoolctl, "ThreadpoolController", _Controller)
    monkeypatch.setattr(threads, "_CONTROLLER", [])
    seen = []
    worker = threading.Thread(target=lambda: seen.append(threads._controller(3)), name="worker")
    worker.start()
    worker.join()
    assert built == ["worker"] and len(seen) == 1  # the first search, wherever it is asked for

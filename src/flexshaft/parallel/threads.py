"""BLAS thread control for the small dense solves of the analyses.

On small machines a multi-threaded BLAS makes 300-700 DOF eigen-problems much slower, not
faster, whenever the other core is busy (measured on the 2-core VM: modes of the baseline at
speed took 0.37-0.41 s on one thread and 2.3-11 s with the default two threads under load).
Dense analyses therefore run with one BLAS thread; parallelism comes from sweeping points in
separate processes.

The public entry points (:func:`flexshaft.assess`, :func:`flexshaft.verdict.assess.assess_point`
and the analyses' own: modes, stability, Campbell, ...) run under :func:`single_blas_thread`, so a
notebook or script that imports flexshaft without setting ``OPENBLAS_NUM_THREADS`` gets the
commands' speed: on the 2-core VM with the other core busy, a screening assessment of the tuned
design through the Python API took 0.77-2.8 s of CPU (medians of 7; up to 3 s for one call)
where one BLAS thread takes 0.35 s (benchmarks/README.md, 2026-12-05). Each entry costs about
10 µs (two calls into each loaded BLAS), and nested entries keep the limit.
"""

from __future__ import annotations

import functools
import threading
from collections.abc import Callable
from contextlib import nullcontext
from typing import Any, ParamSpec, TypeVar

__all__ = ["one_blas_thread", "single_blas_thread"]


_CONTROLLER: list[tuple[int, Any]] = []  # (libraries, the process's ThreadpoolController), found once
_FINDING = threading.Lock()  # one search of the loaded libraries at a time


def _controller(libraries: int):
    """A ThreadpoolController of the loaded BLAS libraries, found again only when the process
    has loaded more shared libraries since (finding them reads /proc: 0.5 ms a call, while the
    analyses enter this context a few hundred times a run).

    Only the main thread looks again. Finding the libraries walks them with ``dl_iterate_phdr``,
    which holds the dynamic loader's lock while it calls back into Python (and so waits for the
    GIL); a thread that holds the GIL and needs that lock (a first touch of a library's
    thread-local storage, a ``dlopen``) then waits for it: both stop for good. It stopped a Dask
    sweep on a threaded LocalCluster (``processes=False``) whose workers imported modules (the
    count changed) and built models at once. Other threads reuse the controller found before,
    which limits every BLAS loaded then (a BLAS loaded later, rare, keeps its own threads)."""
    with _FINDING:
        current = _CONTROLLER[0] if _CONTROLLER else None
        if current is not None and (
            current[0] == libraries or threading.current_thread() is not threading.main_thread()
        ):
            return current[1]
        from threadpoolctl import ThreadpoolController

        _CONTROLLER[:] = [(libraries, ThreadpoolController())]
        return _CONTROLLER[0][1]


def one_blas_thread():
    """Context manager limiting BLAS to one thread (a no-op without threadpoolctl)."""
    try:
        controller = _controller(_loaded_extensions())
    except ImportError:  # pragma: no cover - threadpoolctl is a dependency
        return nullcontext()
    return controller.limit(limits=1, user_api="blas")


def _loaded_extensions() -> int:
    """How many modules the process has imported: a new BLAS comes with a new extension module."""
    import sys

    return len(sys.modules)


_P = ParamSpec("_P")
_R = TypeVar("_R")


def single_blas_thread(func: Callable[_P, _R]) -> Callable[_P, _R]:
    """Run ``func`` with BLAS limited to one thread (the limit in place before is restored)."""

    @functools.wraps(func)
    def wrapper(*args: _P.args, **kwargs: _P.kwargs) -> _R:
        with one_blas_thread():
            return func(*args, **kwargs)

    return wrapper

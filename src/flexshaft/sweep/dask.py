"""A Dask scheduler address, checked before it is used, and a connection with a short timeout.

``run_sweep(..., client="tcp://host:8786")`` and the commands' ``--dask`` take an address. An
address that is not one (``garbage``) used to end in distributed's ``ValueError: missing port
number`` (an internal error of flexshaft), and an unreachable one (``tcp://127.0.0.1:9``) in an
``OSError`` after distributed's 30 s connect timeout, once the study was prepared. Here the form
is checked first (:func:`check_scheduler_address`, no import of Dask) and :func:`connect` gives
up after :data:`CONNECT_TIMEOUT`; both raise :class:`~flexshaft.sweep.study.SweepError` naming
the address and what is allowed.

On a worker, each chunk runs through :func:`evaluate_chunk_on_worker`, which first undoes
the small glibc trim threshold Dask's nanny gives every worker (:func:`worker_heap`: +53 % of
CPU on a Monte-Carlo chunk otherwise).
"""

from __future__ import annotations

import functools
import os
import re
from typing import Any

import numpy as np

from flexshaft.sweep.study import Study, SweepError, evaluate_chunk

__all__ = [
    "CONNECT_TIMEOUT",
    "HEAP_MMAP_THRESHOLD",
    "HEAP_TRIM_THRESHOLD",
    "PROTOCOLS",
    "check_scheduler_address",
    "connect",
    "evaluate_chunk_on_worker",
    "worker_heap",
]

#: Seconds to wait for a scheduler to answer (a scheduler on the network answers in well
#: under a second; distributed's own default waits 30 s).
CONNECT_TIMEOUT = 5.0
#: Protocols of a Dask scheduler address (distributed's communication back-ends).
PROTOCOLS = ("tcp", "tls", "ucx", "ws", "wss", "inproc")

_HOST = r"(?:\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9](?:[A-Za-z0-9._-]{0,252}[A-Za-z0-9])?)"
_ADDRESS = re.compile(rf"^(?:(?P<protocol>[a-z]+)://)?(?P<host>{_HOST}):(?P<port>[0-9]{{1,5}})$")


def _expected(name: str, address: Any) -> str:
    return (
        f"{name}: {address!r} is not a Dask scheduler address; expected PROTOCOL://HOST:PORT, e.g. "
        f"tcp://127.0.0.1:8786 (protocols: {', '.join(PROTOCOLS)}; port 1-65535)"
    )


def check_scheduler_address(address: Any, name: str = "client") -> str:
    """``address`` if it has the form of a scheduler address (``tcp://host:port``, ``host:port``
    for tcp, ``tls://``, ``ucx://``, ``ws://``, ``wss://``; ``inproc://`` as distributed writes it),
    else a :class:`SweepError` naming ``name``."""
    if not isinstance(address, str):
        raise SweepError(_expected(name, address))
    text = address.strip()
    if text.startswith("inproc://") and len(text) > len("inproc://"):
        return text
    match = _ADDRESS.match(text)
    if match is None or (match["protocol"] is not None and match["protocol"] not in PROTOCOLS):
        raise SweepError(_expected(name, address))
    if not 1 <= int(match["port"]) <= 65535:
        raise SweepError(_expected(name, address))
    return text


def connect(address: str, name: str = "client", timeout: float = CONNECT_TIMEOUT):
    """A ``dask.distributed.Client`` of the scheduler at ``address`` (checked first), or a
    :class:`SweepError` naming ``name`` when Dask is missing or no scheduler answers within
    ``timeout`` [s]."""
    address = check_scheduler_address(address, name)
    try:
        from distributed import Client
    except ImportError as exc:  # pragma: no cover - depends on the extra
        raise SweepError(f"{name}: the Dask backend needs the extra: pip install 'flexshaft[dask]'") from exc
    try:
        return Client(address, timeout=timeout)
    except (OSError, TimeoutError) as exc:
        raise SweepError(
            f"{name}: no Dask scheduler answers at {address} within {timeout:g} s ({type(exc).__name__}); start "
            "one there (dask scheduler) or give the address it prints"
        ) from exc


#: glibc's heap settings a Dask worker gets back (:func:`worker_heap`) [bytes]: arrays below
#: ``HEAP_MMAP_THRESHOLD`` come from the heap, which keeps up to ``HEAP_TRIM_THRESHOLD`` of freed
#: memory for the next allocation.
HEAP_MMAP_THRESHOLD = 32 * 2**20
HEAP_TRIM_THRESHOLD = 64 * 2**20
#: A ``MALLOC_TRIM_THRESHOLD_`` below this [bytes] is Dask's (its nanny starts every worker with
#: 65536, distributed's ``nanny.pre-spawn-environ``), not a setting chosen for this work.
_SMALL_TRIM = 2**20


@functools.cache
def worker_heap() -> str:
    """Give this process glibc's heap back if Dask's nanny started it with a small
    ``MALLOC_TRIM_THRESHOLD_`` (once per process); returns what was done.

    That variable makes glibc return freed memory at once and turns off its adaptive mmap
    threshold, so that every array above 128 kB is a fresh ``mmap`` and its pages fault in
    again on every use: a Monte-Carlo chunk took 0.21 s of CPU instead of 0.137 s (+53 %,
    benchmarks/dask_scaling.py). ``mallopt`` sets a 32 MiB mmap threshold and a 64 MiB trim
    threshold instead (measured: 0.137 s). Nothing is changed without the variable, with a
    larger value (the user's own choice) or without glibc.
    """
    value = os.environ.get("MALLOC_TRIM_THRESHOLD_")
    if value is None or not value.strip().isdigit() or int(value) >= _SMALL_TRIM:
        return "unchanged"
    try:
        import ctypes

        libc = ctypes.CDLL("libc.so.6")
        mmap_ok = libc.mallopt(-3, HEAP_MMAP_THRESHOLD)  # M_MMAP_THRESHOLD
        trim_ok = libc.mallopt(-1, HEAP_TRIM_THRESHOLD)  # M_TRIM_THRESHOLD
    except (OSError, AttributeError):  # not glibc (macOS, musl): nothing to undo
        return "unchanged (no glibc)"
    return "heap thresholds set" if mmap_ok == 1 and trim_ok == 1 else "unchanged (mallopt refused)"


def evaluate_chunk_on_worker(study: Study, start: int, stop: int, on_error: str = "raise") -> np.ndarray:
    """:func:`~flexshaft.sweep.study.evaluate_chunk` on a Dask worker, its heap set first
    (:func:`worker_heap`)."""
    worker_heap()
    return evaluate_chunk(study, start, stop, on_error)

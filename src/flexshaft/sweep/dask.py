"""A Dask scheduler address, checked before it is used, and a connection with a short timeout.

``run_sweep(..., client="tcp://host:8786")`` and the commands' ``--dask`` take an address. An
address that is not one (``garbage``) used to end in distributed's ``ValueError: missing port
number`` (an internal error of flexshaft), and an unreachable one (``tcp://127.0.0.1:9``) in an
``OSError`` after distributed's 30 s connect timeout, once the study was prepared. Here the form
is checked first (:func:`check_scheduler_address`, no import of Dask) and :func:`connect` gives
up after :data:`CONNECT_TIMEOUT`; both raise :class:`~flexshaft.sweep.study.SweepError` naming
the address and what is allowed.
"""

from __future__ import annotations

import re
from typing import Any

from flexshaft.sweep.study import SweepError

__all__ = ["CONNECT_TIMEOUT", "PROTOCOLS", "check_scheduler_address", "connect"]

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

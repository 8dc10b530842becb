"""Start the explorer: its workers, then the local web server (uvicorn) on a free port.

:func:`serve` forks the worker processes first (no thread runs yet), binds the socket (port 0:
a free port chosen by the system), prints the page's address and serves until Ctrl-C.
"""

from __future__ import annotations

import ipaddress
import socket
import sys
from pathlib import Path

from flexshaft.cli.common import LoadedDesign, fail
from flexshaft.explore.pareto import Front
from flexshaft.explore.server import Explorer, build_app
from flexshaft.explore.workers import Workers

__all__ = ["is_local", "open_socket", "serve"]


def is_local(host: str) -> bool:
    """Whether ``host`` is a loopback address or ``localhost`` (reachable from this machine only)."""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def open_socket(host: str, port: int) -> socket.socket:
    """A listening TCP socket on ``host``:``port`` (0: a free port), refused as a user error."""
    try:
        infos = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)
    except socket.gaierror as exc:
        fail(f"--host: cannot resolve {host!r} ({exc.strerror})")
    family, _, _, _, address = infos[0]
    sock = socket.socket(family, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        sock.bind(address)
    except OSError as exc:
        sock.close()
        fail(f"--port: cannot listen on {host}:{port} ({exc.strerror}); choose another port or 0 for a free one")
    sock.listen(64)
    sock.set_inheritable(True)
    return sock


def _url(host: str, port: int) -> str:
    shown = f"[{host}]" if ":" in host else host
    return f"http://{shown}:{port}/"


def serve(
    loaded: LoadedDesign,
    *,
    host: str = "127.0.0.1",
    port: int = 0,
    front: Front | None = None,
    out: Path = Path("flexshaft-explore"),
    studies: str = "report",
    processes: int | None = None,
) -> None:
    """Serve the explorer of ``loaded`` until interrupted (see the module docstring); ``front``
    the Pareto front of an optimizer run (:func:`~flexshaft.explore.pareto.read_front`, read by
    the command before, so that a refusal names ``--pareto``)."""
    import uvicorn  # the extra flexshaft[explore]; checked by the command before

    if not is_local(host):
        print(
            f"warning: --host {host} is not a loopback address: anyone who can reach this machine on the "
            "network can use the explorer (it has no login) and run analyses on it",
            file=sys.stderr,
        )
    sock = open_socket(host, port)
    workers = Workers(processes)  # forks now, before uvicorn starts any thread
    bound = sock.getsockname()[1]
    hosts = ["127.0.0.1", "localhost", "[::1]", "::1", host]
    explorer = Explorer(loaded, workers, front=front, out=out, studies=studies)
    app = build_app(explorer, hosts)
    config = uvicorn.Config(app, log_level="warning", access_log=False, lifespan="off")
    server = uvicorn.Server(config)
    print(f"flexshaft explore: {_url(host, bound)}  (design: {loaded.design.name}; Ctrl-C to stop)", flush=True)
    try:
        server.run(sockets=[sock])
    finally:
        workers.close()
        sock.close()

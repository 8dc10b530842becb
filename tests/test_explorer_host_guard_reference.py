"""The explorer answers requests addressed to itself only: its names, or the address reached.

docs/explorer.md: "It listens on this machine only; `--host 0.0.0.0` (or any address that is
not a loopback) makes it reachable from the network"; "It answers requests addressed to its own
names (the loopback names, `--host`) or to the very address a connection arrived on ... and
refuses any other host name with 400: a page of another site cannot reach it through DNS
rebinding" (the second added with this test, stating the rule it checks). A rebinding
page points its own name at this machine, so the browser's ``Host`` header carries that name:
it must be refused (RFC 9110 §15.5.1: 400 Bad Request). A browser on the network that opens
``http://192.168.1.10:port/`` of a server listening on every interface sends ``Host:
192.168.1.10:port``, the address its connection arrived on (the ASGI scope's ``server``,
the socket's local address): it must be answered. Before, the list of names held only the
loopback names and ``--host`` itself (0.0.0.0, which no browser sends), so the documented
``--host 0.0.0.0`` answered nobody on the network.

One request straight to the ASGI application (no server, no worker, a few ms), on the
``/favicon.ico`` route, which answers 204 No Content.
"""

from __future__ import annotations

import asyncio

import pytest

pytest.importorskip("starlette")

from flexshaft.explore.server import build_app

LOOPBACK = ["127.0.0.1", "localhost", "[::1]", "::1"]


def _status(hosts: list[str], host_header: str, local: str) -> int:
    app = build_app(explorer=None, hosts=hosts)  # the icon route reads no state
    scope = {
        "type": "http",
        "asgi": {"version": "3.0"},
        "http_version": "1.1",
        "method": "GET",
        "scheme": "http",
        "path": "/favicon.ico",
        "raw_path": b"/favicon.ico",
        "root_path": "",
        "query_string": b"",
        "headers": [(b"host", host_header.encode())],
        "client": ("192.168.1.20", 50000),
        "server": (local, 8000),
    }
    status: list[int] = []

    async def receive():
        return {"type": "http.request", "body": b"", "more_body": False}

    async def send(message):
        if message["type"] == "http.response.start":
            status.append(message["status"])

    asyncio.run(app(scope, receive, send))
    return status[0]


def test_a_loopback_server_answers_its_names_and_refuses_a_rebound_name():
    hosts = [*LOOPBACK, "127.0.0.1"]
    assert _status(hosts, "127.0.0.1:8000", "127.0.0.1") == 204
    assert _status(hosts, "localhost:8000", "127.0.0.1") == 204
    assert _status(hosts, "[::1]:8000", "::1") == 204
    assert _status(hosts, "attacker.example:8000", "127.0.0.1") == 400  # rebound to 127.0.0.1


def test_a_server_on_every_interface_answers_the_address_a_browser_reached():
    hosts = [*LOOPBACK, "0.0.0.0"]
    assert _status(hosts, "192.168.1.10:8000", "192.168.1.10") == 204
    assert _status(hosts, "attacker.example:8000", "192.168.1.10") == 400
    assert _status(hosts, "192.168.1.11:8000", "192.168.1.10") == 400  # not the address reached


def test_an_ipv4_browser_of_a_server_listening_on_every_ipv6_and_ipv4_interface():
    """With --host :: (dual stack), an IPv4 connection arrives on the IPv4-mapped address
    ::ffff:192.168.1.10 (RFC 4291 §2.5.5.2) while the browser sends Host: 192.168.1.10."""
    hosts = [*LOOPBACK, "::"]
    assert _status(hosts, "192.168.1.10:8000", "::ffff:192.168.1.10") == 204
    assert _status(hosts, "[fe80::1]:8000", "fe80::1") == 204
    assert _status(hosts, "attacker.example:8000", "::ffff:192.168.1.10") == 400

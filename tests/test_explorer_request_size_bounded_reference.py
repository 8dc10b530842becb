"""The explorer's API bounds a request's size before it holds the body (explore/server.py).

docs/explorer.md and the project's rule "every command bounds its work before computing": a
request body over the API's limit (2 × MAX_UPLOAD bytes) is refused without being read in
whole. Before, the server read the whole body into memory and only then compared its length
(hunter h108a's note). References (HTTP semantics, RFC 9110 §8.6: Content-Length is the
body's size in octets; a body without it arrives in chunks until the last):

* a declared Content-Length over the limit is refused before any of the body is received;
* a body without Content-Length, sent in 64 KiB chunks, is refused once the chunks received
  pass the limit: at most ⌈(limit + 1)/65536⌉ chunks are taken, not all 40 of a 2.6 MB body;
* a body under the limit is read whole (the refusal is then about its content, not its size).

The app runs in-process on a recording worker pool (tests/test_explorer_request_reference.py)
through a raw ASGI driver that counts the body messages the app takes; no analysis runs.
"""

from __future__ import annotations

import asyncio
import json
import math

import pytest

from flexshaft.explore.server import MAX_UPLOAD
from tests.test_explorer_api_reference import HOST, tuned  # noqa: F401 (fixture)
from tests.test_explorer_request_reference import recording_app

LIMIT = 2 * MAX_UPLOAD
CHUNK = 65536


@pytest.fixture()
def app(tuned, tmp_path):  # noqa: F811 (the imported fixture)
    """The explorer on a recording worker pool (nothing computed)."""
    return recording_app(tuned, tmp_path)


def _post(explorer, chunks: list[bytes], content_length: int | None):
    """POST /api/update with ``chunks`` as the body to the fixture's app; returns (status,
    answer, chunks taken)."""
    app = explorer.client.app
    headers = [(b"host", HOST.encode()), (b"content-type", b"application/json")]
    if content_length is not None:
        headers.append((b"content-length", str(content_length).encode()))
    scope = {
        "type": "http",
        "asgi": {"version": "3.0"},
        "http_version": "1.1",
        "method": "POST",
        "scheme": "http",
        "path": "/api/update",
        "raw_path": b"/api/update",
        "root_path": "",
        "query_string": b"",
        "headers": headers,
        "client": ("127.0.0.1", 50000),
        "server": (HOST, 8000),
    }
    taken = 0
    status, body = 0, b""

    async def receive():
        nonlocal taken
        if taken < len(chunks):
            taken += 1
            return {"type": "http.request", "body": chunks[taken - 1], "more_body": taken < len(chunks)}
        await asyncio.Event().wait()

    async def send(message):
        nonlocal status, body
        if message["type"] == "http.response.start":
            status = message["status"]
        elif message["type"] == "http.response.body":
            body += message.get("body", b"")

    asyncio.run(asyncio.wait_for(app(scope, receive, send), timeout=60))
    return status, body.decode("utf-8", "replace"), taken


def _big(n_chunks: int) -> list[bytes]:
    return [b" " * CHUNK for _ in range(n_chunks)]


def test_a_declared_length_over_the_limit_is_refused_unread(app):
    chunks = _big(40)  # 2.6 MB > 2 MB
    status, answer, taken = _post(app, chunks, content_length=sum(map(len, chunks)))
    assert 400 <= status < 500 and "request too large" in answer and f"at most {LIMIT} bytes" in answer
    assert taken == 0


def test_a_body_without_a_length_is_read_only_up_to_the_limit(app):
    status, answer, taken = _post(app, _big(40), content_length=None)
    assert 400 <= status < 500 and "request too large" in answer
    assert taken == math.ceil((LIMIT + 1) / CHUNK) < 40


def test_a_body_under_the_limit_is_read_whole(app):
    text = json.dumps({"base": "no such base"}).encode()
    pieces = [text[:5], text[5:]]
    status, answer, taken = _post(app, pieces, content_length=None)
    assert taken == 2 and 400 <= status < 500
    assert "too large" not in answer and "base" in answer

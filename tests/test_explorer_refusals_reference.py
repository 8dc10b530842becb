"""The explorer's refusals of malformed requests (a body or table of the wrong JSON type, an
unknown base, a Pareto point without a front, an upload over its byte limit, a non-finite
sequence number), the name of its exported file, and ``flexshaft --version``'s exit code.

The application is called in-process through the ASGI client of
``tests/test_explorer_api_reference.py`` (imported, with its fixtures and its stand-in worker
pool of ``tests/test_explorer_request_reference.py``, which records the designs it would assess
and answers an update with the design's layup), so each request costs milliseconds. Under that
client an exception of a route is not turned into a 500 answer but raised out of the request:
a malformed request that the server does not refuse fails these tests either way. References,
all rules written by hand:

* HTTP semantics (RFC 9110 §15.5, "The 4xx (Client Error) class of status code indicates that
  the client seems to have erred"): a request the server cannot take is refused with a 4xx, not
  a server error; the server's docstring: "validate the base with the page's overrides through
  the schema (its message, naming the field, when refused)", and "the API takes JSON only";
* the upload's own refusal: "expected a design file of at most 1000000 bytes" counts bytes, and
  UTF-8 (RFC 3629 §3's table: U+0080 to U+07FF take two octets, ``110xxxxx 10xxxxxx``) encodes
  "é" (U+00E9) in two bytes;
* RFC 8259 §6: "Numeric values that cannot be represented in the grammar below (such as
  Infinity and NaN) are not permitted" (so an answer carries no infinite ``seq``);
* the GNU C Library manual, "Argument Syntax" (read in a mirror of the manual,
  aren.cs.ui.ac.id/sda/archive/resources/contest/OnlineJudge/gnudoc/libc/Argument_Syntax.html):
  "Arguments are options if they begin with a hyphen delimiter (`-')." (so the file name in the
  ``flexshaft run`` command the export shows must not begin with '-');
* docs/explorer.md's options table: "`--pareto FOLDER` | a `flexshaft optimize` run folder: its
  Pareto front on the page" (without it there is no front to take a point of);
* flexshaft.cli's docstring: "Exit codes: 0 success"; README.md lists ``flexshaft --version``.
"""

from __future__ import annotations

import json
import re
import shlex

import pytest

from flexshaft.design import embedded_text

pytest.importorskip("starlette")

from flexshaft.explore.server import MAX_UPLOAD
from tests.test_explorer_api_reference import HOST, Client, tuned  # noqa: F401 (fixture)
from tests.test_explorer_request_reference import recording_app


@pytest.fixture()
def app(tuned, tmp_path):  # noqa: F811 (the imported fixture)
    return recording_app(tuned, tmp_path)


def _refused(answer, path: str) -> list[str]:
    """The refusal's messages, after checking that it is a client error naming ``path``."""
    assert 400 <= answer.status_code < 500, (answer.status_code, answer.text)
    problems = answer.json()["problems"]
    assert [p["path"] for p in problems] == [path]
    return [p["message"] for p in problems]


def test_an_upload_over_the_byte_limit_is_refused_before_it_is_parsed(app):
    """A valid design file (the tuned one) behind 5,000 comment lines of 100 "é": 515,000
    characters more, but 2 bytes per "é" (RFC 3629), so 5,000 × 203 = 1,015,000 bytes more
    than the file, over the 1,000,000 bytes the refusal names. It is refused 4xx naming the
    file; the same file without the comment lines loads (200), so the refusal is the size's.
    The body is sent as UTF-8 (json.dumps(ensure_ascii=False)), about 1.02 MB, under the
    request's own 2 MB limit."""
    text = embedded_text("tuned")
    comments = ("# " + "é" * 100 + "\n") * 5000
    assert len(comments) < MAX_UPLOAD < len(comments.encode("utf-8")) == 5000 * 203
    body = json.dumps({"text": comments + text, "filename": "big.toml"}, ensure_ascii=False).encode("utf-8")
    assert len(body) < 2 * MAX_UPLOAD
    (message,) = _refused(app.client.request("POST", "/api/load", body, "application/json"), "big.toml")
    assert f"at most {MAX_UPLOAD} bytes" in message
    answer = app.client.post("/api/load", json={"text": text, "filename": "small.toml"})
    assert answer.status_code == 200, answer.text


@pytest.mark.parametrize("route", ["/api/update", "/api/sweep", "/api/export", "/api/load", "/api/run"])
def test_a_body_that_is_not_a_json_object_is_a_client_error(app, route):
    """A JSON array (valid JSON, not an object) to each POST route: refused 4xx (RFC 9110
    §15.5), the problem on the request itself, nothing computed."""
    (message,) = _refused(app.client.request("POST", route, b"[1, 2]", "application/json"), "<request>")
    assert "object" in message
    assert app.workers.calls == []


def test_a_non_finite_seq_is_no_server_error(app):
    """An update whose ``seq`` is 1e999 (JSON's grammar has it; Python reads it as inf) is
    answered 200 with the design's results, and its answer is strict JSON (RFC 8259 §6: no
    Infinity): the seq answered is a finite integer."""

    def no_constants(name):
        raise AssertionError(f"the answer carries {name}, not JSON")

    body = b'{"overrides": {"shaft.wall_thickness": 0.003}, "seq": 1e999, "session": "p"}'
    answer = app.client.request("POST", "/api/update", body, "application/json")
    assert answer.status_code == 200, answer.text
    data = json.loads(answer.body, parse_constant=no_constants)
    assert isinstance(data["seq"], int)
    assert data["results"] == {"layup": "(60/-60/60/-60/0/0)s"}  # the tuned design's (its file)


def test_an_unknown_base_is_a_client_error_naming_base(app):
    """A base the server does not hold (an upload key of an earlier server, say): every route
    that takes a base refuses it 4xx naming the field ``base`` (the server's docstring: "its
    message, naming the field, when refused"); nothing is computed."""
    for route in ("/api/update", "/api/sweep", "/api/export", "/api/run"):
        body = {"base": "upload-000000000000", "control": "shaft.wall_thickness", "values": [0.002, 0.003]}
        _refused(app.client.post(route, json=body), "base")
    assert app.workers.calls == []


@pytest.mark.parametrize("name", ["(A) shaft", "-- draft 2", "#7 / hot day"])
def test_the_exported_files_name_is_no_option(app, name):
    """A design whose name begins with characters other than letters and digits: the exported
    file's name, and the file argument of the ``flexshaft run`` command shown with it, do not
    begin with '-' (GNU libc manual: "Arguments are options if they begin with a hyphen
    delimiter"), and keep the name's words."""
    text = re.sub(r'^name = ".*"$', f"name = {json.dumps(name)}", embedded_text("tuned"), count=1, flags=re.M)
    key = app.client.post("/api/load", json={"text": text, "filename": "named.toml"}).json()["base"]
    answer = app.client.post("/api/export", json={"base": key})
    assert answer.status_code == 200, answer.text
    data = answer.json()
    assert not data["filename"].startswith("-")
    assert data["filename"].endswith("-explored.toml")
    words = re.findall(r"[a-z0-9]+", name.lower())
    assert re.findall(r"[a-z0-9]+", data["filename"].removesuffix("-explored.toml")) == words
    argv = shlex.split(data["command"])
    assert argv[:3] == ["flexshaft", "run", data["filename"]]


def test_version_exits_0():
    """``flexshaft --version`` prints ``flexshaft <version>`` and exits 0 (flexshaft.cli's
    docstring: "Exit codes: 0 success"), without a command (the option is eager)."""
    from typer.testing import CliRunner

    from flexshaft.cli import app

    result = CliRunner().invoke(app, ["--version"])
    assert result.exit_code == 0, result.output
    assert re.fullmatch(r"flexshaft \d+(\.\d+)*\S*\n", result.output)


@pytest.mark.parametrize("field", ["overrides", "edits", "advanced"])
def test_a_table_given_as_a_list_is_a_client_error_naming_it(app, field):
    """The overrides, the controls' edits and the advanced paths are tables of path -> value; a
    JSON list in their place is refused 4xx naming the field (the server's docstring), and an
    empty table is no refusal (the base design itself is computed)."""
    body = {field: [["shaft.wall_thickness", 0.003]], "seq": 1, "session": field}
    _refused(app.client.post("/api/update", json=body), field)
    assert app.workers.calls == []
    answer = app.client.post("/api/update", json={field: {}, "seq": 2, "session": field})
    assert answer.status_code == 200, answer.text


@pytest.mark.parametrize("index", [None, 0, 3])
def test_a_pareto_point_without_a_front_is_a_client_error(app, index):
    """An explorer started without ``--pareto`` holds no front (docs/explorer.md: "`--pareto
    FOLDER` | a `flexshaft optimize` run folder: its Pareto front on the page"): asking for a
    point, with or without an index, is refused 4xx naming ``pareto``, the message saying
    which option gives one."""
    body = {} if index is None else {"index": index}
    (message,) = _refused(app.client.post("/api/pareto", json=body), "pareto")
    assert "--pareto" in message

"""The explorer's JSON API and its page sessions, without a browser and without an assessment.

The Starlette application (:func:`flexshaft.explore.server.build_app`) is called as the ASGI
application it is (one HTTP request, as uvicorn hands it over; httpx, which Starlette's
``TestClient`` needs, is not a dependency of the extra); the worker pool is replaced by a stand-in that records what the
server would compute (which base design, which overrides) instead of computing it, so each test
costs milliseconds. References, all rules written by hand:

* docs/explorer.md: a sweep takes "2 to 41 points"; *Open a design file* "loads a file ... as
  the new base"; a value the schema refuses comes back with "its message, naming the field";
  the full run goes "through ``flexshaft run``'s own pipeline" with the ``--studies`` option
  "as ``flexshaft run``"; "a request still waiting when a newer one of the same page arrives is
  answered 'superseded' without being computed";
* HTTP semantics (RFC 9110 §15.5): a request refused for its content is a client error, a
  4xx status, never 200 OK; a file that is not served is 404 Not Found;
* API contract (docstring of flexshaft.explore.server; no docs page states it):
  ``GET /runs/<id>/<file>``: "its report", the full run's; derived here: a route serving one
  run's report must not serve files outside its folder (path traversal, CWE-22);
* API contract (docstring of flexshaft.explore.workers.Sessions; no docs page states it): "The
  open pages by id (the oldest forgotten beyond :data:`MAX_SESSIONS`)";
* API contract (set_relay's and full_run's docstrings; no docs page states them): the relay
  queue takes ``put((job, label, seconds))``, and full_run "returns the verdict and the page's
  path" (read here as the page's file name in the run folder, the ``<file>`` of
  ``GET /runs/<id>/<file>``, with the verdict's pass/fail and each check's status).
"""

from __future__ import annotations

import asyncio
import json
import re
import types
from pathlib import Path

import pytest

from flexshaft.cli.common import LoadedDesign
from flexshaft.cli.options import Studies
from flexshaft.design import embedded_text, loads_design, tuned_design

pytest.importorskip("starlette")

from flexshaft.explore import fullrun
from flexshaft.explore.server import MAX_SWEEP_POINTS, Explorer, build_app
from flexshaft.explore.workers import MAX_SESSIONS, Job, Session, Sessions

HOST = "127.0.0.1"


class Answer(types.SimpleNamespace):
    status_code: int
    body: bytes

    @property
    def text(self) -> str:
        return self.body.decode()

    def json(self):
        return json.loads(self.body)


class Client:
    """One HTTP/1.1 request at a time to an ASGI application, with a ``Host`` header of HOST."""

    def __init__(self, app) -> None:
        self.app = app

    def request(self, method: str, path: str, body: bytes = b"", content_type: str | None = None) -> Answer:
        from urllib.parse import unquote

        headers = [(b"host", HOST.encode())]
        if content_type is not None:
            headers.append((b"content-type", content_type.encode()))
        headers.append((b"content-length", str(len(body)).encode()))
        scope = {
            "type": "http",
            "asgi": {"version": "3.0"},
            "http_version": "1.1",
            "method": method,
            "scheme": "http",
            "path": unquote(path),
            "raw_path": path.encode(),
            "root_path": "",
            "query_string": b"",
            "headers": headers,
            "client": ("127.0.0.1", 50000),
            "server": (HOST, 8000),
        }
        sent = [{"type": "http.request", "body": body, "more_body": False}]
        answer = Answer(status_code=0, body=b"")

        async def receive():  # the body, then nothing: the client stays until the answer ends
            if sent:
                return sent.pop(0)
            await asyncio.Event().wait()

        async def send(message):
            if message["type"] == "http.response.start":
                answer.status_code = message["status"]
            elif message["type"] == "http.response.body":
                answer.body += message.get("body", b"")

        asyncio.run(self.app(scope, receive, send))
        return answer

    def get(self, path: str) -> Answer:
        return self.request("GET", path)

    def post(self, path: str, json=None, content: bytes | None = None, headers: dict | None = None) -> Answer:
        if json is not None:
            return self.request("POST", path, _dumps(json), "application/json")
        return self.request("POST", path, content or b"", (headers or {}).get("Content-Type"))


def _dumps(data) -> bytes:
    return json.dumps(data).encode()


class StandInWorkers:
    """The worker pool's interface as the server uses it; ``run`` records its call and returns
    the overrides of the point instead of assessing it."""

    processes = 2

    def __init__(self) -> None:
        self.jobs: dict[str, Job] = {}
        self.calls: list[tuple] = []

    async def run(self, function, *args):
        self.calls.append(args)
        return {"overrides": args[-1]}

    def start_job(self, job, function, *args) -> None:
        self.jobs[job.id] = job


@pytest.fixture(scope="module")
def tuned():
    return tuned_design()


@pytest.fixture()
def app(tuned, tmp_path):
    workers = StandInWorkers()
    explorer = Explorer(LoadedDesign(tuned, embedded_text("tuned"), "tuned"), workers, out=tmp_path / "runs")
    client = Client(build_app(explorer, [HOST]))
    return types.SimpleNamespace(client=client, workers=workers, explorer=explorer)


def test_a_sweep_takes_two_to_41_points(app):
    """docs/explorer.md: "2 to 41 points". 41 values give 41 points computed, each the control's
    value as its override; 42 values and 1 value are refused (a 4xx naming ``values``) with
    nothing computed."""
    assert MAX_SWEEP_POINTS == 41  # the documented limit, so that the numbers below are the docs'
    values = [1e5 * (1 + i) for i in range(41)]
    answer = app.client.post("/api/sweep", json={"control": "bearings[1].kp", "values": values})
    assert answer.status_code == 200
    assert [p["overrides"]["bearings[1].kp"] for p in answer.json()["points"]] == values
    assert len(app.workers.calls) == 41
    for bad in ([*values, 4.3e6], [2e5]):
        answer = app.client.post("/api/sweep", json={"control": "bearings[1].kp", "values": bad})
        assert 400 <= answer.status_code < 500
        assert [p["path"] for p in answer.json()["problems"]] == ["values"]
    assert len(app.workers.calls) == 41


def test_a_loaded_file_is_the_base_of_the_next_requests(app, tuned):
    """docs/explorer.md: *Open a design file* loads a file as the new base. A file differing from
    the command's design in its name and the first actuator's K_p (3e5 N/m, the command's
    5e5): a sweep on the new base assesses points of that design, and its export writes it back
    (loaded again, the same name and K_p: the export with no overrides is the loaded
    design)."""
    text = embedded_text("tuned")
    text = text.replace(f'name = "{tuned.name}"', 'name = "Loaded base"', 1)
    text = re.sub(r"(?m)^kp = 5\.0e5", "kp = 3.0e5", text, count=1)
    loaded = loads_design(text)
    assert loaded.name == "Loaded base" and loaded.bearings[1].kp == 3e5 and tuned.bearings[1].kp == 5e5

    answer = app.client.post("/api/load", json={"text": text, "filename": "loaded.toml"})
    assert answer.status_code == 200
    key = answer.json()["base"]
    assert answer.json()["base_name"] == "Loaded base"

    answer = app.client.post("/api/sweep", json={"base": key, "control": "operating.speed_rpm", "values": [4000, 4500]})
    assert answer.status_code == 200
    bases = [args[0] for args in app.workers.calls]
    assert [b.name for b in bases] == ["Loaded base", "Loaded base"]
    assert all(b.bearings[1].kp == 3e5 for b in bases)

    answer = app.client.post("/api/export", json={"base": key, "overrides": {}})
    assert answer.status_code == 200
    back = loads_design(answer.json()["text"])
    assert back.name == "Loaded base" and back.bearings[1].kp == 3e5


def test_a_refused_value_is_a_client_error_naming_the_field(app):
    """docs/explorer.md's example: a 60 mm wall on the 101.6 mm tube is refused, its message
    naming ``shaft.wall_thickness``; RFC 9110: a refusal is a 4xx, not 200. A body that is not
    JSON is refused the same way, before anything is computed."""
    answer = app.client.post("/api/update", json={"overrides": {"shaft.wall_thickness": 0.06}})
    assert 400 <= answer.status_code < 500
    assert [p["path"] for p in answer.json()["problems"]] == ["shaft.wall_thickness"]
    answer = app.client.post("/api/export", content=b"wall = 60", headers={"Content-Type": "text/plain"})
    assert 400 <= answer.status_code < 500
    answer = app.client.post("/api/sweep", json={"overrides": {"shaft.wall_thickness": 0.06}, "values": [1, 2]})
    assert 400 <= answer.status_code < 500
    assert app.workers.calls == []


def test_a_runs_files_are_served_from_its_folder_only(app, tmp_path):
    """A finished run serves the files of its folder (200, their bytes); a link inside the
    folder to a file outside it, and a path climbing out with ``..``, are 404 Not Found
    (derived here: no path traversal, CWE-22; RFC 9110's 404 for a file not served)."""
    folder = tmp_path / "runs" / "run-001"
    folder.mkdir(parents=True)
    (folder / "report.html").write_text("<p>report</p>", encoding="utf-8")
    secret = tmp_path / "secret.txt"
    secret.write_text("outside the run", encoding="utf-8")
    try:
        (folder / "link.txt").symlink_to(secret)
    except OSError:  # Windows without the symlink privilege
        pytest.skip("symbolic links cannot be created here")
    app.workers.jobs["001"] = Job("001", str(folder), state="done")

    answer = app.client.get("/runs/001/report.html")
    assert answer.status_code == 200 and answer.text == "<p>report</p>"
    assert app.client.get("/runs/001/link.txt").status_code == 404
    assert app.client.get("/runs/001/..%2F..%2Fsecret.txt").status_code == 404
    assert app.client.get("/runs/002/report.html").status_code == 404  # no such run


def test_a_stale_request_waiting_behind_a_newer_one_is_superseded():
    """docs/explorer.md: one assessment at a time per page; a request still waiting when a newer
    one of the same page arrives is answered superseded without being computed. Request 1 runs;
    request 3 arrives, then request 2 (late, its connection slower): when 1 finishes, 3 is
    computed and 2, older than 3, is answered None (superseded) and never computed."""

    async def scenario():
        session = Session(None)
        release = asyncio.Event()
        computed = []

        def compute(seq):
            async def run():
                if seq == 1:
                    await release.wait()
                computed.append(seq)
                return seq

            return run

        first = asyncio.create_task(session.update(1, compute(1)))
        await asyncio.sleep(0)
        third = asyncio.create_task(session.update(3, compute(3)))
        await asyncio.sleep(0)
        second = asyncio.create_task(session.update(2, compute(2)))
        await asyncio.sleep(0)
        release.set()
        results = [await first, await second, await third]
        return [r if r is None else r[0] for r in results], computed

    results, computed = asyncio.run(scenario())
    assert results == [1, None, 3]
    assert computed == [1, 3]


def test_the_oldest_page_is_forgotten_not_the_newest():
    """API contract (docstring of flexshaft.explore.workers.Sessions; no docs page states it):
    the oldest page forgotten beyond MAX_SESSIONS. After MAX_SESSIONS pages, one more
    page keeps its session (the same one on its next request, with its latest request number),
    and the first page, the oldest, gets a fresh one."""
    sessions = Sessions(None)
    first = sessions.get("page-0")
    for i in range(1, MAX_SESSIONS):
        sessions.get(f"page-{i}")
    newest = sessions.get("page-new")
    newest.latest = 7
    assert sessions.get("page-new") is newest and sessions.get("page-new").latest == 7
    assert sessions.get("page-0") is not first


def test_a_full_run_is_flexshaft_runs_pipeline_with_the_studies_asked(tmp_path, monkeypatch, tuned):
    """docs/explorer.md: the full run goes through ``run_pipeline`` with ``--studies`` as
    ``flexshaft run``'s. A stand-in pipeline records its arguments and returns a verdict of two
    checks: the studies it receives are the ones asked (the documented rule). API contract
    (set_relay's and full_run's docstrings; no docs page states it): the run relays each stage
    to the server's queue as (run id, label, seconds) and returns the page's file name, the
    verdict and each check's status."""
    seen = {}
    sent = []

    def pipeline(loaded, folder, progress, *, studies, interactive):
        seen.update(design=loaded.design, folder=folder, studies=studies, source=loaded.source)
        with progress:
            progress.step("modes")
        checks = [types.SimpleNamespace(key="orbit", status="pass"), types.SimpleNamespace(key="whirl", status="fail")]
        verdict = types.SimpleNamespace(passed=False, summary="FAIL: whirl", checks=checks)
        return types.SimpleNamespace(verdict=verdict), folder / "interactive.html", None

    monkeypatch.setattr(fullrun, "run_pipeline", pipeline)
    monkeypatch.setattr(fullrun, "_RELAY", types.SimpleNamespace(put=sent.append))
    for studies in ("none", "full", "report"):
        seen.clear()
        sent.clear()
        result = fullrun.full_run("007", tuned, None, "x.toml", str(tmp_path), studies)
        assert seen["studies"] == Studies(studies)
        assert seen["design"] is tuned and seen["folder"] == Path(tmp_path) and seen["source"] == "x.toml"
        assert [m[:2] for m in sent] == [("007", "modes")]  # API contract (set_relay's docstring)
        assert result["page"] == "interactive.html" and result["passed"] is False  # API contract (full_run's)
        assert result["status"] == {"orbit": "pass", "whirl": "fail"}  # API contract (full_run's)

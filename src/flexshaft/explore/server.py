"""The explorer's web application: one page, a small JSON API, and the local server.

Starlette routes (served by uvicorn, :func:`serve`):

* ``GET /``: the page; ``GET /static/...``: its script, style and plotly.js (the file the
  ``plotly`` wheel ships), all local: the page loads nothing from the network;
* ``GET /api/init``: the base design, its controls (bounds from the schema), the Pareto front;
* ``POST /api/update``: validate the base with the page's overrides through the schema (its
  message, naming the field, when refused), then assess it in the page's worker session;
* ``POST /api/sweep``: one variable over a range, every check's normalised margin;
* ``POST /api/export``: the design file; ``POST /api/load``: a design file as the new base;
* ``POST /api/pareto``: a Pareto point's design; ``POST /api/run``, ``GET /api/run/<id>``: a full
  run through ``flexshaft run``'s pipeline and its progress; ``GET /runs/<id>/<file>``: its report.

Only requests for the server's own host name are answered (a page of another site cannot reach
it through DNS rebinding), and the API takes JSON only.
"""

from __future__ import annotations

import asyncio
import dataclasses
import hashlib
import ipaddress
import itertools
import json
import math
import time
from importlib import resources
from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.middleware import Middleware
from starlette.requests import Request
from starlette.responses import FileResponse, HTMLResponse, JSONResponse, Response
from starlette.routing import Route

from flexshaft.cli.common import LoadedDesign, UserError, refuse_imbalance_cases
from flexshaft.cli.output import prepare_output_folder
from flexshaft.design import Design, DesignError, loads_design, with_overrides
from flexshaft.explore.compute import EXPLORE, sweep_point, update_on
from flexshaft.explore.controls import advanced_overrides, control_overrides, design_controls
from flexshaft.explore.export import explored_toml, run_command
from flexshaft.explore.fullrun import full_run
from flexshaft.explore.pareto import Front, front_design
from flexshaft.explore.workers import Job, Sessions, Workers
from flexshaft.report.interactive_page import plotly_js_path

__all__ = ["Base", "Explorer", "build_app"]

#: Points of a sweep at most (each a screening assessment).
MAX_SWEEP_POINTS = 41
#: Size of a design file the page may load [bytes] (as the CLI's).
MAX_UPLOAD = 1_000_000
_CSP = (
    "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:; "
    "connect-src 'self'; object-src 'none'; base-uri 'none'; frame-ancestors 'none'"
)


@dataclasses.dataclass(frozen=True)
class Base:
    """A design the page starts from: the design, its file text and where it came from."""

    design: Design
    text: str | None
    source: str


class Explorer:
    """The state of one explorer server: its bases, workers, sessions and full runs."""

    def __init__(
        self,
        loaded: LoadedDesign,
        workers: Workers,
        *,
        front: Front | None = None,
        out: Path = Path("flexshaft-explore"),
        studies: str = "report",
    ) -> None:
        self.bases: dict[str, Base] = {"file": Base(loaded.design, loaded.text, loaded.source)}
        if front is not None:
            self.bases["pareto"] = Base(front.base, None, f"{front.folder} (optimizer base)")
        self.front = front
        self.workers = workers
        self.sessions = Sessions(workers)
        self.out = Path(out)
        self.studies = studies
        self._counter = itertools.count(1)

    # -- designs ------------------------------------------------------------------------------
    def base(self, key: Any) -> Base:
        base = self.bases.get(str(key))
        if base is None:
            raise DesignError([_problem("base", f"no such base design (got {key!r})")], "<explorer>")
        return base

    def design(self, body: dict) -> tuple[Base, Design, dict]:
        """The base of a request, the design of its overrides and edits, and the overrides.

        Raises DesignError (the schema's problems, each with its field path)."""
        base = self.base(body.get("base", "file"))
        overrides = _mapping(body.get("overrides"), "overrides")
        design = with_overrides(base.design, overrides)
        edits = _mapping(body.get("edits"), "edits")
        advanced = _mapping(body.get("advanced"), "advanced")
        if edits or advanced:
            overrides = {**overrides, **control_overrides(design, edits), **advanced_overrides(advanced)}
            design = with_overrides(base.design, overrides)
        return base, design, overrides

    def add_base(self, base: Base) -> str:
        key = "upload-" + hashlib.sha256(base.design.model_dump_json().encode()).hexdigest()[:12]
        self.bases[key] = base
        return key


def _problem(path: str, message: str):
    from flexshaft.design import Problem

    return Problem(path, message)


def _mapping(value: Any, name: str) -> dict:
    if value is None:
        return {}
    if not isinstance(value, dict):
        raise DesignError([_problem(name, f"expected a table of path -> value, got {type(value).__name__}")])
    return value


def _refused(exc: DesignError, status: int = 422) -> JSONResponse:
    problems = [{"path": p.path, "message": p.message} for p in exc.problems]
    return JSONResponse({"error": "invalid design", "problems": problems, "message": str(exc)}, status_code=status)


async def _json(request: Request) -> dict:
    if request.headers.get("content-type", "").split(";")[0].strip() != "application/json":
        raise DesignError([_problem("<request>", "the API takes JSON (Content-Type: application/json)")])
    # bounded before it is held: a declared length over the limit is refused unread, and a body
    # without one is read only up to the limit
    limit = MAX_UPLOAD * 2
    declared = request.headers.get("content-length", "")
    if declared.isdigit() and int(declared) > limit:
        raise DesignError([_problem("<request>", f"request too large (at most {limit} bytes)")])
    chunks, size = [], 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > limit:
            raise DesignError([_problem("<request>", f"request too large (at most {limit} bytes)")])
        chunks.append(chunk)
    body = b"".join(chunks)
    try:
        data = json.loads(body)
    except ValueError:
        raise DesignError([_problem("<request>", "the body is not JSON")]) from None
    if not isinstance(data, dict):
        raise DesignError([_problem("<request>", "the body must be a JSON object")])
    return data


def _state(explorer: Explorer, key: str, design: Design, overrides: dict) -> dict:
    base = explorer.bases[key]
    return {
        "base": key,
        "base_name": base.design.name,
        "base_source": base.source,
        "overrides": overrides,
        "controls": [c.to_dict() for c in design_controls(design)],
    }


# ------------------------------------------------------------------------------------------------
# Routes


def _static_file(name: str) -> Path:
    return Path(str(resources.files("flexshaft.explore").joinpath("static", name)))


async def index(request: Request) -> Response:
    page = _static_file("index.html").read_text(encoding="utf-8")
    return HTMLResponse(page, headers={"Content-Security-Policy": _CSP, "Cache-Control": "no-store"})


async def no_icon(request: Request) -> Response:
    return Response(status_code=204)  # no icon: the browser asks, the console stays clean


_STATIC = {"app.js": "text/javascript", "app.css": "text/css"}


async def static(request: Request) -> Response:
    name = request.path_params["name"]
    if name == "plotly.min.js":
        path = plotly_js_path()
        if path is None:
            return Response("plotly is not installed", status_code=404)
        return FileResponse(path, media_type="text/javascript", headers={"Cache-Control": "max-age=86400"})
    if name not in _STATIC:
        return Response("not found", status_code=404)
    return FileResponse(_static_file(name), media_type=_STATIC[name], headers={"Cache-Control": "no-store"})


async def init(request: Request) -> Response:
    explorer: Explorer = request.app.state.explorer
    base = explorer.bases["file"]
    data = _state(explorer, "file", base.design, {})
    data["resolution"] = {
        "name": EXPLORE.name,
        "spinup_speeds": EXPLORE.spinup_speeds,
        "whirl_speeds": EXPLORE.whirl_speeds,
        "campbell_speeds": EXPLORE.campbell_speeds,
    }
    data["front"] = explorer.front.data if explorer.front is not None else None
    data["workers"] = explorer.workers.processes
    return JSONResponse(data)


async def update(request: Request) -> Response:
    explorer: Explorer = request.app.state.explorer
    start = time.perf_counter()
    try:
        body = await _json(request)
        _, design, overrides = explorer.design(body)
    except DesignError as exc:
        return _refused(exc)
    seq = body.get("seq", 0)
    seq = int(seq) if isinstance(seq, (int, float)) and math.isfinite(seq) else 0
    session = explorer.sessions.get(str(body.get("session", "")))
    try:  # what the assessment refuses of a schema-valid design (its size, a "worst" placement's bays)
        outcome = await session.update(seq, lambda: update_on(explorer.workers, design))
    except DesignError as exc:
        return _refused(exc)
    if outcome is None:
        return JSONResponse({"seq": seq, "superseded": True})
    payload, waited = outcome
    data = _state(explorer, str(body.get("base", "file")), design, overrides)
    data.update(
        seq=seq, superseded=seq < session.latest, results=payload, server_s=time.perf_counter() - start, waited_s=waited
    )
    return JSONResponse(data)


async def sweep(request: Request) -> Response:
    explorer: Explorer = request.app.state.explorer
    try:
        body = await _json(request)
        base, design, overrides = explorer.design(body)
        key = str(body.get("control", ""))
        values = body.get("values")
        if not isinstance(values, list) or not 2 <= len(values) <= MAX_SWEEP_POINTS:
            raise DesignError([_problem("values", f"give 2 to {MAX_SWEEP_POINTS} values to sweep")])
        points = [{**overrides, **control_overrides(design, {key: v})} for v in values]
        refuse_imbalance_cases(design, "<request>")  # refused at every point
    except DesignError as exc:
        return _refused(exc)
    start = time.perf_counter()
    results = await asyncio.gather(*(explorer.workers.run(sweep_point, base.design, p) for p in points))
    return JSONResponse({"control": key, "values": values, "points": results, "seconds": time.perf_counter() - start})


def _filename(design: Design) -> str:
    stem = "".join(ch if ch.isalnum() else "-" for ch in design.name.lower())[:40].strip("-") or "design"
    return f"{stem}-explored.toml"


async def export(request: Request) -> Response:
    explorer: Explorer = request.app.state.explorer
    try:
        body = await _json(request)
        base, design, overrides = explorer.design(body)
    except DesignError as exc:
        return _refused(exc)
    filename = _filename(base.design)
    text = explored_toml(
        design,
        base.design,
        overrides,
        base_text=base.text,
        base_source=base.source,
        verdict_summary=str(body.get("verdict", "")),
        filename=filename,
    )
    return JSONResponse({"filename": filename, "text": text, "command": run_command(filename)})


async def load(request: Request) -> Response:
    explorer: Explorer = request.app.state.explorer
    try:
        body = await _json(request)
        text = body.get("text")
        name = str(body.get("filename", "design.toml"))[:200]
        if not isinstance(text, str) or len(text.encode()) > MAX_UPLOAD:
            raise DesignError([_problem(name, f"expected a design file of at most {MAX_UPLOAD} bytes")], name)
        design = loads_design(text, name)
    except DesignError as exc:
        return _refused(exc)
    key = explorer.add_base(Base(design, text, name))
    return JSONResponse(_state(explorer, key, design, {}))


async def pareto(request: Request) -> Response:
    explorer: Explorer = request.app.state.explorer
    try:
        body = await _json(request)
        if explorer.front is None:
            raise DesignError([_problem("pareto", "no optimizer run was given (flexshaft explore --pareto FOLDER)")])
        design, overrides = front_design(explorer.front, body.get("index"))
    except DesignError as exc:
        return _refused(exc)
    return JSONResponse(_state(explorer, "pareto", design, overrides))


async def start_run(request: Request) -> Response:
    explorer: Explorer = request.app.state.explorer
    try:
        body = await _json(request)
        base, design, overrides = explorer.design(body)
    except DesignError as exc:
        return _refused(exc)
    job = f"{next(explorer._counter):03d}"
    folder = explorer.out / f"run-{job}"
    try:
        prepare_output_folder(folder, design, "run", force=False, option="explore --out")
    except UserError as exc:
        return JSONResponse({"error": str(exc)}, status_code=409)
    filename = _filename(base.design)
    text = explored_toml(
        design, base.design, overrides, base_text=base.text, base_source=base.source, filename=filename
    )
    explorer.workers.start_job(
        Job(job, str(folder)),
        full_run,
        job,
        design,
        text,
        f"{filename} (flexshaft explore)",
        str(folder),
        explorer.studies,
    )
    return JSONResponse({"job": job, "folder": str(folder)})


async def run_status(request: Request) -> Response:
    explorer: Explorer = request.app.state.explorer
    job = explorer.workers.jobs.get(request.path_params["job"])
    if job is None:
        return JSONResponse({"error": "no such run"}, status_code=404)
    return JSONResponse(job.to_dict())


async def run_file(request: Request) -> Response:
    explorer: Explorer = request.app.state.explorer
    job = explorer.workers.jobs.get(request.path_params["job"])
    if job is None or job.state != "done":
        return Response("not found", status_code=404)
    folder = Path(job.folder).resolve()
    path = (folder / request.path_params["path"]).resolve()
    if not path.is_relative_to(folder) or not path.is_file():
        return Response("not found", status_code=404)
    return FileResponse(path)


def _host_name(header: str) -> str:
    """The host of a ``Host`` header without its port: ``[::1]:8000`` -> ``::1``."""
    if header.startswith("["):
        return header[1 : header.find("]")] if "]" in header else header
    return header.rsplit(":", 1)[0] if header.count(":") == 1 else header


def _arrival_names(scope: Any) -> set[str]:
    """The address a connection arrived on, as a browser names it: an IPv4 client of a server
    listening on ``::`` arrives on ``::ffff:a.b.c.d`` and sends ``a.b.c.d``."""
    local = (scope.get("server") or (None,))[0]
    if not isinstance(local, str):
        return set()
    try:
        mapped = getattr(ipaddress.ip_address(local), "ipv4_mapped", None)
    except ValueError:  # a Unix socket's path, not an address
        return {local}
    return {local} if mapped is None else {local, str(mapped)}


class OwnHost:
    """Answer only requests addressed to this server (a DNS-rebinding guard): a ``Host`` among
    ``hosts``, or the very address the connection arrived on (the ASGI scope's ``server``), by
    which a browser on the network reaches a server listening on every interface (0.0.0.0). A
    page of another site that rebinds its own name to this machine sends that name, refused."""

    def __init__(self, app: Any, hosts: list[str]) -> None:
        self.app = app
        self.hosts = {_host_name(h) for h in hosts}

    async def __call__(self, scope: Any, receive: Any, send: Any) -> None:
        if scope["type"] in ("http", "websocket"):
            headers = dict(scope.get("headers") or [])
            name = _host_name(headers.get(b"host", b"").decode("latin-1"))
            if name not in self.hosts and name not in _arrival_names(scope):
                await Response("Invalid host header", status_code=400)(scope, receive, send)
                return
        await self.app(scope, receive, send)


def build_app(explorer: Explorer, hosts: list[str]) -> Starlette:
    """The Starlette application of ``explorer``, answering requests for ``hosts`` (or the
    address a connection arrived on) only (:class:`OwnHost`)."""
    app = Starlette(
        routes=[
            Route("/", index),
            Route("/favicon.ico", no_icon),
            Route("/static/{name}", static),
            Route("/api/init", init),
            Route("/api/update", update, methods=["POST"]),
            Route("/api/sweep", sweep, methods=["POST"]),
            Route("/api/export", export, methods=["POST"]),
            Route("/api/load", load, methods=["POST"]),
            Route("/api/pareto", pareto, methods=["POST"]),
            Route("/api/run", start_run, methods=["POST"]),
            Route("/api/run/{job}", run_status),
            Route("/runs/{job}/{path:path}", run_file),
        ],
        middleware=[Middleware(OwnHost, hosts=hosts)],
    )
    app.state.explorer = explorer
    return app

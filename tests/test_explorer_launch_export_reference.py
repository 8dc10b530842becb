"""The explorer's printed address, a failed full run's report, the full run's interactive page and
the provenance flags of the downloaded design file, without a browser and without an assessment.

References, all rules written by hand (none is a number the code produced):

* RFC 3986 §3.2.2 (URI generic syntax, read; also Python's ``urllib.parse.urlsplit``, which
  implements it): "A host identified by an Internet Protocol literal address, version 6
  [RFC3513] or later, is distinguished by enclosing the IP literal within square brackets ("["
  and "]")." So the address ``flexshaft explore --host ::1`` prints must split back into the
  host ``::1`` and the port it listens on; for ``127.0.0.1`` the same without brackets.
* docs/explorer.md, the full run: "runs the current design through ``flexshaft run``'s own
  pipeline (... the report folder, and ``interactive.html``)"; flexshaft.explore.fullrun's
  docstring (API contract): "with ``interactive.html`` when plotly is installed". So the pipeline
  is asked for the interactive page exactly when plotly.js is available
  (``missing_extra() is None``) and not when it is missing (it could not be written).
* API contract (flexshaft.explore.workers.Workers.start_job's comment: a failure is "reported
  to the page, which shows it"; no docs page states it): a full run that fails reports why in
  ``GET /api/run/<id>``'s ``error``, i.e. the message the run raised (a
  ``flexshaft.cli.common.UserError`` is "printed as ``error: ...``" by the command line, its
  message being the whole explanation), not only the exception's class name.
* docs/explorer.md, *Download design (TOML)*: the file keeps "every value its comments mark
  'assumed' or 'calibrated'"; flexshaft.explore.export._same_key's docstring (API contract):
  such a value is flagged ``(CHANGED above)`` when its key "(array elements by name or index)
  may be the changed path". Derived: a marked key whose field name differs from the changed
  path's (``bearings[amb_1].mass`` when ``bearings[1].kp`` changed), or that lies in another
  table (``tailboom.wall_thickness`` when ``shaft.wall_thickness`` changed), cannot be the
  changed path, so it is not flagged; the same field of a bearing named instead of indexed
  (``bearings[amb_1].gap`` when ``bearings[1].gap`` changed) may be, and a key changed as
  written (``shaft.outer_diameter``) is.
"""

from __future__ import annotations

import re
import types
from concurrent.futures import Future
from pathlib import Path
from urllib.parse import urlsplit

import pytest

from flexshaft.cli.common import LoadedDesign, UserError
from flexshaft.design import embedded_text, with_overrides

pytest.importorskip("starlette")
pytest.importorskip("uvicorn")

from flexshaft.explore import fullrun, launch
from flexshaft.explore.export import explored_toml
from flexshaft.explore.server import Explorer, build_app
from flexshaft.explore.workers import Workers
from tests.test_explorer_api_reference import HOST, Client, tuned  # noqa: F401 (fixture)


class _Socket:
    """What serve() uses of the listening socket: its bound address and close()."""

    def __init__(self, address: tuple) -> None:
        self.address = address

    def getsockname(self) -> tuple:
        return self.address

    def close(self) -> None:
        pass


class _NoWorkers:
    def __init__(self, processes=None) -> None:
        self.jobs: dict = {}
        self.processes = 2

    def close(self) -> None:
        pass


class _Server:
    """uvicorn.Server that returns at once instead of serving."""

    def __init__(self, config) -> None:
        self.config = config

    def run(self, sockets=None) -> None:
        pass


@pytest.mark.parametrize(("host", "address"), [("::1", ("::1", 8123, 0, 0)), ("127.0.0.1", ("127.0.0.1", 8123))])
def test_the_printed_address_splits_back_into_the_host_and_port(tuned, host, address, monkeypatch, capsys):  # noqa: F811
    """RFC 3986 §3.2.2: an IPv6 literal host is enclosed in square brackets. serve() with the
    socket, the workers and uvicorn's server replaced by stand-ins (nothing listens, nothing
    forks): the address it prints splits (urllib.parse, RFC 3986) into the given host and the
    bound port 8123."""
    import uvicorn

    monkeypatch.setattr(launch, "open_socket", lambda h, p: _Socket(address))
    monkeypatch.setattr(launch, "Workers", _NoWorkers)
    monkeypatch.setattr(uvicorn, "Server", _Server)
    launch.serve(LoadedDesign(tuned, None, "tuned"), host=host, port=0)
    printed = capsys.readouterr().out
    url = re.search(r"(http://\S+)", printed).group(1)
    parts = urlsplit(url)
    assert parts.hostname == host, url  # an unbracketed IPv6 host reads as no host at all (review r137)
    assert (parts.scheme, parts.port, parts.path) == ("http", 8123, "/")


class _DonePool:
    """A pool whose every submission has already ended with ``outcome`` (an exception raised or a
    value returned), so that the job's callback runs at once, in this thread."""

    def __init__(self, outcome) -> None:
        self.outcome = outcome

    def submit(self, function, *args) -> Future:
        future: Future = Future()
        if isinstance(self.outcome, BaseException):
            future.set_exception(self.outcome)
        else:
            future.set_result(self.outcome)
        return future


def _workers(outcome) -> Workers:
    workers = Workers.__new__(Workers)  # no process forked: the pool is the stand-in above
    workers.jobs = {}
    workers.processes = 1
    workers.pool = _DonePool(outcome)
    return workers


def test_a_failed_full_run_reports_the_message_it_raised(tuned, tmp_path):  # noqa: F811
    """API contract (start_job: a failure is "reported to the page, which shows it"): a full run
    that raises a UserError is reported by ``GET /api/run/<id>`` as failed with the error's own
    message; a run that returns is done with its result and no error."""
    message = "--out: the folder run-001 exists; remove it or choose another --out"
    workers = _workers(UserError(message))
    explorer = Explorer(LoadedDesign(tuned, embedded_text("tuned"), "tuned"), workers, out=tmp_path / "runs")
    client = Client(build_app(explorer, [HOST]))
    started = client.post("/api/run", json={"overrides": {}})
    assert started.status_code == 200
    status = client.get(f"/api/run/{started.json()['job']}").json()
    assert status["state"] == "failed"
    assert message in status["error"]

    workers.pool = _DonePool({"passed": True, "page": "interactive.html"})
    started = client.post("/api/run", json={"overrides": {}})
    status = client.get(f"/api/run/{started.json()['job']}").json()
    assert (status["state"], status["error"], status["result"]["page"]) == ("done", None, "interactive.html")


@pytest.mark.parametrize("plotly_installed", [True, False])
def test_the_full_run_asks_for_the_interactive_page_when_plotly_is_installed(
    tuned,  # noqa: F811
    tmp_path,
    monkeypatch,
    plotly_installed,
):
    """docs/explorer.md: the full run writes "the report folder, and ``interactive.html``";
    fullrun's docstring: "with ``interactive.html`` when plotly is installed". A stand-in
    pipeline records what it is asked: the interactive page exactly when plotly.js is
    available."""
    seen = {}

    def pipeline(loaded, folder, progress, *, studies, interactive):
        seen["interactive"] = interactive
        verdict = types.SimpleNamespace(passed=True, summary="PASS", checks=[])
        page = "interactive.html" if interactive else "report.md"
        return types.SimpleNamespace(verdict=verdict), Path(folder) / page, None

    monkeypatch.setattr(fullrun, "run_pipeline", pipeline)
    monkeypatch.setattr(fullrun, "_RELAY", None)
    monkeypatch.setattr(fullrun, "missing_extra", lambda *a: None if plotly_installed else "install plotly")
    result = fullrun.full_run("001", tuned, None, "x.toml", str(tmp_path), "none")
    assert seen["interactive"] is plotly_installed
    assert (result["page"] == "interactive.html") is plotly_installed


def _flagged(text: str) -> dict[str, bool]:
    """Each kept marked value's key -> whether it is flagged "(CHANGED above)"."""
    head = "values the base file marks as assumed or calibrated"
    section = text.split(head, 1)[1].split("\n\n", 1)[0]
    out = {}
    for line in section.splitlines()[1:]:
        if line.startswith("#   ") and " = " in line:
            out[line[4:].split(" = ", 1)[0]] = line.rstrip().endswith("(CHANGED above)")
    return out


def test_only_marked_values_that_may_be_the_changed_keys_are_flagged(tuned):  # noqa: F811
    """docs/explorer.md keeps the base's assumed values; _same_key's docstring: flagged when the
    marked key "may be the changed path" (see the module docstring for the derivation). Changed:
    bearings[1].gap (amb_1's, by index), bearings[1].kp, shaft.wall_thickness and
    shaft.outer_diameter."""
    overrides = {
        "bearings[1].gap": 0.4e-3,
        "bearings[1].kp": 4e5,
        "shaft.wall_thickness": 0.004,
        "shaft.outer_diameter": 0.11,
    }
    design = with_overrides(tuned, overrides)
    flagged = _flagged(explored_toml(design, tuned, overrides, base_text=embedded_text("tuned"), base_source="tuned"))
    # the keys of the tuned file's comments (docs: kept, each as its line)
    for key in ("bearings[amb_1].gap", "shaft.outer_diameter"):
        assert flagged[key], key  # may be (by name) or is (as written) a changed path
    for key in (
        "tailboom.wall_thickness",  # another table's wall
        "bearings[amb_1].mass",  # another field of the changed bearing
        "bearings[amb_1].force_capacity",
        "bearings[hanger_forward].mass",
        "shaft.fixed_start",  # another field of the changed table
        "tail_rotor.hub_stiffness",
    ):
        assert not flagged[key], key

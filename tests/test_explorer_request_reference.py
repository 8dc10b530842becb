"""The explorer's requests as a client sends them: the JSON media type with its parameter, the
page's latest update, a sweep over the edited layup, and a layup whose plies are separated by
commas.

The application is called in-process through the ASGI client of
``tests/test_explorer_api_reference.py`` (imported, with its fixture), its worker pool a
stand-in that records the designs it would assess, so each test costs milliseconds. References,
all rules written by hand:

* RFC 8259 §11, the application/json registration (quoted verbatim from the RFC Editor's errata
  page for RFC 8259, https://rfc-editor.org/errata/rfc8259, Errata ID 5853): "Note: No
  "charset" parameter is defined for this registration. Adding one really has no effect on
  compliant recipients."; RFC 9110 §8.3.1 only for the grammar ``media-type = type "/" subtype
  *( OWS ";" OWS parameter )``, behind splitting the header at ';'; the server's docstring:
  "the API takes JSON only";
* docs/explorer.md: "a request still waiting when a newer one of the same page arrives is
  answered "superseded" without being computed" (so the page's latest request is not);
* docs/explorer.md: "A sweep of any control over a range", on the design of the page (its
  edits): "Every change is validated by the same schema as a design file";
* docs/explorer.md: "each `a/-a` pair of the stacking notation is one control, rewritten in
  place"; the layup grammar (flexshaft.design.layup's docstring): ``sequence := item (("/" |
  ",") item)*``, so a comma separates plies as a slash does.
"""

from __future__ import annotations

import types

import pytest

from flexshaft.cli.common import LoadedDesign
from flexshaft.design import embedded_text, with_overrides

pytest.importorskip("starlette")

from flexshaft.design.layup import parse_layup
from flexshaft.explore.controls import control_overrides, design_controls
from flexshaft.explore.server import Explorer, build_app
from tests.test_explorer_api_reference import HOST, Client, StandInWorkers, tuned  # noqa: F401 (fixture)


class RecordingWorkers(StandInWorkers):
    """The stand-in pool, answering every computation with a JSON-able record of its design's
    layup (the update's argument is a whole Design, which the API's stand-in cannot echo); one
    process, so that an update of the tuned design's envelope is one ``design_update`` call."""

    processes = 1

    async def run(self, function, *args):
        self.calls.append(args)
        if len(args) == 1:  # design_update(design): the update's payload
            return {"layup": args[0].shaft.layup}
        return {"overrides": args[-1]}


def recording_app(tuned, tmp_path):  # noqa: F811 (the imported fixture's name)
    """The explorer on the tuned design with a recording worker pool: its client and workers."""
    workers = RecordingWorkers()
    explorer = Explorer(LoadedDesign(tuned, embedded_text("tuned"), "tuned"), workers, out=tmp_path / "runs")
    return types.SimpleNamespace(client=Client(build_app(explorer, [HOST])), workers=workers)


@pytest.fixture()
def app(tuned, tmp_path):  # noqa: F811 (the imported fixture)
    return recording_app(tuned, tmp_path)


def test_json_with_a_charset_parameter_is_json(app):
    """``application/json; charset=utf-8`` is the media type application/json with a parameter
    (RFC 9110 §8.3.1's grammar ``type "/" subtype *( OWS ";" OWS parameter )``), and RFC 8259
    §11: "Adding one really has no effect on compliant recipients." The same update body, sent
    with and without the parameter, is answered 200 both times with the same computed
    design; ``text/plain`` is refused (4xx)."""
    body = b'{"overrides": {"shaft.wall_thickness": 0.003}, "seq": 1, "session": "a"}'
    for n, media in enumerate(("application/json", "application/json; charset=utf-8")):
        answer = app.client.request("POST", "/api/update", body.replace(b'"a"', b'"%d"' % n), media)
        assert answer.status_code == 200, (media, answer.text)
        assert answer.json()["results"] == {"layup": "(60/-60/60/-60/0/0)s"}
    assert 400 <= app.client.request("POST", "/api/update", body, "text/plain").status_code < 500


def test_the_pages_latest_update_is_not_superseded(app):
    """docs/explorer.md: only a request overtaken by a newer one of its page is "superseded".
    A page's requests 1 then 2, each alone (nothing newer arrives while it waits): both are
    computed and answered with ``superseded`` false; a second page's request 1 after them is
    its own page's latest, also computed."""
    for session, seq in (("page", 1), ("page", 2), ("other", 1)):
        answer = app.client.post("/api/update", json={"overrides": {}, "seq": seq, "session": session})
        assert answer.status_code == 200
        data = answer.json()
        assert data["seq"] == seq and data["superseded"] is False, data
        assert data["results"] == {"layup": "(60/-60/60/-60/0/0)s"}
    assert len(app.workers.calls) == 3


def test_a_sweep_of_one_angle_keeps_the_other_angles_edit(app):
    """The tuned design file's layup (60/-60/60/-60/0/0)s (its input, not a result) has the
    pairs a1 = 60, a2 = 60, a3 = 0. With a1 set to 30 on the page, a sweep of a2 over 15 and 45
    assesses (30/-30/15/-15/0/0)s and (30/-30/45/-45/0/0)s: the page's edit stays, the swept
    pair is written in place (plies read back through the layup grammar, exact: integers in
    decimal text)."""
    answer = app.client.post("/api/sweep", json={"edits": {"layup.0": 30}, "control": "layup.1", "values": [15, 45]})
    assert answer.status_code == 200, answer.text
    layups = [p["overrides"]["shaft.layup"] for p in answer.json()["points"]]
    half = [parse_layup(text)[:6] for text in layups]
    assert half == [(30.0, -30.0, 15.0, -15.0, 0.0, 0.0), (30.0, -30.0, 45.0, -45.0, 0.0, 0.0)], layups


def test_a_comma_separated_pair_is_one_control(tuned):  # noqa: F811 (the imported fixture)
    """The layup grammar separates plies by '/' or ','; docs/explorer.md: each a/-a pair is one
    control. '(45,-45,0,0)s' has two controls, a1 = 45 and a2 = 0, like '(45/-45/0/0)s'; a1 set
    to 30 writes the plies 30/-30 (the pair, balanced) and leaves 0/0."""
    design = with_overrides(tuned, {"shaft.layup": "(45,-45,0,0)s"})
    angles = [(c.key, c.value) for c in design_controls(design) if c.key.startswith("layup.")]
    assert angles == [("layup.0", 45.0), ("layup.1", 0.0)]
    written = control_overrides(design, {"layup.0": 30})["shaft.layup"]
    assert parse_layup(written)[:4] == (30.0, -30.0, 0.0, 0.0), written

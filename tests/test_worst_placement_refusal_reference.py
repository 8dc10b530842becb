"""A "worst" imbalance placement beyond its bays is refused once, naming its field and file.

Reference: docs/limits.md, "The `"worst"` imbalance placement enumerates all 2^(bays−1) sign
patterns of the bay forces; it is limited to 10 bays (512 load cases ...). Beyond 10 bays use
`"mid_bay"` or `"distributed"`." The field that sets the count is ``loads.imbalance_placement``
(with the bearings' stations), not the operating speed; and "Every refusal of a design file names
the file" (docs/limits.md, the same paragraph).

On the validation's Jeffcott rotor (tests/test_size_estimate_hand_count_reference.py's
``bearings_at``: n bearings at distinct stations bound n − 1 bays), 13 bearings give 12 bays:
2^11 = 2048 load cases, counted by hand. Was (found by hunt h101a, then by the lead at the CLI):

* ``model_guards`` reported the refused load cases under ``operating.speed_rpm``;
* the size estimate capped the count at 2^10 = 1024 ("enumerates 2^(bays-1) = 1,024 load cases
  over 12 bays", a false power of two) and added a memory refusal for cases that never run;
* ``flexshaft check`` / ``run`` / ``compare`` / ``study all`` said "invalid design <problem size>:"
  instead of the file; ``optimize`` refused the budget's memory instead (review r122), and
  ``runup`` and ``thermal`` ended in an internal error (exit 4), ``runup`` after making its folder;
  ``study wall`` / ``gain`` / ``spinup-map`` refused from inside a sweep point without the file,
  after making their folder, and the explorer's server answered 500 (review r124).

Nothing is solved here but the Jeffcott rotor's preflight (a few ms).
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
from test_size_estimate_hand_count_reference import bearings_at, size
from typer.testing import CliRunner

from flexshaft.analyses.preflight import model_guards
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.assembly.size import MAX_WORST_BAYS, check_problem_size
from flexshaft.cli import app
from flexshaft.design import DesignError, design_from_dict
from flexshaft.optimize.files import write_design_file
from flexshaft.resolution import SCREENING

BEARINGS = 13  # 12 bays
BAYS = BEARINGS - 1
CASES = 2 ** (BAYS - 1)  # 2048, docs/limits.md's 2^(bays−1)
STATIONS = [k / BAYS for k in range(BEARINGS)]  # 0, 1/12, ..., 1 m: distinct, on the 1 m shaft
UNLIMITED = {"hard_memory": math.inf, "hard_time": math.inf, "soft_memory": math.inf, "soft_time": math.inf}


def test_the_estimate_counts_two_to_the_bays_minus_one_cases_beyond_the_limit():
    """12 bays: 2^11 = 2048 load cases, the placement's own count (docs/limits.md), not a cap."""
    assert BAYS > MAX_WORST_BAYS == 10
    s = size(bearings_at(STATIONS), "assess")
    assert (s.bays, s.load_cases) == (BAYS, CASES)


def test_the_refusal_names_the_placement_once_and_counts_one_case_against_the_caps():
    """With the memory cap at 1 byte (everything too large), the refusal is the placement's rule
    and the mesh's size problem, whose estimate is for one load case (what "mid_bay" or
    "distributed" would run): never a second "worst" problem with another count."""
    design = design_from_dict(bearings_at(STATIONS))
    with pytest.raises(DesignError) as refused:
        check_problem_size(design, "assess", SCREENING, **UNLIMITED)
    assert [p.path for p in refused.value.problems] == ["loads.imbalance_placement"]
    assert f"2^{BAYS - 1} load cases over {BAYS} bays" in refused.value.problems[0].message
    with pytest.raises(DesignError) as both:
        check_problem_size(design, "assess", SCREENING, **(UNLIMITED | {"hard_memory": 1.0}))
    paths = [p.path for p in both.value.problems]
    assert paths.count("loads.imbalance_placement") == 1 and "mesh.shaft_elements" in paths
    sized = next(p.message for p in both.value.problems if p.path == "mesh.shaft_elements")
    assert " 1 load case(s)" in sized


def test_preflight_names_the_placement_not_the_speed():
    """``model_guards`` (what ``flexshaft check`` reports after the size check): one problem, at
    ``loads.imbalance_placement``, with the 2^(bays−1) count."""
    problems = model_guards(design_from_dict(bearings_at(STATIONS)))
    assert [p.path for p in problems] == ["loads.imbalance_placement"]
    assert f"2^{BAYS - 1}" in problems[0].message


def test_check_names_the_design_file(tmp_path: Path):
    """``flexshaft check FILE``: exit 2 (user error), the file named, one problem at the field;
    with ``--json`` the same in its ``source`` and ``problems``."""
    path = write_design_file(design_from_dict(bearings_at(STATIONS)), tmp_path / "twelve_bays.toml")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2, result.output
    assert f"invalid design {path}:" in result.output and "<problem size>" not in result.output
    assert len(re.findall(r"loads\.imbalance_placement", result.output)) == 1
    as_json = CliRunner().invoke(app, ["check", str(path), "--json"])
    assert as_json.exit_code == 2
    data = json.loads(as_json.stdout)
    assert data["source"] == str(path)
    assert [p["path"] for p in data["problems"]] == ["loads.imbalance_placement"]


@pytest.mark.parametrize(
    "command",
    [
        ["run", "--out", "{out}"],
        ["compare", "--out", "{out}"],
        ["study", "all", "--out", "{out}"],
        ["optimize", "--budget", "4", "--pop-size", "4", "--jobs", "1", "--out", "{out}"],
        ["runup", "--out", "{out}"],
        ["thermal"],
        ["study", "wall", "--jobs", "1", "--out", "{out}"],
        ["study", "gain", "--jobs", "1", "--out", "{out}"],
        ["study", "spinup-map", "--out", "{out}"],
    ],
    ids=lambda c: " ".join(c[:2]) if c[0] == "study" else c[0],
)
def test_every_command_refuses_it_before_computing_naming_the_file(tmp_path: Path, command):
    """Each command that solves the imbalance response refuses the design as a user error (exit
    2), naming the file and the field, and makes no output folder."""
    path = write_design_file(design_from_dict(bearings_at(STATIONS)), tmp_path / "twelve_bays.toml")
    out = tmp_path / "out"
    args = [a.replace("{out}", str(out)) for a in command]
    where = 2 if command[0] == "study" else 1  # the design is the command's first argument
    result = CliRunner().invoke(app, [*args[:where], str(path), *args[where:]])
    assert result.exit_code == 2, result.output
    assert f"invalid design {path}:" in result.output, result.output
    assert "loads.imbalance_placement" in result.output and not out.exists()


def test_the_load_cases_refused_by_the_model_name_the_placement():
    """``imbalance_loads`` of the design's placement: a design error at the field; the same
    count asked for by argument (``placement="worst"`` on a "mid_bay" design) is the argument's
    ValueError, not the design's."""
    model = build_model(design_from_dict(bearings_at(STATIONS)))
    with pytest.raises(DesignError) as refused:
        imbalance_loads(model)
    assert [p.path for p in refused.value.problems] == ["loads.imbalance_placement"]
    data = bearings_at(STATIONS)
    data["loads"]["imbalance_placement"] = "mid_bay"
    mid_bay = build_model(design_from_dict(data))
    assert imbalance_loads(mid_bay).shape[1] == 1
    with pytest.raises(ValueError, match=r"2\^11") as by_argument:
        imbalance_loads(mid_bay, placement="worst")
    assert not isinstance(by_argument.value, DesignError)


class _InlineWorkers:
    """The explorer's worker pool run in the test process (the server's interface)."""

    processes = 1

    def __init__(self) -> None:
        self.jobs: dict = {}

    async def run(self, function, *args):
        return function(*args)

    def start_job(self, job, function, *args) -> None:
        self.jobs[job.id] = job


def test_the_explorer_refuses_it_as_a_client_error_naming_the_field(tmp_path: Path):
    """The explorer's update and sweep answer a refused design with a 4xx naming the field
    (RFC 9110: a refusal is a client error, not a server error), as for a schema refusal
    (tests/test_explorer_api_reference.py)."""
    from test_explorer_api_reference import HOST, Client

    from flexshaft.cli.common import LoadedDesign
    from flexshaft.design import load_design
    from flexshaft.explore.server import Explorer, build_app

    path = write_design_file(design_from_dict(bearings_at(STATIONS)), tmp_path / "twelve_bays.toml")
    loaded = LoadedDesign(load_design(path), path.read_text(), str(path))
    client = Client(build_app(Explorer(loaded, _InlineWorkers(), out=tmp_path / "runs"), [HOST]))
    for route, body in (
        ("/api/update", {"seq": 1, "session": "s"}),
        ("/api/sweep", {"control": "operating.speed_rpm", "values": [900, 1000]}),
    ):
        answer = client.post(route, json=body)
        assert 400 <= answer.status_code < 500, (route, answer.status_code)
        assert [p["path"] for p in answer.json()["problems"]] == ["loads.imbalance_placement"], route


def test_a_sweep_point_refused_alone_keeps_the_others():
    """A sweep whose base has 10 bays (accepted) and one point at 11 (refused): that point alone
    reports the refusal (explore.compute.sweep_point), so the other points' results are kept;
    checked on the refused point alone, refused before anything is computed."""
    from flexshaft.explore.compute import sweep_point

    ten_bays = [k / 10 for k in range(11)] + [1.0]  # the twelfth on the eleventh's station: merged
    base = design_from_dict(bearings_at(ten_bays))
    refused = sweep_point(base, {"bearings[11].x": 0.95})  # 0.95 m splits the last bay: 11 bays
    assert "loads.imbalance_placement" in refused["error"] and "2^10" in refused["error"]

"""The explorer's pieces without a browser: controls and their schema bounds, the layup's angle
pairs, the balance grade, an update's verdict (the screening verdict), the interactive figures
against the checks they draw, the design file out and back, the Pareto front of an optimizer
run, and the command without its extra.

References: the JSON Schema file ``docs/design.schema.json`` (read here independently of the
code that lists the controls), the layup grammar (:func:`flexshaft.design.layup.parse_layup`),
ISO 21940-11's e = G/Ω, and the recipe itself at :data:`~flexshaft.resolution.SCREENING`.
"""

from __future__ import annotations

import asyncio
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from flexshaft.design import DesignError, design_from_dict, embedded_text, loads_design, tuned_design, with_overrides
from flexshaft.design.layup import parse_layup
from flexshaft.resolution import SCREENING
from flexshaft.verdict.assess import assess

pytest.importorskip("starlette")
pytest.importorskip("plotly")

from flexshaft.explore.compute import EXPLORE, design_update, sweep_point, update_on
from flexshaft.explore.controls import advanced_overrides, control_overrides, design_controls, layup_angles
from flexshaft.explore.export import explored_toml, header_comments, run_command
from flexshaft.explore.workers import Workers
from flexshaft.report.interactive import actuator_figure, margins_figure
from flexshaft.report.interactive_page import interactive_page
from flexshaft.verdict.result import normalised_margin

SCHEMA = json.loads((Path(__file__).parents[1] / "docs" / "design.schema.json").read_text(encoding="utf-8"))


def _numeric(prop: dict) -> dict:
    return next((o for o in prop.get("anyOf", ()) if o.get("type") == "number"), prop)


@pytest.fixture(scope="module")
def tuned():
    return tuned_design()


@pytest.fixture(scope="module")
def controls(tuned):
    return {c.key: c for c in design_controls(tuned)}


def test_the_controls_are_the_variables_that_matter(controls):
    """Ply-angle pairs, wall, diameter, each actuator's station and gains, each hanger's
    station, the operating speed and the balance grade of the tuned design."""
    assert set(controls) == {
        "layup.0",
        "layup.1",
        "layup.2",
        "shaft.wall_thickness",
        "shaft.outer_diameter",
        "bearings[0].x",
        "bearings[1].x",
        "bearings[1].kp",
        "bearings[1].kd",
        "bearings[2].x",
        "bearings[2].kp",
        "bearings[2].kd",
        "bearings[3].x",
        "operating.speed_rpm",
        "loads.balance_grade",
    }
    assert controls["bearings[1].kp"].value == 5.0e5 and controls["bearings[1].kd"].value == 1250.0
    assert controls["shaft.wall_thickness"].value == pytest.approx(3.75, rel=1e-12)  # 3.75 mm shown in mm
    # (60/-60/60/-60/0/0)s: three angle pairs, ±60, ±60 and 0/0
    assert [controls[f"layup.{k}"].value for k in range(3)] == [60.0, 60.0, 0.0]


def test_bounds_are_the_schema_files(controls):
    """Every bound is the JSON Schema's (docs/design.schema.json), in the display unit: metres
    shown in mm scale by 1000 exactly."""
    defs = SCHEMA["$defs"]
    shaft, active = defs["Shaft"]["properties"], defs["ActiveBearing"]["properties"]
    wall, kp = _numeric(shaft["wall_thickness"]), _numeric(active["kp"])
    assert controls["shaft.wall_thickness"].minimum == pytest.approx(wall["minimum"] * 1000, rel=1e-15)
    assert controls["shaft.wall_thickness"].maximum == pytest.approx(wall["maximum"] * 1000, rel=1e-15)
    assert (controls["bearings[1].kp"].minimum, controls["bearings[1].kp"].maximum) == (kp["minimum"], kp["maximum"])
    grade = _numeric(defs["Loads"]["properties"]["balance_grade"])
    assert controls["loads.balance_grade"].minimum == grade["exclusiveMinimum"]
    assert controls["loads.balance_grade"].exclusive_minimum
    rpm = _numeric(defs["Operating"]["properties"]["speed_rpm"])
    assert controls["operating.speed_rpm"].maximum == rpm["maximum"]


@pytest.mark.parametrize(
    ("layup", "values", "new", "expected"),
    [
        ("(55/-55/0/0)s", [55.0, 0.0], {0: 45.0, 1: 10.0}, "(45/-45/10/-10)s"),
        ("(±45/0_2)s", [45.0, 0.0], {0: 30.0, 1: 5.0}, "(±30/5_2)s"),  # "_2" is a ply count
        ("[0/90]3", [0.0, 90.0], {1: 80.0}, "[0/80]3"),  # "3" is a repeat count
        ("(30/30/-20)s", [30.0, -20.0], {0: 35.0}, "(35/35/-20)s"),  # an equal pair keeps its signs
    ],
)
def test_layup_angle_pairs_rewrite_the_string_in_place(tuned, layup, values, new, expected):
    """The grammar's angles (not its counts) are the controls; a ± pair moves together."""
    assert [a.value for a in layup_angles(layup)] == values
    design = with_overrides(tuned, {"shaft.layup": layup})
    out = control_overrides(design, {f"layup.{k}": v for k, v in new.items()})
    assert out == {"shaft.layup": expected}
    parse_layup(expected)  # valid stacking notation


def test_control_values_become_si_overrides(tuned):
    out = control_overrides(
        tuned,
        {"shaft.wall_thickness": 2.5, "bearings[1].kp": 2e5, "operating.speed_rpm": 5000.0, "loads.balance_grade": 6.3},
    )
    assert out["shaft.wall_thickness"] == 0.0025  # 2.5 mm
    assert out["bearings[1].kp"] == 2e5 and out["operating.speed_rpm"] == 5000.0
    assert (out["loads.balance_grade"], out["loads.eccentricity"]) == (6.3, 0.0)  # one of the two, as the schema asks
    with pytest.raises(DesignError, match="bearings\\[9\\].kp: no such control"):
        control_overrides(tuned, {"bearings[9].kp": 1.0})
    assert advanced_overrides({"bearings[1].gap": "6e-4", "shaft.layup": '"(45/-45)s"'}) == {
        "bearings[1].gap": 6e-4,
        "shaft.layup": "(45/-45)s",
    }
    with pytest.raises(DesignError, match="bearings\\[1\\].gap: not a TOML value"):
        advanced_overrides({"bearings[1].gap": "six"})


def test_balance_grade_shown_is_the_eccentricity_at_the_top_speed(tuned, controls):
    """ISO 21940-11: e = G/Ω_max. The tuned design gives e = 18.2 µm and the speed range
    to 1.05 × 4800 rpm, so G = e Ω_max = 18.2e-6 m × 527.79 rad/s = 9.606 mm/s; setting that
    grade gives the same eccentricity back (to the 6 digits shown)."""
    omega_max = 1.05 * 4800.0 * 2 * math.pi / 60
    assert controls["loads.balance_grade"].value == pytest.approx(18.2e-6 * omega_max * 1000, rel=1e-12)
    from flexshaft.assembly.balance import design_eccentricity

    graded = with_overrides(tuned, control_overrides(tuned, {"loads.balance_grade": 9.60573}))
    assert design_eccentricity(graded) == pytest.approx(18.2e-6, rel=1e-6)


def test_an_invalid_value_is_refused_by_the_schema_naming_the_field(tuned):
    with pytest.raises(DesignError) as error:
        with_overrides(tuned, control_overrides(tuned, {"shaft.wall_thickness": 60.0}))
    assert [p.path for p in error.value.problems] == ["shaft.wall_thickness"]
    assert "less than outer_diameter/2" in error.value.problems[0].message


#: A coarse mesh for the tests that compute (see :func:`two_point_tuned`).
COARSE = {"mesh.shaft_elements": 8, "mesh.boom_elements": 4}


def _json_number(x: float) -> float | None:
    """Strict JSON has no inf or NaN: the payload sends null (the status says which)."""
    return x if math.isfinite(x) else None


@pytest.fixture(scope="module")
def two_point_tuned(tuned):
    """The tuned design over two of its envelope points (CPU budget, issue 23: each point is a
    whole assessment): the cold day, which governs at K_p 2e5 (actuator 1 beyond its gap), and
    the hot-soak start, where the actuators pass; so the envelope's checks combine points that
    disagree and the figures must draw the governing point's findings. On a coarse mesh (8 shaft,
    4 boom elements; CPU budget, issue 23): every check here compares the explorer with the
    screening assessment of the same design (the same functions on the same numbers), which
    holds at any mesh."""
    data = with_overrides(tuned, COARSE).model_dump()
    data["envelope"]["points"] = [p for p in data["envelope"]["points"] if p["name"] in ("cold_day", "hot_soak_start")]
    return design_from_dict(data)


@pytest.fixture(scope="module")
def update_and_screening(two_point_tuned):
    design = with_overrides(two_point_tuned, {"bearings[1].kp": 2e5})
    return design, design_update(design), assess(design, SCREENING)


def test_an_update_shows_the_screening_verdict(update_and_screening):
    """The explorer draws a Campbell diagram beside the screening grids; it only labels the
    critical speeds, so every check is the screening assessment's, status and margin alike
    (the same functions on the same numbers: no tolerance)."""
    _, payload, screening = update_and_screening
    assert EXPLORE.campbell_speeds > 0 and EXPLORE.spinup_speeds == SCREENING.spinup_speeds
    assert [c["status"] for c in payload["checks"]] == [c.status for c in screening.verdict.checks]
    assert [c["normalised_margin"] for c in payload["checks"]] == [
        _json_number(normalised_margin(c)) for c in screening.verdict.checks
    ]
    assert payload["summary"] == screening.verdict.summary
    assert not payload["passed"]  # K_p 2e5 lets actuator 1 reach its gap
    assert set(payload["figures"]) == {"margins", "campbell", "spinup", "actuators", "stability"}
    json.dumps(payload, allow_nan=False)  # strict JSON


def test_an_envelope_update_on_two_workers_is_the_serial_update(update_and_screening):
    """The server updates a design of several envelope points with the points in its workers
    side by side, then the verdict and figures in one (update_on): the page receives the serial
    update's payload. Reference: design_update in this process. Every point is computed by
    the same functions on the same numbers with one BLAS thread (tests/conftest.py), so every
    number agrees to round-off (1e-12 relative: the processes' BLAS may block the sums
    differently) and every status and label is the same; only the CPU time differs."""
    design, serial, _ = update_and_screening
    workers = Workers(2)
    try:
        parallel = asyncio.run(update_on(workers, design))
    finally:
        workers.close()
    assert parallel["cpu_s"] > 0
    parallel, serial = (
        json.loads(json.dumps({k: v for k, v in p.items() if k != "cpu_s"})) for p in (parallel, serial)
    )

    def same(a, b, where="payload"):
        if isinstance(a, dict):
            assert isinstance(b, dict) and a.keys() == b.keys(), where
            for key in a:
                same(a[key], b[key], f"{where}.{key}")
        elif isinstance(a, list):
            assert isinstance(b, list) and len(a) == len(b), where
            for k, (x, y) in enumerate(zip(a, b)):
                same(x, y, f"{where}[{k}]")
        elif isinstance(a, float) and isinstance(b, float):
            assert a == pytest.approx(b, rel=1e-12, abs=1e-300), where
        else:
            assert a == b, where

    same(parallel, serial)


def test_figures_draw_what_the_checks_judge(update_and_screening):
    """The margin bars are the optimizer's normalised margins; each actuator's excursion curve
    is static offset + spin-up orbit, and its marked peak is the actuator check's finding."""
    design, _, a = update_and_screening
    bars = margins_figure(a)["data"][0]
    expected = [normalised_margin(c) for c in a.verdict.checks]
    # +inf (passed, nothing to measure: no phase crossover) is drawn at the axis end, 3
    expected = [3.0 if m == math.inf else m for m in expected]
    assert bars["x"] == pytest.approx([float(f"{m:.6g}") for m in expected], rel=1e-6)
    figure = actuator_figure(a)
    check = a.verdict.check("actuator_orbit")
    peaks = {
        t["name"].split(":")[0]: t["y"][0]
        for t in figure["data"]
        if t["name"].endswith("checked peak") and t["yaxis"] == "y"
    }
    # the envelope check lists every point's findings; the figure draws the governing point's
    shown = [f for f in check.findings if f.location.get("point", a.governing_point) == a.governing_point]
    assert a.governing_point == "cold_day" and len(shown) < len(check.findings)  # the hot-soak start's: not drawn
    assert {f.location["actuator"] for f in shown} == set(peaks)
    for finding in shown:
        assert peaks[finding.location["actuator"]] == pytest.approx(finding.value * 1000, rel=1e-5)  # mm
    ev = a.evidence.actuators[0]
    curve = next(t for t in figure["data"] if t["name"] == f"{ev.name}: static + spin-up" and t["yaxis"] == "y")
    speeds = a.spinup.up_to(a.operating_speed)
    spin = np.asarray(curve["y"])[speeds]
    assert spin.max() == pytest.approx(
        (ev.static_offset + ev.peak_orbit) * 1000, rel=2e-2
    )  # the check refines the peak
    page = interactive_page(a, "/* plotly */")
    assert "<script src" not in page and "http" not in page.split("</head>")[1].replace('href="report.html"', "")


def test_a_sweep_point_gives_every_checks_normalised_margin(tuned, two_point_tuned, update_and_screening):
    """A sweep's point is the screening assessment of the base with the point's overrides: that
    of the same design (K_p 2e5) assessed directly."""
    design, _, screening = update_and_screening
    assert with_overrides(two_point_tuned, {"bearings[1].kp": 2e5}) == design
    point = sweep_point(two_point_tuned, {"bearings[1].kp": 2e5})
    for c in screening.verdict.checks:
        assert point["margins"][c.key] == _json_number(normalised_margin(c))
    assert "wall_thickness" in sweep_point(tuned, {"shaft.wall_thickness": 0.06})["error"]


def test_the_design_file_loads_back_with_provenance_and_changes_marked(tuned):
    overrides = {"bearings[1].kp": 2e5, "shaft.layup": "(45/-45/0/0)s", "operating.speed_rpm": 4800.0}
    design = with_overrides(tuned, overrides)
    text = explored_toml(
        design, tuned, overrides, base_text=embedded_text("tuned"), base_source="tuned", verdict_summary="FAIL: x"
    )
    back = loads_design(text)
    assert json.loads(back.model_dump_json()) == json.loads(design.model_dump_json())
    assert "CHANGED bearings[1].kp = 200000.0  (was 500000.0)" in text
    assert 'CHANGED shaft.layup = "(45/-45/0/0)s"  (was "(60/-60/60/-60/0/0)s")' in text
    assert "CHANGED operating.speed_rpm" not in text  # set to its own value: not a change
    assert "| flexshaft design file: the tuned final design" in text  # the base's header, kept
    assert "shaft.outer_diameter = 0.1016  # m, 4 in (assumed)" in text  # its assumed values, kept
    assert header_comments("# a\n#\n# b\nname = 1\n# c") == ["a", "", "b"]
    assert run_command("my design.toml") == "flexshaft run 'my design.toml' --strict --out 'my design-results'"


@pytest.mark.filterwarnings("ignore::RuntimeWarning")
def test_a_pareto_point_loads_the_optimizers_design(tmp_path, tuned):
    """A tiny optimizer run (2 screening evaluations of one shared K_p, its first generation):
    each point of pareto.nc is the base with its overrides, and its shaft mass is the one the run
    stored. The tuned design at its nominal point on a coarse mesh (CPU budget, issue 23): reading
    the front back does not depend on how many operating points each evaluation judged, nor on
    the model's size or the number of generations."""
    pytest.importorskip("pymoo")
    from flexshaft.explore.pareto import front_design, read_front
    from flexshaft.optimize import DesignProblem, DesignVariable, optimize

    problem = DesignProblem(
        variables=(DesignVariable(("bearings[1].kp", "bearings[2].kp"), 3e5, 1e6, log=True, name="kp"),),
        base=with_overrides(tuned, {"envelope": None, **COARSE}),
        fidelity="screening",
        objectives=("shaft_mass", "actuator_force"),
    )
    result = optimize(problem, 2, tmp_path / "run", pop_size=2)
    result.save()
    front = read_front(tmp_path / "run")
    assert front.data["x"] == "shaft_mass" and len(front.data["pareto"]["x"]) == result.pareto.sizes["design"]
    design, overrides = front_design(front, 0)
    assert overrides == json.loads(str(result.pareto["overrides"].values[0]))
    assert design.bearings[1].kp == overrides["bearings[1].kp"]
    assert front.data["pareto"]["y"][0] == pytest.approx(float(result.pareto["actuator_force"].values[0]), rel=1e-12)
    with pytest.raises(DesignError, match="no Pareto point 99"):
        front_design(front, 99)
    with pytest.raises(DesignError, match="problem.json is missing"):
        read_front(tmp_path)


def test_explore_without_its_extra_says_how_to_install_it():
    """Exit 2 (a user error) naming the packages and the pip command; no traceback."""
    code = (
        "import sys\n"
        "sys.modules['starlette'] = None\n"
        "from flexshaft.cli import app\n"
        "app(['explore'], prog_name='flexshaft')\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert done.returncode == 2, done.stderr
    assert "pip install 'flexshaft[explore]'" in done.stderr and "starlette" in done.stderr
    assert "Traceback" not in done.stderr


def test_only_loopback_addresses_count_as_local():
    """--host warns unless the address is this machine's loopback (127.0.0.0/8, ::1, localhost)."""
    from flexshaft.explore.launch import is_local

    assert all(is_local(h) for h in ("127.0.0.1", "127.0.0.2", "::1", "localhost"))
    assert not any(is_local(h) for h in ("0.0.0.0", "::", "192.168.1.10", "example.org"))


def test_import_flexshaft_cli_does_not_load_the_web_stack():
    code = (
        "import sys, flexshaft, flexshaft.cli\n"
        "print([m for m in ('starlette', 'uvicorn', 'plotly', 'flexshaft.explore') if m in sys.modules])\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=True)
    assert done.stdout.strip() == "[]"

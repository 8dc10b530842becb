"""The optimizer as an engineer uses it: default objectives that matter (the driveline's total
mass against the margin that limits), which requirements block when nothing passes, design files
that keep the base file's provenance comments, and ``--json``.

References: the driveline mass against ``flexshaft compare``'s mass breakdown
(:func:`flexshaft.comparison.driveline_inventory`) and the design files' own ``mass`` values
added by hand; the smallest margin and the blocking counts against hand-made outputs; the comments
against a plain scan of the base file's lines.
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

pytest.importorskip("pymoo")
xr = pytest.importorskip("xarray")

from typer.testing import CliRunner  # noqa: E402

from flexshaft.assembly import build_model  # noqa: E402
from flexshaft.cli import app  # noqa: E402
from flexshaft.comparison import driveline_inventory  # noqa: E402
from flexshaft.design import baseline_design, embedded_design, embedded_text, loads_design, tuned_design, with_overrides  # noqa: E402
from flexshaft.optimize import DesignProblem, Objective, OptimizationResult, default_variables  # noqa: E402
from flexshaft.optimize.files import design_toml, write_design_file  # noqa: E402
from flexshaft.optimize.mass import ACTUATOR_KG_PER_N, driveline_mass, driveline_mass_parts  # noqa: E402
from flexshaft.optimize.problem import NOT_EVALUATED_VIOLATION, objectives_and_constraints  # noqa: E402
from flexshaft.optimize.reference import zdt1_problem  # noqa: E402
from flexshaft.optimize.toml_comments import read_comments  # noqa: E402

runner = CliRunner()


# ------------------------------------------------------------------------------------------------
# The objectives


def test_driveline_mass_counts_every_part_as_the_comparison_does():
    tuned = build_model(tuned_design())
    # by hand from the design file: two 1.4 kg hangers and two 7.0 kg actuators on the tube
    assert driveline_mass(tuned) == pytest.approx(tuned.shaft_mass + 2 * 1.4 + 2 * 7.0, rel=1e-12)
    for name in ("tuned", "current"):  # five tubes, four couplings, hangers, a damper; no gearbox
        model = build_model(embedded_design(name))
        assert driveline_mass(model) == pytest.approx(driveline_inventory(model).total_mass, rel=1e-12)
    current = build_model(embedded_design("current"))
    gearboxes = [b.name for b in current.design.bearings if b.kind == "contact" and b.role == "gearbox"]
    parts = driveline_mass_parts(current)
    assert gearboxes and not set(gearboxes) & set(parts)  # a gearbox's bearing ends the driveline


def test_an_actuator_without_a_mass_is_estimated_from_its_force_capacity():
    """7.0 kg per 1500 N, the embedded designs' assumption: the tuned design's actuators with
    their mass omitted weigh what the file says they weigh."""
    design = with_overrides(
        tuned_design(), {"bearings[1].mass": 0.0, "bearings[2].mass": 0.0, "bearings[2].force_capacity": 3000.0}
    )
    parts = driveline_mass_parts(build_model(design))
    assert parts["amb_1"] == (pytest.approx(7.0, rel=1e-12), "estimate")
    assert parts["amb_2"] == (pytest.approx(3000.0 * ACTUATOR_KG_PER_N, rel=1e-12), "estimate")
    assert parts["hanger_forward"] == (1.4, "design")


def test_default_objectives_are_driveline_mass_and_the_smallest_margin():
    variables, layup = default_variables(baseline_design())
    problem = DesignProblem(variables, layup=layup)
    assert [(o.output, o.sense) for o in problem.objectives] == [("driveline_mass", "min"), ("min_margin", "max")]
    assert problem.base_text == embedded_text("baseline")  # the embedded file's comments go along
    assert "min_margin" in problem.all_output_names and "min_margin" not in problem.output_names


def test_min_margin_is_the_smallest_constraint_margin_of_the_problem():
    """min over the problem's constraints only (an ignored check does not count); a check not
    evaluated counts as −1, the violation it is."""
    problem = zdt1_problem()
    problem = DesignProblem(
        problem.variables,
        base=problem.base,
        objectives=(Objective("f1"), "min_margin"),
        constraints=problem.constraints,
        layup=problem.layup,
        evaluate=problem.evaluate,
        outputs=problem.outputs,
    )
    rows = np.array([[0.5, 0.4, 0.4, 1.0], [0.5, 0.4, 0.4, np.nan], [0.5, 0.4, -0.2, 1.0]])
    F, G = objectives_and_constraints(problem, rows, [True, True, True])
    np.testing.assert_array_equal(-F[:, 1], [0.4, -NOT_EVALUATED_VIOLATION, -0.2])
    assert problem.limiting(rows) == ["lower", "probe", "lower"]
    only_lower = DesignProblem(
        problem.variables,
        base=problem.base,
        objectives=(Objective("min_margin", "max"),),
        constraints=("margin_lower",),
        layup=problem.layup,
        evaluate=problem.evaluate,
        outputs=problem.outputs,
    )
    F, _ = objectives_and_constraints(only_lower, rows, [True, True, True])
    np.testing.assert_array_equal(-F[:, 0], [0.4, 0.4, -0.2])


# ------------------------------------------------------------------------------------------------
# What blocks


def _result(margins: dict, errors: list[str]) -> OptimizationResult:
    problem = zdt1_problem()
    n = len(errors)
    ev = xr.Dataset(
        {
            **{name: ("evaluation", np.asarray(values, dtype=float)) for name, values in margins.items()},
            "error": ("evaluation", np.array(errors, dtype=str)),
            "feasible": ("evaluation", np.zeros(n, dtype=np.int8)),
        },
        coords={"evaluation": np.arange(n)},
    )
    return OptimizationResult(problem, ev, ev.isel(evaluation=[]).rename({"evaluation": "design"}))


def test_blocking_table_counts_what_each_check_rejects():
    result = _result(
        {"margin_lower": [-0.1, -0.05, 0.2, 0.3, np.nan], "margin_probe": [1.0, np.nan, np.nan, 1.0, np.nan]},
        ["", "", "", "", "refused by the schema"],
    )
    rows = {r["check"]: r for r in result.blocking_checks()}
    # 4 valid designs: lower fails 0 and 1 (0 alone), probe is not evaluated on 1 and 2 (2 alone)
    assert rows["lower"] == {
        "check": "lower",
        "rejected": 2,
        "alone": 1,
        "not_evaluated": 0,
        "best_margin": 0.3,
        "best_evaluation": 3,
    }
    assert rows["probe"]["rejected"] == 2 and rows["probe"]["alone"] == 1 and rows["probe"]["not_evaluated"] == 2
    assert rows["valid design"]["rejected"] == 1
    assert [r["check"] for r in result.blocking_checks()][-1] == "valid design"


# ------------------------------------------------------------------------------------------------
# Design files keep the base file's comments


def _comment_texts(text: str) -> list[str]:
    """Every comment of a TOML file by a plain scan (the embedded files hold no '#' in strings)."""
    out = []
    for line in text.splitlines():
        if "#" in line:
            comment = line[line.index("#") + 1 :].strip()
            if comment and not set(comment) <= set("-"):
                out.append(comment)
    return out


@pytest.mark.parametrize("name", ["baseline", "tuned", "current"])
def test_written_design_keeps_every_comment_and_marks_changed_keys(tmp_path, name):
    base_text = embedded_text(name)
    base = loads_design(base_text)
    changes = {"shaft.wall_thickness": 0.002} if name != "current" else {"bearings[0].mass": 1.5}
    design = with_overrides(base, changes)
    path = write_design_file(design, tmp_path / "x.toml", ["written by a test"], base=base, base_text=base_text)
    text = path.read_text(encoding="utf-8")
    written = " ".join(_comment_texts(text))
    missing = [c for c in _comment_texts(base_text) if c not in written]
    assert not missing, missing[:5]
    provenance = len(re.findall(r"\((?:assumed|calibrated)", base_text))
    assert len(re.findall(r"\((?:assumed|calibrated)", text)) >= provenance > 0 or name == "current"
    assert loads_design(text) == design  # and it still reads back as the design
    marked = [line for line in text.splitlines() if "optimized: was" in line and not line.startswith("#")]
    if name == "current":
        assert marked == [
            "mass = 1.5  # optimized: was 1.4; base note: kg, sealed ball bearing, housing and bracket (assumed)"
        ]
    elif name == "tuned":
        assert marked == [
            "wall_thickness = 0.002  # optimized: was 0.00375; base note: m, 12 equal plies of 0.3125 mm "
            "(tuned: kink-band Tsai-Wu factor on the hot day)"
        ]
    else:
        assert marked == ["wall_thickness = 0.002  # optimized: was 0.003; base note: m, 8 equal plies (assumed)"]


def test_comments_belong_to_the_keys_they_annotate():
    comments = read_comments(embedded_text("tuned"))
    assert comments.keys[("bearings", 1, "kp")].inline == ["N/m, tuned on the spin-up map"]
    assert comments.keys[("bearings", 2, "mass")].inline[1].startswith("laminated stator, 1 kg coils")
    assert comments.keys[("loads", "eccentricity")].inline[0].startswith("m, e_c (calibrated:")
    assert comments.keys[("tailboom", "end_mass")].inline == ["tail rotor, gearboxes, fin, stabilator (assumed)"]
    assert comments.keys[("envelope", "points", 2, "name")].inline[0].startswith("the [thermal] hot day")
    assert comments.preamble[0].startswith("flexshaft design file: the tuned final design")
    # a multi-line array's comments stay with its key; strings holding '#' are not comments
    text = 'a = [\n  1, # one\n  2,\n] # end\nb = "x # y"  # note\n\n[t]\nc = 1\n    # more on c\n'
    c = read_comments(text)
    assert c.keys[("a",)].inline == ["one", "end"] and c.keys[("b",)].inline == ["note"]
    assert c.keys[("t", "c")].inline == ["more on c"]


def test_design_toml_without_a_base_writes_no_marks():
    text = design_toml(tuned_design(), ["a comment"])
    assert "optimized" not in text and loads_design(text) == tuned_design()


# ------------------------------------------------------------------------------------------------
# The command: --json and the blocking table


SMALL = """
name = "two-bay rotor"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7850.0
loss_factor = 0.002
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.05
wall_thickness = 0.005
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "left"
kind = "contact"
x = 0.0
stiffness = { v = 5e7, w = 5e7 }
mass = 0.8                    # kg (assumed)
[[bearings]]
name = "amb"
kind = "active"
x = 1.0
kp = 2e6
kd = 200.0
gap = 1.0e-3
force_capacity = 1.0e4       # N (assumed)
[[bearings]]
name = "right"
kind = "contact"
x = 2.0
stiffness = { v = 5e7, w = 5e7 }
[operating]
speed_rpm = 6000.0
power = 0.0
[loads]
eccentricity = 10e-6
[mesh]
shaft_elements = 6
"""


def test_cli_json_and_the_blocking_table_when_nothing_passes(tmp_path):
    """The small rotor gives no max_spinup_deflection: that check is never evaluated, so no
    design passes and the table names it as what blocks every candidate. A budget of one
    population, 2 designs (CPU budget, issue 23: the counts do not depend on the generations,
    which tests/test_optimize.py searches). The ``--json`` run computes them: its stdout holds
    the JSON alone while the evaluations run (``computed`` 2). The text run then reads the same
    folder (nothing recomputed) and prints the table of what blocks the 2 designs."""
    design = tmp_path / "rotor.toml"
    design.write_text(SMALL, encoding="utf-8")
    args = ["optimize", str(design), "--budget", "2", "--pop-size", "2", "--seed", "3", "--fidelity", "screening"]
    args += ["--var", "bearings[1].kd=100:400"]
    as_json = runner.invoke(app, [*args, "--out", str(tmp_path / "a"), "--json"])
    assert as_json.exit_code == 3
    data = json.loads(as_json.stdout)  # stdout holds the JSON alone
    assert data["computed"] == 2  # both evaluations computed by this run
    text = runner.invoke(app, [*args, "--out", str(tmp_path / "a")])
    assert text.exit_code == 3, text.output
    assert "no design passes: what blocks the 2 evaluated designs" in text.stdout
    assert re.search(r"│ spinup_deflection\s+│\s+2 │", text.stdout), text.stdout
    assert [o["output"] for o in data["objectives"]] == ["driveline_mass", "min_margin"]
    assert data["evaluations"] == 2 and data["feasible"] == 0 and data["pareto"] == [] and not data["passed"]
    blocking = {r["check"]: r for r in data["blocking_checks"]}
    assert blocking["spinup_deflection"] == {
        "check": "spinup_deflection",
        "rejected": 2,
        "alone": blocking["spinup_deflection"]["alone"],
        "not_evaluated": 2,
        "best_margin": None,
        "best_evaluation": -1,
    }
    stored = json.loads((tmp_path / "a" / "blocking_checks.json").read_text(encoding="utf-8"))
    assert stored["checks"] == data["blocking_checks"]
    # the base's driveline mass: the tube, the left bearing's 0.8 kg and the actuator's estimate
    base = data["references"]["base (rotor)"]["outputs"]
    tube = build_model(loads_design(SMALL)).shaft_mass
    assert base["driveline_mass_kg"] == pytest.approx(tube + 0.8 + 1e4 * ACTUATOR_KG_PER_N, rel=1e-9)

"""A sweep's override-function variables, its run-folder identity and its saved provenance.

References are the documented rules of docs/studies.md (hand-written), quoted in each test:

* "A variable with `path=` sets that design-file field ...; `overrides=f` maps a value to
  several fields ...; a variable with neither is a special axis handed to `evaluate` in
  `point.axes`." and "`point.model` is built once per distinct design (consecutive points that
  differ only in special axes share it)". So a variable given by an overrides function is a
  design variable: each of its values reaches the design of its own point, and it is not an
  axis.
* "Every path and value ... is validated before anything runs".
* "A folder whose intact manifest is another study's is refused." A study on another base
  design is another study even when the design keeps its name.
* "Results: ... the study fingerprint and the fixed overrides in global attributes."

The output functions read values back from ``point.design`` / ``point.axes`` and never build a
model, so each test costs a few design validations (and, for the run folder, two small files).
"""

from __future__ import annotations

import json

import pytest

from flexshaft.design import baseline_design, with_overrides
from flexshaft.sweep import Study, SweepError, Variable, run_sweep
from flexshaft.sweep.study import DifferentStudyError, evaluate_chunk


def wall_and_diameter(value):
    """Overrides function: one value sets two fields, wall = value, outer diameter = 40·value."""
    return {"shaft.wall_thickness": value, "shaft.outer_diameter": 40.0 * value}


def _read_design(point):
    shaft = point.design.shaft
    return {
        "wall_seen": float(shaft.wall_thickness),
        "diameter_seen": float(shaft.outer_diameter),
        "n_axes": float(len(point.axes)),
    }


def test_overrides_function_variable_sets_its_fields_at_every_point():
    """Grid speed ∈ (300, 400) (special axis, outermost) × t ∈ (0.0025, 0.0030) (overrides).

    Each point's design carries wall = t and outer diameter = 40 t (the closed form of the
    overrides function), and only the special axis is in ``point.axes`` (n_axes = 1). Points 0
    and 1 share the speed and differ only in t: a model shared between them would hand point 1
    the wall of point 0. The values are copied, not computed: exact equality is the reference.
    """
    ts = [0.0025, 0.0030]
    study = Study(
        "overrides",
        [Variable("speed", [300.0, 400.0], units="rad/s"), Variable("t", ts, overrides=wall_and_diameter)],
        ["wall_seen", "diameter_seen", "n_axes"],
        _read_design,
    )
    out = evaluate_chunk(study, 0, 4)
    assert out.tolist() == [[t, 40.0 * t, 1.0] for _speed in (300.0, 400.0) for t in ts]


def test_overrides_function_values_are_validated_before_running():
    """A value whose overrides give a negative wall is refused by ``validate`` (docs: every
    value is validated before anything runs), naming the variable's value in the message."""
    study = Study("bad", [Variable("t", [0.0025, -0.001], overrides=wall_and_diameter)], ["wall_seen"], _read_design)
    with pytest.raises(SweepError, match="-0.001"):
        study.validate()


def _wall_only(point):
    return {"wall_seen": float(point.design.shaft.wall_thickness)}


def test_run_folder_of_another_base_design_is_refused(tmp_path):
    """Same name, variables, outputs and function, base designs that differ only in the wall
    (0.0025 m vs 0.0035 m; the design name is kept by ``with_overrides``): the second study is
    another study, so its run folder holds none of its results and is refused instead of
    returning the first design's stored walls."""
    base_a = with_overrides(baseline_design(), {"shaft.wall_thickness": 0.0025})
    base_b = with_overrides(baseline_design(), {"shaft.wall_thickness": 0.0035})
    assert base_a.name == base_b.name  # the precondition of the check: names alike
    axis = [Variable("speed", [100.0, 200.0], units="rad/s")]
    first = run_sweep(
        Study("walls", axis, ["wall_seen"], _wall_only, base=base_a), tmp_path, progress=False, as_arrays=True
    )
    assert first["wall_seen"].values.tolist() == [0.0025, 0.0025]
    with pytest.raises(DifferentStudyError):
        run_sweep(Study("walls", axis, ["wall_seen"], _wall_only, base=base_b), tmp_path, progress=False)


def test_results_carry_the_fixed_overrides():
    """The global attribute ``fixed_overrides`` is the JSON of the study's ``fixed`` mapping
    (docs: the fixed overrides in global attributes); the points see them too."""
    fixed = {"shaft.outer_diameter": 0.12, "shaft.wall_thickness": 0.003}
    study = Study("fixed", [Variable("speed", [100.0])], ["wall_seen"], _wall_only, fixed=fixed)
    arrays = run_sweep(study, progress=False, as_arrays=True)
    assert json.loads(arrays.attrs["fixed_overrides"]) == fixed
    assert arrays["wall_seen"].values.tolist() == [0.003]

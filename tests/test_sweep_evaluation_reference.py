"""A sweep's evaluation (sweep/study.py, :func:`evaluate_chunk`) on hand-built grids.

The references are the definitions of the sweep, checked point by point and field by field:
a full-factorial grid in C order (the last variable varies fastest, as the docstring of
:class:`Study` states: "outermost first"), so flat index k of a grid of shape (2, 3) is the
point (k // 3, k % 3); every design variable's value lands in its own design-file field; the
study's ``fixed`` overrides hold at every point; the special axes (and only they) are handed to
the output function in ``point.axes``; each declared output is recorded in its own column.
The output functions read the values back from the point and never build a model, so the
file costs a few milliseconds of design validation (CPU about 0.01 s).
"""

from __future__ import annotations

from flexshaft.sweep import Study, Variable
from flexshaft.sweep.study import evaluate_chunk


def _axes_code(point):
    """Two outputs that differ at every point: p = 100·a + b and q = a (declared p first)."""
    return {"p": 100.0 * point.axes["a"] + point.axes["b"], "q": float(point.axes["a"])}


def test_flat_index_is_c_order_and_outputs_keep_their_columns():
    """Grid a ∈ (1, 2) × b ∈ (10, 20, 30): index k is (a, b) = (a[k // 3], b[k % 3])."""
    study = Study("grid", [Variable("a", [1.0, 2.0]), Variable("b", [10.0, 20.0, 30.0])], ["p", "q"], _axes_code)
    out = evaluate_chunk(study, 0, 6)
    points = [(1, 10), (1, 20), (1, 30), (2, 10), (2, 20), (2, 30)]
    assert out.tolist() == [[100.0 * a + b, float(a)] for a, b in points]
    # a chunk from the middle of the grid: points 2..4
    assert evaluate_chunk(study, 2, 5).tolist() == [[130.0, 1.0], [210.0, 2.0], [220.0, 2.0]]


def _design_fields(point):
    shaft = point.design.shaft
    return {
        "wall_seen": shaft.wall_thickness,
        "diameter": shaft.outer_diameter,
        "speed_axis": float(point.axes["speed"]),
        "n_axes": float(len(point.axes)),
    }


def test_design_fields_fixed_overrides_and_special_axes_at_every_point():
    """A special axis outermost, a design variable innermost, a fixed outer diameter.

    Consecutive points 0 and 1 share the special value and differ in design: each must see
    its own wall (a model keyed on anything but the design values would hand point 1 the
    design of point 0). Every point sees the fixed 0.12 m outer diameter and only the
    special axis in ``axes``.
    """
    walls = [0.0025, 0.0035]
    study = Study(
        "fields",
        [
            Variable("speed", [300.0, 400.0], units="rad/s"),
            Variable(path="shaft.wall_thickness", name="wall", values=walls),
        ],
        ["wall_seen", "diameter", "speed_axis", "n_axes"],
        _design_fields,
        fixed={"shaft.outer_diameter": 0.12},
    )
    out = evaluate_chunk(study, 0, 4)
    expected = [[w, 0.12, s, 1.0] for s in (300.0, 400.0) for w in walls]
    assert out.tolist() == expected

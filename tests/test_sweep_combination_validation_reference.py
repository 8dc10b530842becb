"""A pair of design values that is valid alone but invalid together stops a study before any
point is computed.

Reference: the documented rule of docs/studies.md (hand-written), quoted: "Every path and
value (every combination of design values up to 20 000) is validated before anything runs;
the error names the field, the value and the allowed range." The design rule used is the
shaft's own check (``wall_thickness`` must be less than ``outer_diameter/2``), worked by hand
on the embedded baseline (outer diameter 0.1016 m, wall 0.003 m):

    outer_diameter  wall_thickness  wall < outer/2 ?
    0.1016          0.003           0.003 < 0.0508  yes (the baseline)
    0.1016          0.005           0.005 < 0.0508  yes
    0.008           0.003           0.003 < 0.004   yes
    0.008           0.005           0.005 < 0.004   NO

so each value alone (set on the baseline) is valid and only the last combination is not. In C
order (the last variable varies fastest) that pair is flat point 3, the last one, so a run
that validated the values one at a time would compute points 0, 1, 2 before failing there.
The evaluation only reads a design field (no model is built): a few milliseconds.
"""

from __future__ import annotations

import pytest

from flexshaft.sweep import Output, Study, SweepError, Variable, run_sweep

CALLS: list[int] = []


def _wall(point):
    """The wall thickness of the point's design (no model)."""
    CALLS.append(point.index)
    return {"wall_out": float(point.design.shaft.wall_thickness)}


def _study() -> Study:
    return Study(
        "invalid pair",
        [
            Variable(path="shaft.outer_diameter", name="outer", values=[0.1016, 0.008], units="m"),
            Variable(path="shaft.wall_thickness", name="wall", values=[0.003, 0.005], units="m"),
        ],
        [Output("wall_out", "m")],
        _wall,
    )


def test_each_value_alone_is_valid():
    """The premise of the table above: every single value passes on the baseline."""
    study = _study()
    for v in study.variables:
        for value in v.values:
            study.design_at({v.name: value})  # raises SweepError if invalid


def test_invalid_pair_of_two_design_variables_stops_before_any_point():
    """validate() rejects the pair (0.008, 0.005), naming the field and the values, and
    run_sweep raises before evaluating a single point (CALLS stays empty)."""
    study = _study()
    with pytest.raises(SweepError) as caught:
        study.validate()
    message = str(caught.value)
    assert "wall_thickness" in message
    assert "outer = 0.008" in message and "wall = 0.005" in message
    CALLS.clear()
    with pytest.raises(SweepError):
        run_sweep(study, progress=False, as_arrays=True)
    assert CALLS == []

"""A warning raised while a sweep evaluates a point names that point.

In a sweep of hundreds of designs (an optimizer's generation, ``flexshaft study``), a warning
such as "the response at ω = 139.871 rad/s lies within 6e-6 of an undamped resonance" cannot be
acted on unless it says which design raised it. :func:`flexshaft.sweep.study.evaluate_chunk`
raises each one again, of its own category, prefixed with the point's varying variables.
"""

from __future__ import annotations

import warnings

import pytest

from flexshaft.analyses.banded import ResonanceWarning
from flexshaft.sweep import Output, Study, Variable, evaluate_chunk


def _warns_at_thick_wall(point):
    """Outputs: the wall in mm; a ResonanceWarning at the 3 mm wall and 10 rad/s only."""
    wall = point.design.shaft.wall_thickness
    if wall == 0.003 and point.axes["speed"] == 10.0:
        warnings.warn(ResonanceWarning("near a resonance"), stacklevel=2)
    return {"wall_mm": 1e3 * wall}


def _study(fidelity_values=("screening",)):
    return Study(
        name="warns",
        variables=[
            Variable(path="shaft.wall_thickness", name="wall", values=[0.002, 0.003], units="m"),
            Variable("speed", [0.0, 10.0], units="rad/s"),
            Variable("fidelity", list(fidelity_values)),
        ],
        outputs=[Output("wall_mm", "mm")],
        evaluate=_warns_at_thick_wall,
    )


def test_the_warning_names_its_point_and_keeps_its_category():
    study = _study()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = evaluate_chunk(study, 0, 4)
    # the outputs are the evaluation's, unchanged (C order: wall, then speed)
    assert out[:, 0].tolist() == [2.0, 2.0, 3.0, 3.0]
    ours = [w for w in caught if issubclass(w.category, ResonanceWarning)]
    assert len(ours) == 1  # one point warned, once
    # the single-valued fidelity axis says nothing about which point it was: left out
    assert str(ours[0].message) == "at wall = 0.003, speed = 10.0: near a resonance"


def test_every_variable_is_named_when_none_varies():
    study = Study(
        name="one",
        variables=[
            Variable(path="shaft.wall_thickness", name="wall", values=[0.003], units="m"),
            Variable("speed", [10.0]),
        ],
        outputs=[Output("wall_mm", "mm")],
        evaluate=_warns_at_thick_wall,
    )
    with pytest.warns(ResonanceWarning, match=r"^at wall = 0\.003, speed = 10\.0: near a resonance$"):
        evaluate_chunk(study, 0, 1)


def test_a_warning_is_named_even_when_the_point_then_fails():
    def warn_then_fail(point):
        warnings.warn(UserWarning("first this"), stacklevel=2)
        raise ValueError("then this")

    study = Study(
        name="fails", variables=[Variable("speed", [1.0, 2.0])], outputs=[Output("x")], evaluate=warn_then_fail
    )
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = evaluate_chunk(study, 0, 2, on_error="nan")
    assert [str(w.message) for w in caught] == ["at speed = 1.0: first this", "at speed = 2.0: first this"]
    assert out.shape == (2, 1) and bool(all(out[:, 0] != out[:, 0]))  # NaN where the point failed

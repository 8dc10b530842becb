"""``fs.assess`` and ``assess_point`` refuse arguments of the wrong type with a ValueError
naming the argument and what is allowed, before any computation.

Was: ``fs.assess(design, "screening")`` (a preset's name for the preset) and
``fs.assess("my.toml", fs.SCREENING)`` failed deep inside the size estimate with
``AttributeError: 'str' object has no attribute 'spinup_speeds'`` (or ``'shaft'``), which the
command line would report as an internal error. The reference is the documented rule
(docs/limits.md section 6: every public analysis refuses impossible arguments with a
``ValueError`` naming the argument).
"""

from __future__ import annotations

import pytest

import flexshaft as fs
from flexshaft.analyses.guards import RefusedInputError
from flexshaft.verdict.assess import assess_point


@pytest.mark.parametrize("resolution", ["screening", None, 1])
def test_a_resolution_that_is_not_a_resolution_is_refused_naming_it(resolution) -> None:
    with pytest.raises(RefusedInputError, match=r"resolution must be a flexshaft.Resolution .*fs.SCREENING"):
        fs.assess(fs.tuned_design(), resolution)
    with pytest.raises(RefusedInputError, match=r"resolution must be a flexshaft.Resolution"):
        assess_point(fs.tuned_design(), 0, resolution)


@pytest.mark.parametrize("design", ["my.toml", {}, None])
def test_a_design_that_is_not_a_design_is_refused_naming_it(design) -> None:
    with pytest.raises(RefusedInputError, match=r"design must be a validated flexshaft.design.Design .*load_design"):
        fs.assess(design, fs.SCREENING)


def test_a_resolution_too_fine_to_finish_is_refused_naming_the_resolution() -> None:
    """Was: ``fs.assess(tuned, replace(fs.SCREENING, whirl_speeds=10**7))`` was refused (about
    120 h, docs/limits.md section 5: at most 4 h) as "mesh.shaft_elements: ... use fewer" on the
    36-element design, whose mesh is already the coarse one the docs recommend. The refusal now
    names the grid finer than fs.FINE's."""
    import dataclasses

    from flexshaft.design import DesignError

    with pytest.raises(DesignError) as refusal:
        fs.assess(fs.tuned_design(), dataclasses.replace(fs.SCREENING, whirl_speeds=10**7))
    text = str(refusal.value)
    assert "resolution: whirl_speeds = 10,000,000 (fs.FINE: 81)" in text and "allowed: 4 h" in text
    assert "mesh.shaft_elements" not in text

"""Documented choices and limits of two design-file fields, at their edges.

* docs/limits.md, section 1: "a layup at most 2000" characters (and the parser "at most 1000
  plies"). The rule holds for every layup of the file, so also for a ``[[shaft.segments]]``
  zone's own layup (docs/segmented-driveline.md's example segment: "any of outer_diameter,
  wall_thickness, material, layup may change"). A 2000-character layup of 1000 plies,
  ``"10" + "/0" * 999`` (2 + 2·999 = 2000 characters, 1 + 999 = 1000 plies, counted here), is
  accepted by a segment; ``"-10" + "/0" * 999`` (2001 characters, still 1000 plies, so only
  the length can refuse it) is refused as too long at the segment's ``layup``.
* docs/model.md (forced response): the imbalance placement is "``mid_bay`` (point forces at bay
  centres, all in phase), ``distributed``, or ``worst``", and docs/limits.md, section 6, lists
  "placements one of ``mid_bay``, ``distributed``, ``worst``". Each of the three is accepted by
  ``[loads] imbalance_placement``; a fourth word is refused.

Validation only (no model is built): milliseconds of CPU; no floating point is compared.
"""

from __future__ import annotations

import pydantic
import pytest

from flexshaft.design.loads import Loads
from flexshaft.design.segments import ShaftSegment

#: docs/limits.md: "a layup at most 2000" characters; the parser takes "at most 1000 plies".
DOCUMENTED_LAYUP_CHARACTERS = 2000
DOCUMENTED_PLIES = 1000


def _segment(layup: str) -> ShaftSegment:
    return ShaftSegment(name="mid", x_start=0.0, x_end=1.0, material="fmc_lamina", layup=layup)


def test_a_segment_takes_a_layup_of_the_documented_2000_characters() -> None:
    layup = "10" + "/0" * (DOCUMENTED_PLIES - 1)
    assert len(layup) == DOCUMENTED_LAYUP_CHARACTERS and layup.count("/") + 1 == DOCUMENTED_PLIES
    segment = _segment(layup)
    assert segment.layup == layup


def test_a_segment_refuses_a_layup_one_character_longer() -> None:
    layup = "-10" + "/0" * (DOCUMENTED_PLIES - 1)
    assert len(layup) == DOCUMENTED_LAYUP_CHARACTERS + 1 and layup.count("/") + 1 == DOCUMENTED_PLIES
    with pytest.raises(pydantic.ValidationError) as refused:
        _segment(layup)
    assert [(e["loc"], e["type"]) for e in refused.value.errors()] == [(("layup",), "string_too_long")]


@pytest.mark.parametrize("placement", ["mid_bay", "distributed", "worst"])
def test_each_documented_imbalance_placement_is_accepted(placement: str) -> None:
    loads = Loads(eccentricity=1e-5, imbalance_placement=placement)
    assert loads.imbalance_placement == placement


def test_an_undocumented_imbalance_placement_is_refused() -> None:
    with pytest.raises(pydantic.ValidationError) as refused:
        Loads(eccentricity=1e-5, imbalance_placement="random")
    assert [e["loc"] for e in refused.value.errors()] == [("imbalance_placement",)]

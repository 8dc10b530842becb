"""The metal-strength requirement of a shaft with metal segments: which results reach it, which
limit they meet, and which drivelines it applies to (derived here).

A metal segment fails by static yield (von Mises) or by fatigue (modified Goodman); both are
strength criteria, held to the strength requirement ``min_safety_factor`` (1.5 here), not to the
buckling one (2.0 here, a stability margin). Each segment's evidence is its smallest safety factor
of each criterion, so a segment with n_fatigue = 2.4 and n_yield = 1.6 is governed by yield:
the check's value is 1.6, its margin 1.6 − 1.5 = 0.1, and it passes (it would fail against 2.0).
The requirement applies to every driveline with at least one isotropic (metal) segment, a hybrid
of metal and laminated segments too.

Stand-ins replace the analyses' results; the arithmetic is exact to round-off (1e-15).
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import pytest

from flexshaft.design.requirements import Requirements
from flexshaft.verdict import gather
from flexshaft.verdict.checks import CHECKS, metal_strength
from flexshaft.verdict.evidence import Evidence

REQUIREMENTS = Requirements(min_safety_factor=1.5, min_buckling_safety_factor=2.0)
WORST = {"fatigue": {"safety_factor": 2.4, "station": 0.3}, "yield": {"safety_factor": 1.6, "station": 0.7}}


def test_a_metal_segment_is_governed_by_its_weaker_criterion_against_the_strength_limit():
    metal = NS(evaluated=True, segments=["tube"], notes=(), worst=lambda criterion, segment: WORST[criterion])
    found = gather._metal(NS(metal_strength=metal), {})["metal_strength"]
    assert sorted(m.safety_factor for m in found) == [1.6, 2.4]
    check = metal_strength(Evidence(operating_speed=100.0, metal_strength=found), REQUIREMENTS)
    assert check.status == "pass" and check.value == 1.6 and check.limit == 1.5
    assert check.margin == pytest.approx(0.1, rel=1e-15)
    assert check.location["station"] == 0.7


def test_the_check_applies_to_a_hybrid_shaft():
    (rule,) = [r for r in CHECKS if r.key == "metal_strength"]
    materials = {"steel": NS(kind="isotropic"), "fmc": NS(kind="lamina")}
    hybrid = NS(design=NS(materials=materials), segments=[NS(material="steel"), NS(material="fmc")])
    laminated = NS(design=NS(materials=materials), segments=[NS(material="fmc")])
    assert rule.applies(hybrid) and not rule.applies(laminated)

"""Thesis study 1 at fractional ply angles: the layup it builds and the critical ply it reports.

References:

* the study's variable is the ply angle α of the (α/−α/−α/α) tube, and fractional angles are
  its use: docs/studies.md's table reports study 1's optimum at "best ±47.5°" (hand-written),
  and ply_angle_study's function docstring asks for a step of 1° or finer near the optimum.
  The built laminate's ply angles are therefore exactly (α, −α, −α, α) converted to radians,
  for a fractional α as for a whole one (derived here; to 1e-12 rad: one parse and one deg→rad
  product);
* the critical ply Tsai-Wu names is one of the laminate's plies, so the study's
  ``critical_ply_angle`` has magnitude α (derived here; to 1e-9 deg, a copy of a ply angle);
* wiring: the study evaluates the layup it names (code vs code; the reference is the layup
  string only): its safety factor is that of a model built from the hand-written layup string
  "(α/−α/−α/α)" with the same mesh and loads, through the same calls as critical_ply_outputs
  (same model, same solve: rel 1e-9, far above the 1e-15 round-off of repeating one
  deterministic banded solve and far below the ~2 % change of the safety factor per half
  degree of ply angle there, measured on this mesh for the tolerance only: 16.64, 16.38, 16.08
  at 47, 47.5, 48°).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.response import static_response
from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly.loads import external_static_load, torque_load
from flexshaft.design import baseline_design, with_overrides
from flexshaft.sweep.study import Point
from flexshaft.thesis.ply_angle import one_angle_layup, ply_angle_study

_COARSE = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12, "loads.eccentricity": 0.0}
# 22.5 and 47.5: half degrees near the optimum and off it; a whole-degree rounding moves both
_ANGLES = (22.5, 47.5)


@pytest.mark.parametrize("alpha", _ANGLES)
def test_layup_override_builds_the_fractional_angle_ply_stack(alpha):
    """(α/−α/−α/α) at a half-degree α: the model's laminate plies are α·π/180 with signs
    (+, −, −, +), to 1e-12 rad."""
    design = with_overrides(baseline_design(), {**_COARSE, **one_angle_layup(alpha)})
    angles = Point(0, {}, {}, design).model.shaft.laminate.angles
    expected = np.radians(alpha) * np.array([1.0, -1.0, -1.0, 1.0])
    np.testing.assert_allclose(angles, expected, rtol=0.0, atol=1e-12)


def test_study_at_a_fractional_angle_reports_its_own_critical_ply():
    """The study at α = 47.5° (near the optimum): the critical ply's angle is ±α, and (wiring,
    code vs code) the safety factor is that of the hand-written "(α/−α/−α/α)" layup's static
    Tsai-Wu check (external loads and torque, the study's definition)."""
    base = with_overrides(baseline_design(), _COARSE)
    alpha = 47.5
    ds = ply_angle_study(np.array([alpha]), design=base, progress=False)
    assert abs(float(ds["critical_ply_angle"].values[0])) == pytest.approx(alpha, abs=1e-9)
    model = Point(0, {}, {}, with_overrides(base, {"shaft.layup": f"({alpha}/-{alpha}/-{alpha}/{alpha})"})).model
    r = shaft_safety_factor(model, static_response(model, external_static_load(model) + torque_load(model)))
    assert float(ds["safety_factor"].values[0]) == pytest.approx(r.safety_factor, rel=1e-9)

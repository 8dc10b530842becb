"""The laminate of a two-angle study point holds exactly the point's ply angles.

Thesis study 2 sweeps (α/−α/β/−β)s (docs/studies.md, study 2). By the laminate notation a
symmetric "(…)s" stack is the listed plies followed by their mirror image, so (α/−α/β/−β)s is
the eight plies α, −α, β, −β, −β, β, −α, α. The CLI's angle step may be non-integer
(``flexshaft study two-angle --step`` takes any value >= 1°), so a point such as (22.5°, 67.5°)
must reach the model as 22.5° and 67.5°, not rounded or truncated.
"""

from __future__ import annotations

import numpy as np

from flexshaft.assembly import build_model
from flexshaft.design import tuned_design, with_overrides
from flexshaft.thesis.two_angles import two_angle_layup


def test_non_integer_ply_angles_reach_the_laminate():
    """(22.5/−22.5/67.5/−67.5)s built on the tuned design has the eight plies of the notation
    (module docstring). The angles pass through text, degrees and radians: their round-off is a
    few ulp of 90°, so 1e-12 degrees absolute; a truncation to whole degrees is off by 0.5°."""
    alpha, beta = 22.5, 67.5
    model = build_model(with_overrides(tuned_design(), two_angle_layup((alpha, beta))))
    expected = [alpha, -alpha, beta, -beta, -beta, beta, -alpha, alpha]
    np.testing.assert_allclose(np.degrees(model.shaft.laminate.angles), expected, rtol=0, atol=1e-12)

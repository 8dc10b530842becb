"""Thesis study 5 (torsional buckling vs wall) reports the weaker twist sense.

A laminated tube whose plies are not mirrored in sign about the axis buckles at different
torques in the two senses of twist (the ±α plies take compression in one sense and tension in
the other, and the shell's bending-twisting terms D16, D26 change sign). The driveline's sense of
rotation is fixed, but the study, like the run's check, takes the conservative weaker sense
(thesis §3.2.4, safety factor T_cr/T): so its ``critical_torque`` and its
``buckling_safety_factor`` must describe the same sense, ``critical_torque`` = SF · T with T the
transmitted torque P/Ω, computed here from the design's power P [W] and speed n [rev/min],
Ω = 2π n/60.

The baseline design with the unbalanced layup (45/0/0)s (its +45° plies have no −45° partner:
the two senses differ, measured 893 against 2096 N m at the baseline wall,
while the baseline's balanced (55/−55/0/0)s buckles at the same torque in both), at a coarse
mesh (18 shaft, 12 boom elements: the shell buckling model does not use the beam mesh) and two
walls: a few operations on the study's outputs, relative 1e-12.
"""

from __future__ import annotations

import math

import numpy as np

from flexshaft.design import baseline_design, with_overrides
from flexshaft.thesis.buckling_sweep import buckling_study


def test_buckling_study_critical_torque_is_the_weaker_sense_of_its_safety_factor():
    design = with_overrides(
        baseline_design(), {"mesh.shaft_elements": 18, "mesh.boom_elements": 12, "shaft.layup": "(45/0/0)s"}
    )
    operating = design.operating
    torque = operating.power / (2.0 * math.pi * operating.speed_rpm / 60.0)
    assert torque > 0.0
    ds = buckling_study(np.array([0.002, 0.004]), design=design, progress=False, as_arrays=True)
    critical = np.asarray(ds["critical_torque"].values, dtype=float)
    factor = np.asarray(ds["buckling_safety_factor"].values, dtype=float)
    np.testing.assert_allclose(critical, factor * torque, rtol=1e-12)
    assert critical[1] > critical[0]  # a thicker wall buckles at a larger torque

"""The force capacity an active bearing's force is held to: the design's, else its magnet's
saturation force from the magnet's geometry (derived here).

A horseshoe electromagnet pulls with the Maxwell stress B²/(2μ0) on each of its two pole faces
(area A_a each, inclined at α to the control axis: 22.5° on an 8-pole stator), so one magnet at
the saturation flux density B_sat pulls along its axis with at most

    f_sat = 2 · B_sat²/(2μ0) · A_a cos α = B_sat² A_a cos α/μ0,     μ0 = 4π·1e-7 H/m,

the largest net force of the opposed pair (its other magnet at zero flux). The Jeffcott rotor of
tests/jeffcott_bearing.py with an active bearing of 200 turns, A_a = 8 cm², g0 = 1 mm and
B_sat = 1.2 T: f_sat = 1.2² · 8e-4 · cos 22.5°/μ0 ≈ 846.9 N. Without a design ``force_capacity``
the verdict's actuator-force check (and the Monte-Carlo's force events) hold the bearing to
f_sat; with one, to the design's.

Tolerance 1e-9: a few operations (μ0's 2019 SI value differs from 4π·1e-7 by 5e-10).
"""

from __future__ import annotations

import math

import pytest
from jeffcott_bearing import model_with

from flexshaft.verdict.gather import actuator_limits

GEOMETRY = "kp = 1.0e4\nkd = 2.0\ncoil_turns = 200.0\npole_area = 8e-4\nbias_current = 4.775\nair_gap = 1e-3\n"
F_SAT = 1.2**2 * 8e-4 * math.cos(math.radians(22.5)) / (4e-7 * math.pi)


@pytest.mark.parametrize(("capacity", "expected"), [(None, F_SAT), (500.0, 500.0)])
def test_the_force_capacity_is_the_designs_else_the_magnets_saturation_force(capacity, expected):
    keys = f'kind = "active"\n{GEOMETRY}saturation_flux_density = 1.2\ngap = 5e-4\n'
    if capacity is not None:
        keys += f"force_capacity = {capacity}\n"
    (limits,) = actuator_limits(model_with(keys)).values()
    assert limits.force_capacity == pytest.approx(expected, rel=1e-9)
    assert limits.gap == 5e-4

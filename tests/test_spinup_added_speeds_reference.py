"""Speeds added to a spin-up scan (an assessment adds its refined critical speeds,
:func:`flexshaft.analyses.spinup_response.with_speeds`) carry every load case and keep the scan
in order.

Reference (closed form, derived in tests/test_critical_search_load_cases_reference.py): the rigid
rotor on three springs with the ``"worst"`` imbalance placement, whose anti-phase case (the
second) alone excites the rocking about the middle, I θ̈ + (c/2) θ̇ + (k/2) θ = M_u with the
moment of the two bay forces e M/2 Ω² at ±0.25 m, M_u = e M Ω²/4. At the rocking critical the
worst case is therefore the second, and the largest shaft orbit, at either end (0.5 m from the
middle), is 0.5 |θ|. Tolerance 1e-3, that file's: the tube's polar inertia couples the planes.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_critical_search_load_cases_reference import I_TOTAL, KB, M_TOTAL, TEXT, W_ROCK, C

from flexshaft.analyses.spinup_response import spinup_response, with_speeds
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def _end_orbit(speed: float) -> float:
    moment = 1e-5 * M_TOTAL * speed**2 / 4
    theta = moment / abs(KB / 2 - I_TOTAL * speed**2 + 1j * (C / 2) * speed)
    return 0.5 * theta


def test_an_added_speed_holds_the_worst_case_in_order():
    model = build_model(loads_design(TEXT))
    scan = spinup_response(model, np.linspace(0.2, 1.3, 12) * model.speed, projected=False)
    speed = W_ROCK * 1.001  # between two samples, not one of them
    assert not np.isin(speed, scan.speeds)
    added = with_speeds(model, scan, [speed])
    k = int(np.flatnonzero(added.speeds == speed)[0])
    assert np.all(np.diff(added.speeds) > 0) and added.speeds.size == scan.speeds.size + 1
    assert added.worst_case[k] == 1  # the anti-phase case
    assert added.shaft_peak[k] == pytest.approx(_end_orbit(speed), rel=1e-3)
    # the scan's own samples are kept as they were
    assert np.array_equal(np.delete(added.shaft_peak, k), scan.shaft_peak)
    assert added.response.shape[1] == 2

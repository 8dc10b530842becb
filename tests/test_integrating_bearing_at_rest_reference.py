"""A driveline at rest with an integrating magnetic bearing is judged, not an internal error.

``flexshaft run`` on a design with ``speed_rpm = 0`` and a PID bearing (``integral_gain``) ended
in "internal error: ValueError: actuator(s) b integrate (C(0) infinite)" until the twenty-fifth
session: the point's bearing reactions asked the integrating law for its force on the response
at speed, at 0 rad/s, where its receptance C(0) is infinite. At rest no synchronous load acts (the
imbalance force is U Ω² = 0), so the response at speed is zero and so are the forces it puts on
every bearing; the static reaction of an integrating bearing is the constraint force of the
static equilibrium (docs/magnetic-bearings.md).

Model: tests/jeffcott_bearing.py's Jeffcott rotor with its PID bearing at the disk, at rest,
with a static vertical load P at the disk. The bearing's integrator drives its sensor reading to
zero, so the disk does not move and the bearing carries the whole load, +P (docs/magnetic-
bearings.md: the force carried is G d_s − k_s d_a and the shaft receives its negative, which
balances P; the pinned ends carry nothing: the shaft is undeformed); asserted to 1e-9 of P (one
solve of the constrained static problem, condition about 1e7).
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import PID, disk, model_with

import flexshaft as fs
from flexshaft.analyses.reactions import bearing_reactions

P = 1.0e3  # N


def test_an_integrating_bearing_at_rest_carries_the_static_load_and_no_dynamic_force():
    model = model_with(PID)
    assert model.speed == 0.0 and any(a.integrates for a in model.actuators)
    v, _ = disk(model)
    loads = np.zeros(model.dofs.size)
    loads[v] = P
    q_static = np.zeros(model.dofs.size)  # the integrator holds the disk at its sensor's zero
    reactions = bearing_reactions(model, q_static, np.zeros(model.dofs.size, complex), loads=loads)
    b = reactions["b"]
    assert np.allclose(b.imbalance_force, 0.0, atol=0.0)
    assert b.static_force[1] == pytest.approx(P, rel=1e-9)
    assert b.static_force[2] == pytest.approx(0.0, abs=1e-9 * P)
    with pytest.raises(ValueError, match="q_at_speed must be zero"):
        bearing_reactions(model, q_static, np.ones(model.dofs.size, complex), loads=loads)


def test_the_assessment_of_the_driveline_at_rest_completes():
    """``flexshaft.assess`` (the recipe ``flexshaft run`` judges with) of the same rotor at rest:
    no internal error, and no force at speed on the bearing (U Ω² = 0 at rest)."""
    assessment = fs.assess(model_with(PID).design, fs.SCREENING)
    assert assessment.operating_speed == 0.0
    assert np.all(assessment.bearing_reactions["b"].imbalance_force == 0.0)
    assert assessment.verdict.checks  # judged

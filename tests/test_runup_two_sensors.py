"""Two magnetic bearings, each with its sensor off its magnet, in the run-up: the force each
carries is its own law on its own channels (tests/test_runup_actuator_force_reference.py checks
one such bearing against a closed form; here the question is which channel belongs to which
bearing, which one bearing cannot show).

Reference: the steady synchronous response of the full model (every DOF, no modal basis) and
each bearing's law applied to it, ``G_b(iΩ) d_s,b − k_s d_a,b`` with the bearing's own gains
(:meth:`flexshaft.assembly.model.Actuator.carried_force`, checked against the closed form in
that file): a run-up that starts in the steady state at Ω reports, at t = 0, the same
displacement and force at each magnet. The two bearings have different gains and sensor
offsets of opposite sense, so a channel taken for the other bearing's, or left out, changes
the force by tens of per cent. Proportional laws (K_d = 0): with a derivative part, the
non-collocated laws drive the near-massless tube's MHz bending modes unstable (spillover; the
full model's largest growth rate 2.4e6 1/s at K_d = 2 and 1 A s/m), which the run refuses once
its basis holds such a mode; the derivative part is the single-bearing file's. Tolerance 2e-4,
from the basis: the run's steady start agrees with the full model to 2.4e-3 with 4 modes,
2.2e-4 with 8 and 3.8e-5 with 16 (measured, displacement and force; 16 are used).
"""

from __future__ import annotations

import pytest
from jeffcott_bearing import U, imbalance_vector
from rotors import jeffcott_text

from flexshaft.analyses.transient import SpeedProfile, steady_state_envelope, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

BEARINGS = [  # x [m], sensor offset [m], k_i [N/A], K_p [A/m], K_d [A s/m], k_s [N/m]
    (0.3, 0.08, 100.0, 5.0e3, 0.0, 2.0e5),
    (0.7, -0.06, 60.0, 9.0e3, 0.0, 1.0e5),
]


def two_sensor_rotor():
    text = jeffcott_text(0.0, 0.0, elements=10)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    bearings = "".join(
        f'[[bearings]]\nname = "b{k}"\nx = {x}\nkind = "active"\nsensor_offset = {offset}\n'
        f"ki = {ki}\nkp = {kp}\nkd = {kd}\nks = {ks}\n"
        for k, (x, offset, ki, kp, kd, ks) in enumerate(BEARINGS)
    )
    return build_model(loads_design(head + bearings + tail))


def test_each_bearing_carries_its_own_law_on_its_own_sensor():
    model = two_sensor_rotor()
    assert [a.collocated for a in model.actuators] == [False, False]
    speed = 150.0  # rad/s
    q1 = imbalance_vector(model)
    run = transient_response(
        model, SpeedProfile.constant_acceleration(speed, speed + 1.0, 10.0), loads_per_speed_squared=q1, basis_size=16
    )
    steady = steady_state_envelope(model, [speed], q1)
    assert U > 0 and steady.actuator_force.shape == (2, 1)
    for k in range(2):
        assert run.actuator_displacement[k, 0] == pytest.approx(steady.actuator_displacement[k, 0], rel=2e-4), k
        assert run.actuator_force[k, 0] == pytest.approx(steady.actuator_force[k, 0], rel=2e-4), k

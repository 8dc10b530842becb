"""The static response at the operating speed by default, the harmonic response's static limit
ω = 0, and two integrating magnetic bearings that each hold their sensor at zero, against closed
forms (mutation hunt h35a).

1. ``static_response`` without ``speed`` spins at the model's operating speed (its docstring).
   tests/rotors.py's Jeffcott rotor (k = 48EI/L³ at the disk, the tube massless for statics)
   with the rotating-frame hysteretic loss η = 0.1 of the tube, at 3000 rpm: a constant
   deflection cycles the spinning material at Ω, whose loss adds the circulatory stiffness
   ±iηk in the disk's complex coordinate r = v + iw (tests/test_damping.py derives the
   rotating loss; the spinning material sees the constant deflection at ν = −Ω, so the
   hysteretic force is −k(1 − iη) r), so a force F in v gives k(1 − iη) r = F:
   r = F(1 + iη)/(k(1 + η²)), |r| = F/(k√(1 + η²)), and the disk turns sideways ahead of the
   load, w = +η v for Ω > 0 (the sign is what decides which whirl the loss destabilises).
   At rest r = F/k (0.5 % more).

2. ``frequency_response`` at ω = 0 (allowed: ω >= 0) is the static problem at rest: the
   dashpot's iωc vanishes, so the disk moves F/k.

   Tolerances: both are single condensations of an exact beam solution (cubic elements are exact
   under point loads): round-off only, 1e-10 relative.

3. Two PID bearings, each at its sensor, on a shaft held only axially and in torsion: in
   static equilibrium each integrator holds its sensed displacement at zero, so the shaft is a
   beam on two point supports at x = 0.25 and 0.75 m (statically determinate in each plane).
   F_v = 100 N at x = 0.4 m and F_w = 50 N at x = 0.6 m; moments about the other support give
   the forces the bearings carry: v: 100·(0.75 − 0.4)/0.5 = 70 N and 100·(0.4 − 0.25)/0.5 = 30 N;
   w: 50·(0.75 − 0.6)/0.5 = 15 N and 50·(0.6 − 0.25)/0.5 = 35 N; the displacements at the
   bearings are zero. Tolerance: round-off of an 84-DOF solve, 1e-9 relative on the forces,
   1e-12 of F/k_shaft absolute on the held displacements.

CPU: three small models, about 0.05 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import PID
from rotors import K_SHAFT, disk_dofs, jeffcott_text

from flexshaft.analyses.response import frequency_response, static_actuator_forces, static_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

F = 100.0  # N
ETA = 0.1


def test_static_response_spins_at_the_operating_speed_by_default():
    text = jeffcott_text(ETA, 0.0).replace("speed_rpm = 0.0", "speed_rpm = 3000.0")
    model = build_model(loads_design(text))
    assert model.speed == pytest.approx(3000 * 2 * np.pi / 60, rel=1e-12)
    v, w = disk_dofs(model)
    Q = np.zeros(model.dofs.size)
    Q[v] = F
    q = static_response(model, Q)
    assert np.hypot(q[v], q[w]) == pytest.approx(F / (K_SHAFT * np.sqrt(1 + ETA**2)), rel=1e-10)
    assert q[w] == pytest.approx(ETA * q[v], rel=1e-10)  # signed: w = +η v


def test_harmonic_response_at_zero_frequency_is_the_static_deflection():
    model = build_model(loads_design(jeffcott_text(0.0, 300.0)))
    v, w = disk_dofs(model)
    Q = np.zeros(model.dofs.size)
    Q[v] = F
    q = np.asarray(frequency_response(model, Q, 0.0))
    assert q[v] == pytest.approx(F / K_SHAFT, rel=1e-10)
    assert abs(q[w]) <= 1e-12 * F / K_SHAFT  # v and w uncoupled at rest


TWO_MAGNETS = f"""
name = "two integrating magnets"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800.0
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = 0.05
wall_thickness = 0.005
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "a"
x = 0.25
{PID}
[[bearings]]
name = "b"
x = 0.75
{PID}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 20
"""


def two_point_loads(model) -> np.ndarray:
    """F in v at x = 0.4 m and F/2 in w at x = 0.6 m."""
    dm = model.dofs
    Q = np.zeros(dm.size)
    Q[dm.shaft(dm.node_at("shaft", 0.4), "v")] = F
    Q[dm.shaft(dm.node_at("shaft", 0.6), "w")] = F / 2
    return Q


def assert_beam_reactions(model, Q) -> None:
    """Magnets a (x = 0.25 m) and b (0.75 m) carry the simply supported beam's reactions of
    :func:`two_point_loads`: v 70/30 N, w 15/35 N (moments about each support)."""
    forces = static_actuator_forces(model, Q)
    assert forces["a"] == pytest.approx([70.0, 15.0], rel=1e-9)
    assert forces["b"] == pytest.approx([30.0, 35.0], rel=1e-9)


def test_two_integrating_bearings_carry_the_beam_reactions():
    model = build_model(loads_design(TWO_MAGNETS))
    dm = model.dofs
    Q = two_point_loads(model)
    assert_beam_reactions(model, Q)
    q = static_response(model, Q)
    held = [q[dm.shaft(dm.node_at("shaft", x), f)] for x in (0.25, 0.75) for f in ("v", "w")]
    assert np.abs(held).max() <= 1e-12 * F / K_SHAFT
    assert np.abs(q).max() > 1e-7  # the overhangs and the span do bend

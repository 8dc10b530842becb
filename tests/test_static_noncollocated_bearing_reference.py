"""Static deflection of a rotor held by a non-collocated magnetic bearing, against superposition
on the bearing-free rotor and the linearised magnet's force law (derived here).

The Jeffcott rotor of tests/jeffcott_bearing.py (pinned-pinned tube, 20 kg disk at x = 0.5 m)
with an active bearing whose magnet sits at the disk, x_a = 0.5 m, and whose displacement
sensor sits ``sensor_offset`` = 0.125 m further on, x_s = 0.625 m. The linearised magnet pulls
the shaft with (the linearised law that defines k_s and k_i, docs/magnetic-bearings.md: f = k_s x + k_i i)

    f_shaft = k_s d_a + k_i i,    i = −k_p d_s   (a PD law at ω = 0: C(0) = k_p)

at the MAGNET, from the current set by the displacement at the SENSOR. On the bearing-free rotor
(the same design with k_p = k_s = 0: the same mesh, the tube alone), let q₀ be the deflection
under the external load Q and u the deflection under a unit force at the magnet in the same
plane (the rotor is at rest and axisymmetric: v and w decouple). Superposition gives

    q = q₀ + u f,   d_a = d_a0 + α_a f,   d_s = d_s0 + α_s f   (α_a = u at x_a, α_s = u at x_s)
    f = k_s d_a − k_i k_p d_s  ⇒  f = (k_s d_a0 − g d_s0) / (1 − k_s α_a + g α_s),  g = k_i k_p,

and the bearing carries −f. The verdict's static offset of the bearing (added to its spin-up
orbit against the auxiliary bearing's gap, which sits at the magnet) is |(d_a,v, d_a,w)|. With
k_s = 2e5 N/m and g = 5e5 N/m against the tube's 1.8e6 N/m at the disk, f in the loaded plane is
−12.3 N; k_s acting as a positive stiffness makes it −26.5 N, and a force applied at the sensor
and sensed at the magnet (the transpose) moves the deflections well beyond the tolerance.

Tolerance: both sides are a handful of sparse solves of a 6-node tube whose static stiffness
(rotations included) has a condition number of 3e5; they agree to a relative 1e-9 (round-off
ε·cond ≈ 7e-11, with margin). The model is the shared 4-element rotor (a node at the sensor
added): the superposition holds on any mesh, both sides using the same one.
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import numpy as np
import pytest
from jeffcott_bearing import KI, KP, KS, model_with

from flexshaft.analyses.response import static_actuator_forces, static_response
from flexshaft.assembly.loads import point_load
from flexshaft.verdict import gather

OFFSET = 0.125  # m, sensor beyond the magnet
LOAD_V, LOAD_W = 100.0, -40.0  # N, at the disk (v) and at x = 0.8125 m (w)


def _rotor(kp: float, ks: float):
    return model_with(f'kind = "active"\nkp = {kp}\nkd = 2.0\nks = {ks}\nki = {KI}\nsensor_offset = {OFFSET}')


@pytest.fixture(scope="module")
def rotors():
    return _rotor(KP, KS), _rotor(0.0, 0.0)


def _load(model) -> np.ndarray:
    at_disk = point_load(model, "shaft", (0.0, LOAD_V, 0.0), x=0.5)
    return at_disk + point_load(model, "shaft", (0.0, 0.0, LOAD_W), x=0.8125)


def _superposed(bare, axis: int) -> tuple[float, float]:
    """(f on the shaft, d_a) in plane ``axis`` (0: v, 1: w) from the bearing-free rotor's deflections."""
    a = bare.actuators[0]
    Ba, Bs = a.lateral_rows.toarray(), a.sensing_rows.toarray()
    q0 = static_response(bare, _load(bare), speed=0.0)
    u = static_response(bare, Ba[axis], speed=0.0)  # unit force at the magnet in this plane
    d_a0, d_s0, alpha_a, alpha_s = Ba[axis] @ q0, Bs[axis] @ q0, Ba[axis] @ u, Bs[axis] @ u
    g = KI * KP
    f = float((KS * d_a0 - g * d_s0) / (1.0 - KS * alpha_a + g * alpha_s))
    return f, float(d_a0 + alpha_a * f)


def test_the_magnet_acts_at_its_station_with_the_sensors_displacement(rotors):
    held, bare = rotors
    assert not held.actuators[0].collocated
    q = static_response(held, _load(held), speed=0.0)
    Ba = bare.actuators[0].lateral_rows.toarray()
    expected = static_response(bare, _load(bare), speed=0.0)
    for axis in (0, 1):
        expected = expected + static_response(bare, Ba[axis], speed=0.0) * _superposed(bare, axis)[0]
    np.testing.assert_allclose(q, expected, rtol=1e-9, atol=1e-9 * np.abs(expected).max())


def test_the_bearing_carries_minus_the_force_it_puts_on_the_shaft(rotors):
    held, bare = rotors
    carried = static_actuator_forces(held, _load(held), speed=0.0)[held.actuators[0].name]
    f = np.array([_superposed(bare, 0)[0], _superposed(bare, 1)[0]])
    np.testing.assert_allclose(carried, -f, rtol=1e-9, atol=1e-9 * np.abs(f).max())


def test_the_verdicts_static_offset_is_the_deflection_at_the_magnet(rotors):
    held, bare = rotors
    name = held.actuators[0].name
    spinup = NS(up_to=lambda speed: np.zeros(0, int), actuator_displacement={name: []}, actuator_force={name: []})
    p = NS(
        model=held,
        spinup=spinup,
        static_displacement=static_response(held, _load(held), speed=0.0),
        bearing_reactions={name: NS(static_lateral=0.0)},
        operating_speed=held.speed,
        design=held.design,  # its [operating]: the spin-up checks end at its highest speed
    )
    (evidence,) = gather._actuators(p)
    offset = np.hypot(_superposed(bare, 0)[1], _superposed(bare, 1)[1])
    assert evidence.static_offset == pytest.approx(offset, rel=1e-9)

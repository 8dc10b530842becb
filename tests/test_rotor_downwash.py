"""Hover downwash over the tailboom from momentum theory (thesis eq. 2.56).

Reference: actuator-disk momentum theory in hover (the thesis cites Johnson 1980): the thrust
equals the weight, T = 2 ρ A v², so the induced velocity at the disk is v = √(W / (2 ρ π R²)).
With the thesis's AH-64 numbers (m = 6838 kg, R = 7.315 m, ρ = 1.225 kg/m³, standard g):
v = 12.76 m/s, computed here from the formula, not from the package.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.thermal.environment import ThermalEnvironment


def test_induced_velocity_is_the_momentum_theory_value():
    env = ThermalEnvironment(rotorcraft_mass=6838.0, rotor_radius=7.315, air_density=1.225)
    weight = 6838.0 * 9.80665
    expected = math.sqrt(weight / (2 * 1.225 * math.pi * 7.315**2))
    assert env.downwash_velocity == pytest.approx(expected, rel=1e-9)
    assert expected == pytest.approx(12.76, abs=0.01)
    # thrust = 2 ρ A v² recovers the weight
    v = env.downwash_velocity
    assert 2 * 1.225 * math.pi * 7.315**2 * v**2 == pytest.approx(weight, rel=1e-9)

"""Finite-volume shaft temperature on non-uniform meshes against exact conduction solutions
(mutation hunt h35d).

Closed forms (steady 1-D conduction along the wall, no convection, h = 0; Incropera & DeWitt
§3.1 plane wall and §3.5 with uniform generation), typed here:

* no heat, ends held at T_a and T_b, conductance k_e A_e / L_e per element in series: the heat
  flow q is the same through every element, q = (T_a - T_b) / sum_e L_e/(k_e A_e), and the
  temperature drops by q L_e/(k_e A_e) across each (thermal resistances in series); with one
  k A the profile is the straight line T_a + (T_b - T_a) x / L. The forward end then takes in q
  (end flow -q) and the aft end gives out q.
* uniform heat q' [W/m] per length, one k A, both ends at T_inf:
  T = T_inf + q' x (L - x) / (2 k A), and each end carries away q' L / 2.

The vertex-centred scheme reproduces both exactly on ANY mesh: the flux between two nodes,
k A (T_j - T_i)/L_e, is exact for a linear and for a quadratic profile (the chord slope of a
parabola is its slope at the mid-point), and the source lumped half to each end node is what
the exact flux difference across the control volume requires. So tolerances are rounding
only: 1e-10 relative to the temperature rise. An element's temperature is the mean of its end
nodes (the exact element mean of a linear profile).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.thermal.shaft import solve_shaft_temperature

X = np.array([0.0, 0.1, 0.35, 0.45, 0.9, 1.0, 1.6])  # deliberately non-uniform [m]
L = np.diff(X)
T_INF = 300.0


def test_series_conduction_between_two_end_temperatures():
    k = np.array([5.0, 5.0, 1.0, 3.0, 3.0, 0.5])  # W/(m K), e.g. segments of other laminates
    A = np.array([2e-4, 2e-4, 3e-4, 3e-4, 1e-4, 1e-4])  # m^2
    Ta, Tb = 340.0, 310.0
    res = solve_shaft_temperature(X, np.zeros(L.size), k, A, 0.15, 0.0, T_INF, (Ta, Tb))
    R = L / (k * A)
    q = (Ta - Tb) / R.sum()
    expected = Ta - q * np.concatenate([[0.0], np.cumsum(R)])
    np.testing.assert_allclose(res.temperature, expected, rtol=0, atol=1e-10 * (Ta - Tb))
    assert res.end_flows[0] == pytest.approx(-q, rel=1e-9)
    assert res.end_flows[1] == pytest.approx(q, rel=1e-9)


def test_linear_profile_and_element_means_on_a_non_uniform_mesh():
    Ta, Tb = 350.0, 320.0
    res = solve_shaft_temperature(X, np.zeros(L.size), 4.0, 2e-4, 0.15, 0.0, T_INF, (Ta, Tb))
    line = Ta + (Tb - Ta) * X / X[-1]
    np.testing.assert_allclose(res.temperature, line, rtol=0, atol=1e-10 * (Ta - Tb))
    mid = 0.5 * (X[:-1] + X[1:])
    np.testing.assert_allclose(res.element_temperature, Ta + (Tb - Ta) * mid / X[-1], rtol=0, atol=1e-10 * (Ta - Tb))


def test_uniform_generation_gives_the_exact_parabola():
    k, A, q_line = 4.0, 2e-4, 3.0  # W/(m K), m^2, W/m
    res = solve_shaft_temperature(X, q_line * L, k, A, 0.15, 0.0, T_INF)
    exact = T_INF + q_line * X * (X[-1] - X) / (2 * k * A)
    rise = exact.max() - T_INF
    np.testing.assert_allclose(res.temperature, exact, rtol=0, atol=1e-10 * rise)
    assert res.end_flows == pytest.approx((q_line * X[-1] / 2, q_line * X[-1] / 2), rel=1e-9)

"""One on-line eigenvalue when two lower-branch roots of a gap match one upper-branch root.

Jeffcott rotor (tests/rotors.py) with k_v = 0.22 k in v only, eta = 0.1, Omega = 1.01 w_n.
Per unit disk mass the two planes obey, on T_mu = (1 - mu) T- + mu T+,
(m s^2 + k + k_v + i mu eta k)(m s^2 + k + i mu eta k) + ((1 - mu) eta k)^2 = 0.
mu = 0 (lower branch): k_v > 2 eta k, so both roots are loss-free, 1.0316 and 1.0751 w_n, both
above the spin (wrong side); their vectors lean into w by MAC 0.708 and 0.292 (both >= 0.25).
mu = 1 (upper branch): w root 1.00125 w_n (below the spin: wrong side), v root 1.1055 w_n (own
side).  Only the w path crosses Im s = Omega (mu = 0.371, s = -0.018361 + 1.01 i w_n): one
on-line eigenvalue.  A one-sided pairing also pairs the 0.292 lower root with the w root and
reports the same on-line root twice (derived here).

The closed form is the 2-DOF disk model; the model's tube (3.5e-6 of the disk's mass) moves the
roots by 8.6e-7 relative (measured) and the gap's roots are solved to within 1e-9 Ω of the line:
tolerance 1e-5 relative. The two roots below 2 ω_n (1.01 and 1.105 ω_n) are compared sorted by
frequency, 9 % apart.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text
from scipy.optimize import brentq

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import consistent_roots, damped_modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA, K_V, SPEED = 0.1, 0.22 * K_SHAFT, 1.01 * WN


def _blended(mu):
    a = K_SHAFT + K_V + 1j * mu * ETA * K_SHAFT
    b = K_SHAFT + 1j * mu * ETA * K_SHAFT
    p = np.roots([1.0, a + b, a * b + ((1 - mu) * ETA * K_SHAFT) ** 2])  # m s^2
    s = np.sqrt(p / M_DISK + 0j)
    s = np.where(s.imag < 0, -s, s)
    return s[np.argsort(np.abs(s))]


def test_two_lower_roots_matching_one_upper_root_give_one_line_root():
    lower, upper = _blended(0.0), _blended(1.0)
    assert upper[0].imag < SPEED < lower[0].imag and upper[1].imag > SPEED
    mu = brentq(lambda m: _blended(m)[0].imag - SPEED, 0.0, 1.0, xtol=1e-15)
    line = _blended(mu)[0]
    text = jeffcott_text(ETA, 0.0, elements=4).replace("stiffness = {}", f"stiffness = {{ v = {K_V} }}")
    red = reduce(build_model(loads_design(text)), 6)
    for s in (consistent_roots(red, SPEED)[0], damped_modes(red, SPEED, 3)[0]):
        low = np.sort_complex(s[np.abs(s) < 2 * WN] * -1j) * 1j  # by frequency (Im s)
        assert low.size == 2, low
        assert low[0] == pytest.approx(line, rel=1e-5)
        assert low[1] == pytest.approx(upper[1], rel=1e-5)

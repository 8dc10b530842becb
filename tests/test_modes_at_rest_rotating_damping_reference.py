"""The modes at rest of an operating point are solved at rest, whatever its speed.

Reference (derived here, the Jeffcott rotor of tests/rotors.py): disk mass m, shaft stiffness k,
ω_n = √(k/m), external viscous damping c_e and a rotating hysteretic loss factor η. In the
stationary complex coordinate a whirl r = e^{st}, s = σ + iω, obeys
m s² + c_e s + k (1 + i η sgn(ω − Ω)) = 0; for light damping σ = −c_e/(2m) − (η ω_n/2) sgn(ω − Ω).
At rest (Ω = 0) both whirls decay at σ = −c_e/(2m) − η ω_n/2; with c_e = η k/(2 ω_n),
c_e/(2m) = η ω_n/4, so σ = −(3/4) η ω_n for both. At Ω_op = 1.2 ω_n the forward whirl grows at
σ = +η ω_n/4 instead: ``modes_at_rest`` taken at the operating speed would show it unstable.
First-order in η = 0.02 (the next term is O(η²) ≈ 4e-4 relative) and the tube's mass 3.5e-6 of
the disk's: measured 3e-5 relative in σ and 4e-5 in ω, 1e-3 asserted.
"""

from __future__ import annotations

import numpy as np
from conftest import SMALLEST
from rotors import K_SHAFT, WN, jeffcott_text

from flexshaft.design import loads_design
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict.operating_point import analyse_point

ETA = 0.02


def test_both_whirls_at_rest_decay_at_the_damping_of_rest():
    c_e = 0.5 * ETA * K_SHAFT / WN
    text = jeffcott_text(ETA, c_e).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(1.2 * WN)}")
    point = analyse_point(loads_design(text), SMALLEST, detail=True)
    found = point.modes_at_rest
    assert found is not None
    s = np.asarray(found.eigenvalues)[np.asarray(found.kind) == "lateral"][:2]
    expected = -0.75 * ETA * WN
    assert s.size == 2 and np.all(np.abs(s.real / expected - 1.0) < 1e-3), s
    assert np.all(np.abs(s.imag / WN - 1.0) < 1e-3), s

"""An overdamped torsional mode is matched with its own real root, not another mode's.

Held forward end, near-massless steel shaft (tests/test_torsional.py's ``shaft_text``), elastic
drive to a tail rotor with aerodynamic damping: one slow mode, the rotor J_r = J_tr/n² on the
springs in series 1/k_eff = 1/k_shaft + 1/k_input + n²/k_hub, damped by c_r = dQ/dΩ / n² (the
``[tail_rotor]`` reflection, flexshaft.design.drivetrain: "``aerodynamic_damping/n²`` when
given"). Its characteristic equation J_r s² + c_r s + k_eff = 0 has, for c_r² > 4 J_r k_eff,
the two real roots s = (−c_r ± sqrt(c_r² − 4 J_r k_eff)) / (2 J_r) (derived here).

``torsional_modes`` pairs each undamped mode with the nearest damped root not yet taken. The
real roots came from a complex eigen-solution, which scatters them by round-off to either
side of the real axis, and only roots with Im s > 0 were kept: the overdamped mode found no
root of its own and took the next mode's (ω = 2.3e6 rad/s, ζ ≈ 0), so two modes reported one
eigenvalue. The nearest real root to iω_n is the slower one (|s| smaller), reported with
damped frequency 0 and ζ = −Re s/|s| = 1 (the class's definition).

Tolerance: the shaft's own inertia (1e-7 of the rotor's, tests/test_torsional.py) and the
conditioning of the near-massless nodes move the lumped roots by about 5e-8 relative; 1e-6.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import K_SHAFT, model_of, shaft_text

from flexshaft.analyses.torsional import torsional_modes

J_TR, RATIO, K_INPUT, K_HUB = 12.0, 3.4, 4.0e4, 2.5e5
J_R = J_TR / RATIO**2
K_EFF = 1.0 / (1.0 / K_SHAFT + 1.0 / K_INPUT + RATIO**2 / K_HUB)


def _modes(c_r: float):
    text = shaft_text(
        f"[tail_rotor]\nblades = 4\npolar_inertia = {J_TR}\ngearbox_ratio = {RATIO}\n"
        f"input_stiffness = {K_INPUT}\nhub_stiffness = {K_HUB}\naerodynamic_damping = {c_r * RATIO**2}\n"
    )
    return torsional_modes(model_of(text))


def test_an_overdamped_rotor_mode_takes_its_slower_real_root():
    c_r = 1000.0  # about 4x critical: 2 sqrt(J_r k_eff) = 230 N m s
    assert c_r**2 > 4 * J_R * K_EFF
    slow = (-c_r + np.sqrt(c_r**2 - 4 * J_R * K_EFF)) / (2 * J_R)
    tm = _modes(c_r)
    assert tm.natural_frequencies[0] == pytest.approx(np.sqrt(K_EFF / J_R) / (2 * np.pi), rel=1e-6)
    assert tm.eigenvalues[0].real == pytest.approx(slow, rel=1e-6)
    assert tm.frequencies[0] == 0.0  # a real root: no oscillation
    assert tm.damping_ratios[0] == pytest.approx(1.0, abs=1e-12)


def test_every_mode_keeps_a_root_of_its_own():
    """No root is reported twice: the higher modes keep theirs (each within a part in 1e6 of its
    undamped frequency: the shaft carries no damping)."""
    tm = _modes(1000.0)
    s = tm.eigenvalues
    apart = np.abs(s[:, None] - s[None, :])
    assert np.min(apart[~np.eye(s.size, dtype=bool)]) > 0.0
    higher = 2 * np.pi * tm.natural_frequencies[1:]
    np.testing.assert_allclose(s[1:].imag, higher, rtol=1e-6)


def test_an_underdamped_rotor_mode_keeps_its_complex_root():
    """The same drive at c_r = 50 N m s (below critical): s = −c_r/(2 J_r) + i sqrt(k_eff/J_r − (c_r/(2 J_r))²)."""
    c_r = 50.0
    tm = _modes(c_r)
    sigma = c_r / (2 * J_R)
    expected = complex(-sigma, np.sqrt(K_EFF / J_R - sigma**2))
    assert tm.eigenvalues[0] == pytest.approx(expected, rel=1e-6)

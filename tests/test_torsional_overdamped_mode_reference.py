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
root of its own, and every mode shifted to the next one's root (mode 1, 110.7 rad/s, reported
s = 2.3e6i, ζ ≈ 0; the last mode reused a root already taken). Now a lossless system's real
roots (Im s = 0 exactly from a real eigen-solution: LAPACK's 2x2 standardisation sets it to
0) are kept. The nearest real root to iω_n is the slower one (|s| smaller), reported with
damped frequency 0 and ζ = −Re s/|s| = 1 (the class's definition).

With the forward end free in twist (a disk J_1 there) the driveline also has a rigid-body
twist: J_1 θ_1'' + k (θ_1 − θ_2) = 0, J_r θ_2'' + c_r θ_2' + k (θ_2 − θ_1) = 0 give
s (J_1 J_r s³ + J_1 c_r s² + (J_1 + J_r) k s + c_r k) = 0 (derived here): the rigid twist's
root 0, which it takes (round-off put it at ±1e-7 and gave the overdamped mode ζ = −1 on one
BLAS kernel, +1 on another), and three real roots for c_r = 1000 N m s, of which the
overdamped elastic mode reports one (the class's docstring: "without loss the one nearest iω_n
of those left").

Tolerance: the shaft's own inertia is 1e-7 of the rotor's (tests/test_torsional.py); the
roots agree with the lumped closed forms to 1e-10 measured (default, Prescott and Haswell
kernels), and across kernels to 1e-7 for the slowest root (-1.09 s^-1 beside a spectrum up to
4e7 rad/s): asserted to 1e-6.
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
    assert tm.frequencies[0] == 0.0  # a real root from a real eigen-solution: Im s = 0 exactly
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


def test_a_rigid_twist_takes_the_root_at_the_origin_and_the_elastic_mode_a_real_root():
    c_r, j_1 = 1000.0, 1000.0
    text = shaft_text(
        f'[[disks]]\nname = "hub"\nx = 0.0\nmass = 1.0\npolar_inertia = {j_1}\n'
        f"[tail_rotor]\nblades = 4\npolar_inertia = {J_TR}\ngearbox_ratio = {RATIO}\n"
        f"input_stiffness = {K_INPUT}\nhub_stiffness = {K_HUB}\naerodynamic_damping = {c_r * RATIO**2}\n",
        fixed_start='["u", "v", "w"]',
    )
    tm = torsional_modes(model_of(text))
    cubic = np.roots([j_1 * J_R, j_1 * c_r, (j_1 + J_R) * K_EFF, c_r * K_EFF])
    assert np.all(np.abs(cubic.imag) == 0.0) and np.all(cubic.real < 0)  # overdamped: three real roots
    assert tm.natural_frequencies[0] == 0.0 and tm.eigenvalues[0] == 0.0
    elastic = np.sqrt(K_EFF * (j_1 + J_R) / (j_1 * J_R))
    # the mass matrix's conditioning, J_1 over a shaft node's 5.6e-9 kg m² (1.8e11), bounds the
    # eigen-solutions' error by about ε·1.8e11 = 4e-5 (measured 1.3e-5 for ω_n): asserted to 5e-5
    assert 2 * np.pi * tm.natural_frequencies[1] == pytest.approx(elastic, rel=5e-5)
    assert np.min(np.abs(tm.eigenvalues[1] - cubic.real) / np.abs(cubic.real)) < 5e-5
    assert tm.damping_ratios[1] == pytest.approx(1.0, abs=1e-12)  # never −1: a decaying root
    elastic_roots = tm.eigenvalues[1:]  # each elastic mode its own root
    apart = np.abs(elastic_roots[:, None] - elastic_roots[None, :])
    assert np.min(apart[~np.eye(elastic_roots.size, dtype=bool)]) > 0.0

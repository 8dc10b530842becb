"""Mode numbering: every list of modes is in increasing damped frequency, and the modes at rest,
the Campbell diagram and the whirl stability number a mode alike.

The tuned design has heavily damped actuator modes (ζ ≈ 0.13) beside lightly damped shaft modes
near 54 Hz: ordered by |s| (the undamped natural frequency) mode 9 at 53.96 Hz came before
mode 10 at 53.66 Hz in the tables, which print the damped frequency Im s / 2π.
"""

from __future__ import annotations

import numpy as np

import flexshaft as fs
from flexshaft.analyses import campbell, stability
from flexshaft.analyses.eigen import lowest_modes
from flexshaft.design import embedded_design
from flexshaft.thesis.designs import thesis_tuned_design

#: Modal basis shared by the three analyses compared, so that they solve the same reduced
#: problem; each refines its roots by Newton's method to 1e-10 relative (analyses.eigen), so
#: the same root agrees to far better than 1e-8 between them.
BASIS = 60
SAME_ROOT = 1e-8


def test_lowest_modes_picks_by_damped_frequency_among_the_lowest_undamped():
    """Hand-made roots: a heavily damped one (|s| 51, Im 9) is numbered before two light ones
    (Im 10, 10.5); a near-critically damped root (Im 1, |s| 1e6) is not chosen although its Im
    is the lowest, because it is not among the 2n of lowest |s|."""
    s = np.array([-1e6 + 1j, -1 + 10j, -0.01 + 10.5j, -50 + 9j, -0.1 + 60j, -0.1 + 70j, -0.1 + 80j])
    np.testing.assert_array_equal(lowest_modes(s, 2), [3, 1])
    np.testing.assert_array_equal(lowest_modes(s, 3), [3, 1, 2])
    assert 0 not in lowest_modes(s, 3)
    np.testing.assert_array_equal(lowest_modes(np.array([5 + 0j, -1 + 3j]), 2), [0, 1])  # divergent root first


def test_modes_are_numbered_by_damped_frequency_and_a_short_list_starts_a_long_one():
    model = fs.build_model(thesis_tuned_design())  # the design of the issue (the tuned design as the thesis tuned it)
    for speed in (0.0, model.speed):
        short = fs.modes(model, speed, 10, basis_size=BASIS)
        long = fs.modes(model, speed, 12, basis_size=BASIS)
        assert np.all(np.diff(long.frequencies) >= 0), long.frequencies
        np.testing.assert_allclose(short.eigenvalues, long.eigenvalues[:10], rtol=SAME_ROOT)
    # the case of the issue: the heavily damped 53.66 Hz mode before the 53.96 Hz one
    at_rest = fs.modes(model, 0.0, 12)
    heavy = int(np.argmax(at_rest.damping_ratios))
    assert at_rest.damping_ratios[heavy] > 0.1
    light = [k for k in range(12) if at_rest.damping_ratios[k] < 0.05 and 53.8 < at_rest.frequencies[k] < 54.1]
    assert light and heavy < light[0]


def test_campbell_and_stability_number_the_modes_as_the_modes_at_rest():
    """Column k of the Campbell diagram and of the whirl stability at rest is mode k + 1 of the
    table of modes at rest (the report's critical speeds and whirl onset name modes by it)."""
    model = fs.build_model(embedded_design("tuned"))
    at_rest = fs.modes(model, 0.0, 12, basis_size=BASIS)
    speeds = np.linspace(0.0, model.speed, 5)
    c = campbell(model, speeds, n_modes=12, basis_size=BASIS)
    s = stability(model, speeds, n_modes=10, basis_size=BASIS)
    np.testing.assert_allclose(c.eigenvalues[0], at_rest.eigenvalues, rtol=SAME_ROOT)
    np.testing.assert_allclose(s.eigenvalues[0], at_rest.eigenvalues[:10], rtol=SAME_ROOT)

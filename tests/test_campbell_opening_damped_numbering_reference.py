"""The Campbell diagram's first speed takes the modes of lowest damped frequency with their shapes.

Documented rule (docs/model.md: "Modes are numbered by damped frequency Im s ... the n of lowest
Im s among the 2n of lowest |s|"), on the rotor of
tests/test_heavily_damped_bearing_mode_numbering_reference.py: the Jeffcott test tube
(tests/rotors.py: near-massless pinned-pinned steel tube, rotating-frame loss factor η) with a
lighter midspan disk (m = 0.5 kg) on a stiff, heavily damped contact bearing at the disk
(stiffness k_b, dashpot c in v and w). Derived here (as there):

* the antisymmetric shaft pair (A): the disk sits on its node, s_A = iω₂√(1 + iη) to first
  order, ω₂ the tube's second pinned-pinned frequency;
* the disk pair (B): the tube condenses onto the disk as k_s(1 + iησ), k_s = 48EI/L³; at the
  speeds used, Ω ≤ 0.11 ω₂ < Im s_B ≈ 0.96 ω₂, so the forward whirl is above the spin
  (σ = +1) and the backward whirl has the loss k_s(1 + iη) on either branch: both B roots solve
  m s² + c s + k_b + k_s(1 + iη) = 0 (the tube's gyroscopic term splits them by 2–4e-8; the
  disk has no polar inertia). The shaft's loss moves s_B by < 1e-7 (4e-8 relative): the 5e-4
  check verifies the numbering and shapes, not the branch.

|s_B| ≈ 1.08 ω₂ > |s_A| but Im s_B < Im s_A, so of n = 3 modes the rule lists the disk's axial
mode and the B pair, not the A pair, from the first speed on. The tracked curves at the first
speed are those roots with their own shapes: each B curve is a whirl of the disk (forward and
backward), not a root without a shape.

Tolerance: the tube's mass (7.1e-5 kg) is 1.4e-4 of the disk's, which the condensation to k_s
neglects; s_B is asserted to 5e-4 relative (measured 4e-5), while s_A lies 8 % away. Speeds
0.05-0.11 ω₂ stay under the design speed limit (1e6 rev/min). CPU: a 48-DOF model, three
speeds, under 0.1 s.
"""

from __future__ import annotations

import numpy as np

# the heavily-damped-bearing rotor of the numbering test at rest, its closed-form disk pair
from test_heavily_damped_bearing_mode_numbering_reference import ETA, W2, _disk_root, _model

from flexshaft.analyses import campbell
from flexshaft.analyses.eigen import lowest_modes, reduce
from flexshaft.analyses.hysteretic_roots import lowest_roots

SPEEDS = np.array([0.05, 0.08, 0.11]) * W2


def test_the_first_speed_tracks_the_damped_bearing_pair_with_its_whirl():
    s_b = _disk_root()
    s_a = 1j * W2 * np.sqrt(1 + 1j * ETA)
    assert abs(s_b) > 1.05 * abs(s_a) and s_b.imag < 0.97 * s_a.imag  # the premise, from the closed forms
    assert SPEEDS.max() < 0.2 * s_b.imag  # the B pair lies above the spin at every speed
    c = campbell(_model(), SPEEDS, n_modes=3)
    for k in range(SPEEDS.size):
        high = c.eigenvalues[k][c.eigenvalues[k].imag > 0.5 * W2]  # the axial mode lies far below
        assert high.size == 2, (k, c.eigenvalues[k])
        np.testing.assert_allclose(high, [s_b, s_b], rtol=5e-4)
        assert sorted(c.whirl[k][c.eigenvalues[k].imag > 0.5 * W2]) == ["backward", "forward"], (k, c.whirl[k])


def test_lowest_roots_gives_the_numbered_modes_their_vectors():
    """lowest_roots' contract (its docstring): unit modal coordinates for the modes of
    lowest_modes, the rule quoted above; here those are the axial mode and the B pair."""
    red = reduce(_model(), 20)
    s, Y = lowest_roots(red, SPEEDS[0], 3)
    wanted = lowest_modes(s, 3)
    np.testing.assert_allclose(s[wanted][s[wanted].imag > 0.5 * W2], [_disk_root()] * 2, rtol=5e-4)
    np.testing.assert_allclose(np.linalg.norm(Y[:, wanted], axis=0), 1.0, rtol=1e-12)

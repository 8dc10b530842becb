"""A passive check without loss counts the real roots of an overdamped mode among its roots.

Rule: the API contract of ``RootStability.n_roots`` (its docstring in
flexshaft.analyses.root_stability: code, not a hand-written doc): the roots examined at each
speed are the oscillatory roots (Im s > 0) and the real roots of the loss-free state matrix;
only a passive check *with* the loss, which solves no loss-free state matrix, counts its
loss-consistent roots alone.

Reference (derived here). The Jeffcott-like rotor of tests/rotors.py without loss (η = 0) and
with its disk dashpot at ζ_e = 2 (c_e = 4 m ω_n): a passive driveline (no actuator law), whose
disk obeys m s² + c_e s + k = 0 in each lateral plane, two real roots −(2 ± √3) ω_n per
plane: four real roots. At rest they are exactly real; at 1.5 ω_n the model's gyroscopic
coupling leaves them an imaginary part, Im/|s| = 3.8e-9 at most (measured on the reduced
state matrix, default and Prescott kernels alike), 260 times below the code's real-root
threshold |Im s| ≤ 1e-6 |s|, so they are still read as real. Every other root is
lightly damped (ζ ≤ 4e-10 measured: the dashpot sits at the disk, which the tube's own modes
barely move), so it contributes one oscillatory root and no real one. The roots examined
therefore exceed the oscillatory roots listed by exactly four at each speed, and the basis's
2 n_b states are the 2 × (n_b − 2) oscillatory roots and their conjugates plus the four real
roots. Counts are integers: compared exactly. A few hundredths of a second.
"""

from __future__ import annotations

import numpy as np
from rotors import M_DISK, WN, jeffcott

from flexshaft.analyses.root_stability import root_stability


def test_the_overdamped_disk_modes_real_roots_are_counted_at_every_speed():
    model = jeffcott(0.0, 4 * M_DISK * WN)
    assert not model.has_loss
    result = root_stability(model, [0.0, 1.5 * WN])
    assert result.method == "passive" and result.stable
    assert result.basis_size > 2  # a reduced basis beyond the disk's two modes: the tube's modes too
    for count, roots in zip(result.n_roots, result.roots):
        assert np.all(roots.imag > 0)
        assert roots.size == result.basis_size - 2  # the disk's two modes give no oscillatory root
        assert count == roots.size + 4  # the four real roots −(2 ± √3) ω_n, two per plane
        assert count == 2 * result.basis_size - roots.size  # every state's root counted once

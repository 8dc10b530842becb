"""Critical speeds of the Campbell diagram and the onset of whirl instability, against exact
crossings.

References (derived here):

* an undamped rotor without gyroscopic stiffening (the Jeffcott rotor of tests/rotors.py: a
  disk without polar inertia) has whirl frequencies ω_n independent of Ω, so the excitation
  line ω = kΩ of order k crosses them at Ω = ω_n / k exactly (a line crossing a constant:
  the linear interpolation between grid speeds is exact);
* :func:`onset_speed` interpolates the damping ratio linearly between the last stable and the
  first unstable speed (its docstring): for a damping ratio that is linear in Ω the
  interpolated zero is the exact one, whatever the grid; the earliest crossing of all modes
  counts.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import WN, jeffcott

from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.stability import onset_speed


def test_critical_speeds_of_each_excitation_order_are_omega_n_over_k():
    model = jeffcott(0.0, 0.0)
    speeds = np.linspace(0.0, 1.6 * WN, 9)  # coarse: the crossings fall between grid points
    c = campbell(model, speeds, n_modes=2, harmonics=(1.0, 2.0, 3.0), damped=False)
    found = {}
    for crit in c.critical_speeds:
        found.setdefault(crit.harmonic, []).append(crit.speed)
    assert sorted(found) == [1.0, 2.0, 3.0]
    for k, values in found.items():
        # the two planar disk modes each cross once; the tube's mass (7e-6 of the disk's)
        # moves ω_n by a few 1e-6 from its closed form
        assert len(values) == 2
        assert values == pytest.approx([WN / k] * 2, rel=1e-5)


def zeta_curves(speeds, zeta0, crossing, omega=300.0):
    """Eigenvalues of a mode whose damping ratio falls linearly to zero at ``crossing``."""
    zeta = zeta0 * (1.0 - speeds / crossing)
    return omega * (-zeta + 1j * np.sqrt(1.0 - zeta**2))


def test_onset_speed_is_the_zero_of_a_linear_damping_ratio():
    speeds = np.linspace(0.0, 1000.0, 7)  # grid 166.7 rad/s
    first = zeta_curves(speeds, 0.02, 590.0)
    later = zeta_curves(speeds, 0.05, 780.0, omega=900.0)
    stable = zeta_curves(speeds, 0.03, 5000.0, omega=50.0)
    eig = np.column_stack([stable, later, first])
    speed, mode, index = onset_speed(speeds, eig)
    assert mode == 2 and speed == pytest.approx(590.0, rel=1e-12)
    assert speeds[index - 1] < 590.0 < speeds[index]
    # the same mode alone, and with its crossing just past a grid point
    speed, _, _ = onset_speed(speeds, zeta_curves(speeds, 0.02, 700.0)[:, None])
    assert speed == pytest.approx(700.0, rel=1e-12)
    assert onset_speed(speeds, stable[:, None]) == (None, None, None)

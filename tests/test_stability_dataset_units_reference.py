"""The whirl-stability data file's speeds are in the units it names (rad/s), on the Jeffcott
rotor of tests/rotors.py with the viscous internal-damping method.

Reference, derived here (as in tests/test_stability.py's module docstring): the shaft's viscous
internal damping c_i = η k / ω_ref condenses onto the disk, and in complex coordinates r = v + iw
the forward mode obeys m s² + (c_e + c_i) s + k − iΩ c_i = 0. At the onset Re s = 0: with
s = iω the real part gives −mω² + k = 0, ω = ω_n, and the imaginary part
ω(c_e + c_i) − Ω c_i = 0, so Ω_onset = ω_n (1 + c_e / c_i) = ω_n (1 + 2 ζ_e / η) = 1.5 ω_n here.

The grid (0, 1.2 ω_n, 2 ω_n) brackets the onset between its last two speeds, where the regula
falsi solves it to 1e-7 of the speed. Tolerance 1e-5 relative: the near-massless shaft (3.5e-6 of
the disk's mass; its modal mass shifts ω_n, hence the onset, by −½ (17/35) 3.5e-6 ≈ −8.6e-7, a
deterministic offset) and the reduced basis (chosen for a relative eigenvalue accuracy of 1e-6)
move the onset by O(1e-6) (measured −8.5e-7); a unit slip to rpm is a factor 30/π ≈ 9.55.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.stability import stability

ETA, ZETA_E = 0.02, 0.005
C_E = 2 * ZETA_E * M_DISK * WN
C_I = ETA * K_SHAFT / WN  # ω_ref = ω_n


@pytest.fixture(scope="module")
def dataset():
    model = jeffcott(ETA, C_E)
    result = stability(
        model, np.array([0.0, 1.2, 2.0]) * WN, n_modes=2, damping_model="viscous", reference_frequency=WN
    )
    return result.to_dataset()


def test_the_data_file_gives_the_closed_form_onset_in_rad_per_second(dataset):
    onset = WN * (1 + C_E / C_I)
    assert onset == pytest.approx(1.5 * WN, rel=1e-12)  # 1 + 2 ζ_e / η
    assert dataset.attrs["onset_kind"] == "oscillatory"
    assert dataset.attrs["onset_speed_units"] == "rad/s"
    assert dataset.attrs["onset_speed"] == pytest.approx(onset, rel=1e-5)


def test_the_data_file_gives_the_reference_frequency_in_rad_per_second(dataset):
    """The viscous method's ω_ref is the one given, ω_n = √(k/m) [rad/s] (an echo of the input:
    a float copied, so 1e-12 relative; the units attribute is what it checks)."""
    assert dataset.attrs["reference_frequency_units"] == "rad/s"
    assert dataset.attrs["reference_frequency"] == pytest.approx(np.sqrt(K_SHAFT / M_DISK), rel=1e-12)

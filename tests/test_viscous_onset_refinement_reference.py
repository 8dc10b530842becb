"""The viscous method's onset is solved for, not read off the grid (mutation hunt 23c).

Reference (derived, as in tests/test_stability.py): the Jeffcott-like rotor of tests/rotors.py
with the thesis's viscous internal damping ``c_i = η k/ω_ref`` and an external dashpot c_e
has, in complex coordinates r = v + i w, the forward root of

    m s² + (c_e + c_i) s + k − iΩ c_i = 0.

At the stability threshold s = iω is a root: the real part gives ω² = k/m = ω_n², the
imaginary part (c_e + c_i) ω = Ω c_i, so the onset is Ω* = ω_n (1 + c_e/c_i). With η = 0.1,
ζ_e = c_e/(2 m ω_n) = 0.05 and ω_ref = ω_n, c_e/c_i = 2 ζ_e/η = 1: Ω* = 2 ω_n.

The grid has two speeds, 0.2 ω_n and 5 ω_n, stable and unstable. The damping ratio is far from
linear in Ω across that bracket: its linear interpolation puts the zero 4 % above Ω* (the
closed-form roots at the two speeds, computed below, say so too). The product's onset is the
mode's ζ = 0 solved by regula falsi, each evaluation a Newton solve of the viscous problem
(stability._refine_onset), so it must be Ω* to the model's accuracy.

Tolerance 1e-5 relative: the tube carries 3.5e-6 of the disk's mass (density 0.1 kg/m³), which
moves ω_n by about 1e-6; the refinement stops at 1e-7 of the speed. The mode the description
names is read back from the tracked eigenvalues: the forward root that crosses Re s = 0.
CPU: one two-speed stability run on 8 elements, about 0.03 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.stability import stability

ETA, ZETA_E = 0.1, 0.05
C_E = 2 * ZETA_E * M_DISK * WN
C_I = ETA * K_SHAFT / WN  # ω_ref = ω_n
SPEEDS = np.array([0.2, 5.0]) * WN


def _forward_root(speed: float) -> complex:
    roots = np.roots([M_DISK, C_E + C_I, K_SHAFT - 1j * speed * C_I])
    return roots[np.argmax(roots.imag)]


@pytest.fixture(scope="module")
def result():
    return stability(jeffcott(ETA, C_E), SPEEDS, n_modes=2, damping_model="viscous", reference_frequency=WN)


def test_the_onset_is_the_closed_form_threshold_not_the_grid_interpolation(result):
    expected = WN * (1 + C_E / C_I)
    assert expected == pytest.approx(2 * WN, rel=1e-12)
    # the grid alone: linear interpolation of ζ = −Re s/|s| between the closed-form roots
    zeta = [-s.real / abs(s) for s in map(_forward_root, SPEEDS)]
    linear = SPEEDS[0] + zeta[0] / (zeta[0] - zeta[1]) * (SPEEDS[1] - SPEEDS[0])
    assert abs(linear / expected - 1) > 0.03
    assert result.onset_kind == "oscillatory"
    assert result.onset_speed == pytest.approx(expected, rel=1e-5)


def test_the_description_names_the_forward_mode_that_crosses(result):
    text = result.onset_description()
    assert text is not None and text.endswith(", forward whirl")
    number = int(text.split(",")[0].removeprefix("mode "))
    column = result.eigenvalues[:, number - 1]  # modes are numbered from 1
    assert column[0].real < 0 < column[1].real
    assert column[1] == pytest.approx(_forward_root(SPEEDS[1]), rel=1e-5)

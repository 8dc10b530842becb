"""The modes' printed table against the damped Jeffcott rotor's closed form (derived here).

The Jeffcott rotor of tests/rotors.py (a 20 kg disk at the middle of a near-massless
pinned-pinned tube, k = 48EI/L³) with a dashpot c at the disk obeys, in each plane, the single
mass m ẍ + c ẋ + k x = 0: s = −ζω_n ± iω_n√(1 − ζ²) with ζ = c/(2√(km)), ω_n = √(k/m). Its first
two modes are the lateral pair at f = ω_n√(1 − ζ²)/2π [Hz], i.e. 60 f [rpm]; its third is the
tube's first axial mode, far above (hundreds of Hz).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.modal import modes

ZETA = 0.05
C_DISK = ZETA * 2 * np.sqrt(K_SHAFT * M_DISK)
F_DAMPED = WN * np.sqrt(1 - ZETA**2) / (2 * np.pi)  # [Hz]


def _modes():
    return modes(jeffcott(0.0, C_DISK), 0.0, n_modes=3)


def test_text_table_prints_the_damped_frequency_in_hz_and_in_rpm():
    """The printed row of mode 1 shows f = ω_d/2π under 'f [Hz]' and 60 f under 'f [rpm]'.

    The table prints 4 significant digits: each column must match the closed form to half a unit
    of its last digit (5e-4 relative at worst, 4 digits), far above the tube-mass error of the
    model (measured 9e-7 relative) and far below a unit slip (a factor 60 between the columns)."""
    text = str(_modes())
    header = next(line for line in text.splitlines() if line.lstrip().startswith("mode"))
    assert "f [Hz]" in header and "f [rpm]" in header
    row = next(line.split() for line in text.splitlines() if line.split()[:1] == ["1"])
    hz, rpm = float(row[1]), float(row[2])
    assert hz == pytest.approx(F_DAMPED, rel=5e-4)
    assert rpm == pytest.approx(60.0 * F_DAMPED, rel=5e-4)

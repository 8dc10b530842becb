"""The validation quantities' damped and undamped lateral frequencies of a damped Jeffcott rotor.

:mod:`flexshaft.validation.quantities` distinguishes ``lateral_natural_frequencies`` (the
undamped |s|) from ``lateral_damped_frequencies`` (Im s). For the Jeffcott rotor of
tests/rotors.py (a 20 kg disk at the middle of a near-massless pinned-pinned steel tube,
k = 48EI/L³) with a dashpot c = 2ζ√(km) at the disk, ζ = 0.1, at rest, the disk obeys
m ẍ + c ẋ + k x = 0 in each plane; x = e^{st} gives m s² + c s + k = 0, so
s = −ζω_n ± iω_n√(1 − ζ²) with ω_n = √(k/m), and |s|² = ζ²ω_n² + ω_n²(1 − ζ²) = ω_n². The
lowest degenerate pair has |s| = ω_n and Im s = ω_n √(1 − ζ²) (0.5 % below ω_n).

Tolerance 1e-4: the tube's mass (3.5e-6 of the disk's) and the 4-element tube (exact for a point
load at its middle node) move the single-mass values by ~1e-6. CPU: one dense eigen-solution of
a 4-element model.

Written for the mutation h39b-quantities-damped-as-undamped of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.design import loads_design
from flexshaft.validation.quantities import lateral_damped_frequencies, lateral_natural_frequencies

ZETA = 0.1


@pytest.fixture(scope="module")
def design():
    return loads_design(jeffcott_text(0.0, 2 * ZETA * math.sqrt(K_SHAFT * M_DISK), elements=4))


def test_the_undamped_frequency_is_the_modulus_of_the_root(design):
    assert lateral_natural_frequencies(design, speed_rpm=0.0, count=1, stride=2) == pytest.approx([WN], rel=1e-4)


def test_the_damped_frequency_is_the_imaginary_part(design):
    damped = lateral_damped_frequencies(design, speed_rpm=0.0, count=1, stride=2)
    assert damped == pytest.approx([WN * math.sqrt(1 - ZETA**2)], rel=1e-4)

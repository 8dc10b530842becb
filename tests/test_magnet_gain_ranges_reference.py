"""The magnet gains' ranges at their ends (:func:`flexshaft.assembly.checks.check_magnet`).

docs/design-reference.md's rows of the active bearing: ``ki`` in (0, 1e6] N/A (a magnet with
k_i = 0 makes no force from its current: no feedback at all), ``ks`` in [0, 1e12] N/m. The
check holds gains computed from a magnet geometry to the same ranges; each is checked exactly at
its ends (binary-exact values) and one ulp beyond, on the Jeffcott rotor of
tests/jeffcott_bearing.py with its active bearing (index 0); NaN gains are refused too.

A bearing designed by its magnet geometry (N = 1e4 turns, A = 1e-2 m², i₀ = 10 A, g₀ = 1 µm,
pole angle 22.5°, each within its own row's range) has, for the differential pair of magnets
(F = μ₀N²A cos α/4 [(i₀ + i)²/(g₀ − x)² − (i₀ − i)²/(g₀ + x)²] linearised),
k_i = μ₀N²A cos α i₀/g₀² = 1.16e13 N/A and k_s = k_i i₀/g₀ = 1.16e20 N/m: both far beyond
their ranges, so the check refuses them and names ``coil_turns``, the first of the geometry
fields the gains come from. The gains themselves are checked against that closed form with
rtol 1e-9 (μ₀ = 4π × 1e-7 differs from the CODATA 2018 value by 5.5e-10). CPU: milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE
from rotors import jeffcott_text

from flexshaft.assembly.checks import check_magnet, magnet_gains
from flexshaft.design import DesignError, loads_design


@pytest.fixture(scope="module")
def design():
    text = jeffcott_text(0.0, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    return loads_design(f'{head}[[bearings]]\nname = "b"\nx = 0.5\n{ACTIVE}\n{tail}')


@pytest.mark.parametrize("ki, ks", [(1e6, 1e12), (np.nextafter(0.0, 1.0), 0.0), (177.0, 8.47e5)])
def test_gains_within_their_ranges_pass(design, ki, ks):
    check_magnet(design, 0, ki, ks)


@pytest.mark.parametrize(
    "ki, ks, name",
    [
        (0.0, 0.0, "ki"),
        (np.nextafter(1e6, 2e6), 0.0, "ki"),
        (177.0, np.nextafter(1e12, 2e12), "ks"),
        (177.0, -np.nextafter(0.0, 1.0), "ks"),
        (np.nan, 0.0, "ki"),
        (177.0, np.nan, "ks"),
    ],
)
def test_gains_beyond_their_ranges_are_refused(design, ki, ks, name):
    with pytest.raises(DesignError, match=rf"bearings\[0\]\.{name}"):
        check_magnet(design, 0, ki, ks)


GEOMETRY = "\n".join(
    ['kind = "active"', "kp = 5000.0", "kd = 2.0", "coil_turns = 1e4", "pole_area = 1e-2", "bias_current = 10.0"]
    + ["air_gap = 1e-6"]
)


def test_gains_from_a_magnet_geometry_beyond_their_ranges_name_the_coil_turns():
    text = jeffcott_text(0.0, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    design = loads_design(f'{head}[[bearings]]\nname = "b"\nx = 0.5\n{GEOMETRY}\n{tail}')
    ki, ks = magnet_gains(design.bearings[0])  # what the model is built with
    expected_ki = 4e-7 * np.pi * 1e4**2 * 1e-2 * np.cos(np.radians(22.5)) * 10.0 / 1e-6**2
    np.testing.assert_allclose([ki, ks], [expected_ki, expected_ki * 10.0 / 1e-6], rtol=1e-9)
    with pytest.raises(DesignError) as refused:
        check_magnet(design, 0, ki, ks)
    for name in ("ki", "ks"):
        assert f"bearings[0].coil_turns: gives the magnet gain {name} =" in str(refused.value)

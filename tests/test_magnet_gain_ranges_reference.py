"""The magnet gains' ranges at their ends (:func:`flexshaft.assembly.checks.check_magnet`).

docs/design-reference.md's rows of the active bearing: ``ki`` in (0, 1e6] N/A (a magnet with
k_i = 0 makes no force from its current: no feedback at all), ``ks`` in [0, 1e12] N/m. The
check holds gains computed from a magnet geometry to the same ranges; each is checked exactly at
its ends (binary-exact values) and one ulp beyond, on the Jeffcott rotor of
tests/jeffcott_bearing.py with its active bearing (index 0). CPU: milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE
from rotors import jeffcott_text

from flexshaft.assembly.checks import check_magnet
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
    ],
)
def test_gains_beyond_their_ranges_are_refused(design, ki, ks, name):
    with pytest.raises(DesignError, match=rf"bearings\[0\]\.{name}"):
        check_magnet(design, 0, ki, ks)

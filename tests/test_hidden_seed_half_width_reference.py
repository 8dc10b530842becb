"""A resonance is held by a found peak only within its own half-power band Re Ω ± |Im Ω|.

:func:`flexshaft.analyses.criticals._hidden_resonances` seeds a refinement at each root Ω_k of
the synchronous problem that no peak found holds, "none within its half-power band
Re Ω_k ± |Im Ω_k|" (its docstring), and records |Im Ω_k| as the seed's width.

Reference (closed form): the Jeffcott-like rotor of tests/rotors.py with a dashpot
c = 2ζ m ω_n at the disk (ζ = 0.002, no loss) under a forward imbalance u (1, −i) at the disk.
Its response is one circular whirl, so the span of the scan's responses is one vector (to
5e-10, below) and the projected synchronous problem is the single-degree-of-freedom
k − mΩ² + i c Ω = 0, whose root
with Re > 0 is Ω = (i c + √(4 m k − c²))/(2m) = ω_n (√(1 − ζ²) + i ζ): half-power half-width
|Im Ω| = ζ ω_n (derived: |k − mΩ² + icΩ|² doubles from its minimum at Ω ≈ ω_n(1 ± ζ) to
first order in ζ), centre Re Ω = ω_n √(1 − ζ²). On a scan of spacing 0.01 ω_n the band
(0.004 ω_n wide) spans fewer than four intervals, so the root is a candidate. A damped peak
"found" 1.1 ζω_n from Re Ω (either side) is outside that band: the root is seeded, with width
ζω_n at Re Ω (the projected orbit's maximum, located to 1e-4 ζω_n = 2e-7 ω_n near its largest
sample of Re Ω + ζω_n (−2 … 2, an eighth apart); the peak Ω_p = ω_n/√(1 − 2ζ²) lies 6e-6 ω_n
from the centre); one found 0.9 ζω_n above it holds it.
The offsets sit 0.1 ζω_n either side of the band's edge, so a hold comparison scaled by 0.8
or 1.2 fails one of the tests.

Model's departure from the closed form: the tube's mass, 3.5e-6 of the disk's, shifts ω_n and
ζ by about that: measured, the projected root lies 4.3e-4 ζω_n (9e-7 ω_n) below the closed
form's Re Ω and its |Im Ω| is 1.7e-6 below ζω_n, both far inside the 0.1 ζω_n margin. The
projected problem (three responses, their span's second direction 5e-10 of the first) also
has a second root of the same width 0.093 ζω_n above the first: it is held with the first
(0.81 ζω_n from the peak found at +0.9) and, within the first seed's band, not seeded twice;
a peak found 0.9 ζω_n *below* is left out, 0.993 ζω_n from that second root, too near its
band's edge to assert on any machine. Tolerance: rtol 1e-4 on the width; 2e-6 on the
speed, against the orbit's maximum Ω_p (measured 8.4e-7 from it: the tube's mass), which the
centre Re Ω is 6.0e-6 ω_n away from (1.5 ζ² ω_n; review r117), far below the window's
ζ/8 = 2.5e-4 relative. CPU: 3 banded solves and a 3-column projection, a few milliseconds per
call.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.criticals import LateralCritical, _hidden_resonances
from flexshaft.analyses.peak_projection import PeakBasis
from flexshaft.analyses.response import imbalance_response

ZETA = 0.002
CENTRE, HALF_WIDTH = WN * np.sqrt(1 - ZETA**2), ZETA * WN
PEAK = WN / np.sqrt(1 - 2 * ZETA**2)  # the unbalance orbit's maximum Ω_p


@pytest.fixture(scope="module")
def setting():
    model = jeffcott(0.0, 2 * ZETA * M_DISK * WN)
    v, w = disk_dofs(model)
    loads = np.zeros((model.dofs.size, 1), complex)
    loads[v, 0], loads[w, 0] = 1e-4, -1e-4j  # forward imbalance u = 1e-4 kg m
    speeds = np.linspace(0.5, 1.5, 101) * WN  # spacing 0.01 ω_n
    columns = np.asarray(imbalance_response(model, speeds[[10, 50, 90]], loads))[model.dofs.free, 0, :]
    return model, loads, speeds, PeakBasis(model, columns)


def _found(offset: float) -> list[LateralCritical]:
    return [LateralCritical(CENTRE + offset * HALF_WIDTH, 1.0 / (2 * ZETA), {"af_method": "half-power"})]


def test_a_peak_outside_the_half_power_band_leaves_the_root_seeded(setting):
    model, loads, speeds, span = setting
    for offset in (1.1, -1.1):
        (seed,) = _hidden_resonances(model, loads, speeds, None, _found(offset), span)
        assert seed.width == pytest.approx(HALF_WIDTH, rel=1e-4)
        assert seed.speed == pytest.approx(PEAK, rel=2e-6)  # the window's next sample is 2.5e-4 away
        assert seed.replaces is None


def test_a_peak_inside_the_half_power_band_holds_the_root(setting):
    model, loads, speeds, span = setting
    assert _hidden_resonances(model, loads, speeds, None, _found(0.9), span) == []

"""Hilpert's cross-flow correlation is flagged in range exactly over its documented range.

Reference: documented rule, docs/thermal.md ("Hover"): Hilpert with Incropera Table 7.2
constants is "valid 0.4 ≤ Re ≤ 4×10⁵ and Pr ≥ 0.7"; outside it the last row is extrapolated and
flagged (``nusselt.in_range = False``). Air's Pr = 0.71 is inside the Pr limit, so the flag
follows Re alone here: in range for Re from 0.4 through the whole top row 4×10⁴..4×10⁵ (a
cross-flow at Re ~ 1e5), out of range above 4×10⁵ and below 0.4. The Re values are a factor
≥ 1.25 from the limits (no tie with a limit; the flag is an exact comparison).
"""

from __future__ import annotations

import pytest

from flexshaft.thermal.correlations import forced_cylinder_nusselt, hilpert_nusselt

PR_AIR = 0.71


@pytest.mark.parametrize("Re", [0.5, 30.0, 1e3, 2e4, 5e4, 1e5, 3.2e5])
def test_inside_the_documented_range_is_in_range(Re):
    assert hilpert_nusselt(Re, PR_AIR).in_range
    assert forced_cylinder_nusselt(Re, PR_AIR, "hilpert").in_range


@pytest.mark.parametrize("Re", [0.3, 5e5, 2e6])
def test_outside_the_documented_range_is_flagged(Re):
    nu = hilpert_nusselt(Re, PR_AIR)
    assert not nu.in_range
    assert nu.note  # the flag says why (user-facing; the physics is the flag above)

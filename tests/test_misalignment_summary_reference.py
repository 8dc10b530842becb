"""The coupling-misalignment summary line names the most misaligned coupling.

Reference (derived here): a coupling whose flanges sit at a static relative slope α_s and
whirl with a relative-slope amplitude α_d sees at worst, when the whirl is in phase with the
static slope, the angle α_s + α_d. The summary must report the coupling with the LARGEST such
angle, in degrees (α · 180/π), since that is the one nearest its allowable angle.

Hand-picked angles, with the largest in the middle so that neither the first nor the last
coupling is the answer, and no tie:

    A: 0.002 + 0.001 = 0.003 rad
    B: 0.010 + 0.020 = 0.030 rad = 0.030 · 180/π = 1.7189°  -> printed to 3 digits "1.72"
    C: 0.005 + 0     = 0.005 rad

The numbers are exact sums of decimal inputs far from a rounding boundary of the 3-digit
format (1.7189 is 0.0039 from 1.715), so the string comparison is machine-independent.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.misalignment import CouplingMisalignment


def _result(static, dynamic):
    n = len(static)
    nan = np.full(n, np.nan)
    return CouplingMisalignment(
        names=("A", "B", "C"),
        stations=np.array([1.0, 2.0, 3.0]),
        static_angle=np.array(static, float),
        dynamic_angle=np.array(dynamic, float),
        allowable_angle=nan,
        static_moment=nan,
        axial_offset=np.zeros(n),
        axial_force=nan,
        twist=np.zeros(n),
        torque=nan,
    )


def test_summary_names_the_largest_static_plus_whirl_angle():
    """B (0.03 rad = 1.72°) is reported, not the mildest A (0.003 rad = 0.172°)."""
    text = repr(_result([0.002, 0.010, 0.005], [0.001, 0.020, 0.0]))
    assert text == "CouplingMisalignment(3 couplings, largest 1.72° at B)"


def test_summary_counts_the_whirl_not_only_the_static_angle():
    """Statically C is the most misaligned (0.005 > 0.004 > 0.001 rad), but B's whirl makes its
    total 0.004 + 0.006 = 0.010 rad = 0.573° (0.5730 to 4 digits, 0.0005 from the 3-digit
    rounding boundary 0.5725) the largest."""
    text = repr(_result([0.001, 0.004, 0.005], [0.0, 0.006, 0.0]))
    assert text == "CouplingMisalignment(3 couplings, largest 0.573° at B)"

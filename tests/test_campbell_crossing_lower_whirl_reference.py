"""A Campbell crossing takes the whirl of its lower sample (hunt h45a).

Reference (hand-built curves, the documented definition of
:func:`flexshaft.analyses.campbell.critical_speeds`): "a crossing takes its whirl from the lower
sample" (its docstring; the rest exception does not apply above rest). One lateral curve with
damped frequency ω = (150, 210, 250) rad/s at Ω = (100, 200, 300) rad/s meets ω = Ω where
g = ω − Ω = (50, 10, −50) changes sign: linearly, Ω_c = 200 + 10/60 · 100 = 216.667 rad/s (exact
to round-off: rel 1e-12). The whirl changes from forward at 200 to backward at 300 rad/s: the
crossing is labelled forward.
CPU: microseconds.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.campbell import critical_speeds


def test_a_crossing_takes_the_whirl_of_its_lower_sample():
    speeds = np.array([100.0, 200.0, 300.0])
    eig = (np.array([150.0, 210.0, 250.0]) * 1j - 1.0)[:, None]
    whirl = np.array([["forward"], ["forward"], ["backward"]])
    kind = np.full((3, 1), "lateral")
    (crit,) = critical_speeds(speeds, eig, whirl, kind)
    assert crit.speed == pytest.approx(200.0 + 100.0 / 6.0, rel=1e-12)
    assert (crit.mode, crit.harmonic, crit.whirl) == (0, 1.0, "forward")

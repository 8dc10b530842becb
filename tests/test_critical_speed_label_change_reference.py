"""A critical speed whose mode turns lateral inside the sample interval is kept.

:func:`~flexshaft.analyses.campbell.critical_speeds` finds the crossings of the lateral
curves with ω = kΩ. A tracked mode's label can change between two samples (a torsional or
coupled mode veering into a lateral one): the crossing is then the lateral mode's, at the
upper sample, and takes that sample's whirl (the lower sample, not lateral, has none to
give). Only a crossing with neither bracketing sample lateral is not a lateral critical
speed.

Reference (closed form): a curve Im s = 120 + 0.2 Ω rad/s meets ω = Ω at Ω = 120/0.8 = 150
rad/s; sampled at Ω = 100 and 200 (Im s = 140, 160) the linear interpolation is exact, so the
crossing is 150 rad/s to round-off (rel 1e-12). With ω = 2Ω it meets at 120/1.8 = 66.67 rad/s,
outside the samples: no crossing.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.campbell import critical_speeds

SPEEDS = np.array([100.0, 200.0])
EIG = (-1.0 + 1j * (120.0 + 0.2 * SPEEDS))[:, None]
WHIRL = np.array([["none"], ["forward"]])


def test_a_mode_turning_lateral_inside_the_interval_keeps_its_crossing():
    crit = critical_speeds(SPEEDS, EIG, WHIRL, np.array([["torsional"], ["lateral"]]), harmonics=(1.0, 2.0))
    assert len(crit) == 1
    assert crit[0].speed == pytest.approx(150.0, rel=1e-12)
    assert (crit[0].mode, crit[0].harmonic, crit[0].whirl) == (0, 1.0, "forward")


def test_a_crossing_with_no_lateral_sample_is_not_a_critical_speed():
    kind = np.array([["torsional"], ["torsional"]])
    assert critical_speeds(SPEEDS, EIG, np.array([["none"], ["none"]]), kind) == ()

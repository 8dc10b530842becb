"""Which Campbell mode names a critical speed, and the scan refused at a zero operating speed
(mutation hunt h35a).

1. ``label_critical_speeds``: a refined peak is named by the tracked mode whose 1× critical
   speed is nearest, if that one is within 3 % of the peak's speed (its docstring and
   ``lateral_critical_speeds``'s: "nearest (within 3 %)"), as "<mode from 1> (<whirl>)". A
   hand-built Campbell diagram with critical speeds at 70 rad/s (mode 0, forward) and 125 rad/s
   (mode 1, backward), distances relative to the peak's speed as the code measures them: a peak
   at 72 rad/s is 2/72 = 2.8 % from the first (and 74 % from the second): "1 (forward)"; a peak
   at 120 rad/s is 5/120 = 4.2 % from the second: no label. A peak at 100 rad/s is 30 % and 25 %
   away from them: no label.

2. ``scan_critical_speeds`` at a zero operating speed: no scan (its speeds would all be 0), so
   no critical speeds (None, not an empty tuple: nothing was searched) with the note "the
   operating speed is zero" (its docstring).

Exact arithmetic on typed numbers; CPU a few milliseconds (one 8-element model built).
"""

from __future__ import annotations

import numpy as np
from rotors import jeffcott

from flexshaft.analyses.campbell import Campbell, CriticalSpeed
from flexshaft.analyses.criticals import LateralCritical, label_critical_speeds, scan_critical_speeds


def _campbell() -> Campbell:
    speeds = np.array([0.0, 100.0, 200.0])
    eig = np.full((3, 2), -1.0 + 100j)
    whirl = np.full((3, 2), "forward")
    crit = (CriticalSpeed(70.0, 0, 1.0, "forward"), CriticalSpeed(125.0, 1, 1.0, "backward"))
    return Campbell(speeds, eig, whirl, np.zeros((3, 2)), crit, np.full((3, 2), "lateral"))


def _peak(speed: float) -> LateralCritical:
    return LateralCritical(speed, 12.0, {"station": 0.5, "af_method": "half-power"})


def test_a_peak_is_named_by_the_nearest_campbell_critical_within_three_percent():
    labelled = label_critical_speeds((_peak(72.0), _peak(100.0), _peak(120.0)), _campbell())
    assert [c.location.get("mode", "") for c in labelled] == ["1 (forward)", "", ""]
    assert [c.speed for c in labelled] == [72.0, 100.0, 120.0]
    assert all(c.amplification_factor == 12.0 for c in labelled)


def test_no_scan_at_a_zero_operating_speed():
    model = jeffcott(0.0, 0.0)
    assert model.speed == 0.0
    found = scan_critical_speeds(model, np.array([0.0, 1.0]), None)
    assert found.criticals is None
    assert found.search_top == 0.0
    assert found.note == "the operating speed is zero"

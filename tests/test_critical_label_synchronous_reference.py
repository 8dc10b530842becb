"""A critical speed is named by a 1× crossing only, also on a Campbell diagram drawn with more
harmonics.

docs/requirements.md (critical speeds, rule 5): "Each peak is labelled with the tracked Campbell
mode whose 1× critical speed is within 3 %." An imbalance peak is a synchronous (1×)
resonance; a diagram drawn with ``harmonics=(1, 2)`` also lists the 2× crossings, at half the
speed of the same mode's 1× crossing, and those must not name a peak. Hand-built diagram (mode
0 forward crosses 2× at 50 rad/s and 1× at 100 rad/s; mode 1 backward crosses 1× at 130 rad/s
and 2× at 129 rad/s), distances relative to the peak's speed as the rule states them:

* a peak at 50.5 rad/s is 1 % from the 2× crossing and 98 % from the nearest 1× one: no label
  (the nearest crossing of any harmonic named it "1 (forward)" before the twenty-fifth session);
* a peak at 101 rad/s is 1 % from mode 0's 1× crossing: "1 (forward)";
* a peak at 128.9 rad/s, nearer mode 1's 2× crossing (0.08 %) than its 1× one (0.85 %): "2
  (backward)" from the 1× crossing.

Exact arithmetic on typed numbers; no model is built.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.campbell import Campbell, CriticalSpeed
from flexshaft.analyses.criticals import LateralCritical, label_critical_speeds


def _campbell() -> Campbell:
    speeds = np.array([0.0, 100.0, 200.0])
    eig = np.full((3, 2), -1.0 + 100j)
    whirl = np.full((3, 2), "forward")
    crit = (
        CriticalSpeed(50.0, 0, 2.0, "forward"),
        CriticalSpeed(100.0, 0, 1.0, "forward"),
        CriticalSpeed(129.0, 1, 2.0, "backward"),
        CriticalSpeed(130.0, 1, 1.0, "backward"),
    )
    return Campbell(speeds, eig, whirl, np.zeros((3, 2)), crit, np.full((3, 2), "lateral"))


def _peak(speed: float) -> LateralCritical:
    return LateralCritical(speed, 12.0, {"station": 0.5, "af_method": "half-power"})


def test_only_the_synchronous_crossings_name_a_peak():
    peaks = tuple(_peak(s) for s in (50.5, 101.0, 128.9))
    labelled = label_critical_speeds(peaks, _campbell())
    assert [c.location.get("mode", "") for c in labelled] == ["", "1 (forward)", "2 (backward)"]
    assert [c.speed for c in labelled] == [50.5, 101.0, 128.9]

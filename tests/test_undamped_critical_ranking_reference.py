"""An undamped critical speed ranks above every damped one (hunt h45a).

Reference (closed form). The undamped Jeffcott rotor's unbalance orbit is
|q| = m e Ω² / |k − M Ω²|, infinite at Ω = √(k/M): a critical speed with an infinite
amplification factor (a singular peak, no refined orbit recorded) has an unbounded orbit. So

* its peak orbit, when none was recorded, is +inf (it outranks any finite orbit when a hidden
  resonance's refinement replaces a stalled one), while a damped critical without a recorded
  orbit has none to offer (0);
* it is a maximum of the shaft's orbit envelope by definition, without any solve near it (the
  model is not needed: ``None`` is passed, any solve would fail).
Exact comparisons (no arithmetic). CPU: microseconds.
"""

from __future__ import annotations

import math

from flexshaft.analyses.criticals import LateralCritical, _envelope_peak, _peak_orbit


def test_an_undamped_critical_without_a_recorded_orbit_has_an_unbounded_one():
    assert _peak_orbit(LateralCritical(300.0, math.inf, {"station": 0.5})) == math.inf
    assert _peak_orbit(LateralCritical(300.0, 12.0, {"station": 0.5})) == 0.0
    assert _peak_orbit(LateralCritical(300.0, 12.0, {"station": 0.5, "peak_orbit": 2e-4})) == 2e-4


def test_an_undamped_critical_is_an_envelope_maximum_without_a_solve():
    assert _envelope_peak(None, None, LateralCritical(300.0, math.inf, {"station": 0.5})) is True

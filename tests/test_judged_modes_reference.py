"""Which whirl-stability curves the report draws as judged by the log-decrement requirement
(report/run_sections.py, ``_judged_modes``), on hand-built curves and modes.

The whirl-damping check judges the lateral whirl modes with at least 10 % of their kinetic energy
in the shaft at the operating speed (flexshaft.verdict.gather). Four tracked modes over Ω = 0,
100, 200 rad/s, the operating speed 150 rad/s:

* a shaft mode s = −3 + 60i (shaft share 0.7): judged;
* a boom mode whose frequency rises 0.1 rad/s per rad/s, s = −2 + (20 + 0.1 Ω)i (shaft share
  0.05): interpolated to −2 + 35i at 150 rad/s, where the modes list it: not judged (matched at
  the curve's nearest speed, 100 or 200 rad/s, it would miss by 5/35 = 14 %, beyond the 2 %
  tolerance, and be drawn as judged);
* a torsional mode −0.5 + 50i (share 0.9, but not lateral): not judged;
* a curve at −1 + 80i that no mode matches within 2 %: drawn as judged (nothing is greyed out
  without a reason).

No model is built: CPU milliseconds.
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import numpy as np

from flexshaft.report import run_sections


def _assessment(operating: float):
    speeds = np.array([0.0, 100.0, 200.0])
    curves = np.column_stack(
        [np.full(3, -1 + 10j), -2 + 1j * (20.0 + 0.1 * speeds), np.full(3, -0.5 + 50j), np.full(3, -1 + 80j)]
    )
    modes = NS(
        eigenvalues=np.array([-3 + 60j, -2 + 35j, -0.5 + 50j]),
        kind=np.array(["lateral", "lateral", "torsional"]),
        shaft_fractions=np.array([0.7, 0.05, 0.9]),
    )
    return NS(stability=NS(speeds=speeds, eigenvalues=curves), modes_at_speed=modes, model=NS(speed=operating))


def test_the_shaft_modes_at_the_operating_speed_are_judged():
    judged = run_sections._judged_modes(_assessment(150.0))
    assert judged.tolist() == [True, False, False, True]


def test_an_operating_speed_beyond_the_curves_judges_nothing_apart():
    assert run_sections._judged_modes(_assessment(250.0)) is None

"""When the projected spin-up sweep gives way to full solves (analyses.sweep_projection).

Reference: the rule docs/model.md states for the spin-up scan (hand-written): "Scans under 40
speeds, a singular reduced model, a basis over 48 columns (...) or more than 40 % of the speeds
solved in full fall back to full solves". The 40 % limit is checked on the 1.5 m steel tube of
tests/test_eigen_accuracy.py on 12 elements (two 1e7 N/m end bearings; undamped natural
frequencies 322, 1163 and 2199 rad/s, each a pair, computed from the model's matrices), under a
forward rotating unbalance at x = 0.5 m, scanned from 10 to 2500 rad/s (past those three):

* at 100 speeds the 13 initial full solves do not reach the 1e-8 estimate: a round of 12 more
  does (25 full solves, within 40 % of 100), and the scan is projected;
* at 40 speeds the same 13 initial solves (the same span, as finely spread) need a round too,
  and 13 plus any round of four or more speeds exceeds 40 % of 40 speeds: the whole scan is
  solved in full, or at most 16 of its speeds are.

Why a round of four or more (the sweep_projection module docstring's greedy): the first model
compared with is the ends-only one, so a scan with criticals inside needs at least one round; a
round takes the local maxima of the error indicator with the solved speeds at zero, one in each
of the 12 gaps between the 13 initial speeds (12 measured at both 100 and 40 speeds), and 13 +
12 = 25 > 16. The 100-speed scan's round is checked to hold four or more. The rule's other route
to full solves (speeds of a large resonance sensitivity κ, docs/model.md) adds none here: the
bearings are damped and the 100-speed scan's 25 full solves are the 13 + 12 of the greedy.

The rule is a count (no floating-point tolerance). CPU: about 0.05 s.
"""

from __future__ import annotations

import numpy as np
from test_eigen_accuracy import SHAFT

import flexshaft
from flexshaft.analyses.sweep_projection import imbalance_sweep
from flexshaft.design import loads_design

#: The limit docs/model.md states.
FULL_FRACTION = 0.4


def test_a_scan_that_would_solve_over_40_percent_in_full_is_solved_in_full():
    model = flexshaft.build_model(loads_design(SHAFT.replace("shaft_elements = 30", "shaft_elements = 12")))
    dm = model.dofs
    node = dm.node_at("shaft", 0.5)
    loads = np.zeros((dm.size, 1), complex)  # U = 1e-4 kg m forward: Q₁ = U (1, −i) on (v, w)
    loads[dm.shaft(node, "v"), 0], loads[dm.shaft(node, "w"), 0] = 1e-4, -1e-4j
    # the same span more finely: 13 initial solves are not enough, a round is needed
    fine = imbalance_sweep(model, np.linspace(10.0, 2500.0, 100), loads)
    assert fine.rounds >= 1 and fine.basis_size > 0
    assert 13 < fine.full_solves <= FULL_FRACTION * 100
    assert fine.full_solves - 13 >= 4  # a round's size: 13 + 4 > 40 % of 40 below
    assert fine.error_estimate.max() <= 1e-8
    # 40 speeds: 13 initial + a round of >= 4 exceeds 16, so the greedy gives way
    ns = 40
    sweep = imbalance_sweep(model, np.linspace(10.0, 2500.0, ns), loads)
    assert sweep.full.all() or sweep.full_solves <= FULL_FRACTION * ns, sweep.full_solves
    assert sweep.full.all() == (sweep.basis_size == 0)

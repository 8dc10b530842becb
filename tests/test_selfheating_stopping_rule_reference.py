"""Self-heating's stopping rule and load multipliers reach the Picard loop as the caller gives
them.

:func:`flexshaft.thermal.selfheating.self_heating` documents ``tol`` ("converged when
max |ΔT| < tol [K]"), ``max_iter`` ("iteration limit") and ``imbalance_scale, static_scale``
("multipliers of the imbalance and static loads [-]", default 1: the design's loads as given).
Closed forms derived here:

* **Tolerance above every admissible change.** The loop starts at the shaft's air temperature
  T_air and stops with a runaway as soon as an iterate exceeds the allowable temperature T_allow.
  No iterate falls below T_air (the heat is ≥ 0, the shaft convects to air at T_air and both
  ends are held at T_air; measured minimum T_air + 1.4e-3 K), so any first iterate that is not
  a runaway changes by at most T_allow − T_air, and with
  ``tol > T_allow − T_air`` the first iterate already meets max |ΔT| < tol: status
  ``"converged"`` after exactly 1 iteration.
* **Tolerance nobody meets.** ``tol = 0``: max |ΔT| < 0 is false for every iterate, so a loop that
  does not run away stops at the limit: ``"not_converged"`` after exactly ``max_iter`` iterations
  (one history entry per iterate).
* **Default static multiplier.** At the first iterate every element is at T_air, so the moduli,
  hence the static stiffness and the loss stiffness, do not depend on the multipliers. The static
  deflection is linear in its load and the static heat a quadratic form of it: Q_static(s) =
  s² Q_static(1). With the documented default s = 1, Q_static(default) = Q_static(s=2) / 4 in
  every element. Multiplying by 2 and 4 is exact in binary floating point and the two runs solve
  the same matrix with the same right-hand side direction, so only the last-bit rounding of the
  quadratic form differs: rel 1e-12 leaves 4 orders above double rounding (≈1e-16 × a few
  hundred operations) and is far below the effect checked (a factor 1 vs 0).
"""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft as fs
import flexshaft.thermal.selfheating as selfheating
from flexshaft.thermal.options import options_of

SCALE = 100.0  # the baseline's static loads x100 warm its hottest element several K above the air


@pytest.fixture(scope="module")
def model():
    return fs.build_model(fs.baseline_design())


def test_a_tolerance_above_the_allowable_rise_stops_after_the_first_iterate(model):
    allowable = options_of(model).matrix_law.allowable_temperature
    tol = allowable + 1.0  # > T_allow − T_air since T_air > 0 K
    result = selfheating.self_heating(model, imbalance_scale=0.0, static_scale=SCALE, tol=tol)
    assert result.allowable_temperature == allowable
    assert result.status == "converged"
    assert result.iterations == 1
    assert len(result.history) == 1


def test_a_zero_tolerance_runs_exactly_to_the_callers_limit(model):
    result = selfheating.self_heating(model, imbalance_scale=0.0, static_scale=SCALE, tol=0.0, max_iter=2)
    assert result.status == "not_converged"
    assert result.iterations == 2
    assert len(result.history) == 2


def test_the_default_static_multiplier_is_one(model):
    default = selfheating.self_heating(model, imbalance_scale=0.0, max_iter=1).thermal.sources.static
    doubled = selfheating.self_heating(model, imbalance_scale=0.0, static_scale=2.0, max_iter=1).thermal.sources.static
    assert doubled.max() > 0.0  # the baseline's static loads (torque, manoeuvre) do heat
    np.testing.assert_allclose(default, doubled / 4.0, rtol=1e-12, atol=1e-12 * doubled.max())

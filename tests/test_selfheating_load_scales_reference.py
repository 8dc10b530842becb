"""Self-heating's two load multipliers each scale their own heat mechanism, and a non-finite
iterate is a runaway.

* :func:`flexshaft.thermal.selfheating.self_heating` multiplies the imbalance loads by
  ``imbalance_scale`` and the static loads by ``static_scale``. The response is linear in its
  loads at given moduli, and each mechanism's heat (:class:`~flexshaft.thermal.heat.HeatSources`:
  ``vibration`` from the imbalance response, ``static`` from the static deflection cycled by the
  rotation) is a quadratic form of its own response. A load scaled by zero therefore has zero
  response and dissipates exactly nothing, at whatever temperature the other mechanism warms the
  shaft to: with ``imbalance_scale = 0`` the vibration heat is 0 W in every element and the static
  heat is not, and the other way round.
* The module's runaway rule: "an iterate exceeds the law's allowable temperature, i.e. there is
  no fixed point below it". An iterate that is not finite (a heat that overflowed, inf − inf or
  0 × inf in the chain) has no fixed point below the allowable either: it is a runaway at that
  iterate, not an iteration that merely did not converge (``"not_converged"``, max_iter reached
  below the allowable).
"""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft as fs
import flexshaft.thermal.selfheating as selfheating

SCALE = 100.0  # the baseline's static loads x100 warm its hottest element ~8 K above the air


@pytest.fixture(scope="module")
def model():
    return fs.build_model(fs.baseline_design())


def test_static_loads_alone_heat_only_through_the_static_mechanism(model):
    result = selfheating.self_heating(model, imbalance_scale=0.0, static_scale=SCALE)
    assert result.status == "converged"
    sources = result.thermal.sources
    np.testing.assert_array_equal(sources.vibration, 0.0)
    assert sources.static.max() > 1.0  # [W]: the static deflection cycled by the rotation heats


def test_imbalance_alone_heats_only_through_the_vibration_mechanism(model):
    result = selfheating.self_heating(model, imbalance_scale=SCALE, static_scale=0.0)
    assert result.status == "converged"
    sources = result.thermal.sources
    np.testing.assert_array_equal(sources.static, 0.0)
    assert sources.vibration.max() > 0.0


# inf is above the allowable and a runaway by the comparison alone; nan compares false with every
# number, so only the nan case needs the rule "not finite: runaway"
@pytest.mark.parametrize("bad", [np.nan, np.inf], ids=["nan", "inf"])
def test_a_non_finite_iterate_is_a_runaway_at_that_iterate(bad):
    T_inf, allowable = 300.0, 400.0

    def update(T):  # the first iterate warms to 320 K, the second diverges
        return np.full_like(T, T_inf + 20.0) if T[0] < T_inf + 10.0 else np.full_like(T, bad)

    fp = selfheating.fixed_point(update, np.full(3, T_inf), allowable, max_iter=20)
    assert fp.status == "runaway"
    assert fp.iterations == 2

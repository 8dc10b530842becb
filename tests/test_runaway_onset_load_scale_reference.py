"""The thermal-runaway onset scales every load: the imbalance and the static loads alike.

``runaway_onset`` (flexshaft.thermal.selfheating) looks for the load factor s at which the
self-heating has no fixed point below the allowable temperature; its docstring and
``self_heating``'s ("multipliers of the imbalance and static loads, to find where runaway
starts") make s one factor on both. The self-heating run is replaced here by a stand-in whose
heat comes from the static load alone, the mechanism of a shaft bent by manoeuvre loads (the
static deflection cycled by the rotation, thesis §2.8.2): peak temperature
T(s) = 300 K + 50 K · s² against an allowable 400 K, so runaway starts at s* = √2 exactly. The
onset is the first runaway scale of the list, then bisected ``refine`` times between the last
stable and the first runaway scale: after 30 halvings of [1.25, 1.5] the bracket is 2.3e-10
wide, the tolerance.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

import flexshaft.thermal.selfheating as selfheating


@pytest.fixture
def static_heating(monkeypatch):
    calls = []

    def stand_in(model, options=None, loss_model=None, *, imbalance_scale=1.0, static_scale=1.0, **kwargs):
        calls.append((imbalance_scale, static_scale))
        peak = 300.0 + 50.0 * static_scale**2
        return SimpleNamespace(status="runaway" if peak > 400.0 else "converged", max_temperature=peak)

    monkeypatch.setattr(selfheating, "self_heating", stand_in)
    return calls


def test_the_first_runaway_scale_of_the_list(static_heating):
    onset, results = selfheating.runaway_onset(object(), [1.0, 1.25, 1.5, 2.0])
    assert onset == 1.5
    assert [r.status for r in results] == ["converged", "converged", "runaway"]
    assert static_heating == [(1.0, 1.0), (1.25, 1.25), (1.5, 1.5)]


def test_bisection_converges_on_the_static_loads_onset(static_heating):
    onset, _ = selfheating.runaway_onset(object(), [1.0, 1.25, 1.5], refine=30)
    assert onset == pytest.approx(math.sqrt(2.0), abs=0.25 / 2**30)
    assert all(i == s for i, s in static_heating)

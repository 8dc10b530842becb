"""A load scale whose self-heating iteration merely ran out of iterations is not the runaway onset.

docs/thermal.md (self-heating section): "**Runaway** = an iterate exceeds the allowable
temperature, i.e. no fixed point below it", and ``runaway_onset``'s docstring: the first load
multiple "at which the self-heating has no fixed point below the allowable temperature". An
iteration stopped by its limit with every iterate below the allowable ("not_converged") has not
shown that; the onset is the first scale that ran away.

The self-heating run is replaced by the affine Picard map T ← (1 − ρ) T*(s) + ρ T, ρ = 0.9,
with the equilibrium T*(s) = 300 K + 50 K · s² (a static-load heating, as in
tests/test_runaway_onset_load_scale_reference.py), iterated by the product's ``fixed_point``
from T_0 = 300 K against an allowable 400 K with 5 iterations at most. Derived here: the
iterates are T_n = T* − ρⁿ (T* − T_0).

* s = 1: T* = 350 K, every iterate below 400 K; the last step
  |T_5 − T_4| = ρ⁴ (1 − ρ) · 50 K = 3.28 K > tol = 1e-3 K, so "not_converged".
* s = 3: T* = 750 K; T_1 = 345 K, T_2 = 385.5 K, T_3 = 421.95 K > 400 K: "runaway" at n = 3.

So the onset of the list [1, 3] is 3 (exactly, the list's own value), not 1.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

import flexshaft.thermal.selfheating as selfheating

RHO, T0, ALLOWABLE = 0.9, 300.0, 400.0


def _stand_in(model, options=None, loss_model=None, *, imbalance_scale=1.0, static_scale=1.0, **kwargs):
    t_star = T0 + 50.0 * static_scale**2

    def update(T):
        return (1.0 - RHO) * t_star + RHO * T

    fp = selfheating.fixed_point(update, np.array([T0]), ALLOWABLE, tol=1e-3, max_iter=5)
    return SimpleNamespace(status=fp.status, max_temperature=float(fp.temperature.max()), iterations=fp.iterations)


def test_an_unconverged_scale_below_the_allowable_is_not_the_onset(monkeypatch):
    monkeypatch.setattr(selfheating, "self_heating", _stand_in)
    onset, results = selfheating.runaway_onset(object(), [1.0, 3.0])
    assert onset == 3.0  # the onset rule: the first scale that runs away
    # the stand-in behaves as derived in the docstring (guards the reference itself)
    assert [r.status for r in results] == ["not_converged", "runaway"]
    assert results[0].max_temperature < ALLOWABLE
    assert results[1].iterations == 3


def test_a_list_of_only_unconverged_scales_has_no_onset(monkeypatch):
    """Every scale's equilibrium lies below 400 K (s ≤ 1.2: T* ≤ 372 K): no runaway, no onset."""
    monkeypatch.setattr(selfheating, "self_heating", _stand_in)
    onset, results = selfheating.runaway_onset(object(), [0.8, 1.0, 1.2])
    assert [r.status for r in results] == ["not_converged"] * 3
    assert onset is None

"""A self-heating iteration that stops without converging fails the temperature check: its last
temperature is no equilibrium (review of hunt h52b: the verdict passed on it).

Reference (derived here): the Picard iteration T ← f(T) = a + ρ T with 0 < ρ < 1 has the
equilibrium T* = a/(1 − ρ) and, from T_0 < T*, the iterates T_n = T* − ρⁿ (T* − T_0): they rise
toward T* and stay below it. With ρ = 0.98, T_0 = 300 K and T* = 420 K (a = 8.4 K), sixty steps
reach T_60 = 420 − 120 · 0.98⁶⁰ = 384.29 K: below an allowable of 400 K although the equilibrium
lies 20 K above it. :func:`flexshaft.thermal.selfheating.fixed_point` stops there "not_converged"
(each step still moves by 120 ρⁿ (1 − ρ) ≈ 0.7 K > tol); judged on that temperature the check
would pass with a 15.7 K margin. docs/requirements.md, the `temperature` row: a runaway or an
iteration that did not converge fails; a converged equilibrium below the allowable passes.

The iterates are sums of a few products: 1e-9 relative on T_60 (60 steps of round-off).
No model: a stand-in point holds the iteration's result. Milliseconds.
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.design.requirements import Requirements
from flexshaft.thermal.selfheating import fixed_point
from flexshaft.verdict import gather
from flexshaft.verdict.checks import temperature
from flexshaft.verdict.evidence import Evidence

RHO, T0, T_STAR, ALLOWABLE = 0.98, 300.0, 420.0, 400.0
A = T_STAR * (1.0 - RHO)  # 8.4 K


def _judged(max_iter: int, t_star: float = T_STAR):
    """The temperature check of a point whose self-heating is the affine iteration above."""
    a = t_star * (1.0 - RHO)
    fp = fixed_point(lambda T: a + RHO * T, np.full(3, T0), ALLOWABLE, tol=1e-4, max_iter=max_iter)
    shaft = NS(temperature=fp.temperature, x=np.array([0.0, 1.0, 2.0]))
    point = NS(thermal=NS(self_heating=NS(status=fp.status), shaft_temperature=shaft, loss_model="rotating"))
    point.conditions = None
    values = gather._temperature(point, {})
    evidence = Evidence(operating_speed=500.0, allowable_temperature=ALLOWABLE, **values)
    return fp, temperature(evidence, Requirements())


def test_an_iteration_stopped_below_the_allowable_short_of_an_equilibrium_above_it_fails():
    fp, check = _judged(max_iter=60)
    assert fp.status == "not_converged"
    assert fp.temperature.max() == pytest.approx(T_STAR - (T_STAR - T0) * RHO**60, rel=1e-9)  # 384.29 K
    assert fp.temperature.max() < ALLOWABLE < T_STAR
    assert check.status == "fail"
    assert "did not converge" in check.note


def test_the_converged_equilibrium_below_the_allowable_passes():
    """T* = 390 K < 400 K: converged (ρⁿ · 90 K < 1e-4 K after 700 steps) and passed, with the
    margin of the equilibrium, 10 K (to the tolerance 1e-4 / (1 − ρ) = 5e-3 K)."""
    fp, check = _judged(max_iter=1000, t_star=390.0)
    assert fp.status == "converged"
    assert check.status == "pass"
    assert check.margin == pytest.approx(10.0, abs=5e-3)


def test_the_same_equilibrium_above_the_allowable_runs_away_when_the_iteration_is_long_enough():
    """T_n passes 400 K at n = ln(20/120)/ln(0.98) = 88.7: the 89th iterate runs away (and fails)."""
    fp, check = _judged(max_iter=1000)
    assert fp.status == "runaway" and fp.iterations == 89
    assert check.status == "fail"

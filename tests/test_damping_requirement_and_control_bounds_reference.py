"""Edges of the whirl-damping requirement and of the bearing and magnet quantities.

References, independent of flexshaft's code:

* the free-decay logarithmic decrement of a viscously damped oscillator, derived here: the
  free decay x(t) = A e^(−ζω_n t) cos(ω_d t), ω_d = ω_n √(1 − ζ²), falls over one period
  T_d = 2π/ω_d by the ratio e^(ζω_n T_d), so δ = ζω_n T_d = 2πζ/√(1 − ζ²) (as docs/requirements.md
  states). At ζ = 0 it is 0: a requirement ``min_damping_ratio = 0`` asks for
  bare stability (δ ≥ 0), like ``min_log_decrement = 0``, not for the default δ ≥ 0.1 of an
  omitted requirement. At ζ = 1 (critical damping) the free decay does not oscillate, δ has no
  period to be measured over and the formula divides by zero: the schema's ζ ∈ [0, 1) refuses
  1 and accepts the largest double below it. ζ = 1/(2π)·0.1/√(1 + (0.1/2π)²) inverts δ = 0.1
  (the closed-form inverse ζ = δ/√(4π² + δ²)), checked to 1e-15 (a few roundings).
* docs/limits.md's range table: ``Damping`` "0 to 1e9 N s/m" (an undamped bearing, c = 0, is
  the usual idealisation of a rolling-element support), ``IntegralGain`` "0 to 1e15" (K_I = 0 is
  a PD law written out, as an omitted ``integral_gain`` is), ``Current`` "above 0, up to 10 kA":
  a magnet's current gain k_i = 4 k i_0/g_0² (docs/magnetic-bearings.md) vanishes at i_0 = 0,
  and the schema's ``CurrentGain`` refuses k_i = 0 ("above 0"), so a zero bias current is
  refused too.

Each check validates one number (pydantic) or reads one property: exact, no tolerance beyond
the stated one. Written for the mutations h51c-req-damping-ratio-one-accepted,
h51c-req-zero-damping-ratio-falls-to-default, h51c-q-zero-bias-current,
h51c-q-zero-integral-gain-refused and h51c-q-undamped-bearing-refused of scripts/mutations.toml
(it also catches h51c-req-zero-log-decrement-refused and -falls-to-default).
"""

from __future__ import annotations

import math

import pytest
from pydantic import ValidationError
from test_requirement_quantities_reference import _accepts

from flexshaft.design.quantities import Current, CurrentGain, Damping, IntegralGain
from flexshaft.design.requirements import Requirements


def test_a_zero_damping_ratio_requires_bare_stability():
    assert Requirements(min_damping_ratio=0.0).required_log_decrement == 0.0  # 2π·0/√1
    assert Requirements(min_log_decrement=0.0).required_log_decrement == 0.0
    assert Requirements().required_log_decrement == 0.1  # omitted: API 617's δ ≥ 0.1


def test_the_damping_ratio_that_inverts_the_default_decrement():
    delta = 0.1
    zeta = delta / math.sqrt(4.0 * math.pi**2 + delta**2)  # the closed-form inverse
    assert zeta == pytest.approx(0.0159, abs=5e-5)  # docs/requirements.md: ζ = 0.0159 ⇔ δ = 0.1
    assert Requirements(min_damping_ratio=zeta).required_log_decrement == pytest.approx(delta, rel=1e-15)


def test_a_critically_damped_requirement_is_refused():
    with pytest.raises(ValidationError, match="min_damping_ratio"):
        Requirements(min_damping_ratio=1.0)
    below = math.nextafter(1.0, 0.0)
    assert math.isfinite(Requirements(min_damping_ratio=below).required_log_decrement)


def test_an_undamped_bearing_and_a_pd_law_are_accepted():
    assert _accepts(Damping, 0.0) and _accepts(Damping, 1e9)
    assert not _accepts(Damping, -1.0)
    assert _accepts(IntegralGain, 0.0) and _accepts(IntegralGain, 1e15)
    assert not _accepts(IntegralGain, -1.0)


def test_a_magnet_without_bias_current_is_refused_like_its_zero_current_gain():
    assert not _accepts(CurrentGain, 0.0)  # k_i = 4 k i_0 / g_0² = 0 at i_0 = 0
    assert not _accepts(Current, 0.0)
    assert _accepts(Current, math.nextafter(0.0, 1.0)) and _accepts(Current, 1e4)
    assert not _accepts(Current, math.nextafter(1e4, math.inf))

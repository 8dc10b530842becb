"""A transfer function one degree improper (the ideal derivative) is accepted and evaluated.

Reference: the rule in :mod:`flexshaft.assembly.controller` (``Controller`` docstring: "The
numerator may exceed the denominator's degree by one (an ideal derivative: PD, unfiltered
PID)"; ``from_transfer_function`` refuses only a law "improper by more than one degree").
Closed forms derived here, for s = iω:

* PD ``C(s) = kd s + kp`` (num = [kd, kp], den = [1]): ``C(iω) = kp + i kd ω``; its
  realization ``C(s) = E s + D + C(sI − A)⁻¹B`` has no states, ``D = kp``, ``E = kd``
  (the realization's docstring).
* unfiltered PID ``C(s) = (kd s² + kp s + ki)/s``: ``C(iω) = kp + i (kd ω − ki/ω)``, one
  controller state (the integrator), ``E = kd``, ``D = kp``.

The transfer functions are handed over as duck-typed objects with ``num``/``den`` (as a
``scipy.signal`` system, ``dt = None``) and in python-control's nested ``[[array]]`` form with
``dt = 0``. Tolerance 1e-13 relative: the values are a few products and sums of doubles of
order 1e3-1e6 (no cancellation: real and imaginary parts are checked separately against
non-zero references); the realization's solve of a 1×1 system adds one rounding.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly.controller import Controller

KP, KD, KI = 2.0e5, 150.0, 4.0e6  # [N/m], [N s/m], [N/(m s)]
OMEGAS = (30.0, 2.0 * np.pi * 60.0, 5.0e3)  # [rad/s]


class _ScipyLike:
    """A continuous-time SISO system as ``scipy.signal`` holds it (flat num/den, dt None)."""

    def __init__(self, num, den):
        self.num, self.den, self.dt = list(num), list(den), None


class _PythonControlLike:
    """python-control's SISO ``TransferFunction`` layout: ``[[array]]`` num/den, dt = 0."""

    def __init__(self, num, den):
        self.num, self.den, self.dt = [[np.array(num)]], [[np.array(den)]], 0


def _realized(law: Controller, s: complex) -> complex:
    A, B, C, D, E = law.realization()
    states = (C @ np.linalg.solve(s * np.eye(A.shape[0]) - A, B)).item() if A.size else 0.0
    return E * s + D + states


@pytest.mark.parametrize("wrap", [_ScipyLike, _PythonControlLike])
def test_pd_transfer_function_is_accepted_as_an_ideal_derivative(wrap):
    law = Controller.from_transfer_function(wrap([KD, KP], [1.0]))
    assert law.relative_degree == -1
    A, _, _, D, E = law.realization()
    assert A.shape == (0, 0) and (D, E) == pytest.approx((KP, KD), rel=1e-15)
    for w in OMEGAS:
        value = complex(law(1j * w))
        assert value.real == pytest.approx(KP, rel=1e-13)
        assert value.imag == pytest.approx(KD * w, rel=1e-13)
        assert _realized(law, 1j * w) == pytest.approx(KP + 1j * KD * w, rel=1e-13)


@pytest.mark.parametrize("wrap", [_ScipyLike, _PythonControlLike])
def test_unfiltered_pid_transfer_function_is_accepted(wrap):
    law = Controller.from_transfer_function(wrap([KD, KP, KI], [1.0, 0.0]))
    A, _, _, D, E = law.realization()
    assert A.shape == (1, 1) and (D, E) == pytest.approx((KP, KD), rel=1e-15)
    assert law.integrates
    for w in OMEGAS:
        expected = KP + 1j * (KD * w - KI / w)
        value = complex(law(1j * w))
        assert value.real == pytest.approx(KP, rel=1e-13)
        assert value.imag == pytest.approx(expected.imag, rel=1e-13)
        assert _realized(law, 1j * w) == pytest.approx(expected, rel=1e-13)


def test_two_degrees_improper_is_refused():
    """The documented limit on the other side: ``kd s² + kp`` (relative degree −2) is refused."""
    with pytest.raises(ValueError, match="improper by more than one degree"):
        Controller.from_transfer_function(_ScipyLike([KD, 0.0, KP], [1.0]))

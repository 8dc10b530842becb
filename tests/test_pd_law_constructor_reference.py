"""The PD law's constructor against the textbook law ``C(s) = k_p + k_d s``, evaluated by hand.

Reference: a proportional-derivative law maps the displacement d to ``k_p d + k_d ḋ``, i.e.
``C(s) = k_p + k_d s`` (Åström & Murray, *Feedback Systems*, 2008, ch. 10, the PID law with
k_i = 0 and no derivative filter). Its static stiffness is C(0) = k_p, its damping
dC/ds = k_d, and it has no state: the realization ``E s + D`` has E = k_d, D = k_p. The
unfiltered PID constructor without integral action is the same law.

Written for the mutation h18a-pd-coefficients-ascending of scripts/mutations.toml (the
coefficients written lowest power first: k_p s + k_d), which the suite did not catch: the
design's bearings build their laws from the coefficients, not through ``Controller.pd``.
Each value is two floating-point operations on numbers of order 1 to 1e8: agreement to a
relative 1e-13 (a few ε ≈ 2e-16, with margin).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly.controller import Controller

KP, KD = 3.0e6, 1.2e3  # k_p [N/m], k_d [N s/m]: k_p/k_d = 2500 rad/s, so both terms matter
S = np.array([0.0, 1j * 100.0, 1j * 2500.0, -4.0 + 30.0j, 1j * 1.0e5])


@pytest.mark.parametrize("law", [Controller.pd(KP, KD), Controller.pid(KP, 0.0, KD)], ids=["pd", "pid-without-ki"])
def test_pd_law_is_kp_plus_kd_s(law):
    np.testing.assert_allclose(law(S), KP + KD * S, rtol=1e-13)
    assert law.is_pd
    assert law.kp == pytest.approx(KP, rel=1e-13)  # static stiffness C(0)
    assert law.kd == pytest.approx(KD, rel=1e-13)  # damping dC/ds
    A, B, C, D, E = law.realization()
    assert A.shape == (0, 0)  # no controller state
    assert (D, E) == pytest.approx((KP, KD), rel=1e-13)


def test_pd_law_damps_and_stiffens_by_its_own_gains():
    """At s = iω the real part is the stiffness k_p at every ω and the imaginary part the
    damping force ω k_d: a law written k_p s + k_d would give a stiffness k_d and ω k_p."""
    omega = 700.0
    value = Controller.pd(KP, KD)(1j * omega)
    assert value.real == pytest.approx(KP, rel=1e-13)
    assert value.imag == pytest.approx(omega * KD, rel=1e-13)

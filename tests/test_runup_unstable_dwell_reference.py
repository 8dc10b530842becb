"""A dwell above the whirl onset is refused before integrating, at the Jeffcott growth rate.

:func:`~flexshaft.analyses.transient.transient_response` refuses, before it integrates, a run
that holds an unstable speed long enough for a free whirl to grow more than MAX_GROWTH-fold
(``∫ max(0, largest Re λ) dt > ln MAX_GROWTH``), naming the growth rate.

Rotor: the Jeffcott disk of tests/rotors.py (m = 20 kg at midspan of a near-massless
pinned-pinned tube, k = 48EI/L³, ω_n = √(k/m)) with a loss factor η = 0.02 in the rotating
frame and no external damping. The run-up's causal loss (module docstring of
:mod:`flexshaft.analyses.transient`) is the viscous D = kη/(ω_n + Ω) on the velocity relative
to the spin, so in complex coordinates r = v + i w the free whirl obeys

    m s² + D (s − iΩ) + k = 0,

whose forward root has, to first order in D, Re s = ηω_n(Ω − ω_n)/(2(ω_n + Ω)) (derived:
s = iω_n + δ, 2imω_nδ + D(iω_n − iΩ) = 0): at Ω = 2ω_n, ηω_n/6 = 1.0 1/s, growth. The rate
is asserted against the exact root of the quadratic (np.roots) to 5e-3 (the message's three
digits; the tube's mass, 3.5e-6 of the disk's, and the two-mode basis are far below).

* a dwell of 10 s grows e^{10}-fold > MAX_GROWTH = 1e3 (e^{6.9}): refused before the
  integrator is reached;
* a dwell of 3 s grows e^{3}-fold < 1e3: handed to the integrator (here a stand-in that
  records the call; the run itself is not this test's subject).

Written for the mutations h35b-transient-growth-rate-min and h35b-transient-growth-limit-not-log
of scripts/mutations.toml. CPU: two two-mode setups, no integration.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

import flexshaft.analyses.transient as transient_module
from flexshaft.analyses.envelope import MAX_GROWTH
from flexshaft.analyses.guards import UnstableResponseError
from flexshaft.analyses.transient import SpeedProfile, transient_response

ETA = 0.02
SPEED = 2.0 * WN


class _Reached(Exception):
    pass


def _integrator(*args, **kwargs):
    raise _Reached


def _run(model, dwell):
    return transient_response(
        model, SpeedProfile.table([0.0, dwell], [SPEED, SPEED]), basis_size=2, initial="rest", output_step=0.5
    )


def test_a_dwell_growing_beyond_max_growth_is_refused_before_integrating(monkeypatch):
    monkeypatch.setattr(transient_module, "integrate_envelope", _integrator)
    model = jeffcott(ETA, 0.0, "rotating")
    D = K_SHAFT * ETA / (WN + SPEED)
    roots = np.roots([M_DISK, D, K_SHAFT - 1j * D * SPEED])
    rate = roots.real.max()
    assert rate == pytest.approx(ETA * WN / 6, rel=0.02)  # the first-order form, at Ω = 2 ω_n
    assert rate * 3.0 < np.log(MAX_GROWTH) < rate * 10.0 < MAX_GROWTH
    with pytest.raises(UnstableResponseError) as refused:
        _run(model, 10.0)
    reported = float(re.search(r"growth rate ([-+0-9.e]+) 1/s", str(refused.value)).group(1))
    assert reported == pytest.approx(rate, rel=5e-3)
    with pytest.raises(_Reached):  # e^3 < MAX_GROWTH: integrated
        _run(model, 3.0)

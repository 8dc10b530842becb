"""The stiffness a magnetic bearing lends the modal basis is its static stiffness
k_i k_p − k_s (its positive part), wherever its sensor sits.

Derivation, from the linearised magnet (docs/magnetic-bearings.md, ``Actuator``): the magnet
pulls the shaft with f = k_s d_a + k_i i and the PD law commands i = −(k_p + k_d s) d_s. At rest
(s = 0) with the sensor reading the displacement at the magnet (d_s = d_a = d, exact for a rigid
translation, and the basis's approximation for a remote sensor) f = −(k_i k_p − k_s) d: a
spring of k_i k_p − k_s on the actuation rows. The basis stiffness is that spring when it is
positive and 0 otherwise (the basis problem K + Σ k_a BᵀB must stay positive semi-definite;
docstring of ``Actuator.basis_stiffness``). It cannot depend on the sensor's station: the
negative stiffness belongs to the magnet, so it is subtracted whether the law is collocated or
not.

Numbers (tests/jeffcott_bearing.py): k_i = 100 N/A, k_p = 5e3 A/m, k_s = 2e5 N/m, so
k_i k_p − k_s = 3e5 N/m; with k_p = 1e3 A/m, 1e5 − 2e5 < 0: 0. A rigid unit translation of the
shaft in v (d_a = (1, 0)) then stores qᵀ K_p q = 3e5 N/m in the model's basis stiffness matrix.
A unit v at the magnet's node alone stores the same (module below: it tells the magnet's rows
from the sensor's). The clip to 0 of a negative spring is the code's documented convention (the
basis problem must stay positive semi-definite), not physics. Products of binary-exact decimals:
1e-12 relative asserted. Cheap: four 4-element models.

Written for the mutation h35c-model-basis-stiffness-ks-sign of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import KD, KI, KP, KS, model_with

REMOTE = "\nsensor_offset = 0.125"


def _law(kp: float) -> str:
    return f'kind = "active"\nkp = {kp}\nkd = {KD}\nks = {KS}\nki = {KI}'


@pytest.mark.parametrize("sensor", ["", REMOTE], ids=["collocated", "remote sensor"])
@pytest.mark.parametrize(("kp", "expected"), [(KP, KI * KP - KS), (1e3, 0.0)], ids=["stiff", "weak"])
def test_the_basis_stiffness_is_the_static_stiffness(sensor, kp, expected):
    model = model_with(_law(kp) + sensor)
    actuator = model.actuators[0]
    assert actuator.collocated == (sensor == "")
    assert actuator.basis_stiffness == pytest.approx(expected, rel=1e-12, abs=1e-12)
    q = np.zeros(model.dofs.size)
    q[model.dofs.values(np.arange(model.dofs.size), "shaft", "v")] = 1.0  # rigid unit translation in v
    assert q @ (model.Kp @ q) == pytest.approx(expected, rel=1e-12, abs=1e-12)
    # a unit v at the magnet's node alone (slopes 0): the spring acts on the magnet's own
    # displacement, qᵀK_p q = k (B_a q)² = k. A remote sensor 0.125 m away, mid-element of the
    # 0.25 m elements, would read the Hermite value 1/2 there (N₁(½) = 1/2): a basis built on
    # B_aᵀB_s instead of B_aᵀB_a would store k/2 (a review: the rigid translation reads 1 at both)
    at_magnet = np.asarray(actuator.lateral_rows[0].toarray()).ravel()
    assert np.count_nonzero(at_magnet) == 1 and at_magnet.max() == 1.0
    assert at_magnet @ (model.Kp @ at_magnet) == pytest.approx(expected, rel=1e-12, abs=1e-12)

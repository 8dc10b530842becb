"""The assumed matrix temperature law, evaluated by hand (docs/thermal.md, DESIGN.md, the
``[thermal]`` matrix_* keys):

    E_T(T) = E_T,ref exp(-(T - T_ref)/theta_E),  G_LT likewise,
    eta(T) = min(eta_ref exp(+(T - T_ref)/theta_eta), eta_max),  for eta_T and eta_LT,
    E_L and its loss factor unchanged.

A loss factor above 1 is no cap at all once the exponential runs away (the self-heating fixed
point and the whirl damping would see an ever lossier matrix): the cap must bind. Values below
are computed with math.exp here; tolerance 1e-12 (rounding).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.thermal.matrix import MatrixTemperatureLaw

REFERENCE = {"E_L": 115e9, "E_T": 0.10e9, "G_LT": 0.035e9, "loss_E_L": 0.003, "loss_E_T": 0.12, "loss_G_LT": 0.3}


@pytest.mark.parametrize("dT", [-40.0, 30.0, 60.0, 200.0])
def test_law_softens_the_matrix_and_caps_its_loss_factors(dT):
    law = MatrixTemperatureLaw(modulus_decay=40.0, loss_growth=60.0, max_loss_factor=1.0)
    got = law.properties(REFERENCE, law.reference_temperature + dT)
    soft, lossy = math.exp(-dT / 40.0), math.exp(dT / 60.0)
    assert got["E_L"] == REFERENCE["E_L"] and got["loss_E_L"] == REFERENCE["loss_E_L"]
    for name in ("E_T", "G_LT"):
        assert got[name] == pytest.approx(REFERENCE[name] * soft, rel=1e-12)
        assert got["loss_" + name] == pytest.approx(min(REFERENCE["loss_" + name] * lossy, 1.0), rel=1e-12)


def test_the_cap_binds_at_the_given_maximum():
    # 0.3 e^(120/60) = 2.2 and 0.12 e^2 = 0.89: with eta_max = 0.5 both are capped at 0.5
    law = MatrixTemperatureLaw(loss_growth=60.0, max_loss_factor=0.5)
    got = law.properties(REFERENCE, law.reference_temperature + 120.0)
    assert got["loss_G_LT"] == 0.5 and got["loss_E_T"] == 0.5

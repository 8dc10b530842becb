"""The default matrix law caps the transverse and shear loss factors at 1 (documented rule).

Reference: docs/thermal.md ("Without a table"): E_T and G_LT scale by exp(−(T − T_ref)/θ_E),
their loss factors by exp(+(T − T_ref)/θ_η) "(capped at 1)", with θ_E = 40 K, θ_η = 60 K,
T_ref = 20 °C. A law built with these documented constants and no explicit cap, evaluated at
ΔT = +120 K on loss factors 0.3 (η_T) and 0.1 (η_LT), gives by hand:

* η_T: 0.3 e^{2} = 2.217 > 1, so exactly 1 (the cap);
* η_LT: 0.1 e^{2} = 0.7389 < 1, so 0.1 e^{2} (a cap below 0.739, the mutant's 0.5
  among them, would show here; any other cap below 2.2 shows in η_T above);
* E_T, G_LT: × e^{−3}; E_L and η_L unchanged.

Tolerance 1e-14 relative: one exp and one product in double precision.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.thermal.matrix import MatrixTemperatureLaw

REFERENCE = {"E_L": 130e9, "E_T": 9e9, "G_LT": 5e9, "loss_E_L": 0.005, "loss_E_T": 0.3, "loss_G_LT": 0.1}


def test_default_law_caps_loss_factors_at_one():
    T_ref = 293.15
    law = MatrixTemperatureLaw(reference_temperature=T_ref, modulus_decay=40.0, loss_growth=60.0)
    new = law.properties(REFERENCE, T_ref + 120.0)
    assert new["loss_E_T"] == 1.0
    assert new["loss_G_LT"] == pytest.approx(0.1 * math.exp(2.0), rel=1e-14, abs=0)
    assert new["E_T"] == pytest.approx(9e9 * math.exp(-3.0), rel=1e-14, abs=0)
    assert new["G_LT"] == pytest.approx(5e9 * math.exp(-3.0), rel=1e-14, abs=0)
    assert new["E_L"] == 130e9 and new["loss_E_L"] == 0.005

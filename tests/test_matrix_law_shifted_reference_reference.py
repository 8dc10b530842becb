"""The assumed matrix law measured from the law's own reference temperature, not 20 °C.

Reference (docs/thermal.md, "Lamina properties over temperature", hand-written): without a
table, "E_T and G_LT scale by exp(−(T − T_ref)/θ_E), their loss factors by
exp(+(T − T_ref)/θ_η) (capped at 1); E_L and η_L do not change", with T_ref the
``[thermal] matrix_reference_temperature_c`` (an envelope point re-references the law to its
material temperature, so T_ref ≠ 20 °C is an everyday product path). Here T_ref = 50 °C and
T = 70 °C, so ΔT = 20 K and, with θ_E = 40 K and θ_η = 60 K, derived here:

    E_T(T) = E_T0 · e^(−1/2),  G_LT(T) = G_LT0 · e^(−1/2),
    η_T(T) = η_T0 · e^(1/3),   η_LT(T) = η_LT0 · e^(1/3),   E_L, η_L unchanged.

A law that measured ΔT from 20 °C would scale by e^(−50/40) and e^(50/60) instead: factors
2.1 and 1.6 away. Tolerance 1e-12 relative: each value is one product of a datum with one
``exp`` (a few ulp), far below the tested differences.
"""

import math

import pytest

from flexshaft.laminate import Lamina
from flexshaft.thermal.matrix import MatrixTemperatureLaw
from flexshaft.units import celsius_to_kelvin

T_REF = celsius_to_kelvin(50.0)
T_HOT = celsius_to_kelvin(70.0)
LAW = MatrixTemperatureLaw(reference_temperature=T_REF, modulus_decay=40.0, loss_growth=60.0)
REFERENCE = {"E_L": 120e9, "E_T": 4e9, "G_LT": 2.5e9, "loss_E_L": 0.002, "loss_E_T": 0.05, "loss_G_LT": 0.07}


def test_properties_scale_from_the_law_reference_temperature():
    """``properties`` at T_ref + 20 K: the closed-form factors e^(−1/2) and e^(1/3)."""
    soft, lossy = math.exp(-0.5), math.exp(1.0 / 3.0)
    new = LAW.properties(REFERENCE, T_HOT)
    assert new["E_T"] == pytest.approx(REFERENCE["E_T"] * soft, rel=1e-12)
    assert new["G_LT"] == pytest.approx(REFERENCE["G_LT"] * soft, rel=1e-12)
    assert new["loss_E_T"] == pytest.approx(REFERENCE["loss_E_T"] * lossy, rel=1e-12)
    assert new["loss_G_LT"] == pytest.approx(REFERENCE["loss_G_LT"] * lossy, rel=1e-12)
    assert new["E_L"] == REFERENCE["E_L"] and new["loss_E_L"] == REFERENCE["loss_E_L"]


def test_analysis_lamina_below_a_shifted_reference_stiffens():
    """The analyses' complex lamina at T_ref − 20 K (30 °C, i.e. above 20 °C but below the
    reference): E_T and G_LT stiffen by e^(+1/2), their loss factors fall by e^(−1/3); measured
    from 20 °C they would soften instead (e^(−10/40)), so the sign of the change is tested too."""
    lamina = Lamina.from_loss_factors(
        REFERENCE["E_L"],
        REFERENCE["E_T"],
        REFERENCE["G_LT"],
        0.3,
        1500.0,
        REFERENCE["loss_E_L"],
        REFERENCE["loss_E_T"],
        REFERENCE["loss_G_LT"],
    )
    cold = LAW.lamina(lamina, celsius_to_kelvin(30.0))
    stiff, dry = math.exp(0.5), math.exp(-1.0 / 3.0)
    for name in ("E_T", "G_LT"):
        modulus = complex(getattr(cold, name))
        assert modulus.real == pytest.approx(REFERENCE[name] * stiff, rel=1e-12)
        assert modulus.imag / modulus.real == pytest.approx(REFERENCE["loss_" + name] * dry, rel=1e-12)
        assert modulus.real > REFERENCE[name]
    assert complex(cold.E_L) == complex(lamina.E_L)

"""The ply's transverse shear moduli G_13, G_23 follow its in-plane moduli, at any temperature.

Transverse isotropy of a unidirectional ply (the 2-3 plane, across the fibres, is isotropic, so
any plane containing the fibres is equivalent to any other): the 1-3 plane is the 1-2 plane
turned about the fibres, so G_13 behaves as G_LT; the 2-3 plane is isotropic, so
G_23 = E_T / (2 (1 + ν_23)) with the matrix-dominated ν_23 held fixed, so G_23 ∝ E_T. Hence, when
the matrix warms and a temperature table scales E_T and G_LT by different factors, an explicit
G_13 scales by G_LT(T)/G_LT(T_ref) and an explicit G_23 by E_T(T)/E_T(T_ref) (complex ratios: the
loss factors follow too). By the same proportionality a complex G_23 carries the loss factor of
E_T, and G_13 that of G_LT (correspondence principle with real ν_23).

Numbers, chosen by hand: a two-row table at 20 °C and 60 °C in which E_T halves (8 → 4 GPa) and
G_LT falls by a quarter (4 → 3 GPa), their loss factors rising from 0.05 to 0.08 and 0.12;
explicit G_13 = 3.5 GPa, G_23 = 3 GPa (loss factor 0.05 at 20 °C). At 60 °C:
G_13 = 3.5 × 0.75 = 2.625 GPa with G_LT's loss factor 0.12, G_23 = 3 × 0.5 = 1.5 GPa with E_T's
0.08 (the complex ratio 3(1 + 0.12i)/(4(1 + 0.05i)) times 3.5(1 + 0.05i)). Every ratio is a product of a few
binary fractions of exact decimal inputs: tolerance 1e-12 relative (rounding).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.design.materials import Lamina as LaminaMaterial
from flexshaft.laminate import Lamina, Laminate, transverse_shear_stiffness
from flexshaft.thermal.matrix import LaminaTable, MatrixTemperatureLaw

T_REF, T_HOT = 293.15, 333.15
ETA = 0.05
TABLE = LaminaTable(
    (T_REF, T_HOT), (("E_T", (8e9, 4e9)), ("G_LT", (4e9, 3e9)), ("loss_E_T", (ETA, 0.08)), ("loss_G_LT", (ETA, 0.12)))
)
LAW = MatrixTemperatureLaw(reference_temperature=T_REF, table=TABLE, allowable_temperature=400.0)


def test_analysis_lamina_scales_g13_with_g_lt_and_g23_with_e_t():
    ply = Lamina.from_loss_factors(120e9, 8e9, 4e9, 0.3, 1500.0, 0.002, ETA, ETA, G_13=3.5e9, G_23=3e9)
    hot = LAW.lamina(ply, T_HOT)
    G13, G23 = hot.transverse_shear_moduli
    assert G13 == pytest.approx(2.625e9 * (1 + 0.12j), rel=1e-12)
    assert G23 == pytest.approx(1.5e9 * (1 + 0.08j), rel=1e-12)


def test_design_lamina_scales_g13_with_g_lt_and_g23_with_e_t():
    material = LaminaMaterial.model_validate(
        {
            "kind": "lamina",
            "density": 1500.0,
            "E_L": 120e9,
            "E_T": 8e9,
            "G_LT": 4e9,
            "nu_LT": 0.3,
            "loss_E_T": ETA,
            "loss_G_LT": ETA,
            "X_t": 1e9,
            "X_c": 8e8,
            "Y_t": 4e7,
            "Y_c": 1e8,
            "S": 5e7,
            "G_13": 3.5e9,
            "G_23": 3e9,
        }
    )
    hot = LAW.material(material, T_HOT)
    assert hot.E_T == pytest.approx(4e9, rel=1e-12) and hot.G_LT == pytest.approx(3e9, rel=1e-12)
    assert hot.G_13 == pytest.approx(2.625e9, rel=1e-12)
    assert hot.G_23 == pytest.approx(1.5e9, rel=1e-12)


def test_explicit_g23_carries_the_loss_factor_of_e_t_and_g13_that_of_g_lt():
    # a hoop ply (90°): A55 = k t G_23, A44 = k t G_13 (Q_55 = G_13 cos² + G_23 sin²)
    eta_T, eta_LT = 0.1, 0.3
    ply = Lamina.from_loss_factors(120e9, 8e9, 4e9, 0.3, 1500.0, 0.0, eta_T, eta_LT, G_13=3.5e9, G_23=3e9)
    A = transverse_shear_stiffness(Laminate(np.array([np.pi / 2]), np.array([1e-3]), ply))
    k_t = ply.shear_correction * 1e-3
    assert A[0, 0] == pytest.approx(k_t * 3e9 * (1 + 1j * eta_T), rel=1e-12)
    assert A[1, 1] == pytest.approx(k_t * 3.5e9 * (1 + 1j * eta_LT), rel=1e-12)

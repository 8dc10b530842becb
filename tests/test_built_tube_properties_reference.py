"""The laminated shaft tube that ``build_model`` hands to the analyses: its complex moduli and
its transverse shear stiffness, for one-ply tubes whose answers are written by hand.

* **Moduli of a one-ply tube.** The wall's equivalent moduli are E* = 1/(t a₁₁) and
  G* = 1/(t a₆₆) with a = A⁻¹ (thesis eq. 2.4). For a single ply A = t Q̄(θ) and a = S̄(θ)/t, the
  ply's rotated compliance. At θ = 0 S̄₁₁ = 1/E_L*, S̄₆₆ = 1/G_LT*; at θ = 90° S̄₁₁ = 1/E_T*
  (the fibres run round the tube: the axial direction is the transverse one), whatever the
  Poisson ratio (Jones 1999, eq. 2.84 with cos θ = 0). With the correspondence principle each
  modulus is complex, M(1 + iη_M), with its own loss factor: the [0] tube's E* = E_L(1 + iη_L) and
  G* = G_LT(1 + iη_G), the [90] tube's E* = E_T(1 + iη_T). The loss factors are chosen unequal
  (0.01, 0.04, 0.07) so that one read in another's place is seen.
* **Transverse shear of a [0] tube** (first-order shear deformation): A₅₅ = k t G₁₃* (the x-z
  plane of a ply along x is its 1-3 plane), A₄₄ = k t G₂₃* (the y-z plane, across the fibres),
  k = 5/6 by default (Reissner); G₁₃ carries the loss factor of G_LT and G₂₃ that of E_T
  (transverse isotropy: G₂₃ = E_T/(2(1 + ν₂₃)) with ν₂₃ real). G₁₃ = 5 GPa and G₂₃ = 3 GPa
  are given explicitly, both above the schema's bound E_T/(4(1 − ν_LT ν_TL)) ≈ 2 GPa.

* **A 45° ply: the Poisson ratio enters.** The rotated compliance (Jones 1999, eqs. 2.98 and
  2.99; S₁₁ = 1/E_L, S₂₂ = 1/E_T, S₁₂ = −ν_LT/E_L, S₆₆ = 1/G_LT) at θ = 45° (sin²θ cos²θ = ¼,
  sin⁴θ + cos⁴θ = ½) is S̄₁₁ = ¼ (S₁₁ + S₂₂ + 2 S₁₂ + S₆₆) and
  S̄₆₆ = ½ (2 S₁₁ + 2 S₂₂ − 4 S₁₂ − S₆₆) + ½ S₆₆ = S₁₁ + S₂₂ − 2 S₁₂, so
  E* = 1/(¼ (1/E_L* + 1/E_T* + 1/G_LT* − 2 ν_LT/E_L*)) and G* = 1/(1/E_L* + 1/E_T* + 2 ν_LT/E_L*),
  with the major Poisson ratio ν_LT (real) and the complex moduli. The minor ratio
  ν_TL = ν_LT E_T/E_L in its place moves E* by 1.2 % and G* by 3.5 %.

Each answer is a product or quotient of a few decimal inputs (one 1×1 or 3×3 inversion of a
well-conditioned ply matrix): 1e-12 relative asserted. Cheap: three 4-element models.

Written for the mutations h35c-build-lamina-transverse-loss-is-fibre-loss and
h35c-build-lamina-g13-g23-swapped of scripts/mutations.toml; the 45° test for
h38b-build-lamina-minor-poisson.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.laminate import transverse_shear_stiffness

E_L, E_T, G_LT = 120e9, 8e9, 4e9
ETA_L, ETA_T, ETA_G = 0.01, 0.04, 0.07
G_13, G_23 = 5e9, 3e9
WALL = 0.002

DESIGN = """
name = "one-ply tube"
[materials.ply]
kind = "lamina"
density = 1500.0
E_L = 120e9
E_T = 8e9
G_LT = 4e9
nu_LT = 0.3
loss_E_L = 0.01
loss_E_T = 0.04
loss_G_LT = 0.07
X_t = 1e9
X_c = 8e8
Y_t = 4e7
Y_c = 1e8
S = 5e7
G_13 = 5e9
G_23 = 3e9
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = 0.06
wall_thickness = 0.002
material = "ply"
layup = "{layup}"
fixed_start = ["u", "v", "w", "theta"]
[[bearings]]
name = "aft"
kind = "contact"
x = 1.0
stiffness = { v = 1e7, w = 1e7 }
[operating]
speed_rpm = 1000.0
power = 0.0
[mesh]
shaft_elements = 4
"""


def _shaft(layup: str):
    return build_model(loads_design(DESIGN.replace("{layup}", layup))).shaft


def test_a_zero_ply_tube_has_the_fibre_modulus_and_the_in_plane_shear_modulus_with_their_losses():
    shaft = _shaft("0")
    assert shaft.youngs_modulus == pytest.approx(E_L * (1 + 1j * ETA_L), rel=1e-12)
    assert shaft.shear_modulus == pytest.approx(G_LT * (1 + 1j * ETA_G), rel=1e-12)


def test_a_hoop_ply_tube_has_the_transverse_modulus_with_its_own_loss():
    shaft = _shaft("90")
    assert shaft.youngs_modulus == pytest.approx(E_T * (1 + 1j * ETA_T), rel=1e-12)


def test_a_zero_ply_tube_shears_through_g13_in_xz_and_g23_across_the_fibres():
    shaft = _shaft("0")
    stiffness = transverse_shear_stiffness(shaft.laminate)
    k = 5.0 / 6.0
    assert stiffness[0, 0] == pytest.approx(k * WALL * G_13 * (1 + 1j * ETA_G), rel=1e-12)  # A55
    assert stiffness[1, 1] == pytest.approx(k * WALL * G_23 * (1 + 1j * ETA_T), rel=1e-12)  # A44
    assert abs(stiffness[0, 1]) <= 1e-12 * abs(stiffness[0, 0])  # A45 = 0 for a ply along x
    assert np.isfinite(stiffness).all()


def test_a_45_degree_ply_tube_has_the_off_axis_moduli_with_the_major_poisson_ratio():
    shaft = _shaft("45")
    nu = 0.3
    e_l, e_t, g_lt = E_L * (1 + 1j * ETA_L), E_T * (1 + 1j * ETA_T), G_LT * (1 + 1j * ETA_G)
    youngs = 1.0 / (0.25 * (1 / e_l + 1 / e_t + 1 / g_lt - 2 * nu / e_l))
    shear = 1.0 / (1 / e_l + 1 / e_t + 2 * nu / e_l)
    # one 3x3 inversion of the rotated ply stiffness (condition number about 20): 1e-12 relative
    assert shaft.youngs_modulus == pytest.approx(youngs, rel=1e-12)
    assert shaft.shear_modulus == pytest.approx(shear, rel=1e-12)

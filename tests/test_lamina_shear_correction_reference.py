"""The lamina's transverse shear correction factor k reaches the first-order shear stiffness.

First-order shear deformation theory gives the wall's transverse shear stiffness
A_ij = k Σ_k Q_ij,k t_k (derived here: the transverse shear strains (γ_xz, γ_yz) rotate by the
ply angle α like a vector, γ13 = cγxz + sγyz, γ23 = −sγxz + cγyz, and the stresses back), so each
ply's transverse shear moduli give:

    Q55 = G13 cos²α + G23 sin²α,  Q44 = G13 sin²α + G23 cos²α,  Q45 = (G13 − G23) cos α sin α.

Derived here for the stacks used below:

* **A [0] ply of thickness t** (cos α = 1): A55 = k t G13*, A44 = k t G23*, A45 = 0.
* **A balanced [+45/−45] stack**, each ply t/2 (cos²α = sin²α = ½, cos α sin α = ±½):
  A55 = A44 = k t (G13* + G23*)/2 and A45 = k (t/2)(G13* − G23*)(½ − ½) = 0.

The factor k is the design field ``shear_correction`` (default 5/6): the user's value, not the
default, whenever the user gives another. Moduli are complex through the correspondence
principle: G13* = G13 (1 + iη_G) and G23* = G23 (1 + iη_T) (the loss factors of G_LT and E_T,
as :meth:`flexshaft.laminate.Lamina.from_loss_factors` documents).

k = 0.6 is chosen far from 5/6 (a 28 % change): a factor dropped on the way shows at once.
Each answer is a sum of two products of decimal inputs: 1e-12 relative (round-off of a few
multiplications, nothing ill-conditioned).

Written for the mutation h52a-lamina-shear-correction-dropped of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.laminate import Lamina, Laminate, transverse_shear_stiffness

E_L, E_T, G_LT, NU_LT = 120e9, 8e9, 4e9, 0.3
ETA_L, ETA_T, ETA_G = 0.01, 0.04, 0.07
G_13, G_23 = 5e9, 3e9
K_SHEAR = 0.6
WALL = 0.002

DESIGN = f"""
name = "one-ply tube with its own shear correction"
[materials.ply]
kind = "lamina"
density = 1500.0
E_L = {E_L}
E_T = {E_T}
G_LT = {G_LT}
nu_LT = {NU_LT}
loss_E_L = {ETA_L}
loss_E_T = {ETA_T}
loss_G_LT = {ETA_G}
X_t = 1e9
X_c = 8e8
Y_t = 4e7
Y_c = 1e8
S = 5e7
G_13 = {G_13}
G_23 = {G_23}
shear_correction = {K_SHEAR}
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = 0.06
wall_thickness = {WALL}
material = "ply"
layup = "0"
fixed_start = ["u", "v", "w", "theta"]
[[bearings]]
name = "aft"
kind = "contact"
x = 1.0
stiffness = {{ v = 1e7, w = 1e7 }}
[operating]
speed_rpm = 1000.0
power = 0.0
[mesh]
shaft_elements = 4
"""

G13_STAR = G_13 * (1 + 1j * ETA_G)
G23_STAR = G_23 * (1 + 1j * ETA_T)


def test_a_designed_zero_ply_tube_shears_with_the_designed_correction_factor():
    laminate = build_model(loads_design(DESIGN)).shaft.laminate
    stiffness = transverse_shear_stiffness(laminate)
    assert stiffness[0, 0] == pytest.approx(K_SHEAR * WALL * G13_STAR, rel=1e-12)  # A55
    assert stiffness[1, 1] == pytest.approx(K_SHEAR * WALL * G23_STAR, rel=1e-12)  # A44
    assert abs(stiffness[0, 1]) <= 1e-12 * abs(stiffness[0, 0])  # A45 = 0 along the fibres


def test_a_balanced_45_stack_from_loss_factors_carries_its_correction_factor():
    lamina = Lamina.from_loss_factors(
        E_L, E_T, G_LT, NU_LT, 1500.0, ETA_L, ETA_T, ETA_G, G_13=G_13, G_23=G_23, shear_correction=K_SHEAR
    )
    laminate = Laminate(np.radians([45.0, -45.0]), np.full(2, WALL / 2), lamina)
    stiffness = transverse_shear_stiffness(laminate)
    mean = K_SHEAR * WALL * 0.5 * (G13_STAR + G23_STAR)
    assert stiffness[0, 0] == pytest.approx(mean, rel=1e-12)
    assert stiffness[1, 1] == pytest.approx(mean, rel=1e-12)
    # the two plies' A45 cancel; their size is k (t/2)(G13 - G23)/2, cancellation leaves round-off
    assert abs(stiffness[0, 1]) <= 1e-12 * abs(mean)

"""Study 5's shell model and study 2's angle units (:mod:`flexshaft.thesis.buckling_sweep`,
:mod:`flexshaft.thesis.two_angles`).

References:

* **Study 5 is the shear-deformable shell.** Its module docstring: "the torsional-buckling
  safety factor ... (the shear-deformable shell of shaft_buckling)". That shell's short waves
  tend to the shear-crimping limit (docs/model.md, flexshaft/buckling/shear.py)
  T_crimp = 2πR²(√(A44 A55) ∓ A45), A44, A55, A45 = k Σ Q_s t_ply, with, for a ply at θ,
  Q44 = G23 cos²θ + G13 sin²θ, Q55 = G13 cos²θ + G23 sin²θ, Q45 = (G13 − G23) cosθ sinθ, the
  defaults G13 = G_LT, G23 = E_T/(2(1 + 0.5)) = E_T/3 and k the lamina's shear correction
  (docs/model.md), R = (D_o − t)/2 the mid-surface radius. Closed form: for very short buckles
  the wall's rotations cannot follow, so γ_xz = w_x, γ_yz = w_y; the wall is stable while
  A55 a² + 2A45 ab + A44 b² − 2N ab > 0 for all (a, b) = (w_x, w_y) (N the shear flow T/(2πR²)), and the first
  real root, at (N − A45)² = A44 A55, gives T = 2πR²(√(A44 A55) ∓ A45) (docs/model.md's formula,
  ~lines 304-306, with its G_23 default E_T/(2(1+ν_23)) = E_T/3, ~line 301). Computed here by
  hand from the design's lamina. The critical torque is the lowest of crimping and the global helices, so it
  never exceeds T_crimp; on the baseline (55/−55/0/0)s wall (3 mm, D_o 101.6 mm) docs/model.md
  states that crimping governs (2511 N m, against 7298 N m for the classical shell, which has no
  crimping): the study's torque there is T_crimp (balanced plies: A45 = 0, both senses equal).
  Measured relative difference 2e-16 (2e-16 at 2 mm too); tolerance 1e-9 (a sum of 8 plies and
  one square root).
  A thinner wall (2 mm) is checked against the bound only.
* **Study 2's angles are degrees.** ``two_angle_study``'s docstring: "``alphas`` and ``betas``
  [deg]": the map's alpha and beta coordinates carry units "deg".

Coarse mesh (18 shaft, 12 boom elements): the shell buckling model and the strength check's
units do not depend on the beam mesh.
"""

from __future__ import annotations

import math

import numpy as np

from flexshaft.design import baseline_design, with_overrides
from flexshaft.thesis.buckling_sweep import buckling_study
from flexshaft.thesis.two_angles import two_angle_study

COARSE = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}


def _crimping_torque(design, wall: float) -> float:
    """2πR²(√(A44 A55) − |A45|) of the design's (55/−55/0/0)s wall by hand [N m]."""
    mat = design.materials[design.shaft.material]
    g13 = mat.G_13 if mat.G_13 is not None else mat.G_LT
    g23 = mat.G_23 if mat.G_23 is not None else mat.E_T / 3.0
    k = mat.shear_correction
    plies = [55.0, -55.0, 0.0, 0.0, 0.0, 0.0, -55.0, 55.0]
    t_ply = wall / len(plies)
    a44 = a55 = a45 = 0.0
    for theta in plies:
        c, s = math.cos(math.radians(theta)), math.sin(math.radians(theta))
        a44 += k * (g23 * c * c + g13 * s * s) * t_ply
        a55 += k * (g13 * c * c + g23 * s * s) * t_ply
        a45 += k * (g13 - g23) * c * s * t_ply
    radius = (design.shaft.outer_diameter - wall) / 2.0
    return 2.0 * math.pi * radius**2 * (math.sqrt(a44 * a55) - abs(a45))


def test_buckling_study_is_the_shear_deformable_shell_with_its_crimping_limit():
    design = with_overrides(baseline_design(), COARSE)
    assert design.shaft.layup == "(55/-55/0/0)s" and design.shaft.wall_thickness == 0.003
    walls = np.array([0.002, 0.003])
    ds = buckling_study(walls, design=design, progress=False, as_arrays=True)
    critical = np.asarray(ds["critical_torque"].values, dtype=float)
    crimp = np.array([_crimping_torque(design, w) for w in walls])
    assert np.all(critical <= crimp * (1.0 + 1e-9))
    np.testing.assert_allclose(critical[1], crimp[1], rtol=1e-9)  # crimping governs at 3 mm (docs/model.md)
    assert round(crimp[1]) == 2511  # docs/model.md: "the wall crimps at 2511 N m" (baseline)


def test_two_angle_map_axes_are_in_degrees():
    design = with_overrides(baseline_design(), COARSE)
    ds = two_angle_study(np.array([55.0]), np.array([0.0]), design=design, progress=False)
    assert ds["alpha"].attrs["units"] == "deg"
    assert ds["beta"].attrs["units"] == "deg"

"""Axial conductivity of the laminated wall, which sets the shaft's conduction to its ends.

Reference, derived here: a ply is transversely isotropic in its plane, with conductivity k_L
along the fibres and k_T across them. Its conductivity tensor in the shaft axes is the rotation
R(α) diag(k_L, k_T) R(α)ᵀ (a second-order tensor), whose xx component is
k_L cos²α + k_T sin²α. Heat flowing along x crosses every ply in parallel (same gradient, fluxes
add), so the wall's axial conductivity is the thickness-weighted mean of the plies' k_xx
(rule of mixtures for parallel conductors). Hence [0] → k_L, [90] → k_T, [±45] → (k_L + k_T)/2.

The tensor is rotated in the test with an explicit rotation matrix (not the package's formula),
and the thickness weighting is checked with unequal plies and a total thickness ≠ 1 m, so a
missing normalisation or a sin/cos swap cannot pass. Equalities hold to round-off (1e-12).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.design import baseline_design, with_overrides
from flexshaft.laminate import Lamina, Laminate
from flexshaft.thermal.analysis import ISOTROPIC_SHAFT_CONDUCTIVITY, shaft_conductivity, shaft_thermal
from flexshaft.thermal.options import ThermalOptions, thermal_options
from flexshaft.thermal.shaft import FIBRE_CONDUCTIVITY, TRANSVERSE_CONDUCTIVITY, laminate_axial_conductivity

K_L, K_T = 7.0, 0.25  # W/(m K), distinct enough that any swap shows
LAMINA = Lamina.isotropic(E=70e9, G=26e9, density=1600.0)


def rotated_kxx(angle_rad: float, k_L: float = K_L, k_T: float = K_T) -> float:
    """xx component of R diag(k_L, k_T) Rᵀ, R the in-plane rotation by the ply angle."""
    c, s = math.cos(angle_rad), math.sin(angle_rad)
    R = np.array([[c, -s], [s, c]])
    return float((R @ np.diag([k_L, k_T]) @ R.T)[0, 0])


def laminate(angles_deg, thicknesses) -> Laminate:
    return Laminate(np.radians(angles_deg), np.asarray(thicknesses, dtype=float), LAMINA)


@pytest.mark.parametrize(
    "angles, expected",
    [([0.0], K_L), ([90.0], K_T), ([-90.0], K_T), ([45.0, -45.0], (K_L + K_T) / 2), ([30.0], 0.75 * K_L + 0.25 * K_T)],
)
def test_single_angle_stacks_follow_the_rotated_tensor(angles, expected):
    lam = laminate(angles, [0.75e-3] * len(angles))
    assert laminate_axial_conductivity(lam, K_L, K_T) == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(np.mean([rotated_kxx(math.radians(a)) for a in angles]), rel=1e-12)


def test_plies_conduct_in_parallel_weighted_by_thickness():
    # [0 (1 mm) / 90 (3 mm) / 55 (0.5 mm) / -55 (0.5 mm)], total 5 mm
    angles, t = [0.0, 90.0, 55.0, -55.0], np.array([1.0, 3.0, 0.5, 0.5]) * 1e-3
    expected = sum(ti * rotated_kxx(math.radians(a)) for a, ti in zip(angles, t)) / t.sum()
    assert laminate_axial_conductivity(laminate(angles, t), K_L, K_T) == pytest.approx(expected, rel=1e-12)
    # the weighting, not the ply count: the same plies, equal thicknesses, give the plain mean
    equal = laminate(angles, [1.25e-3] * 4)
    assert laminate_axial_conductivity(equal, K_L, K_T) == pytest.approx(
        np.mean([rotated_kxx(math.radians(a)) for a in angles]), rel=1e-12
    )


def test_conductivity_lies_between_the_ply_bounds_and_is_independent_of_wall_thickness():
    for total in (1e-3, 3e-3, 0.02):
        lam = Laminate.from_layup("(55/-55/0/0)s", total, LAMINA)
        k = laminate_axial_conductivity(lam, K_L, K_T)
        assert K_T < k < K_L
        assert k == pytest.approx(0.5 * K_L + 0.5 * rotated_kxx(math.radians(55.0)), rel=1e-12)


def test_the_model_path_uses_the_design_layup_and_the_options_ply_conductivities():
    # the baseline wall (55/-55/0/0)s: half the plies at 0°, half at ±55°
    model = fs.build_model(baseline_design())
    expected_default = 0.5 * FIBRE_CONDUCTIVITY + 0.5 * rotated_kxx(
        math.radians(55.0), FIBRE_CONDUCTIVITY, TRANSVERSE_CONDUCTIVITY
    )
    assert shaft_conductivity(model) == pytest.approx(expected_default, rel=1e-12)
    options = ThermalOptions(fibre_conductivity=K_L, transverse_conductivity=K_T)
    expected = 0.5 * K_L + 0.5 * rotated_kxx(math.radians(55.0))
    assert shaft_conductivity(model, options) == pytest.approx(expected, rel=1e-12)
    # the design's [thermal] table reaches the same number through thermal_options
    design = with_overrides(
        baseline_design(), {"thermal.fibre_conductivity": K_L, "thermal.transverse_conductivity": K_T}
    )
    assert shaft_conductivity(model, thermal_options(design.thermal)) == pytest.approx(expected, rel=1e-12)
    # and the temperature solution is solved with it
    assert shaft_thermal(model, options).conductivity == pytest.approx(expected, rel=1e-12)


def test_a_90_degree_wall_and_an_isotropic_shaft():
    design = with_overrides(baseline_design(), {"shaft.layup": "(90/-90)s"})
    model = fs.build_model(design)
    options = ThermalOptions(fibre_conductivity=K_L, transverse_conductivity=K_T)
    assert shaft_conductivity(model, options) == pytest.approx(K_T, rel=1e-12)
    metal = fs.build_model(with_overrides(baseline_design(), {"shaft.material": "al6061_t6", "shaft.layup": None}))
    assert shaft_conductivity(metal, options) == ISOTROPIC_SHAFT_CONDUCTIVITY

"""The thermal summary's ``tailboom_flags`` (flexshaft.thermal.study.thermal_summary) against the
validity ranges of the boom's Nusselt correlations, with the Reynolds and Rayleigh numbers
computed by hand.

References:

* **Documented rule** (docs/thermal.md, "Hover" and "Parked"): Hilpert is valid for
  0.4 ≤ Re ≤ 4×10⁵ and Pr ≥ 0.7, Churchill–Chu for 10⁻⁵ ≤ Ra ≤ 10¹², and a condition outside
  its correlation's range is flagged (``nusselt.in_range = False``) and listed under
  ``tailboom_flags``.
* **Hover, derived here**: Re_D = V D / ν with the momentum-theory downwash
  V = √(m g / (2 ρ π R²)) (docs/thermal.md eq. 2.56) from the design's ``[thermal]``
  ``rotorcraft_mass``, ``rotor_radius`` and ``air_density`` and the standard gravity
  g_n = 9.80665 m/s² (a defined constant): ≈ 12.8 m/s on the baseline. The equivalent diameter
  is the documented rule (docs/thermal.md, "Equivalent diameter"): the circle with the boom's
  mean skin perimeter, Ramanujan's perimeter at the length-averaged outer semi-axes; derived
  here: the outer semi-axes are the mid-line ones of ``[tailboom]`` averaged over root and tip
  plus half the wall, a = (a_root + a_tip)/2 + t/2, b likewise, and D = P/π with Ramanujan's
  second approximation P = π (a + b) (1 + 3λ / (10 + √(4 − 3λ))), λ = ((a − b)/(a + b))²
  (≈ 0.68 m on the baseline). ν = μ/ρ of dry air at the film temperature
  T_f = (T_skin + T_∞)/2: Sutherland's law μ = 1.716e-5 (T/273.15)^1.5 (273.15 + 110.4)/(T +
  110.4) Pa s and the ideal gas ρ = p/(R T), p = 101325 Pa, R = 287.05 J/(kg K). At the
  baseline's T_f ≈ 308 K this gives ν ≈ 1.64e-5 m²/s and Re ≈ 5.3×10⁵ > 4×10⁵ (32 % above the
  limit, far more than the few % by which this hand ν and the package's air properties could
  differ): hover must be flagged.
* **Parked, derived here**: Ra = g β ΔT D³ Pr / ν² with β = 1/T_f. Upper side: Pr < 1 for air
  and ν ≥ ν(T_∞) (ν grows with T, T_f ≥ T_∞) give Ra < g ΔT D³ / (T_f ν(T_∞)²) ≈ 2.45×10⁹ at
  the baseline's ΔT ≈ 63 K, 400 times below 10¹². Lower side: β ≥ 1/T_skin, ν ≤ ν(T_skin)
  (T_f ≤ T_skin) and Pr ≥ 0.5 (air's is ≈ 0.706 at the film, docs/thermal.md "Air") give, for
  any ΔT > 1e-3 K, Ra > g · 1e-3 K · D³ · 0.5 / (T_skin ν(T_skin)²) ≈ 9×10³ ≫ 10⁻⁵: parked
  must not be flagged.

The baseline design with a coarse mesh (the boom temperatures do not depend on the mesh; CPU).
"""

from __future__ import annotations

import math

import pytest

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.study import thermal_summary


def _kinematic_viscosity(T):
    """ν [m²/s] of dry air at T [K] and 101325 Pa: Sutherland's law over the ideal-gas density."""
    mu = 1.716e-5 * (T / 273.15) ** 1.5 * (273.15 + 110.4) / (T + 110.4)
    return mu / (101325.0 / (287.05 * T))


#: Standard gravity g_n [m/s²] (a defined constant).
STANDARD_GRAVITY = 9.80665


def _downwash(thermal):
    """Momentum-theory hover downwash V = √(m g / (2 ρ π R²)) [m/s] of a ``[thermal]`` table."""
    weight = thermal.rotorcraft_mass * STANDARD_GRAVITY
    return math.sqrt(weight / (2.0 * thermal.air_density * math.pi * thermal.rotor_radius**2))


def _equivalent_diameter(tailboom):
    """D = P/π [m]: Ramanujan's second perimeter of the ellipse with the root/tip-averaged
    mid-line semi-axes plus half the wall (the outer skin)."""
    t = tailboom.wall_thickness
    a = 0.5 * (tailboom.root_semi_axes[0] + tailboom.tip_semi_axes[0]) + t / 2
    b = 0.5 * (tailboom.root_semi_axes[1] + tailboom.tip_semi_axes[1]) + t / 2
    lam = ((a - b) / (a + b)) ** 2
    return (a + b) * (1.0 + 3.0 * lam / (10.0 + math.sqrt(4.0 - 3.0 * lam)))


@pytest.fixture(scope="module")
def summary():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    return design, thermal_summary(design, fs.build_model(design))


def test_the_hover_boom_beyond_hilperts_reynolds_range_is_flagged(summary):
    design, out = summary
    assert design.thermal.boom_convection == "hilpert"
    ambient = design.thermal.ambient_temperature_c + 273.15
    film = (out["tailboom_c"]["hover"] + 273.15 + ambient) / 2.0
    reynolds = _downwash(design.thermal) * _equivalent_diameter(design.tailboom) / _kinematic_viscosity(film)
    assert reynolds > 1.2 * 4e5  # hand value ≈ 5.3e5, outside Hilpert's table
    assert set(out["tailboom_flags"]) >= {"hover"}
    assert out["tailboom_flags"]["hover"]  # a note says why


def test_the_parked_boom_inside_churchill_chus_rayleigh_range_is_not_flagged(summary):
    design, out = summary
    ambient = design.thermal.ambient_temperature_c + 273.15
    skin = out["tailboom_c"]["parked"] + 273.15
    film = (skin + ambient) / 2.0
    cube = _equivalent_diameter(design.tailboom) ** 3
    upper = STANDARD_GRAVITY / film * (skin - ambient) * cube / _kinematic_viscosity(ambient) ** 2
    assert upper < 1e12 / 100.0  # hand bound ≈ 2.45e9
    assert skin - ambient > 1e-3
    lower = STANDARD_GRAVITY / skin * 1e-3 * cube * 0.5 / _kinematic_viscosity(skin) ** 2
    assert lower > 1e-5  # hand bound at ΔT = 1e-3 K ≈ 9e3
    assert "parked" not in out["tailboom_flags"]

"""The thermal summary's ``tailboom_flags`` (flexshaft.thermal.study.thermal_summary) against the
validity ranges of the boom's Nusselt correlations, with the Reynolds and Rayleigh numbers
computed by hand.

References:

* **Documented rule** (docs/thermal.md, "Hover" and "Parked"): Hilpert is valid for
  0.4 ≤ Re ≤ 4×10⁵ and Pr ≥ 0.7, Churchill–Chu for 10⁻⁵ ≤ Ra ≤ 10¹², and a condition outside
  its correlation's range is flagged (``nusselt.in_range = False``) and listed under
  ``tailboom_flags``.
* **Hover, derived here**: Re_D = V D / ν with the momentum-theory downwash V = 12.76 m/s
  (docs/thermal.md eq. 2.56, recomputed from the formula in tests/test_rotor_downwash.py), the
  equivalent diameter D = 0.682 m (docs/thermal.md) and ν = μ/ρ of dry air at the film
  temperature T_f = (T_skin + T_∞)/2: Sutherland's law μ = 1.716e-5 (T/273.15)^1.5 (273.15 +
  110.4)/(T + 110.4) Pa s and the ideal gas ρ = p/(R T), p = 101325 Pa, R = 287.05 J/(kg K).
  At the baseline's T_f ≈ 308 K this gives ν ≈ 1.64e-5 m²/s and Re ≈ 5.3×10⁵ > 4×10⁵ (32 %
  above the limit, far more than the few % by which this hand ν and the package's air
  properties could differ): hover must be flagged.
* **Parked, derived here**: Ra = g β ΔT D³ Pr / ν² with β = 1/T_f, Pr < 1 for air and ν ≥ ν(T_∞) (ν grows with
  T, T_f ≥ T_∞) gives Ra < 3e9 at the baseline's ΔT ≈ 63 K, and Ra > 1e-5 for any ΔT above
  a micro-kelvin: parked must not be flagged.

The baseline design with a coarse mesh (the boom temperatures do not depend on the mesh; CPU).
"""

from __future__ import annotations

import pytest

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.study import thermal_summary


def _kinematic_viscosity(T):
    """ν [m²/s] of dry air at T [K] and 101325 Pa: Sutherland's law over the ideal-gas density."""
    mu = 1.716e-5 * (T / 273.15) ** 1.5 * (273.15 + 110.4) / (T + 110.4)
    return mu / (101325.0 / (287.05 * T))


@pytest.fixture(scope="module")
def summary():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    return design, thermal_summary(design, fs.build_model(design))


def test_the_hover_boom_beyond_hilperts_reynolds_range_is_flagged(summary):
    design, out = summary
    assert design.thermal.boom_convection == "hilpert"
    ambient = design.thermal.ambient_temperature_c + 273.15
    film = (out["tailboom_c"]["hover"] + 273.15 + ambient) / 2.0
    reynolds = 12.76 * 0.682 / _kinematic_viscosity(film)
    assert reynolds > 1.2 * 4e5  # hand value ≈ 5.3e5, outside Hilpert's table
    assert set(out["tailboom_flags"]) >= {"hover"}
    assert out["tailboom_flags"]["hover"]  # a note says why


def test_the_parked_boom_inside_churchill_chus_rayleigh_range_is_not_flagged(summary):
    design, out = summary
    ambient = design.thermal.ambient_temperature_c + 273.15
    skin = out["tailboom_c"]["parked"] + 273.15
    film = (skin + ambient) / 2.0
    rayleigh_bound = 9.81 / film * (skin - ambient) * 0.682**3 / _kinematic_viscosity(ambient) ** 2
    assert 1e-5 < rayleigh_bound < 1e12 / 100.0  # hand bound ≈ 3e9
    assert skin - ambient > 1e-3
    assert "parked" not in out["tailboom_flags"]

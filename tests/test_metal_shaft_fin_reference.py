"""Temperature of an aluminium shaft heated along its length, against the fin equation.

An isotropic (6061-T6 aluminium) tube of wall area A = π(D_o² − D_i²)/4, convecting perimeter
P = π D_o, heat transfer coefficient h to air at T_∞, generating q' [W/m] uniformly, its two ends
held at T_∞. The rise θ = T − T_∞ obeys the fin equation k A θ'' − h P θ + q' = 0 (derived:
conduction, convection and generation on a slice dx), whose solution with θ(0) = θ(L) = 0 is

    θ(x) = (q'/(h P)) [1 − cosh(m (x − L/2)) / cosh(m L/2)],   m² = h P/(k A),

so the midspan rise is (q'/(h P)) (1 − 1/cosh(m L/2)). The conductivity is the solver's default
for a metal shaft, which must be aluminium's: 167 W/(m K), the Aluminum Association typical
value of 6061-T6 at 77 °F (Glemco 6061-T6 material data sheet; the 6061 range is 151-202 W/(m K)
in the Wikipedia alloy table). With h = 1 W/(m² K) on a 2 m, 50 × 2 mm tube, m L ≈ 3.5: the
conduction to the ends matters (a tenfold lower k would put the midspan rise within 1 % of
q'/(h P)). The thermal model is the linear finite element with lumped convection and source,
second-order: on 40 elements its error is about (m Δx)²/12 ≈ 7e-4 of q'/(h P); tolerance 2e-3.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict
from flexshaft.thermal import HeatSources, shaft_thermal
from flexshaft.thermal.analysis import shaft_conductivity
from flexshaft.thermal.heat import thermal_stations

K_6061_T6 = 167.0  # W/(m K), Aluminum Association typical at 77 °F (module docstring)
LENGTH, D_O, WALL = 2.0, 0.05, 0.002
H, Q_PER_LENGTH, T_AIR = 1.0, 3.0, 300.0


@pytest.fixture(scope="module")
def aluminium_shaft():
    data = {
        "name": "aluminium tube",
        "materials": {"al": {"kind": "isotropic", "E": 68.9e9, "G": 26.0e9, "density": 2700.0}},
        "shaft": {
            "x_start": 0.0,
            "x_end": LENGTH,
            "outer_diameter": D_O,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": LENGTH, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 40},
    }
    return build_model(design_from_dict(data))


def test_the_default_metal_conductivity_is_aluminium_6061_t6(aluminium_shaft):
    assert shaft_conductivity(aluminium_shaft) == pytest.approx(K_6061_T6, rel=1e-12)


def test_midspan_rise_of_a_uniformly_heated_shaft_is_the_fin_solution(aluminium_shaft):
    model = aluminium_shaft
    x = thermal_stations(model)
    power = Q_PER_LENGTH * np.diff(x)
    sources = HeatSources(x, power, np.zeros_like(power), "thesis", model.speed)
    result = shaft_thermal(model, air_temperature=T_AIR, heat_transfer_coefficient=H, sources=sources)
    d_i = D_O - 2 * WALL
    area, perimeter = np.pi * (D_O**2 - d_i**2) / 4, np.pi * D_O
    m = np.sqrt(H * perimeter / (K_6061_T6 * area))
    scale = Q_PER_LENGTH / (H * perimeter)
    exact = scale * (1.0 - np.cosh(m * (x - LENGTH / 2)) / np.cosh(m * LENGTH / 2))
    assert m * LENGTH == pytest.approx(3.53, abs=0.01)  # conduction matters (docstring)
    rise = result.temperature.temperature - T_AIR
    assert np.max(np.abs(rise - exact)) < 2e-3 * scale

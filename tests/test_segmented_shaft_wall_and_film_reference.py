"""Per-segment wall conductivity and film coefficient of a segmented shaft (mutation hunt h35d).

A 2 m shaft of two zones: 0-1.5 m an aluminium tube D_o = 50 mm (isotropic), 1.5-2.0 m a
carbon/polyurethane tube D_o = 80 mm laid up 0/0/90 (equal plies), the short zone meshed finer
(zero-mass marker disks add nodes there, so it has MORE elements over LESS length).
References, typed here:

* wall conductivity along x: the isotropic tube's handbook k = 167 W/(m K) (6061-T6), the
  laminate's plies conducting in parallel, k = sum t_k (k_L cos^2 a_k + k_T sin^2 a_k) / t,
  here (2 k_L + k_T)/3 = (2 * 5 + 0.5)/3 = 3.5 W/(m K) with the default ply conductivities
  k_L = 5, k_T = 0.5 W/(m K): each element carries its own zone's value;
* film coefficient of a cylinder spinning in still air (Becker 1963 / Kays & Bjorklund 1958, as
  quoted by Incropera & DeWitt): Nu_D = 0.133 Re_w^(2/3) Pr^(1/3), Re_w = Omega D^2 / nu,
  h = Nu_D k_air / D, air at T_air (flexshaft.thermal.air, tested elsewhere): each element gets
  its own diameter's h;
* the reported Nusselt number is the one of the diameter covering the most LENGTH (the
  documented rule of ShaftThermal.nusselt), here the 1.5 m of D = 50 mm, although the 80 mm
  zone has more elements.

Tolerance 1e-12 (the same arithmetic in another order).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict
from flexshaft.thermal.air import air_properties
from flexshaft.thermal.analysis import shaft_thermal
from flexshaft.thermal.heat import element_tubes
from flexshaft.thermal.options import ThermalOptions

OMEGA, T_AIR = 300.0, 300.0
CF = {
    "kind": "lamina",
    "density": 1600.0,
    "E_L": 120.0e9,
    "E_T": 8.0e9,
    "G_LT": 4.0e9,
    "nu_LT": 0.3,
    "X_t": 2.0e9,
    "X_c": 1.0e9,
    "Y_t": 40.0e6,
    "Y_c": 140.0e6,
    "S": 60.0e6,
}


@pytest.fixture(scope="module")
def result():
    data = {
        "name": "metal and fmc",
        "materials": {
            "al": {"kind": "isotropic", "E": 70e9, "G": 26e9, "density": 2700.0, "loss_factor": 0.01},
            "cf": CF,
        },
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
            "segments": [
                {"name": "metal", "x_start": 0.0, "x_end": 1.5},
                {
                    "name": "fmc",
                    "x_start": 1.5,
                    "x_end": 2.0,
                    "outer_diameter": 0.08,
                    "wall_thickness": 0.003,
                    "material": "cf",
                    "layup": "0/0/90",
                },
            ],
        },
        "disks": [{"name": f"m{k}", "x": x, "mass": 0.0} for k, x in enumerate((1.6, 1.7, 1.8, 1.9))],
        "bearings": [{"name": "far", "kind": "contact", "x": 2.0, "stiffness": {"u": 0.0}}],
        "operating": {"speed": OMEGA, "power": 1e3},
        "loads": {"eccentricity": 1e-5},
        "mesh": {"shaft_elements": 2},
    }
    model = build_model(design_from_dict(data))
    return model, shaft_thermal(model, ThermalOptions(), "thesis", air_temperature=T_AIR)


def becker_h(D: float) -> tuple[float, float]:
    air = air_properties(T_AIR)
    Re = OMEGA * D**2 / air.kinematic_viscosity
    nu = 0.133 * Re ** (2 / 3) * air.prandtl ** (1 / 3)
    return nu, nu * air.conductivity / D


def zones(model) -> np.ndarray:
    Do = np.array([t.outer_diameter for t in element_tubes(model)])
    ends = model.dofs.shaft_element_x
    wide = Do > 0.07
    assert np.count_nonzero(wide) > np.count_nonzero(~wide)  # more elements on the short zone
    assert np.sum(np.diff(ends, axis=1)[wide]) == pytest.approx(0.5, rel=1e-12)
    return wide


def test_each_element_conducts_with_its_own_wall(result):
    model, res = result
    wide = zones(model)
    expected = np.where(wide, (2 * 5.0 + 0.5) / 3, 167.0)
    np.testing.assert_allclose(np.broadcast_to(res.conductivity, wide.shape), expected, rtol=1e-12)


def test_each_element_convects_with_its_own_diameters_film(result):
    model, res = result
    wide = zones(model)
    expected = np.where(wide, becker_h(0.08)[1], becker_h(0.05)[1])
    np.testing.assert_allclose(res.temperature.element_heat_transfer, expected, rtol=1e-12)


def test_the_reported_nusselt_is_the_longest_zones(result):
    model, res = result
    zones(model)
    assert res.nusselt.value == pytest.approx(becker_h(0.05)[0], rel=1e-12)

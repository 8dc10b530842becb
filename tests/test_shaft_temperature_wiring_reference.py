"""What the shaft temperature a PASS rests on is read from: its hottest point, its air, its
envelope points and the self-heating's pieces (mutation hunt h42a).

References, each typed here:

* the discrete maximum principle: a conducting, convecting wall with no heat source has no
  interior extremum, so its hottest node is its hotter Dirichlet end (ends at 300 K and 320 K
  in air at 300 K: the maximum is 320 K = 46.85 °C, 0 °C = 273.15 K by definition), whichever
  end it is (the fore end hot as well as the aft one: the hottest node, not the last);
* without a tailboom the shaft's air is the ambient (the docstrings of ``shaft_air_temperature``
  and of the envelope's step 2), not the sky's radiative temperature;
* the hover boom's skin balance, as tests/test_boom_energy_balance_reference.py types it (thesis
  eq. 2.55) alpha_s G s = eps sigma (T^4 - T_sky^4) + h (T - T_amb), G = S_c f cos(theta_s), at the
  momentum-theory downwash V = sqrt(m g / (2 rho pi R^2)), with the correlation the options name:
  Hilpert's Nu_D = C Re^m Pr^(1/3) (Incropera & DeWitt, Fundamentals of Heat and Mass Transfer,
  eq. 7.52 with Table 7.2), C = 0.027, m = 0.805 (the 4e4-4e5 row that file types; the baseline
  boom's Re = 5.3e5 takes that last row, as flexshaft.thermal.correlations documents), or
  Churchill & Bernstein's (1977) cross-flow form (ibid. eq. 7.54)
  Nu_D = 0.3 + 0.62 Re^(1/2) Pr^(1/3) / [1 + (0.4/Pr)^(2/3)]^(1/4) [1 + (Re/282000)^(5/8)]^(4/5)
  (air properties from flexshaft.thermal.air at the film temperature, tested against tables
  elsewhere); the balance's slope in T is < 100 W/(m^2 K) and the code solves T to 1e-10 K, so
  it closes to 1e-8 of the absorbed flux; the other correlation puts the skin 5 K away (317.3 K
  against 322.3 K), far outside it;
* the envelope's points as the baseline design lists them, in order (cold_day, standard_day,
  hot_soak_start), the hot-soak start's material temperature the parked boom's: the thesis's
  Table 2.1 finding of 89 °C parked, stated to the degree (±0.5 °C), to which the baseline's
  sunlit share is calibrated (tests/test_thermal.py); the hover skin (Table 2.1: 44 °C) or the
  ambient (25.6 °C) in its place is 45 K or 63 K away;
* a given air temperature is the shaft's end temperature (Dirichlet ends at T_infinity, docs
  of ``self_heating``): the ends come back at exactly it;
* an isotropic (metal) segment keeps its own E and G at any temperature (the matrix law acts
  on laminae only): 6061-T6 E = 68.9 GPa, G = 26 GPa as the baseline's materials table gives.
"""

from __future__ import annotations

import copy
import math

import numpy as np
import pytest

import flexshaft as fs
import flexshaft.thermal.selfheating as selfheating
from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict, embedded_design
from flexshaft.design.thermal_schema import Thermal
from flexshaft.thermal.air import air_properties
from flexshaft.thermal.analysis import ShaftThermal, shaft_air_temperature
from flexshaft.thermal.envelope import envelope_conditions
from flexshaft.thermal.matrix import MatrixTemperatureLaw
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.shaft import solve_shaft_temperature
from flexshaft.thermal.tailboom import boom_equivalent_diameter

SIGMA = 5.670374419e-8  # W/(m^2 K^4), CODATA 2018
G0 = 9.80665


def no_heat_wall(ends: tuple[float, float]) -> ShaftThermal:
    x = np.linspace(0.0, 2.0, 21)
    temp = solve_shaft_temperature(x, np.zeros(20), 5.0, 1e-4, 0.2, 10.0, 300.0, ends)
    return ShaftThermal(None, temp, None, 5.0)  # type: ignore[arg-type]


@pytest.mark.parametrize("ends", [(300.0, 320.0), (320.0, 300.0)], ids=["aft-hot", "fore-hot"])
def test_the_hottest_point_of_a_sourceless_wall_is_its_hot_end_in_kelvin_and_celsius(ends):
    thermal = no_heat_wall(ends)
    assert thermal.max_temperature == pytest.approx(320.0, rel=1e-12)
    assert thermal.max_temperature_c == pytest.approx(46.85, rel=1e-12)
    result = selfheating.SelfHeating("converged", np.full(20, 305.0), thermal, 1, 373.15, np.array([320.0]))
    assert result.max_temperature == pytest.approx(320.0, rel=1e-12)
    assert result.max_temperature_c == pytest.approx(46.85, rel=1e-12)
    assert result.margin == pytest.approx(53.15, rel=1e-12)


def test_without_a_tailboom_the_shaft_air_is_the_ambient_not_the_sky():
    options = thermal_options(Thermal(ambient_temperature_c=30.0, sky_temperature_c=-10.0))
    assert shaft_air_temperature(None, options) == pytest.approx(303.15, rel=1e-14)


def churchill_bernstein(Re: float, Pr: float) -> float:
    return 0.3 + 0.62 * Re**0.5 * Pr ** (1 / 3) / (1 + (0.4 / Pr) ** (2 / 3)) ** 0.25 * (
        1 + (Re / 282000.0) ** (5 / 8)
    ) ** (4 / 5)


def hilpert(Re: float, Pr: float) -> float:
    assert 4e4 <= Re <= 6e5  # the row of Table 7.2 typed here, carried past 4e5 (the baseline boom's 5.3e5)
    return 0.027 * Re**0.805 * Pr ** (1 / 3)


@pytest.mark.parametrize("method", ["hilpert", "churchill_bernstein"])
def test_the_shaft_air_is_the_hover_skin_of_the_options_correlation(method):
    options = thermal_options(Thermal(boom_convection=method))
    tailboom = fs.baseline_design().tailboom
    T = shaft_air_temperature(tailboom, options)
    env, D = options.environment, boom_equivalent_diameter(tailboom)
    film = air_properties(0.5 * (T + env.ambient_temperature), env.air_pressure)
    V = math.sqrt(env.rotorcraft_mass * G0 / (2 * env.air_density * math.pi * env.rotor_radius**2))
    Re = V * D / film.kinematic_viscosity
    h = (
        {"hilpert": hilpert, "churchill_bernstein": churchill_bernstein}[method](Re, film.prandtl)
        * film.conductivity
        / D
    )
    alpha = env.emissivity if env.solar_absorptivity is None else env.solar_absorptivity
    absorbed = alpha * env.solar_constant * env.solar_fraction * math.cos(env.solar_zenith) * env.solar_area_fraction
    radiated = env.emissivity * SIGMA * (T**4 - env.sky_temperature**4)
    convected = h * (T - env.ambient_temperature)
    assert absorbed > 100.0  # a sunlit boom: the balance is not trivially zero
    assert absorbed - radiated - convected == pytest.approx(0.0, abs=1e-8 * absorbed)


def test_every_envelope_point_is_evaluated_in_order_and_the_hot_soak_is_the_parked_boom():
    design = fs.baseline_design()
    conditions = envelope_conditions(design)
    assert [c.name for c in conditions] == ["cold_day", "standard_day", "hot_soak_start"]
    hot = conditions[-1]
    assert hot.material_temperature_c == pytest.approx(89.0, abs=0.5)  # thesis Table 2.1, parked
    assert hot.material_temperature == pytest.approx(89.0 + 273.15, abs=0.5)
    assert hot.material_temperature == max(c.material_temperature for c in conditions)


def test_a_given_air_temperature_is_the_shaft_ends_temperature():
    model = fs.build_model(fs.baseline_design())
    assert abs(shaft_air_temperature(model.design.tailboom) - 300.0) > 5.0  # the hover air differs
    result = selfheating.self_heating(model, loss_model="rotating", air_temperature=300.0)
    assert result.status == "converged"
    T = result.thermal.temperature.temperature
    assert (T[0], T[-1]) == (300.0, 300.0)
    assert result.thermal.temperature.air_temperature == 300.0
    # the heat grows as the load squared: x150 warms ~17 K (test_selfheating_fixed_point_reference.py), x1 ~1e-3 K
    assert 300.0 <= result.max_temperature < 301.0


def test_a_metal_segment_keeps_its_own_moduli_in_the_self_heating():
    data = copy.deepcopy(embedded_design("baseline").model_dump())
    for material in data["materials"].values():
        material.pop("temperature_table", None)
    shaft = data["shaft"]
    shaft.update(material="al6061_t6", layup=None)
    half = 0.5 * (shaft["x_start"] + shaft["x_end"])
    shaft["segments"] = (
        {"name": "metal", "x_start": shaft["x_start"], "x_end": half},
        {
            "name": "fmc",
            "x_start": half,
            "x_end": shaft["x_end"],
            "material": "t700_adiprene",
            "layup": "(55/-55/0/0)s",
        },
    )
    model = build_model(design_from_dict(data))
    metal = np.array([t.laminate is None for t in selfheating.element_tubes(model)])
    assert metal.any() and not metal.all()
    E, G = selfheating._element_moduli(model, MatrixTemperatureLaw(), np.full(metal.size, 350.0))
    assert np.allclose(E[metal].real, 68.9e9, rtol=1e-12)
    assert np.allclose(G[metal].real, 26.0e9, rtol=1e-12)


def preflight_data(threshold_c: float) -> dict:
    """The baseline (no tables, no envelope) with the law's θ_E = 5 K and its reference set so
    that the t700 ply turns invalid below ``threshold_c``: nu^2 E_T f / E_L = 1 at
    f = exp(-(T* - T_ref)/θ_E), i.e. T_ref = T* + θ_E ln(E_L / (nu^2 E_T)) (the plane-stress
    determinant, tests/test_thermal_preflight_allowable_reference.py)."""
    data = copy.deepcopy(embedded_design("baseline").model_dump())
    for material in data["materials"].values():
        material.pop("temperature_table", None)
    data["envelope"] = None
    lamina = data["materials"]["t700_adiprene"]
    shift = 5.0 * math.log(lamina["E_L"] / (lamina["nu_LT"] ** 2 * lamina["E_T"]))
    data["thermal"].update(matrix_modulus_decay=5.0, matrix_reference_temperature_c=threshold_c + shift)
    return data


def test_the_preflight_range_starts_at_the_shaft_air_not_the_ambient():
    """The self-heating's range starts at the shaft's air, the hover skin (sunlit: above the
    ambient, 25.6 °C here); a ply invalid only below a threshold between the two is no
    problem, and one invalid up to above the hover air is."""
    from flexshaft.thermal.preflight import thermal_guards

    design = design_from_dict(preflight_data(0.0))
    ambient_c = design.thermal.ambient_temperature_c
    hover_c = shaft_air_temperature(design.tailboom, thermal_options(design.thermal)) - 273.15
    assert hover_c > ambient_c + 10.0
    between = 0.5 * (ambient_c + hover_c)
    assert thermal_guards(design_from_dict(preflight_data(between))) == []
    problems = thermal_guards(design_from_dict(preflight_data(hover_c + 2.0)))
    assert len(problems) == 1 and "'t700_adiprene'" in problems[0].message

"""A comparison's overrides reach every number of :func:`flexshaft.thermal.study.thermal_results`.

The baseline design (coarse mesh, as tests/test_thermal_study_reference.py) has
``internal_damping = "rotating"`` and the Becker shaft convection; a comparison asks for the
"thesis" loss model and Kendoush's correlation:

* **the code's Kendoush correlation**, Nu_D = 0.6366 (Re_ω Pr)^{1/2}, Re_ω = Ω D²/ν, typed
  here as :mod:`flexshaft.thermal.correlations` states it (a wiring check of the override, not
  a check of the correlation: its 2/π and its Reynolds number are unverified against Kendoush
  1996, docs/testing.md, the two surviving mutations): the shaft's h
  is Nu k_air/D with the air's properties at the shaft air temperature (Becker's
  0.133 Re^{2/3} Pr^{1/3} gives 1.8 times Kendoush's h on this shaft (checked), so an ignored override
  is visible);
* **the thermal-design sweeps under the asked loss model**: the convection sweep's
  correlation profile closes the control-volume balance (thesis eqs. 2.61-2.65, the helper of
  tests/test_thermal_study_reference.py) with the "thesis" heat and Kendoush's h, and not with
  the design's "rotating" heat (which differs by a factor ~2 on this shaft, checked there).

Tolerance: the correlation is one formula on the same air properties (rel 1e-12); the balance's
residual is round-off of a diagonally dominant tridiagonal solve, 1e-8 of the largest node heat.

Written for the mutations h43d-study-convection-override-ignored and
h43d-study-profiles-design-loss-model of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_thermal_study_reference import _residual

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.air import air_properties
from flexshaft.thermal.heat import heat_sources
from flexshaft.thermal.study import thermal_results


def test_the_loss_model_and_convection_overrides_reach_the_shaft_and_the_sweeps():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    model = fs.build_model(design)
    assert design.analysis.internal_damping == "rotating" and design.thermal.shaft_convection == "becker"
    r = thermal_results(design, model, loss_model="thesis", convection="kendoush")
    assert r.options.shaft_convection == "kendoush"
    own = r.shaft["thesis"]
    T_air = own.temperature.air_temperature
    air = air_properties(T_air, r.options.environment.air_pressure)
    D = model.shaft.outer_diameter
    Re = model.speed * D**2 / air.kinematic_viscosity
    h = 0.6366 * np.sqrt(Re * air.prandtl) * air.conductivity / D
    assert own.temperature.heat_transfer_coefficient == pytest.approx(h, rel=1e-12)

    label = next(k for k in r.profiles.by_h if "correlation" in k)
    rise = r.profiles.by_h[label]
    x, k, wall = r.profiles.x, own.conductivity, design.shaft.wall_thickness
    asked = heat_sources(model, "thesis").total
    assert _residual(x, rise, asked, k, wall, D, h) < 1e-8
    assert _residual(x, rise, heat_sources(model, "rotating").total, k, wall, D, h) > 1e-2

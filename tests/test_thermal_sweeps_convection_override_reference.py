"""The thermal-design wall sweep (thesis figure 3.18) under a convection override: every
profile of :func:`flexshaft.thermal.study.thermal_results`'s ``profiles.by_wall`` closes the
shaft's control-volume energy balance with the shaft convection asked for.

docs/thermal.md: "CLI: `flexshaft thermal [DESIGN] [--loss-model thesis|rotating] [--convection
becker|kendoush] [--self-heating] [--sweeps] [--json]`; the two overrides default to the
design's choices", and ``thermal_results`` "returns a `ThermalResults` (boom and shaft results,
the self-heating equilibrium, the sweeps' profiles)". The code's signature,
``thermal_results(design, model, loss_model=None, convection=None, ...)``, carries the same
override; the profiles are the thermal-design sweeps of that result, so a wall-sweep profile
must be the shaft with wall t under the same options as the rest of the result. The
wall sweep keeps D_o and the shaft air temperature, so the correlation's h is the design's.

References, derived here (as tests/test_thermal_results_overrides_reference.py and
tests/test_thermal_study_reference.py):

* **Kendoush's correlation as the code states it** (flexshaft.thermal.correlations),
  Nu_D = 0.6366 (Re_ω Pr)^{1/2}, Re_ω = Ω D²/ν, h = Nu k_air/D with the air's properties at the
  shaft air temperature (a wiring check of the override, not of the correlation).
* **Energy balance of each control volume** (thesis §2.8.2, eqs. 2.61-2.65; the helper
  ``_residual`` of tests/test_thermal_study_reference.py): with θ the rise above the air,
  G_{i−1}(θ_{i−1} − θ_i) + G_i(θ_{i+1} − θ_i) − h π D_o ℓ_i θ_i + s_i = 0 at interior nodes, with
  the heat s and the wall area of the design rebuilt at wall t under the design's loss model.

Becker's correlation (the design's) gives about 1.8 times Kendoush's h on this shaft (checked
below), so a profile computed under the design's convection instead of the override leaves a
residual of the order of the heat (> 1e-2). Tolerance: the profile is a tridiagonal solve of a
diagonally dominant system, so the residual is round-off, 1e-8 of the largest node heat; the
correlation is one formula on the same air properties (rel 1e-12).

Baseline design with a coarse mesh (12 shaft elements: the balance holds on any mesh; CPU).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_thermal_study_reference import _residual

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.air import air_properties
from flexshaft.thermal.analysis import shaft_thermal
from flexshaft.thermal.heat import heat_sources
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.study import thermal_results


def test_wall_sweep_profiles_use_the_convection_override():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    model = fs.build_model(design)
    assert design.thermal.shaft_convection == "becker"
    lm = design.analysis.internal_damping
    r = thermal_results(design, model, convection="kendoush")
    own = r.shaft[lm]
    T_air = own.temperature.air_temperature
    air = air_properties(T_air, r.options.environment.air_pressure)
    D = model.shaft.outer_diameter
    Re = model.speed * D**2 / air.kinematic_viscosity
    h_kendoush = 0.6366 * np.sqrt(Re * air.prandtl) * air.conductivity / D
    assert own.temperature.heat_transfer_coefficient == pytest.approx(h_kendoush, rel=1e-12)
    h_becker = shaft_thermal(model, thermal_options(design.thermal), lm).temperature.heat_transfer_coefficient
    assert h_becker > 1.5 * h_kendoush  # the design's own correlation is visibly different

    x, k = r.profiles.x, own.conductivity
    assert len(r.profiles.by_wall) == 3
    for label, rise in r.profiles.by_wall.items():
        t = float(label.split()[1]) * 1e-3  # "wall 1.5 mm"
        at_wall = fs.build_model(with_overrides(design, {"shaft.wall_thickness": t}))
        heat = heat_sources(at_wall, lm)
        np.testing.assert_array_equal(heat.x, x)
        assert _residual(x, rise, heat.total, k, t, D, h_kendoush) < 1e-8
        assert _residual(x, rise, heat.total, k, t, D, h_becker) > 1e-2

"""The shaft's air in the convection sweep, and a convection override in the sweeps of a boomless
design (:mod:`flexshaft.thermal.study`).

References (documented rules and the correlations typed by hand):

* **the sweep's air**: :func:`~flexshaft.thermal.study.convection_sweep`'s ``air_temperature``
  defaults to the design's boom hover temperature (its docstring, as
  :func:`~flexshaft.thermal.study.wall_thickness_sweep`'s; docs/thermal.md: the shaft's air in
  operation is the boom's hover skin temperature). The rotating-cylinder correlation's h depends
  on the air's properties, so a ``None`` entry's h is Becker's
  Nu_D = 0.133 Re_ω^{2/3} Pr^{1/3}, Re_ω = Ω D²/ν (:mod:`flexshaft.thermal.correlations`,
  Becker 1963), h = Nu k_air / D with the air at the hover temperature. On the baseline the
  hover skin is 18.5 K above the 25.6 °C ambient and h at the ambient is 2 % higher (checked),
  far outside the tolerance;
* **a boomless design's sweeps under the override**: without a tailboom the shaft's air is the
  ambient (docs/thermal.md, "the ambient without a boom"), and ``thermal_summary(sweeps=True)``
  recomputes the sweeps (no profiles are kept without a boom). Under ``convection="kendoush"``
  the correlation entry's label carries Kendoush's h, Nu_D = 0.6366 (Re_ω Pr)^{1/2} (typed as
  :mod:`flexshaft.thermal.correlations` states it; a wiring check of the override, not of the
  correlation), rounded to whole W/(m² K); Becker's h is 1.8 times it on this shaft (checked),
  a different label. The correlation entry and the design's own wall entry are the design's
  shaft at Kendoush's h, the ``h = 20 W/m²K`` entry the same shaft at h = 20. With the local
  heat balance q' = h π D ΔT (derived here; the shaft's axial conduction is small on this
  design) the peak rise scales as 1/h at the same heat, so either entry over the h = 20 entry
  is 20 / h_Kendoush; under Becker's h it would be 20 / 146.7 = 0.136 instead of 0.251.

Tolerances: the correlation is one formula on the same air properties (rel 1e-12, round-off of
a few powers). The 1/h scaling leaves out the axial conduction, which spreads the heat and
lowers the peak less where h is larger: measured, rise(h = 5) / rise(h = 20) = 3.9948 against
4 (0.13 %) and the correlation entry's ratio 0.25128 against 20 / h_Kendoush = 0.25120
(0.03 %); rel 1e-2 is several times that correction and far below the 80 vs 147 W/(m² K)
difference (46 %).

Written for the mutations h99e-convection-sweep-air-ambient and
h99e-summary-sweeps-no-boom-options of scripts/mutations.toml.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.air import air_properties
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.study import convection_sweep, thermal_summary
from flexshaft.thermal.tailboom import boom_equivalent_diameter, tailboom_temperature


def _coarse():
    return with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})


def test_the_convection_sweep_correlation_is_at_the_boom_hover_air():
    design = _coarse()
    model = fs.build_model(design)
    options = thermal_options(design.thermal)
    assert options.shaft_convection == "becker"
    env = options.environment
    hover = tailboom_temperature(
        "hover", boom_equivalent_diameter(design.tailboom), env, options.boom_convection
    ).temperature
    assert hover - env.ambient_temperature > 10.0  # the rule is visible on this design

    D = model.shaft.outer_diameter

    def becker(T):
        air = air_properties(T, env.air_pressure)
        Re = model.speed * D**2 / air.kinematic_viscosity
        return 0.133 * Re ** (2.0 / 3.0) * air.prandtl ** (1.0 / 3.0) * air.conductivity / D

    sweep = convection_sweep(model, [None, 10.0])
    assert list(sweep["from_correlation"]) == [True, False]
    assert sweep["heat_transfer_coefficient"][0] == pytest.approx(becker(hover), rel=1e-12)
    assert abs(becker(env.ambient_temperature) / becker(hover) - 1.0) > 1e-2
    assert sweep["heat_transfer_coefficient"][1] == 10.0


def test_a_boomless_designs_sweeps_follow_the_convection_override():
    design = with_overrides(_coarse(), {"tailboom": None, "loads.point": [], "envelope": None})
    model = fs.build_model(design)
    assert design.thermal.shaft_convection == "becker"
    out = thermal_summary(design, model, loss_model="thesis", convection="kendoush", sweeps=True)

    env = thermal_options(design.thermal).environment
    air = air_properties(env.ambient_temperature, env.air_pressure)
    D = model.shaft.outer_diameter
    Re = model.speed * D**2 / air.kinematic_viscosity
    h_kendoush = 0.6366 * np.sqrt(Re * air.prandtl) * air.conductivity / D
    h_becker = 0.133 * Re ** (2.0 / 3.0) * air.prandtl ** (1.0 / 3.0) * air.conductivity / D
    assert h_becker / h_kendoush > 1.5  # an ignored override changes the label
    assert out["shaft_thesis_loss_model"]["h_W_m2K"] == pytest.approx(h_kendoush, abs=0.006)

    by_h = out["peak_rise_K_by_convection"]
    (label,) = [k for k in by_h if "correlation" in k]
    shown = re.search(r"h = (\d+) W", label)
    assert shown is not None and int(shown.group(1)) == round(h_kendoush)

    assert out["shaft_thesis_loss_model"]["peak_rise_K"] > 0.0
    at_20 = by_h["h = 20 W/m²K"]
    assert by_h[label] / at_20 == pytest.approx(20.0 / h_kendoush, rel=1e-2)
    wall = f"wall {design.shaft.wall_thickness * 1e3:.1f} mm"
    assert out["peak_rise_K_by_wall"][wall] / at_20 == pytest.approx(20.0 / h_kendoush, rel=1e-2)

"""The wall-thickness sweep's heat is the heat the shaft loses: conservation of energy.

In steady state the heat generated in the shaft (both mechanisms: the imbalance vibration and
the static deflection cycled by the rotation) leaves it by convection along the surface and by
conduction through its two held ends: Q = Σ h P Δx (T − T_∞) + q_fore + q_aft. The sweep's
``heat`` at a wall must equal that outflow of the same shaft's temperature solution, computed
here by :func:`flexshaft.thermal.analysis.shaft_thermal` from its convected heat and end flows
(the energy balance closes to the linear solve's round-off, 1e-9 relative). On the baseline the
static mechanism is most of the heat (docs/thesis-reproduction.md: 93 % with the thesis loss
model), so a sweep that reported one mechanism alone would miss the balance by far more.

One wall on the baseline design with a coarse mesh (the balance holds on any mesh; CPU budget).
"""

from __future__ import annotations

import pytest

import flexshaft as fs
from flexshaft.assembly import build_model
from flexshaft.design import with_overrides
from flexshaft.thermal.analysis import shaft_thermal
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.study import wall_thickness_sweep


def test_swept_heat_leaves_the_shaft_by_convection_and_its_ends():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    sweep = wall_thickness_sweep(design, [design.shaft.wall_thickness])
    thermal = shaft_thermal(build_model(design), thermal_options(design.thermal), design.analysis.internal_damping)
    temperature = thermal.temperature
    outflow = temperature.convected.sum() + sum(temperature.end_flows)
    assert outflow > 0.0
    assert sweep["heat"][0] == pytest.approx(outflow, rel=1e-9)
    assert sweep["peak_rise"][0] == pytest.approx(temperature.peak_rise, rel=1e-9)

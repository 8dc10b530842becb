"""``shaft_thermal``'s asked loss model sets the heat its temperature carries (hunt h46c).

The baseline design's ``[analysis] internal_damping`` is "rotating"; asked for "thesis",
:func:`~flexshaft.thermal.analysis.shaft_thermal` must heat the shaft with the thesis loss
model's sources (its docstring), which differ from the design's by more than 20 % on this shaft
(checked here). The reference is the shaft's control-volume energy balance (thesis eqs.
2.61-2.65), assembled by hand in tests/test_thermal_study_reference.py (``_residual``): the
returned temperature rise closes it with the "thesis" heat and not with the "rotating" heat.

Tolerance as there: round-off of a diagonally dominant tridiagonal solve, 1e-8 of the largest
node heat; the wrong heat leaves a residual above 1e-2. Coarse mesh (12 shaft elements): ~0.1 s.
"""

from __future__ import annotations

from test_thermal_study_reference import _residual

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.analysis import shaft_thermal
from flexshaft.thermal.heat import heat_sources
from flexshaft.thermal.options import thermal_options


def test_the_asked_loss_model_heats_the_shaft():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    model = fs.build_model(design)
    assert design.analysis.internal_damping == "rotating"
    thesis, rotating = heat_sources(model, "thesis").total, heat_sources(model, "rotating").total
    assert abs(thesis.sum() - rotating.sum()) > 0.2 * rotating.sum()
    own = shaft_thermal(model, thermal_options(design.thermal), "thesis")
    t = own.temperature
    rise = t.temperature - t.air_temperature
    args = (own.conductivity, design.shaft.wall_thickness, design.shaft.outer_diameter, t.heat_transfer_coefficient)
    assert _residual(t.x, rise, thesis, *args) < 1e-8
    assert _residual(t.x, rise, rotating, *args) > 1e-2

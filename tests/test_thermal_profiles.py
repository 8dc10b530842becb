"""The thermal-design profiles of a segmented shaft (stage-1 deferred item 3): the stations of
``temperature_profiles`` are those of the shaft's thermal model, one per temperature.

Was: ``"x": model.dofs.shaft_x``, the mesh's 55 shaft nodes of ``current`` (couplings add
nodes) against the thermal model's 51 temperatures, which broke the report's figure.
"""

from __future__ import annotations

import numpy as np

from flexshaft.assembly import build_model
from flexshaft.design import embedded_design
from flexshaft.thermal.study import convection_sweep, temperature_profiles


def test_the_profiles_of_a_segmented_shaft_share_the_thermal_models_stations():
    design = embedded_design("current")
    model = build_model(design)
    profiles = temperature_profiles(design, model)
    reference = convection_sweep(model, [20.0])["x"]  # the thermal model's own stations
    np.testing.assert_array_equal(profiles.x, reference)
    assert model.dofs.shaft_x.size != reference.size  # the case the old code got wrong
    for rise in (*profiles.by_wall.values(), *profiles.by_h.values()):
        assert rise.shape == profiles.x.shape and np.all(np.isfinite(rise))
    assert profiles.x[0] == design.shaft.x_start and profiles.x[-1] == design.shaft.x_end

"""The wall-thickness sweep (:func:`flexshaft.thermal.study.wall_thickness_sweep`, thesis figure
3.18) reports the temperature *rise* above the shaft's air.

Reference: the shaft's thermal model holds both ends at the air temperature (Dirichlet ends,
:mod:`flexshaft.thermal.shaft`), so the rise is exactly 0 at the first and last station, and it
is positive inside (the shaft generates heat and only loses it to cooler air and ends: maximum
principle of the steady conduction–convection equation). The absolute temperature would be the
air's, about 300 K, at the ends.

One wall on the baseline design with a coarse shaft mesh (the boundary condition holds at any
mesh; CPU budget). Tolerance: the ends are set, not solved: 1e-9 K.
"""

from __future__ import annotations

import numpy as np

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.study import wall_thickness_sweep


def test_the_swept_rise_is_zero_at_the_held_ends_and_positive_inside():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    sweep = wall_thickness_sweep(design, [design.shaft.wall_thickness])
    (rise,) = sweep["rise"]
    assert abs(rise[0]) <= 1e-9 and abs(rise[-1]) <= 1e-9
    assert np.all(rise[1:-1] > 0.0)

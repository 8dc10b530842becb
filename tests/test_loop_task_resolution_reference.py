"""Reference: the bearing-loop task of an operating point runs at its resolution's grid.

docs/magnetic-bearings.md: the loops' frequency grid puts points at the lightly damped
closed-loop poles, three per pole (its top and half width) by default; "The screening resolution
(``SCREENING.loop_peak_samples = 1``) puts one point at each such pole, its top, and lets the
refinement bracket the peak between the neighbouring grid points: 288 instead of 464 grid
solves on the tuned driveline, the same margins to 2e-8". The point recipe's task
(:func:`flexshaft.verdict.point_tasks._roots_and_loops`) must hand that choice on: its loops
are those of the public :func:`~flexshaft.analyses.bearing_loops.bearing_loops` at the
every-root check's poles of the operating speed with ``peak_samples = 1``, on the tuned
driveline coarsened to 18 shaft and 12 boom elements (as tests/test_point_tasks_reference.py).

Both are the same computation on the same inputs in one process, so the grids agree to
round-off (1e-12 relative asserted; the grid's points are the poles' imaginary parts and a
logarithmic spacing, no solve); the one-point grid is the smaller one, and its peak
sensitivity agrees with the three-point grid's to 1e-6 (the documented 2e-8 on the embedded
designs; 1.4e-11 measured here), so what the resolution changes is the grid's cost, not the
margins.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.bearing_loops import bearing_loops
from flexshaft.assembly import build_model
from flexshaft.design import tuned_design, with_overrides
from flexshaft.resolution import SCREENING
from flexshaft.verdict import point_tasks


def test_the_screening_loops_have_one_grid_point_per_pole():
    assert SCREENING.loop_peak_samples == 1
    model = build_model(with_overrides(tuned_design(), {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}))
    roots, loops = point_tasks._roots_and_loops(model, SCREENING)
    assert loops is not None
    poles = roots.resolved_roots_at(model.speed)
    one = bearing_loops(model, poles=poles, peak_samples=1)
    three = bearing_loops(model, poles=poles, peak_samples=3)
    assert [(lp.actuator, lp.axis) for lp in loops] == [(lp.actuator, lp.axis) for lp in one]
    for task, direct, fine in zip(loops, one, three, strict=True):
        assert task.frequencies.size == direct.frequencies.size < fine.frequencies.size
        np.testing.assert_allclose(task.frequencies, direct.frequencies, rtol=1e-12)
        peak = task.margins.peak_sensitivity
        assert abs(peak / direct.margins.peak_sensitivity - 1.0) < 1e-12
        assert abs(peak / fine.margins.peak_sensitivity - 1.0) < 1e-6

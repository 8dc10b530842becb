"""Ranges of the assessment grids and of the wall-thickness buckling study (mutation hunt 23d).

References (the documented conventions, with the physical reason each must hold):

* :mod:`flexshaft.resolution`: speed ranges are fractions of Ω_op, "1 rad/s when it is zero".
  A design at rest must still get a grid of distinct, increasing speeds (a grid of zeros would
  leave the spin-up and stability analyses one degenerate speed), i.e. exactly the fractions
  themselves in rad/s: spin-up 0.02 … scan_top, stability 0 … whirl_top, Campbell 0 … scan_top.
* The Campbell diagram spans the range searched for lateral critical speeds, rest to
  scan_top × Ω_op (the report draws the criticals on it; a diagram running on to whirl_top
  would show crossings no check searched); the whirl-stability speeds run on to whirl_top.
* Thesis study 5 (:func:`flexshaft.thesis.buckling_sweep.buckling_study`): its default sweep is
  10 walls from 1.5 to 6 mm (the function's documented default). Physically a wall must be
  thinner than the tube's outer radius (D_o/2 = 50.8 mm for the baseline) and, for the
  thin-shell buckling model, thin against it; the sweep must also pass through the baseline's
  own wall so that the study shows the design.

Exact comparisons (linspace of exactly representable endpoints) up to 1e-15 relative.
CPU: no analysis is run (the sweep engine is replaced by one that returns the study), ~1 ms.
"""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft.thesis.buckling_sweep as buckling_sweep
from flexshaft.design import baseline_design
from flexshaft.resolution import RESOLUTIONS


@pytest.mark.parametrize("name", sorted(RESOLUTIONS))
def test_a_design_at_rest_gets_the_fractions_in_rad_per_s(name):
    r = RESOLUTIONS[name]
    spin = r.spin_speeds(0.0)
    assert spin == pytest.approx(np.linspace(0.02, r.scan_top, r.spinup_speeds), rel=1e-15)
    assert np.all(np.diff(spin) > 0)
    whirl = r.stability_speeds(0.0)
    assert whirl[0] == 0.0 and whirl[-1] == pytest.approx(r.whirl_top, rel=1e-15)
    assert np.all(np.diff(whirl) > 0)
    if r.campbell_speeds:
        assert r.campbell_grid(0.0)[-1] == pytest.approx(r.scan_top, rel=1e-15)


@pytest.mark.parametrize("name", sorted(RESOLUTIONS))
def test_the_campbell_diagram_spans_the_critical_speed_search(name):
    r = RESOLUTIONS[name]
    operating = 503.0  # rad/s
    assert r.whirl_top != r.scan_top  # the two tops differ at every preset
    if r.campbell_speeds:
        grid = r.campbell_grid(operating)
        assert grid.size == r.campbell_speeds and grid[0] == 0.0
        assert grid[-1] == pytest.approx(r.spin_speeds(operating)[-1], rel=1e-15)
        assert grid[-1] == pytest.approx(r.scan_top * operating, rel=1e-15)
    assert r.stability_speeds(operating)[-1] == pytest.approx(r.whirl_top * operating, rel=1e-15)


def test_the_default_wall_sweep_is_thin_walled_and_contains_the_baseline(monkeypatch):
    monkeypatch.setattr(buckling_sweep, "run_sweep", lambda study, **run: study)
    study = buckling_sweep.buckling_study()
    (variable,) = study.variables
    walls = np.asarray(variable.values, dtype=float)
    assert variable.path == "shaft.wall_thickness"
    assert walls == pytest.approx(np.linspace(1.5e-3, 6e-3, 10), rel=1e-15)
    shaft = baseline_design().shaft
    assert walls.max() < 0.2 * shaft.outer_diameter / 2  # thin against the radius (t/R < 0.2)
    assert walls.min() <= shaft.wall_thickness <= walls.max()

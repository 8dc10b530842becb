""":func:`clustered_receptance` refines each of the ``n_peaks`` largest peaks, by its definition.

Docstring of :func:`flexshaft.analyses.spinup.clustered_receptance`: the spin-up curve's
interior local maxima are ranked by height, and around each of the ``n_peaks`` largest the
``n_fine`` speeds from its left to its right neighbour are added (each speed solved once). A
driveline has several lightly damped resonances in its spin-up (the tailboom's and the shaft's),
and a peak between samples is under-estimated unless its own cluster resolves it.

The curve is written by hand (the spin-up curves replaced by a fixed array on a 21-speed grid):
local maxima at indices 5 (height 3), 9 (height 1) and 14 (height 2). With ``n_peaks = 2`` the
added speeds are exactly the two clusters around indices 5 and 14, and none around 9. The
receptance itself is the Jeffcott rotor's of tests/jeffcott_bearing.py (a real solve of every
added speed). Exact set comparison of the speeds: rel 1e-12 (linspace round-off).

Written for the mutation h43d-spinup-clusters-highest-peak-only of scripts/mutations.toml.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from jeffcott_bearing import model_with

from flexshaft.analyses import spinup


def test_each_of_the_n_largest_peaks_gets_its_own_cluster(monkeypatch):
    model = model_with('kind = "active"\nkp = 5.0e3\nkd = 100.0')
    grid = np.linspace(100.0, 500.0, 21)
    curve = np.full(grid.size, 0.1)
    curve[5], curve[9], curve[14] = 3.0, 1.0, 2.0
    monkeypatch.setattr(spinup, "spinup_curves", lambda rec, controllers: SimpleNamespace(shaft_peak=curve))
    n_fine = 5
    rec = spinup.clustered_receptance(model, (5.0e3, 100.0), grid, n_peaks=2, n_fine=n_fine)
    clusters = [np.linspace(grid[k - 1], grid[k + 1], n_fine) for k in (5, 14)]
    assert rec.speeds == pytest.approx(np.union1d(grid, np.concatenate(clusters)), rel=1e-12)

"""The Campbell grids of the report and fine presets as documented (hunt h101f).

References (documented values and rules, quoted from hand-written docs or the product's
docstring; no number produced by the code):

* A documented configuration value, not a rule: docs/examples.md describes what
  examples/thesis_baseline.py passes, "`--quick` uses 60 spin-up speeds and 12 Campbell speeds
  instead of 651 and 60", so without ``--quick`` (``REPORT``, as ``flexshaft run``) the
  Campbell diagram has 60 speeds. Its
  ends are the product's docstring (flexshaft.resolution, ``Resolution.campbell_speeds``:
  "Speeds of the Campbell diagram, rest to ``scan_top`` × Ω_op"), the top the scan's 1.3 Ω_op
  (docs/architecture.md: the spin-up range "2 % to 130 % of the operating speed").
* A rule: docs/architecture.md: ``FINE`` is "twice the report's density, to check
  convergence". Over the same range, twice the density of 60 speeds (59 intervals) is 118 or
  119 intervals: the fine spacing is the report's over 118/59 = 2 to 119/59 = 2.017; the test
  allows 2 ± 2 % (the integer count, not round-off). A fine grid at the report's count would be
  1 time as dense. This rule alone also catches h101f-resolution-report-campbell-30 (the report
  at 30 speeds, 29 intervals, under a fine grid of 120: spacing ratio 119/29 = 4.10, measured
  by review r121), besides the count of 60 above.

No analysis; microseconds.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.resolution import FINE, REPORT

OMEGA = 400.0  # rad/s, Ω_op


def test_the_reports_campbell_diagram_has_the_documented_60_speeds_to_the_scan_top():
    grid = REPORT.campbell_grid(OMEGA)
    assert grid.size == 60
    assert grid[0] == 0.0 and grid[-1] == pytest.approx(1.3 * OMEGA, rel=1e-15)


def test_the_fine_campbell_diagram_is_twice_as_dense_as_the_reports():
    fine, report = FINE.campbell_grid(OMEGA), REPORT.campbell_grid(OMEGA)
    assert fine[0] == report[0] and fine[-1] == pytest.approx(report[-1], rel=1e-15)
    ratio = np.diff(report)[0] / np.diff(fine)[0]
    assert ratio == pytest.approx(2.0, rel=0.02)

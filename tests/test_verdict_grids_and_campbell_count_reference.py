"""The VERDICT preset judges on the report's grids, and a Campbell diagram needs two speeds
(:mod:`flexshaft.resolution`).

References (documented rules, quoted from hand-written docs; no number produced by the code):

* docs/architecture.md:63-69: the presets are ``SCREENING`` (the optimizer's coarse
  evaluation), "``VERDICT`` (the report's grids, the checks only)", ``REPORT``; the report's
  whirl-stability speeds are "41 to 1.5 × the operating speed" and its spin-up speeds "651
  from 2 % to 130 % of the operating speed". docs/optimizer.md:126-128 (the fidelity table):
  ``verdict`` runs "651 speeds (0.2 % of Ω_op apart)" and "41" whirl speeds, and its margins
  equal the full run's to 1e-9. So VERDICT's spin-up and whirl-stability grids are REPORT's,
  point for point: 41 whirl speeds from rest to 1.5 Ω_op, i.e. 40 intervals of
  1.5/40 = 0.0375 Ω_op. Both sides are ``np.linspace`` of the same ends and count, so equality
  is exact; the spacing is compared to 1e-12 relative (linspace round-off, ~1e-16 × 40).
* A Campbell diagram follows each mode's frequency across speed, from rest to the top of the
  scan; one speed (``np.linspace(0, top, 1)`` = ``[0]``) has no range to follow anything
  across, so the only meaningful counts are 0 (no diagram, the VERDICT and SCREENING presets)
  and at least 2. A Resolution asking for 1 is refused (the message is user-facing); 0 and 2
  are accepted, and 2 gives the two ends, rest and scan_top × Ω_op.

No analysis; microseconds.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.resolution import REPORT, VERDICT, Resolution

OMEGA = 400.0  # rad/s, Ω_op


def test_the_verdict_preset_judges_on_the_reports_grids():
    """VERDICT's spin-up and whirl grids are REPORT's: 651 and 41 speeds over the same ranges."""
    assert np.array_equal(VERDICT.spin_speeds(OMEGA), REPORT.spin_speeds(OMEGA))
    assert np.array_equal(VERDICT.stability_speeds(OMEGA), REPORT.stability_speeds(OMEGA))
    whirl = VERDICT.stability_speeds(OMEGA)
    assert whirl.size == 41
    assert whirl[0] == 0.0 and whirl[-1] == pytest.approx(1.5 * OMEGA, rel=1e-15)
    assert np.diff(whirl) == pytest.approx(np.full(40, 1.5 / 40 * OMEGA), rel=1e-12)
    assert VERDICT.spin_speeds(OMEGA).size == 651


def test_a_campbell_diagram_of_one_speed_is_refused():
    """campbell_speeds 1 refused; 0 (no diagram) and 2 (rest and the scan top) accepted."""
    counts = {"spinup_speeds": 5, "whirl_speeds": 5, "report_detail": False}
    with pytest.raises(ValueError, match="campbell_speeds must be 0"):
        Resolution("one", campbell_speeds=1, **counts)
    assert Resolution("none", campbell_speeds=0, **counts).campbell_grid(OMEGA).size == 0
    two = Resolution("two", campbell_speeds=2, **counts).campbell_grid(OMEGA)
    assert two[0] == 0.0 and two[1] == pytest.approx(1.30 * OMEGA, rel=1e-15)

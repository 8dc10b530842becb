"""The resolution presets' grid densities as documented, and the smallest grid (hunt h41a).

A documented contract, not a derivation: the densities are restated from
:mod:`flexshaft.resolution`'s docstring and from where users read them, docs/optimizer.md:128-129
(the fidelity table: "651 speeds (0.2 % of Ω_op apart)", "261 speeds (0.5 %)") and
docs/architecture.md:63-69 (``FINE``: "twice the report's density, to check convergence"). The
spin-up peak is refined between samples, so the spacing bounds what the refinement must bridge.

* SCREENING: "261 spin speeds (0.5 % of the operating speed apart)"; REPORT: "651 spin speeds
  (0.2 % apart)". The scan runs from 0.02 to 1.30 Ω_op, so the spacing is 1.28/260 = 0.49 %
  and 1.28/650 = 0.197 % of Ω_op: at most the documented figure.
* FINE: "twice the report's density, to check that its numbers have converged": the spin-up
  and the whirl-stability spacings are exactly half the report's (1300 = 2 · 650 and
  80 = 2 · 40 intervals over the same ranges); 1e-12 relative (linspace round-off). Not
  checked here: FINE's Campbell grid has 120 speeds against the report's 60, 119 against 59
  intervals, 2.02 times as dense rather than exactly twice.
* A grid needs two points: ``linspace(a, b, 1)`` is ``[a]`` alone (no range, no refinement
  between samples) and one mode tracks nothing to compare; 2 is the smallest count accepted.

No analysis; microseconds. Written for h41a-resolution-fine-spin-not-doubled,
h41a-resolution-screening-spin-1pct and h41a-resolution-count-one-accepted of
scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.resolution import FINE, REPORT, SCREENING, Resolution

OMEGA = 400.0  # rad/s, Ω_op


@pytest.mark.parametrize(("preset", "documented"), [(SCREENING, 0.005), (REPORT, 0.002)])
def test_the_spin_up_spacing_is_the_documented_fraction_of_the_operating_speed(preset, documented):
    spacing = np.diff(preset.spin_speeds(OMEGA)) / OMEGA
    assert np.max(spacing) <= documented
    assert np.max(spacing) > 0.9 * documented  # not needlessly finer than documented either


def test_the_fine_grids_are_twice_as_dense_as_the_reports():
    for fine, report in [
        (FINE.spin_speeds(OMEGA), REPORT.spin_speeds(OMEGA)),
        (FINE.stability_speeds(OMEGA), REPORT.stability_speeds(OMEGA)),
    ]:
        assert fine[0] == report[0] and fine[-1] == pytest.approx(report[-1], rel=1e-15)
        assert np.diff(fine) == pytest.approx(np.full(fine.size - 1, 0.5 * np.diff(report)[0]), rel=1e-12)


@pytest.mark.parametrize("field", ["spinup_speeds", "whirl_speeds", "modes", "campbell_modes"])
def test_a_count_of_one_is_refused_and_two_accepted(field):
    counts = {"spinup_speeds": 5, "whirl_speeds": 5, "campbell_speeds": 0, "report_detail": False}
    with pytest.raises(ValueError, match=f"{field} must be an integer >= 2"):
        Resolution("one", **{**counts, field: 1})
    assert getattr(Resolution("two", **{**counts, field: 2}), field) == 2

"""Speeds added to a spin-up scan: their error estimate is zero, the scan's own stay with their
speeds, and a speed the scan already holds is not added again.

:func:`flexshaft.analyses.spinup_response.with_speeds` solves each added speed in full (so its
estimated error is 0, the docstring's rule) and merges it into the scan in order of speed. The
reference is bookkeeping worked by hand: a scan of 12 speeds whose estimates are set to the
distinct values 1, 2, …, 12 (×1e-3), two speeds added between samples 2 and 3 and between
samples 8 and 9 (0-based): the merged estimates read 1, 2, 3, 0, 4, …, 9, 0, 10, 11, 12. A speed
equal to a sample of the scan is skipped (the scan returned as it was). The model is the rigid
rotor of tests/test_spinup_added_speeds_reference.py, solved in full at every speed.
"""

from __future__ import annotations

import dataclasses

import numpy as np
from test_critical_search_load_cases_reference import TEXT

from flexshaft.analyses.spinup_response import spinup_response, with_speeds
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def _scan():
    model = build_model(loads_design(TEXT))
    scan = spinup_response(model, np.linspace(0.2, 1.3, 12) * model.speed, projected=False)
    return model, dataclasses.replace(scan, error_estimate=np.arange(1.0, 13.0) * 1e-3)


def test_added_speeds_have_zero_estimate_and_the_scans_keep_theirs():
    model, scan = _scan()
    s = scan.speeds
    extra = [0.5 * (s[8] + s[9]), 0.5 * (s[2] + s[3])]  # given out of order
    added = with_speeds(model, scan, extra)
    assert np.array_equal(added.speeds, np.sort(np.concatenate([s, extra])))
    expected = np.array([1, 2, 3, 0, 4, 5, 6, 7, 8, 9, 0, 10, 11, 12]) * 1e-3
    assert np.array_equal(added.error_estimate, expected)


def test_a_speed_the_scan_holds_is_not_added_again():
    model, scan = _scan()
    added = with_speeds(model, scan, [scan.speeds[3], scan.speeds[7]])
    assert np.array_equal(added.speeds, scan.speeds)
    assert np.array_equal(added.error_estimate, scan.error_estimate)

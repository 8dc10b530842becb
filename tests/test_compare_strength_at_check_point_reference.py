"""``flexshaft compare``'s strength figure shows each design's curve at the point where its
strength check governs (report/compare.py): its minimum is the verdict's value.

docs/requirements.md: "A figure drawn at another point says so in its caption". Before, the
tuned design's curve was the governing point's (cold_day: 5.24 at x = 3.21 m) while its
Tsai-Wu check reads 1.68 at hot_day (audit a1). Reference: the verdict's own check (value and
point), an independent path (verdict/gather.py reads the point's strength result); the curve's
minimum is the same double as the check's value (rel 1e-12). The embedded comparison is the
session's shared one (tests/conftest.py), no extra analysis.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.report.compare import _strength_curve


def test_each_curves_minimum_is_its_strength_checks_value(embedded_comparison):
    for label, run in zip(embedded_comparison.labels, embedded_comparison.runs):
        key = "tsai_wu" if run.strength_total is not None else "metal_strength"
        check = run.verdict.check(key)
        x, sf, criterion = _strength_curve(run)
        sf = np.asarray(sf, float)
        k = int(np.nanargmin(np.where(np.isfinite(sf), sf, np.nan)))
        assert sf[k] == pytest.approx(check.value, rel=1e-12), (label, criterion)
        point = check.location.get("point")
        if point is not None and len(run.points) > 1:
            assert criterion.endswith(f" at {point}"), criterion
        if math.isfinite(check.location.get("station", math.nan)):
            assert x[k] == pytest.approx(check.location["station"], abs=1e-9)

"""Without an imbalance response a coupling sees no whirling angle: its total angle is the static
one (flexshaft.analyses.misalignment; mutation hunt h56c).

The hinged tubes of tests/test_misalignment_reference.py (two aluminium tubes on pinned ends
joined at x = a = 0.8 m by a hinge of angular stiffness k = 100 N m/rad, L = 2 m), loaded by an
oblique static force P = (30, 40) N at ξ = 0.5 m and given no dynamic response (no imbalance
case: the shaft does not whirl). The span is statically determinate: the hinge carries the
bending moment M = |P| ξ b/L = 50 × 0.5 × 1.2/2 = 15 N m, so its static angle is M/k = 0.15 rad
(derived there and here). The whirling angle of a shaft that does not whirl is zero, so the
largest angle the coupling sees, static plus whirling (CouplingMisalignment.total_angle), is
0.15 rad, finite and comparable with the allowable angle. The Hermite beam is exact for statics
of point loads at nodes: tolerance 1e-8 (the hinge's round-off). CPU: one small static solve.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_misalignment_reference import XI, A, B, K, _response, hinged  # noqa: F401 (fixture)

from flexshaft.analyses.misalignment import coupling_misalignment


def test_no_whirl_leaves_the_total_angle_the_static_one(hinged):  # noqa: F811 (fixture)
    q = _response(hinged, 30.0, 40.0).real
    result = coupling_misalignment(hinged, q)
    static = 50.0 * XI * B / (A + B) / K
    assert result.dynamic_angle[0] == 0.0
    assert np.isfinite(result.total_angle[0])
    assert result.total_angle[0] == pytest.approx(static, rel=1e-8)

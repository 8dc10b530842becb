"""The critical speeds refined on projected models of their peaks, against the all-full refinement.

:mod:`flexshaft.analyses.peak_projection` evaluates the refinement rounds of a peak on a Galerkin
model spanned by full responses near it, and checks every round by full solves at the samples
that make the peak's numbers (to ``PEAK_TOLERANCE`` = 1e-7 relative in orbit). The reference is
the same refinement with a full banded solve at every speed (``projected=False``), on the
embedded designs (lightly and heavily damped peaks, one-sided, two-sided and bounded
bandwidths, close peak pairs).

Tolerance: a 1e-7 error of the orbit at the samples that set the vertex and the half-power
crossings moves the vertex speed and each interpolated crossing (linear in 1/A², whose
relative error is twice the orbit's) by about 2e-7 of the local sample interval, so the critical
speed by far less than 1e-7 relative and the AF (speed over bandwidth) by at most ~4e-7
relative; 1e-6 leaves a factor 2.5 for the three quantities compounding.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.criticals import lateral_critical_speeds
from flexshaft.analyses.peak_projection import ProjectedOrbit
from flexshaft.analyses.response import imbalance_response, orbit_amplitude
from flexshaft.analyses.spinup_response import spinup_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design.io import embedded_design
from flexshaft.design.points import design_at_point
from flexshaft.resolution import SCREENING
from flexshaft.thermal.envelope import point_conditions


def _models():
    for name in ("baseline", "current"):
        yield name, build_model(embedded_design(name).model_copy(update={"envelope": None}))
    tuned = embedded_design("tuned")
    assert tuned.envelope is not None
    for point in tuned.envelope.points[:2]:
        yield f"tuned/{point.name}", build_model(design_at_point(tuned, point, point_conditions(tuned, point)))


@pytest.mark.parametrize("name, model", list(_models()), ids=lambda v: v if isinstance(v, str) else "")
def test_projected_refinement_matches_full_solves(name, model):
    scan = spinup_response(model, SCREENING.spin_speeds(model.speed))
    full = lateral_critical_speeds(model, top=SCREENING.scan_top, scan=(scan.speeds, scan.orbits), projected=False)
    fast = lateral_critical_speeds(model, top=SCREENING.scan_top, scan=(scan.speeds, scan.orbits), projected=True)
    assert len(fast) == len(full) and len(full) >= 3
    for a, b in zip(fast, full):
        assert a.speed == pytest.approx(b.speed, rel=1e-6)
        assert a.amplification_factor == pytest.approx(b.amplification_factor, rel=1e-6)
        assert a.location.get("af_method") == b.location.get("af_method")
        assert a.location.get("peak_orbit", 0.0) == pytest.approx(b.location.get("peak_orbit", 0.0), rel=1e-6)


def test_projected_orbit_agrees_with_the_full_response():
    """The Galerkin model interpolates at the speeds of its basis (the full solution is in the
    span) and what it returns agrees with the full imbalance response at every speed to the
    check's tolerance at the checked samples; elsewhere near the peak to far better than the
    AF's own 0.5 % resolution."""
    model = build_model(embedded_design("tuned").model_copy(update={"envelope": None}))
    loads = imbalance_loads(model)[:, :1]
    node = model.dofs.n_shaft_nodes // 2
    rows = (int(model.dofs.shaft(node, "v")), int(model.dofs.shaft(node, "w")))
    peak = 174.8  # the tuned design's third critical speed [rad/s] (tests above)
    basis = np.array([0.98, 1.0, 1.02]) * peak
    orbit = ProjectedOrbit(model, loads[:, 0], rows, basis)

    def reference(speeds):
        q = imbalance_response(model, speeds, loads)
        return orbit_amplitude(q[rows[0], 0], q[rows[1], 0])

    assert orbit.projected(basis) == pytest.approx(reference(basis), rel=1e-8)
    speeds = np.linspace(0.97, 1.03, 41) * peak
    values = orbit(speeds)
    exact = reference(speeds)
    assert np.max(np.abs(values - exact) / exact) < 1e-4
    assert orbit.full_solves < speeds.size  # it did not fall back to full solves everywhere

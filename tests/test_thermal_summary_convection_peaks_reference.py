"""The thermal summary's peak rise for each convection coefficient
(``thermal_summary(..., sweeps=True)["peak_rise_K_by_convection"]``, flexshaft.thermal.study)
against the largest rise of the shaft's energy balance solved by hand.

Derived reference (thesis §2.8.2, eqs. 2.61-2.65, vertex-centred finite volumes, as in
tests/test_thermal_study_reference.py): with θ = T − T_∞ the rise above the air, node i owning
half of each adjacent element (length ℓ_i = ½ Σ L_e, heat s_i = ½ Σ P_e), conductance
G_e = k A_w/L_e, A_w = π (D_o² − D_i²)/4, and the perimeter π D_o::

    G_{i−1} (θ_{i−1} − θ_i) + G_i (θ_{i+1} − θ_i) − h π D_o ℓ_i θ_i + s_i = 0

at every interior node, θ = 0 at the two held ends: a tridiagonal system solved here densely
for each h of the summary's sweep (5 and 20 W/m²K and the rotating-cylinder correlation's h),
with the element heats P_e of the design's own loss model. The summary's number for "h" is the
largest θ of that profile (the hot spot), not its mean (below 2/3 of it on this profile,
checked) nor another h's. Tolerance 1e-8 relative: both are solves of the same well-conditioned
(diagonally dominant) equations; round-off only.

The baseline design with a coarse mesh (12 shaft elements: the balance holds on any mesh; CPU,
about 0.1 s of test time for the summary's three wall models and its profiles).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_thermal_study_reference import control_volumes

import flexshaft as fs
from flexshaft.design import with_overrides
from flexshaft.thermal.analysis import shaft_thermal
from flexshaft.thermal.heat import heat_sources
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.study import thermal_summary


def _hand_profile(x, element_heat, k, wall, outer, h):
    G, ell, s = control_volumes(x, element_heat, k, wall, outer)
    n = x.size
    A = np.zeros((n, n))
    rhs = np.zeros(n)
    A[0, 0] = A[-1, -1] = 1.0  # held ends: θ = 0
    for i in range(1, n - 1):
        A[i, i - 1], A[i, i + 1] = G[i - 1], G[i]
        A[i, i] = -G[i - 1] - G[i] - h * np.pi * outer * ell[i]
        rhs[i] = -s[i]
    return np.linalg.solve(A, rhs)


def test_each_convection_peak_is_the_hot_spot_of_its_own_balance():
    design = with_overrides(fs.baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6})
    model = fs.build_model(design)
    options = thermal_options(design.thermal)
    loss_model = design.analysis.internal_damping
    out = thermal_summary(design, model, sweeps=True)
    own = shaft_thermal(model, options, loss_model)
    heat = heat_sources(model, loss_model)
    h_corr = own.temperature.heat_transfer_coefficient
    peaks = out["peak_rise_K_by_convection"]
    labels = ["h = 5 W/m²K", "h = 20 W/m²K", f"h = {h_corr:.0f} W/m²K (correlation)"]
    assert list(peaks) == labels
    for label, h in zip(labels, (5.0, 20.0, h_corr)):
        wall, outer = design.shaft.wall_thickness, model.shaft.outer_diameter
        rise = _hand_profile(heat.x, heat.total, own.conductivity, wall, outer, h)
        assert rise.max() > 1.5 * rise[1:-1].mean()  # the hot spot stands out of the mean
        assert peaks[label] == pytest.approx(rise.max(), rel=1e-8)

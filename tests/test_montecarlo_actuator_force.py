"""The Monte-Carlo imbalance's actuator force is the force the bearing carries, its whole law
``k_i (K_p + iΩK_d) − k_s`` times the displacement at its magnet (collocated), as the verdict's
actuator-force check has it, not the controller's current demand C(iΩ) = K_p + iΩK_d alone (it
was, until this test: off by |law|/|C|, here a factor 60, on any magnet with k_i ≠ 1 N/A or
k_s ≠ 0; the shipped designs have k_i = 1 and k_s = 0, which the old and new agree on).

Reference: the Jeffcott rotor with a PD magnet at its disk (tests/jeffcott_bearing.py, gains
written there): the carried force of a collocated bearing is the law, a complex number at each
speed, times the (v, w) displacement, so every unit response of the force is law × the unit
response of the displacement, and a sample's force ellipse is the displacement's scaled by
|law|: its major semi-axis |law| times the orbit. One speed (150 rad/s) so that the sample's
peak over the speeds is that speed's value. Tolerance 1e-6: the unit responses are stored in
complex64 (relative round-off 6e-8 each).
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, active_law, model_with

from flexshaft.montecarlo import EccentricityDistribution, draw_imbalance, sample_outputs, unit_responses

SPEED = 150.0  # rad/s


@pytest.fixture(scope="module")
def case():
    model = model_with(ACTIVE)
    return model, unit_responses(model, [SPEED], "mid_bay", refine=False)


def test_each_unit_force_is_the_law_times_the_unit_displacement(case):
    _, units = case
    law = active_law(SPEED)
    assert abs(law) > 50 * abs(5.0e3 + 1j * SPEED * 2.0)  # the law is far from the controller's C(iΩ)
    np.testing.assert_allclose(units.actuator_force, law * units.actuator, rtol=1e-6, atol=0)


def test_a_samples_force_is_the_law_times_its_orbit(case):
    model, units = case
    draws = draw_imbalance(range(8), units.n_bays, EccentricityDistribution("disk", 2e-5), "mid_bay", 3)
    out = sample_outputs(model, units, draws, strength=False)
    orbit, force = out["actuator_orbit_b"], out["actuator_force_b"]
    assert np.all(orbit > 0)
    np.testing.assert_allclose(force, abs(active_law(SPEED)) * orbit, rtol=1e-6)
    np.testing.assert_allclose(out["actuator_load_b"], force + units.static_force[0], rtol=1e-12)

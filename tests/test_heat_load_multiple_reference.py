"""The shaft's heat under scaled loads is quadratic in the load multiple (mutation hunt 23d).

Derived reference. The response is linear in the load: the imbalance response at Ω and the
static deflection of loads scaled by s are s times those of the unscaled loads (the model is
linear, K, M, G, C and the loss do not depend on the amplitude). The heat of either mechanism
is a quadratic form of the amplitude, P = (ω/2) Re(Xᴴ K'' X) (thesis eq. 2.60), so

    vibration(s_i, s_s) = s_i² · vibration(1, 1),      static(s_i, s_s) = s_s² · static(1, 1),

each mechanism scaled by its own multiple only, in both loss models. The self-heating runaway
search (:func:`flexshaft.thermal.selfheating.runaway_onset`) rests on exactly this scaling.
A coarse 6-element aluminium tube with a loss factor, an imbalance and a lateral load factor
suffices: the identity holds for any linear model. Tolerance 1e-12 relative (rounding of one
linear solve and a quadratic form). CPU: two responses, a few milliseconds.
"""

from __future__ import annotations

import pytest
from test_shaft_heat_whirl_reference import lossy_tube

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict
from flexshaft.thermal.heat import heat_sources, shaft_response_amplitudes


@pytest.fixture(scope="module")
def model():
    loads = {"eccentricity": 1e-4, "load_factor": [0.0, 1.0, 0.5]}
    return build_model(design_from_dict(lossy_tube(loads)))


@pytest.mark.parametrize("loss_model", ["thesis", "rotating"])
def test_heat_scales_with_the_square_of_each_load_multiple(model, loss_model):
    unit = heat_sources(model, loss_model, *shaft_response_amplitudes(model, 1.0, 1.0))
    assert unit.vibration.max() > 0 and unit.static.max() > 0  # both mechanisms present
    s_i, s_s = 2.0, 3.0
    scaled = heat_sources(model, loss_model, *shaft_response_amplitudes(model, s_i, s_s))
    assert scaled.vibration == pytest.approx(s_i**2 * unit.vibration, rel=1e-12, abs=0)
    assert scaled.static == pytest.approx(s_s**2 * unit.static, rel=1e-12, abs=0)

"""Self-heating's fixed point against its own defining equation, its runaway rule and its onset.

* A converged self-heating temperature T* solves T* = Θ(P(q(T*))): the ply moduli at T*
  (the matrix law), the WARM shaft's forced response q (imbalance and static loads), the heat
  P dissipated by that response in the warm shaft's loss stiffness, and the shaft's steady
  temperature Θ. The test re-evaluates that chain once at T*, written out from the physics
  (moduli → model → response → heat → temperature), and requires it to return T* to within
  the fixed point's tolerance. A fixed point of any other map (e.g. the heat of the COLD shaft's
  response) does not satisfy it.
* Runaway is "no equilibrium with every element below the allowable": the hottest element
  decides (a material limit holds at every point, not on average).
* The onset of runaway found by bisection lies between a stable and a runaway load, here
  against a stand-in self-heating whose threshold is known exactly.
"""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft as fs
import flexshaft.thermal.selfheating as selfheating
from flexshaft.laminate import Laminate, equivalent_moduli
from flexshaft.thermal.analysis import shaft_air_temperature, shaft_thermal
from flexshaft.thermal.heat import element_tubes, heat_sources, shaft_response_amplitudes, shaft_stiffness_matrices
from flexshaft.thermal.matrix import matrix_law_for
from flexshaft.thermal.options import ThermalOptions

SCALE = 150.0  # loads x150: the baseline shaft's hottest element warms ~17 K above the air


@pytest.fixture(scope="module")
def model():
    return fs.build_model(fs.baseline_design())


def test_converged_self_heating_solves_its_own_fixed_point_equation(model):
    tol = 1e-6
    result = selfheating.self_heating(model, loss_model="rotating", imbalance_scale=SCALE, static_scale=SCALE, tol=tol)
    assert result.status == "converged"
    T = result.element_temperature
    options = ThermalOptions()
    law = matrix_law_for(model.design.shaft_material, options.matrix_law)
    # moduli of each element's laminate at its own temperature
    moduli = [
        equivalent_moduli(Laminate(t.laminate.angles, t.laminate.thicknesses, law.lamina(t.laminate.lamina, Te)))
        for t, Te in zip(element_tubes(model), T)
    ]
    E = np.array([m[0] for m in moduli])
    G = np.array([m[1] for m in moduli])
    warm = selfheating.model_with_shaft_moduli(model, E, G)
    # the warm shaft's response and the heat it dissipates in the warm shaft's loss stiffness
    q_imbalance, q_static = shaft_response_amplitudes(warm, SCALE, SCALE)
    sources = heat_sources(
        warm, "rotating", q_imbalance, q_static, loss_stiffness=shaft_stiffness_matrices(warm, E, G).imag
    )
    T_air = shaft_air_temperature(model.design.tailboom, options)
    again = shaft_thermal(warm, options, "rotating", air_temperature=T_air, sources=sources)
    # Picard with contraction g < 1 stops when |T_k − T_{k−1}| < tol; then |Θ(T_k) − T_k| ≤ g tol
    # < tol. 10 tol is the allowance for round-off in the moduli (T rounded to 1e-6 K).
    assert np.max(np.abs(again.temperature.element_temperature - T)) < 10 * tol
    assert T.max() - T_air > 10.0  # the case heats enough for the warm/cold response to matter


def test_runaway_is_decided_by_the_hottest_element_not_the_mean():
    T_inf, allowable = 300.0, 350.0
    # a fixed map: elements settle at +10 K and +80 K (mean +45 K, below the allowable's +50 K)
    fp = selfheating.fixed_point(lambda T: np.array([T_inf + 10.0, T_inf + 80.0]), np.full(2, T_inf), allowable)
    assert fp.status == "runaway"
    fp = selfheating.fixed_point(lambda T: np.array([T_inf + 10.0, T_inf + 40.0]), np.full(2, T_inf), allowable)
    assert fp.status == "converged"


class _StandIn:
    def __init__(self, status: str) -> None:
        self.status = status


def test_runaway_onset_bisection_brackets_a_known_threshold(monkeypatch):
    threshold = 3.7  # the stand-in runs away above this load multiple
    monkeypatch.setattr(
        selfheating,
        "self_heating",
        lambda model, options, loss_model, imbalance_scale, static_scale, **kw: _StandIn(
            "runaway" if imbalance_scale > threshold else "converged"
        ),
    )
    refine = 12
    onset, _ = selfheating.runaway_onset(None, [1.0, 2.0, 4.0, 8.0], refine=refine)
    # the first runaway scale is 4 and the last stable one 2: the bracket [2, 4] halves 12 times,
    # so the returned (runaway) end lies within 2/2^12 above the threshold
    assert threshold < onset <= threshold + 2.0 / 2**refine

"""The static loop gain L(0) of a magnetic bearing's loop (flexshaft.analyses.bearing_loops)
where it sets a margin at ω = 0, against the statics of a rigid rotor on two point supports.

Rotor and laws: the rigid rotor of tests/test_loop_robustness.py (FE tube 1e4 times stiffer
than steel, one plane per axis, magnets at x₁ = 0.1 m and x₂ = 0.9 m, k_i = 100 N/A,
k_s = 5e5 N/m). With two point supports a rigid rotor (translation and tilt) is statically
determinate, so each loop's static plant follows from moments alone, the other bearing closed:

* **Bearing 1 integrates** (PID): at ω = 0 it holds its sensed displacement at zero, a pin at
  x₁. A unit force at bearing 2's magnet x₂, pulled on by that magnet's negative stiffness k_s
  alone, turns the rotor about the pin: moments about x₁, (1 + k_s y₂)(x₂ − x₁) = 0, so
  y₂ = −1/k_s, and the displacement is y(x) = y₂ (x − x₁)/(x₂ − x₁). Bearing 2 runs a PD law
  (k_p = 2.5e4 A/m) and senses at x_s = x₂ − 0.1 m = 0.8 m (``sensor_offset = −0.1``):
  L₂(0) = k_i k_p y(x_s) = −(k_i k_p/k_s)(x_s − x₁)/(x₂ − x₁) = −5 × 0.875 = −4.375, a phase
  crossover at ω = 0 whose lower gain margin is −20 log₁₀ 4.375 = −12.82 dB. Loading the
  sensor instead of the magnet gives the factor squared (−11.66 dB); reading the magnet
  instead of the sensor drops it (−13.98 dB).
* **Neither bearing integrates** and each PD law is weaker than its magnet (k_i k_p = 2e5 <
  k_s = 5e5 N/m, collocated): the same determinacy gives each loop, the other closed,
  P(0) = −1/k_s whatever the other bearing's stiffness (B D Bᵀ with B = [b₁ b₂] invertible:
  b_jᵀ (B D Bᵀ)⁻¹ b_j = 1/D_jj), so L(0) = −k_i k_p/k_s = −0.4: |L| < 1 on the negative real
  axis at ω = 0, an upper gain margin of 20 log₁₀ 2.5 = 7.96 dB (the gain that would make the
  rotor statically stiff). The loop's static value is the closed loop T(0) = L/(1 + L) =
  −2/3 < 0, and its sign carries the crossover: |T| = 2/3 reads L = 2, no crossover.

Both references are exact for a flexible shaft too: the loads leave it unloaded (no net force
at the loaded magnet, no reaction at the pin), so its stiffness does not enter; measured
1.5e-12 relative on a steel rotor, 1e-8 to 2e-8 on this 1e4-times-stiffened one (round-off of
its stiffness). Tolerance 1e-6 relative. The rotor is at rest: the speed-dependent
(circulatory) part of the static solve is not exercised here.
CPU: two small models and their loops on the default grid, about 0.1 s of test time.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_loop_robustness import KI, KS, PID, X_BEARINGS, rotor_text

from flexshaft.analyses.bearing_loops import bearing_loops
from flexshaft.assembly import build_model
from flexshaft.design import loads_design, with_overrides

PD_LAW = {"kp": 2.5e4, "kd": 16.0, "integral_gain": 0.0}
SENSOR_OFFSET = -0.1  # bearing 2's sensor inboard of its magnet [m]


def _margins(text: str, overrides: dict) -> dict:
    model = build_model(with_overrides(loads_design(text), overrides))
    loops = bearing_loops(model, frequency_range=(0.5, 2000.0))
    return {(lp.actuator, lp.axis): lp.margins for lp in loops}


def test_a_remote_sensor_beside_an_integrating_bearing_scales_the_static_loop_by_the_pivot_lever():
    overrides = {f"bearings[1].{k}": v for k, v in PD_LAW.items()}
    overrides["bearings[1].sensor_offset"] = SENSOR_OFFSET
    margins = _margins(rotor_text(2.1e15, PID), overrides)
    x1, x2 = X_BEARINGS
    lever = (x2 + SENSOR_OFFSET - x1) / (x2 - x1)
    assert lever == pytest.approx(0.875)
    static = -KI * PD_LAW["kp"] / KS * lever  # L₂(0), pinned at bearing 1
    expected = 20.0 * np.log10(1.0 / abs(static))
    assert expected == pytest.approx(-12.8196, abs=1e-4)
    for axis in ("v", "w"):
        m = margins[("amb_2", axis)]
        assert m.phase_crossovers[0] == 0.0
        assert m.gain_margin_lower_db == pytest.approx(expected, rel=1e-6)


def test_a_pd_loop_weaker_than_its_magnet_crosses_minus_180_degrees_at_zero_frequency():
    weak = {"kp": 2.0e3, "kd": 16.0, "integral_gain": 0.0}
    overrides = {f"bearings[{j}].{k}": v for j in (0, 1) for k, v in weak.items()}
    margins = _margins(rotor_text(2.1e15, PID), overrides)
    static = -KI * weak["kp"] / KS
    assert static == pytest.approx(-0.4)
    expected = 20.0 * np.log10(1.0 / abs(static))
    assert expected == pytest.approx(7.9588, abs=1e-4)
    assert len(margins) == 4
    for m in margins.values():
        assert m.phase_crossovers[0] == 0.0
        assert m.gain_margin_upper_db == pytest.approx(expected, rel=1e-6)  # the ω = 0 crossover sets it

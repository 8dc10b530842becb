"""The thermal analyses that take a model solve, when no options are given, with the model's own
design file's ``[thermal]`` table, as ``flexshaft run`` does (:func:`flexshaft.thermal.options.options_of`).

Before, ``self_heating(model)`` and ``shaft_thermal(model)`` used the baseline's table whatever
the design said: a notebook user who set ``allowable_temperature_c = 60`` in the design file got
the runaway judged against 100 °C, and ply conductivities of their own were ignored, while the
run honoured both. References, independent of the code's conversions:

* the allowable temperature: the design file's 60 °C in kelvin, 60 + 273.15 = 333.15 K (the
  Celsius scale's definition, exact in binary to the last bit of the sum);
* the wall's axial conductivity: the plies' conductivity tensor diag(k_L, k_T) rotated by the
  ply angle with an explicit rotation matrix, xx component, thickness-weighted over the
  baseline's (55/−55/0/0)s wall: half its plies at 0° (k_L), half at ±55°
  (k_L cos²55° + k_T sin²55°) — the derivation of tests/test_laminate_conductivity.py;
* a model without a design: the defaults, the baseline's 100 °C allowable (373.15 K) and its
  ply conductivities of docs/thermal.md (5.0 and 0.5 W/(m K)).

Tolerances: the conductivity is a four-term weighted sum of the typed inputs, 1e-12 relative is
a thousand times round-off; the temperatures are one addition, compared to 1e-9 K.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.design import baseline_design, with_overrides
from flexshaft.thermal.analysis import shaft_conductivity, shaft_thermal
from flexshaft.thermal.options import options_of
from flexshaft.thermal.selfheating import self_heating

K_L, K_T = 7.0, 0.25  # W/(m K): far from the defaults 5.0 and 0.5, so the source shows


def _kxx(angle_deg: float) -> float:
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    R = np.array([[c, -s], [s, c]])
    return float((R @ np.diag([K_L, K_T]) @ R.T)[0, 0])


@pytest.fixture(scope="module")
def own_table_model():
    design = with_overrides(
        baseline_design(),
        {
            "thermal.allowable_temperature_c": 60.0,
            "thermal.fibre_conductivity": K_L,
            "thermal.transverse_conductivity": K_T,
        },
    )
    return fs.build_model(design)


def test_self_heating_judges_runaway_against_the_design_files_allowable(own_table_model):
    result = self_heating(own_table_model)
    assert result.allowable_temperature == pytest.approx(60.0 + 273.15, abs=1e-9)


def test_the_shaft_temperature_conducts_with_the_design_files_ply_conductivities(own_table_model):
    expected = 0.5 * _kxx(0.0) + 0.25 * _kxx(55.0) + 0.25 * _kxx(-55.0)
    assert shaft_conductivity(own_table_model) == pytest.approx(expected, rel=1e-12)
    assert shaft_thermal(own_table_model).conductivity == pytest.approx(expected, rel=1e-12)


def test_a_model_without_a_design_takes_the_documented_defaults():
    class Bare:
        design = None

    options = options_of(Bare())
    assert options.allowable_temperature == pytest.approx(100.0 + 273.15, abs=1e-9)
    assert (options.fibre_conductivity, options.transverse_conductivity) == (5.0, 0.5)

"""The thermal options refuse a ply conductivity that is not a positive finite number, across
the fibres as along them.

Physics (derived here): Fourier's law q = −k ∇T with the second law (heat flows from hot to
cold) needs k ≥ 0; a negative k_T makes the wall conductivity of docs/thermal.md ("Wall
conductivity": k = Σ t_k (k_L cos²α_k + k_T sin²α_k)/t) smaller than the fibres alone give,
and NaN or infinity carries no number at all. A zero k_T (a 90° ply as a perfect insulator)
breaks no physical law; 0 is refused by the options' own rule (API contract: ThermalOptions,
"finite and > 0" [W/(m K)]). The design
schema bounds the design file's values; this checks the runtime options a notebook builds
directly. The positive values the docs list (5.0 and 0.5 W/(m K)) are accepted as given. No
tolerance: the options store the numbers they are given.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.thermal.options import ThermalOptions


@pytest.mark.parametrize("value", [0.0, -0.5, math.nan, math.inf])
@pytest.mark.parametrize("name", ["fibre_conductivity", "transverse_conductivity"])
def test_a_non_positive_or_non_finite_ply_conductivity_is_refused(name, value):
    with pytest.raises(ValueError, match=name):
        ThermalOptions(**{name: value})


def test_the_documented_positive_conductivities_are_accepted():
    options = ThermalOptions(fibre_conductivity=5.0, transverse_conductivity=0.5)
    assert (options.fibre_conductivity, options.transverse_conductivity) == (5.0, 0.5)

"""The Monte-Carlo study's ply check: the Tsai-Wu safety factor at the operating speed, only
when asked for.

References:

* **The ply check asked for.** :func:`flexshaft.montecarlo.steady.run_montecarlo` evaluates
  per sample "the ply Tsai-Wu safety factor at the operating speed (static loads and torque plus
  the sample's imbalance response)" (module docstring). On a single [0] ply tube with no
  power, no external load and every bay's eccentricity 0 nothing bends or twists: the ply
  carries the spin's hoop stress alone, σ₂ = N_y/t = ρ Ω² r_m² (derived here: thin-ring
  equilibrium, N_y = ρ t Ω² r_m², the product's documented free-thin-tube model of the
  shaft_strength module; the exact thick ring peaks ~4 % higher at the inner wall),
  so Tsai-Wu under a uniaxial transverse tension meets the envelope at σ₂ = Y_t:
  R = Y_t/(ρ Ω² r_m²) (derived there), 107.7 for the tube below at 3000 rpm.
* **The ply check not asked for.** ``strength=False``: ``safety_factor`` is "NaN when
  ``strength`` is False" (:func:`flexshaft.montecarlo.samples.sample_outputs`) and the dataset
  says why ("not applicable, NaN in every sample: ... or strength was not asked for",
  ``_mark_not_applicable``): a finite factor under that comment would be a number the run says
  it did not compute.

Tolerance 1e-9: with zero eccentricity every imbalance weight is exactly 0, so the operating
field is exactly the spin's; the factor is float64 algebra on the ply stiffness and the Tsai-Wu
quadratic (round-off ~1e-14, conditioning O(1)), as in the cited test. Two spin-up speeds and
three samples: about 0.05 s each (the first Monte-Carlo run in a process also pays ~0.5 s of
lazy imports, xarray, already paid in the suite by the other Monte-Carlo tests).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_shaft_strength_fields_reference import E_L, E_T, G_LT, NU, R_O, WALL, X0, X1, X_C, X_T, Y_C, Y_T, D, S

from flexshaft.design import design_from_dict
from flexshaft.montecarlo import run_montecarlo
from flexshaft.montecarlo.samples import EccentricityDistribution

RHO = 1600.0  # kg/m^3
SPEED_RPM = 3000.0


@pytest.fixture(scope="module")
def unidirectional_tube():
    """A [0] ply tube, clamped at x = 0 and pinned at a contact stop at its end: one bay."""
    return design_from_dict(unidirectional_tube_data())


def unidirectional_tube_data() -> dict:
    """The design-file data of :func:`unidirectional_tube` (for variants of it)."""
    ply = {"kind": "lamina", "density": RHO, "E_L": E_L, "E_T": E_T, "G_LT": G_LT, "nu_LT": NU}
    ply |= {"X_t": X_T, "X_c": X_C, "Y_t": Y_T, "Y_c": Y_C, "S": S}
    return {
        "name": "[0] tube",
        "materials": {"ply": ply},
        "shaft": {
            "x_start": X0,
            "x_end": X1,
            "outer_diameter": D,
            "wall_thickness": WALL,
            "material": "ply",
            "layup": "0",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "stop", "kind": "contact", "x": X1, "stiffness": {}}],
        "operating": {"speed_rpm": SPEED_RPM, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 4},
    }


def _run(design, strength: bool):
    balanced = EccentricityDistribution("fixed", 0.0)
    return run_montecarlo(design, 3, distribution=balanced, n_speeds=2, strength=strength).dataset


def test_each_sample_carries_the_spinning_plys_hoop_safety_factor(unidirectional_tube):
    """strength=True: every sample's factor is Y_t/(ρ Ω² r_m²)."""
    omega = SPEED_RPM * np.pi / 30.0
    r_m = R_O - WALL / 2.0
    expected = Y_T / (RHO * omega**2 * r_m**2)
    factors = _run(unidirectional_tube, strength=True)["safety_factor"].values
    np.testing.assert_allclose(factors, expected, rtol=1e-9)


def test_the_ply_check_not_asked_for_is_not_computed(unidirectional_tube):
    """strength=False on the same laminated tube: NaN in every sample, and the comment says so."""
    factor = _run(unidirectional_tube, strength=False)["safety_factor"]
    assert np.isnan(factor.values).all(), factor.values
    assert "strength was not asked for" in factor.attrs["comment"]

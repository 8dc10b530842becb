"""Which loss model and which loss stiffness the shaft heat uses, against closed-form energies.

Documented rule (docs/thermal.md, "Loss model"): "The heat generated in the shaft follows the
design's `[analysis] internal_damping` ... The API's `loss_model=None` means the design's
choice; an explicit value ... overrides it for a comparison."

Derived here (the beam theory of tests/test_heat_bending_and_torsion_reference.py): on the lossy
aluminium tube (2 m, 50 x 2 mm, E = 70 GPa, G = 26 GPa, eta = 0.02, 3000 rpm, 6 Euler-Bernoulli
elements, pinned ends) a static deflection s(x) = A x (x - L) in the v plane (slope
gamma = ds/dx) has s'' = 2A, exact in the cubic Hermite elements, so an element of length L_e
stores U_e = (EI/2) int (s'')^2 dx = 2 EI A^2 L_e. With a loss factor eta_e in that element
(E* = E(1 + i eta_e), K'' = eta_e K) its heat is
  - thesis model (the deflection cycled as a planar vibration at Omega): P_e = Omega eta_e U_e,
  - rotating model (a circular orbit of the same radius at Omega): P_e = 2 Omega eta_e U_e
    (each fibre cycles kappa r, so the energy per cycle goes with J = 2I; docs/thermal.md,
    "Shaft heat generation": the rotating model "dissipates **twice** the thesis's value").
The API's ``loss_stiffness`` (the self-heating passes each element's at its temperature) sets
the heat element by element: a loss factor varying along the shaft shows in it.

Tolerance 1e-10 relative: the shape is exact in the elements; what remains is rounding of sums
of order 1e2 terms of a well-scaled quadratic form.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_shaft_heat_whirl_reference import field_vector, lossy_tube

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict
from flexshaft.thermal.heat import heat_sources, shaft_loss_matrices

E, G, ETA, LENGTH = 70e9, 26e9, 0.02, 2.0
DO, DI = 0.05, 0.046
I = np.pi * (DO**4 - DI**4) / 64
A = 1e-4  # [1/m]: s = A x (x - L)
OMEGA = 3000.0 * 2 * np.pi / 60
FACTOR = {"thesis": 1.0, "rotating": 2.0}  # heat per (Omega eta U)


def model_with(internal_damping: str | None):
    design = lossy_tube({"eccentricity": 0.0})
    if internal_damping is not None:
        design["analysis"] = {"internal_damping": internal_damping}
    return build_model(design_from_dict(design))


def bent(model) -> np.ndarray:
    return field_vector(model, {"v": lambda x: A * x * (x - LENGTH), "gamma": lambda x: A * (2 * x - LENGTH)}).real


def closed_form(model, etas, loss_model: str) -> np.ndarray:
    ends = model.dofs.shaft_element_x
    return FACTOR[loss_model] * OMEGA * np.asarray(etas) * 2 * E * I * A**2 * (ends[:, 1] - ends[:, 0])


@pytest.mark.parametrize("choice", ["thesis", "rotating", None])
def test_no_loss_model_given_means_the_designs_internal_damping(choice):
    """Default of ``[analysis] internal_damping`` is "rotating" (docs/model.md: `"rotating"`
    (default; exact for an axisymmetric shaft))."""
    model = model_with(choice)
    expected_model = choice or "rotating"
    zero = np.zeros(model.dofs.size, dtype=complex)
    src = heat_sources(model, None, zero, bent(model))
    assert src.loss_model == expected_model
    np.testing.assert_allclose(src.static, closed_form(model, ETA, expected_model), rtol=1e-10)
    # an explicit choice overrides the design's
    other = "thesis" if expected_model == "rotating" else "rotating"
    src = heat_sources(model, other, zero, bent(model))
    np.testing.assert_allclose(src.static, closed_form(model, ETA, other), rtol=1e-10)


@pytest.mark.parametrize("loss_model", ["thesis", "rotating"])
def test_a_given_loss_stiffness_sets_each_elements_heat(loss_model):
    """Loss factors 0.01 ... 0.06 along the six elements (as a temperature field would give)."""
    model = model_with(None)
    etas = np.linspace(0.01, 0.06, len(model.dofs.shaft_element_x))
    Kpp = shaft_loss_matrices(model, E * (1 + 1j * etas), G * (1 + 1j * etas))
    zero = np.zeros(model.dofs.size, dtype=complex)
    src = heat_sources(model, loss_model, zero, bent(model), loss_stiffness=Kpp)
    np.testing.assert_allclose(src.static, closed_form(model, etas, loss_model), rtol=1e-10)

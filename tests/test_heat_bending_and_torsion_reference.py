"""Heat of the hysteretic shaft against closed-form strain energies (mutation hunt h35d).

Derived references (beam theory, independent of flexshaft.thermal.heat). An isotropic tube with
loss factor eta has E* = E(1 + i eta), G* = G(1 + i eta), so K'' = eta K and the mean power of a
harmonic amplitude X cycled at omega is (omega/2) X^H K'' X = omega eta U(X) with the elastic
strain energy U = X^H K X / 2 (thesis eq. 2.60). Take shapes the elements represent exactly:

* bending, Euler-Bernoulli (shear deformation off): the quadratic deflection s(x) = A x (x - L),
  zero at both pinned ends as a real deflection of the shaft is, is exact in the cubic Hermite
  elements, with s'' = 2A, so over the shaft length L U = (EI/2) int (s'')^2 dx = 2 EI A^2 L per
  bent plane. The nodal slopes are the derivatives of the deflection, ds/dx = A (2x - L):
  gamma = dv/dx, beta = -dw/dx (the flexshaft convention (gamma, -beta) = d(v, w)/dx); with the
  wrong sign of beta the elements would bend w into another shape with another energy.
  - thesis model, a static deflection in v, in w, or in both (v = w = s: U of both planes, the
    planes uncoupled in an isotropic tube) cycled as a vibration at Omega: P = Omega eta U,
    2 Omega eta EI A^2 L per bent plane;
  - rotating model, the same static deflection becomes a circular orbit of the same radius at
    Omega (every fibre passes the extreme strain each turn): twice that, 4 Omega eta EI A^2 L;
  - a circular whirl of radius |s| (v = s, w = -/+ i s with consistent slopes): the
    thesis model sees both planes at Omega, P = Omega eta (2 U) = 4 Omega eta EI A^2 L; the
    rotating model freezes the forward whirl (P = 0) and cycles the backward one at 2 Omega,
    P = 2 Omega eta (2 U) = 8 Omega eta EI A^2 L.
* torsion: a linear twist theta = Theta x / L is exact in the linear torsion elements,
  U = GJ Theta^2 / (2 L); a torsional vibration of amplitude Theta is cycled at Omega in both
  models (the rotation does not change a twist), P = Omega eta GJ Theta^2 / (2 L).

The lossy aluminium tube of tests/test_shaft_heat_whirl_reference.py (2 m, 50 x 2 mm,
E = 70 GPa, G = 26 GPa, eta = 0.02, 3000 rpm, 6 elements). Tolerance 1e-10 relative: the
shapes are exact in the elements, what remains is rounding of sums of order 1e2 terms.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_shaft_heat_whirl_reference import field_vector, lossy_tube

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict
from flexshaft.thermal.heat import heat_sources

E, G, ETA, LENGTH = 70e9, 26e9, 0.02, 2.0
DO, DI = 0.05, 0.046
I = np.pi * (DO**4 - DI**4) / 64
J = np.pi * (DO**4 - DI**4) / 32
A = 1e-4  # [1/m]: s = A x (x - L)
OMEGA = 3000.0 * 2 * np.pi / 60


@pytest.fixture(scope="module")
def model():
    return build_model(design_from_dict(lossy_tube({"eccentricity": 0.0})))


def whirl(model, sense: complex) -> np.ndarray:
    """v = s, w = sense * s, slopes gamma = dv/dx, beta = -dw/dx."""
    return field_vector(
        model, {"v": shape, "gamma": slope, "w": lambda x: sense * shape(x), "beta": lambda x: -sense * slope(x)}
    )


def shape(x):
    return A * x * (x - LENGTH)  # s = A x (x - L): zero at the pinned ends


def slope(x):
    return A * (2 * x - LENGTH)  # ds/dx


PLANES = {
    "v": {"v": shape, "gamma": slope},
    "w": {"w": shape, "beta": lambda x: -slope(x)},
    "v and w": {"v": shape, "gamma": slope, "w": shape, "beta": lambda x: -slope(x)},
}


@pytest.mark.parametrize("planes", PLANES)
def test_static_bending_heat_is_the_closed_form_strain_energy(model, planes):
    zero = np.zeros(model.dofs.size, dtype=complex)
    bend = field_vector(model, PLANES[planes]).real
    energy = 2 * E * I * A**2 * LENGTH * (2 if planes == "v and w" else 1)  # U of the bent planes
    thesis = heat_sources(model, "thesis", zero, bend).static.sum()
    rotating = heat_sources(model, "rotating", zero, bend).static.sum()
    assert thesis == pytest.approx(OMEGA * ETA * energy, rel=1e-10)
    assert rotating == pytest.approx(2 * OMEGA * ETA * energy, rel=1e-10)


def test_whirl_with_slopes_heats_as_the_closed_form(model):
    zero = np.zeros(model.dofs.size)
    energy = 2 * E * I * A**2 * LENGTH  # U of one plane
    forward, backward = whirl(model, -1j), whirl(model, 1j)  # W = -i V forward, +i V backward
    for X in (forward, backward):
        assert heat_sources(model, "thesis", X, zero).vibration.sum() == pytest.approx(
            OMEGA * ETA * 2 * energy, rel=1e-10
        )
    rotating_f = heat_sources(model, "rotating", forward, zero).vibration
    rotating_b = heat_sources(model, "rotating", backward, zero).vibration
    assert np.max(np.abs(rotating_f)) <= 1e-10 * OMEGA * ETA * energy
    assert rotating_b.sum() == pytest.approx(2 * OMEGA * ETA * 2 * energy, rel=1e-10)


def test_torsional_vibration_heats_alike_in_both_models(model):
    zero = np.zeros(model.dofs.size)
    theta = 1e-3  # [rad] twist amplitude over the shaft
    twist = field_vector(model, {"theta": lambda x: theta * x / LENGTH})
    expected = OMEGA * ETA * G * J * theta**2 / (2 * LENGTH)
    for loss_model in ("thesis", "rotating"):
        assert heat_sources(model, loss_model, twist, zero).vibration.sum() == pytest.approx(expected, rel=1e-10)

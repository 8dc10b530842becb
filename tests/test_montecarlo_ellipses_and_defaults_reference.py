"""Monte-Carlo sample outputs on elliptic orbits, over two bearings, and the samples' defaults, by hand.

* **Ellipses.** A sample's response is Σ_b U_b e^{iψ_b} × (unit response of bay b) (linearity;
  :mod:`flexshaft.montecarlo.steady`). Hand-made unit responses ``v = A, w = −iB`` (A, B real)
  trace the ellipse (A cos φt, B sin φt), whose major semi-axis is max(A, B) (the orbit
  amplitude, :func:`~flexshaft.analyses.response.orbit_amplitude`); with B = 2A the
  orbit is 2A, not the v amplitude A. The governing orbit and force are the largest over the
  bearings: here the second bearing's.
* **Zero eccentricity.** A perfectly balanced rotor (scale 0) is a valid distribution ("scale
  must be a finite eccentricity >= 0 m"), all of whose samples are 0.
* **Default speeds.** :func:`unit_responses` without speeds takes ``n_speeds`` evenly spaced from
  SLOW_START = 2 % to 100 % of the operating speed [rad/s] (its docstring); the two-bay rotor of
  tests/test_montecarlo_bounds.py runs at 6000 rpm = 200π rad/s.

* **Static state in the ply check.** A sample's Tsai-Wu factor is that of the static state (torque,
  external loads) plus its imbalance response at the operating speed (the verdict's). On the
  single-[0]-ply tube of tests/test_shaft_strength_fields_reference.py at 3000 rpm, a static bend
  v = a x² (curvature κ = 2a) and no imbalance response: the bending state (N_y = 0) gives the
  outer fibres σ₁ = ±E_L r_o κ, the spin (N_x = 0) the hoop stress σ₂ = ρΩ²r_m² (ring
  equilibrium, Timoshenko & Goodier 1970 §32), superposed; scaled together by R, Tsai-Wu
  (F₁ = 1/X_t − 1/X_c, F₁₁ = 1/(X_t X_c), likewise F₂, F₂₂, F₁₂ = −½√(F₁₁F₂₂), Tsai & Hahn; the
  module docstring of :mod:`flexshaft.strength`) reads a R² + b R = 1, R the positive root,
  smallest over the two fibres. Without the static state the spin alone would give
  Y_t/(ρΩ²r_m²) ≈ 108 instead of ≈ 32.

Tolerances: complex64 unit responses (rel 1e-6 covers their 6e-8 round-off); the speeds are
float64 arithmetic (1e-12); the ply check is float64 algebra on exact element fields (1e-9, as
tests/test_shaft_strength_fields_reference.py).

Written for the mutations h51d-mc-actuator-orbit-v-only, h51d-mc-force-max-first-bearing,
h51d-mc-zero-scale-refused, h51d-mc-default-speeds-in-hz and h51d-mc-strength-without-static of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_montecarlo_bounds import SMALL  # the two-bay rotor with a magnet between its bearings
from test_shaft_strength_fields_reference import E_L, R_O, WALL, X_C, X_T, Y_C, Y_T, _field, _tube

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.montecarlo.samples import (
    EccentricityDistribution,
    ImbalanceDraws,
    UnitResponses,
    sample_outputs,
    unit_responses,
)

SPEEDS = np.array([100.0, 200.0, 300.0])


def _ellipse(a, b):
    """(2, ...) v, w of the ellipses v = a, w = −i b."""
    return np.stack([np.asarray(a, complex), -1j * np.asarray(b, complex)])


def test_orbits_are_major_semi_axes_and_the_largest_is_over_every_bearing():
    """U = 1e-3 kg m (1 kg bay at 1e-3 m). Bearing a: ellipse A = 0.1, B = 0.2 m/(kg m) at the
    second speed (orbit 2e-4 m); bearing b: A = 0.3, B = 0.15 at the third (3e-4 m). Forces: a
    1e5 by 4e5 N/(kg m) (400 N), b 2e5 by 1e5 (200 N) at the first speed: force max 400 N at a,
    orbit max 3e-4 m at b."""
    act = np.stack(
        [
            _ellipse([[0.01], [0.01]], [[0.02], [0.01]]),
            _ellipse([[0.1], [0.02]], [[0.2], [0.02]]),
            _ellipse([[0.02], [0.3]], [[0.01], [0.15]]),
        ]
    )  # (speeds, 2, act, station)
    force = np.stack(
        [
            _ellipse([[1e5], [2e5]], [[4e5], [1e5]]),
            _ellipse([[1e4], [1e4]], [[1e4], [1e4]]),
            _ellipse([[1e4], [1e4]], [[1e4], [1e4]]),
        ]
    )
    shaft = np.stack([_ellipse([[1.0]], [[0.5]])] * 3)
    units = UnitResponses(
        speeds=SPEEDS,
        bays=np.array([[0.0, 1.0]]),
        bay_mass=np.ones(1),
        stations=np.array([0.5]),
        elements=np.array([[0.5, 0.5]]),
        element_stations=np.zeros((1, 4), int),
        element_bay=np.zeros(1, int),
        shaft=shaft.astype(np.complex64),
        actuator=act.astype(np.complex64),
        actuator_force=force.astype(np.complex64),
        operating=np.zeros((1, 1), complex),
        static=np.zeros(1),
        actuator_names=("a", "b"),
        placement="mid_bay",
        static_offset=np.zeros(2),
        static_force=np.zeros(2),
    )
    draws = ImbalanceDraws(np.array([[1e-3]]), np.array([[1.1]]), np.array([[0.5]]))
    out = sample_outputs(None, units, draws, strength=False)
    assert out["shaft_peak"][0] == pytest.approx(1e-3, rel=1e-6)  # major semi-axis 1 of (1, 0.5)
    assert out["actuator_orbit_a"][0] == pytest.approx(2e-4, rel=1e-6)
    assert out["actuator_orbit_b"][0] == pytest.approx(3e-4, rel=1e-6)
    assert out["actuator_orbit_max"][0] == pytest.approx(3e-4, rel=1e-6)
    assert out["actuator_force_a"][0] == pytest.approx(400.0, rel=1e-6)
    assert out["actuator_force_b"][0] == pytest.approx(200.0, rel=1e-6)
    assert out["actuator_force_max"][0] == pytest.approx(400.0, rel=1e-6)
    # the same with the bearings' order swapped: the largest is still found
    swapped = UnitResponses(
        **{
            **units.__dict__,
            "actuator": act[:, :, ::-1].astype(np.complex64),
            "actuator_force": force[:, :, ::-1].astype(np.complex64),
        }
    )
    out = sample_outputs(None, swapped, draws, strength=False)
    assert out["actuator_force_max"][0] == pytest.approx(400.0, rel=1e-6)
    assert out["actuator_orbit_max"][0] == pytest.approx(3e-4, rel=1e-6)


@pytest.mark.parametrize("kind", ["fixed", "disk", "uniform", "rayleigh"])
def test_a_perfectly_balanced_rotor_is_a_valid_distribution(kind):
    dist = EccentricityDistribution(kind, 0.0)
    assert np.all(dist.sample(np.random.default_rng(1), 5) == 0.0)


def test_default_speeds_run_from_two_percent_to_the_operating_speed():
    model = build_model(loads_design(SMALL))
    omega = 6000.0 * np.pi / 30.0
    assert model.speed == pytest.approx(omega, rel=1e-12)
    units = unit_responses(model, n_speeds=4, refine=False)
    assert units.speeds == pytest.approx(np.linspace(0.02, 1.0, 4) * omega, rel=1e-12)


def test_the_sample_ply_check_carries_the_static_state():
    model = _tube("0")
    a = 2.0e-3  # 1/m²: κ = 4e-3 1/m, σ₁ = 24 MPa
    zero = np.zeros((1, 2, 1, 1))
    units = UnitResponses(
        speeds=np.array([100.0]),
        bays=np.array([[0.0, 1.6]]),
        bay_mass=np.ones(1),
        stations=np.array([0.8]),
        elements=np.array([[0.8, 0.8]]),
        element_stations=np.zeros((1, 4), int),
        element_bay=np.zeros(1, int),
        shaft=zero.astype(np.complex64),
        actuator=np.zeros((1, 2, 0, 1), np.complex64),
        actuator_force=np.zeros((1, 2, 0, 1), np.complex64),
        operating=np.zeros((model.dofs.size, 1), complex),
        static=_field(model, a=a),
        actuator_names=(),
        placement="mid_bay",
    )
    draws = ImbalanceDraws(np.array([[1e-3]]), np.array([[0.3]]), np.array([[0.5]]))
    out = sample_outputs(model, units, draws, n_phases=36)
    omega = 3000.0 * np.pi / 30
    s2 = 1600.0 * omega**2 * (R_O - WALL / 2) ** 2
    f1, f2 = 1 / X_T - 1 / X_C, 1 / Y_T - 1 / Y_C
    f11, f22 = 1 / (X_T * X_C), 1 / (Y_T * Y_C)
    f12 = -0.5 * np.sqrt(f11 * f22)
    factors = []
    for s1 in (E_L * R_O * 2 * a, -E_L * R_O * 2 * a):
        qa = f11 * s1**2 + f22 * s2**2 + 2 * f12 * s1 * s2
        qb = f1 * s1 + f2 * s2
        factors.append((-qb + np.sqrt(qb * qb + 4 * qa)) / (2 * qa))
    assert out["safety_factor"][0] == pytest.approx(min(factors), rel=1e-9)

"""Monte-Carlo sample outputs by superposition, on unit responses whose numbers are chosen here.

A sample's response is Σ_b U_b e^{iψ_b} × (unit response of bay b) (linearity; module docstring
of :mod:`flexshaft.montecarlo.steady`). With hand-made unit responses the outputs are arithmetic
(derived):

* a forward circle ``v = X, w = −iX`` has the orbit radius |X|
  (:func:`~flexshaft.analyses.response.orbit_amplitude`, the major semi-axis);
* the peak deflection is the largest over nodes and speeds, at the speed where it occurs;
* the excursion of an active bearing is its static offset + its peak orbit, and the governing
  excursion the largest of those sums (the verdict's actuator check judges each bearing);
  likewise static + peak force;
* two bays whose unbalances are equal and opposite (ψ = 0 and π) on identical unit responses
  cancel: the sample's ply check sees the spin alone. A single [0] ply spinning free carries
  σ₂ = N_y/t = ρ Ω² r_m² (ring equilibrium, N_y = ρ t Ω² r_m², Timoshenko & Goodier 1970 §32)
  and nothing else, so Tsai-Wu gives R = Y_t/(ρ Ω² r_m²).
* The station weights of an unbalance inside an element are the cubic Lagrange basis at its
  position ξ: they sum to 1 and reproduce x (a cubic interpolant is exact for 1 and x), so
  Σ w_j = U e^{iψ} and Σ w_j x_j = U e^{iψ} x_b (derived).
* The golden-section refinement of a peak: a Lorentzian proxy 1/((s − s₀)² + h²) peaked at
  s₀ = 1.2345 between grid points 0.1 apart gets a refined speed within width × s of s₀.
* A force capacity given to :func:`run_montecarlo` replaces each bearing's (its docstring), as
  the gap does (tests/test_montecarlo_exceedance_reference.py).

Tolerances: the unit responses are stored in complex64 (rel 1e-6 covers its 6e-8 round-off);
the ply check and the weights are float64 algebra (1e-9).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_montecarlo_bounds import SMALL  # the two-bay rotor with a magnet between its bearings
from test_shaft_strength_fields_reference import R_O, WALL, Y_T, _field, _tube

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.montecarlo import run_montecarlo
from flexshaft.montecarlo.samples import (
    ImbalanceDraws,
    UnitResponses,
    _peak_refined_speeds,
    combine,
    sample_outputs,
    unit_responses,
)

SPEEDS = np.array([100.0, 200.0, 300.0])


def _units(shaft, actuator, force, offset, force_static, operating=None, static=None, n_bays=1):
    """Unit responses of ``n_bays`` mid-bay stations (one per bay) on bays of 1 m, 1 kg each."""
    n_st = n_bays
    return UnitResponses(
        speeds=SPEEDS,
        bays=np.array([[b, b + 1.0] for b in range(n_bays)]),
        bay_mass=np.ones(n_bays),
        stations=np.arange(n_bays) + 0.5,
        elements=np.array([[b + 0.5, b + 0.5] for b in range(n_bays)]),
        element_stations=np.array([[b] * 4 for b in range(n_bays)]),
        element_bay=np.arange(n_bays),
        shaft=np.asarray(shaft, np.complex64),
        actuator=np.asarray(actuator, np.complex64),
        actuator_force=np.asarray(force, np.complex64),
        operating=np.zeros((1, n_st), complex) if operating is None else operating,
        static=np.zeros(1) if static is None else static,
        actuator_names=("a", "b"),
        placement="mid_bay",
        static_offset=np.asarray(offset, float),
        static_force=np.asarray(force_static, float),
    )


def _forward(radius):
    """(2, ...) v, w of forward circles of the given radii."""
    radius = np.asarray(radius, complex)
    return np.stack([radius, -1j * radius])


def test_peaks_excursions_and_loads_of_a_sample_by_superposition():
    """U = 1e-3 kg m at ψ = 0.7 rad. Shaft: two nodes, radii (per kg m) 1, 3, 2 [m] at node 0
    and 0.5, 0.5, 4 at node 1 over the three speeds: peak 4e-3 m at 300 rad/s. Bearing a: peak
    orbit 0.1 m/(kg m) (1e-4 m), no offset; b: 0.05 (5e-5 m) with 1e-4 m offset: excursions
    1e-4 and 1.5e-4 m, the governing one 1.5e-4 m (not 1e-4 + 1e-4). Forces: a 2e5 N/(kg m)
    peak (200 N) + 10 N, b 1e5 (100 N) + 150 N: loads 210 and 250 N."""
    shaft = np.stack([_forward([[1.0], [0.5]]), _forward([[3.0], [0.5]]), _forward([[2.0], [4.0]])])
    act = np.stack([_forward([[0.1], [0.02]]), _forward([[0.05], [0.05]]), _forward([[0.02], [0.01]])])
    force = np.stack([_forward([[1e5], [1e5]]), _forward([[2e5], [0.5e5]]), _forward([[1e5], [0.2e5]])])
    units = _units(shaft, act, force, offset=[0.0, 1e-4], force_static=[10.0, 150.0])
    draws = ImbalanceDraws(np.array([[1e-3]]), np.array([[0.7]]), np.array([[0.5]]))
    out = sample_outputs(None, units, draws, strength=False)
    assert out["shaft_peak"][0] == pytest.approx(4e-3, rel=1e-6)
    assert out["shaft_peak_speed"][0] == 300.0
    assert out["actuator_orbit_a"][0] == pytest.approx(1e-4, rel=1e-6)
    assert out["actuator_excursion_b"][0] == pytest.approx(1.5e-4, rel=1e-6)
    assert out["actuator_excursion_max"][0] == pytest.approx(1.5e-4, rel=1e-6)
    assert out["actuator_force_a"][0] == pytest.approx(200.0, rel=1e-6)
    assert out["actuator_load_max"][0] == pytest.approx(250.0, rel=1e-6)
    assert np.isnan(out["safety_factor"][0])  # strength=False


def test_opposite_unbalances_on_identical_bays_cancel_in_the_ply_check():
    """Two bays, the same bending field per kg m, U = 1e-3 kg m at ψ = 0 and π: nothing bends,
    the [0] ply carries the spin's hoop stress alone, R = Y_t/(ρ Ω² r_m²) at 3000 rpm."""
    model = _tube("0")
    q1 = _field(model, a=2.0)  # 4 1/m per kg m: 4e-3 1/m at 1e-3 kg m, σ₁ ≈ 24 MPa if it added
    zeros = np.zeros((3, 2, 2, 2))
    units = _units(
        zeros,
        zeros,
        zeros,
        [0.0, 0.0],
        [0.0, 0.0],
        operating=np.column_stack([q1, q1]).astype(complex),
        static=np.zeros(model.dofs.size),
        n_bays=2,
    )
    draws = ImbalanceDraws(np.array([[1e-3, 1e-3]]), np.array([[0.0, np.pi]]), np.full((1, 2), 0.5))
    out = sample_outputs(model, units, draws, n_phases=36)
    omega = 3000.0 * np.pi / 30
    r_m = R_O - WALL / 2
    assert out["safety_factor"][0] == pytest.approx(Y_T / (1600.0 * omega**2 * r_m**2), rel=1e-9)


@pytest.fixture(scope="module")
def small_units():
    model = build_model(loads_design(SMALL))
    return unit_responses(model, [model.speed], "uniform", refine=False)


def test_the_weights_of_an_unbalance_inside_an_element_are_its_lagrange_basis(small_units):
    """Bay 1 at ξ-fraction 0.37 of the bay, bay 2 at 0.81: per bay, Σ w = U e^{iψ} and
    Σ w x_station = U e^{iψ} x_b (the cubic basis reproduces 1 and x)."""
    units = small_units
    e, psi, pos = np.array([[2e-5, 3e-5]]), np.array([[0.4, 2.5]]), np.array([[0.37, 0.81]])
    idx, weights = combine(units, ImbalanceDraws(e, psi, pos))
    idx, weights = idx.reshape(units.n_bays, 4), weights.reshape(units.n_bays, 4)
    for b in range(units.n_bays):
        unbalance = e[0, b] * units.bay_mass[b] * np.exp(1j * psi[0, b])
        lo, hi = units.bays[b]
        x_b = lo + pos[0, b] * (hi - lo)
        assert weights[b].sum() == pytest.approx(unbalance, rel=1e-9)
        assert weights[b] @ units.stations[idx[b]] == pytest.approx(unbalance * x_b, rel=1e-9)


def test_the_golden_section_refinement_finds_a_narrow_peak_between_grid_points():
    s0, h = 1.2345, 1e-5
    speeds = np.arange(1.0, 1.55, 0.1)
    refined = _peak_refined_speeds(lambda s: 1.0 / ((s - s0) ** 2 + h**2), speeds)
    assert np.min(np.abs(refined - s0)) < 2e-6 * s0


def test_a_force_capacity_given_to_the_run_replaces_the_design_capacity():
    """One sample on a 2-speed grid, no strength (the limits do not depend on the samples)."""
    result = run_montecarlo(loads_design(SMALL), 1, grade_mm_s=2.5, force_limit=500.0, n_speeds=2, strength=False)
    assert result.limits["amb"].force_capacity == 500.0
    assert result.limits["amb"].gap == 1.0e-3

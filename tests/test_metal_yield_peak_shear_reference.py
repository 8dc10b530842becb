"""First-cycle yield of a metal shaft: the peak shear is the mean plus the alternating shear.

Shigley (Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., §7-4, eqs.
7-15 and 7-16, as quoted in :mod:`flexshaft.analyses.metal_strength`): the first cycle reaches
the largest stresses σ_max = σ_m + σ_a and τ_max = τ_m + τ_a, and the distortion-energy (von
Mises) stress of a plane state (σ_x, σ_θ, τ) is derived here from the second invariant of the
deviator, σ' = √(σ_x² − σ_x σ_θ + σ_θ² + 3τ²); on the worst fibre (σ_x = −σ_max, the
compressed side, against a tensile hoop stress σ_θ) it is √(σ_max² + σ_max σ_θ + σ_θ² + 3 τ_max²).
n_y = S_y/σ'. The states below are chosen so that the numbers are exact: pure shear
τ_m = τ_a = τ gives σ' = 2√3 τ; a pure alternating shear τ_a alone gives σ' = √3 τ_a. The
function is a closed form: tolerance 1e-12 (round-off).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.metal_strength import von_mises_yield_factor

S_Y = 276.0e6  # 6061-T6 typical tensile yield strength [Pa] (any positive value would do)


def test_mean_and_alternating_shear_add_in_the_first_cycle():
    """τ_m = τ_a = 20 MPa, no normal stress: σ' = √3 (τ_m + τ_a), n_y = S_y/(√3 · 40 MPa)."""
    tau = 20.0e6
    factor = von_mises_yield_factor(0.0, 0.0, tau, tau, S_Y)
    assert float(factor) == pytest.approx(S_Y / (np.sqrt(3.0) * 2.0 * tau), rel=1e-12)


def test_a_purely_alternating_shear_yields_like_a_static_one():
    """τ_a = 50 MPa alone: its first peak is a static shear of 50 MPa, n_y = S_y/(√3 τ_a)."""
    tau_a = 50.0e6
    factor = von_mises_yield_factor(0.0, 0.0, tau_a, 0.0, S_Y)
    assert float(factor) == pytest.approx(S_Y / (np.sqrt(3.0) * tau_a), rel=1e-12)


def test_combined_state_with_a_hoop_stress():
    """σ_m = 30, σ_a = 10, τ_m = 15, τ_a = 5, σ_θ = 8 MPa (worst fibre, σ_x = −40 MPa):
    σ'² = 40² + 40·8 + 8² + 3·20² = 1600 + 320 + 64 + 1200 = 3184 MPa²."""
    mpa = 1.0e6
    factor = von_mises_yield_factor(10 * mpa, 30 * mpa, 5 * mpa, 15 * mpa, S_Y, hoop=8 * mpa)
    assert float(factor) == pytest.approx(S_Y / (np.sqrt(3184.0) * mpa), rel=1e-12)

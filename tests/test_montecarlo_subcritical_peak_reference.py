"""Monte-Carlo spin-up of a subcritical rotor: the peak is at the operating speed, and equals
the operating-speed orbit of the same unbalance (closed form, derived here).

The pinned steel tube of tests/test_montecarlo_unbalance_on_a_pinned_tube_reference.py
(D = 50 mm, wall 5 mm, L = 2 m, ω₁ = 204 rad/s, operating speed 100 rpm = 10.5 rad/s), here
meshed with 10 elements, one bay between its two bearings, the unbalance at mid-bay
(``placement="mid_bay"``). An unbalance U = e m (m = ρ A L, the bay's rotating mass) rotating
at Ω drives the force F = U Ω², whose steady response on this isotropic rotor is a forward
circle. For a simply supported Euler–Bernoulli beam under a harmonic point load F at x = a the
modal sum (mass-normalised modes √(2/(ρAL)) sin(nπx/L), ω_n = (nπ/L)² √(EI/ρA), derived here)
gives the deflection

    w(x) = (2 F/(ρ A L)) Σ_n sin(nπa/L) sin(nπx/L) / (ω_n² − Ω²),

largest at mid-span for a = L/2. Below ω₁ every term grows with Ω, so the peak over the
spin-up is at its top speed. unit_responses' docstring: the default grid runs "from a slow start
(SLOW_START, 2 %) to 100 % of the operating speed", so ``shaft_peak_speed`` is Ω_op (1e-12:
round-off of the evenly spaced grid) and ``shaft_peak`` is U Ω_op² w(L/2)/F.
Deviations from the closed form: the bearings' compliance 1e-11 m/N against the tube's
4.4e-6 m/N at mid-span (≲ 2.3e-6 relative), the elements' rotary inertia and the gyroscopic
coupling (they enter only the dynamic part, (Ω/ω₁)² = 2.6e-3 of the response, at the level of
(π r_g/L)² ~ 6e-4 of it: ~2e-6), the FE discretisation of the mass (static part exact at the
nodes for cubic elements, the dynamic part converged to ~1e-5 of itself) and the complex64
storage of the unit responses (6e-8); the elements are Euler–Bernoulli (docs/model.md: shear
off by default). Measured deviation 4.8e-7; 1e-4 asserted (40 times the largest estimate). A
grid that stops one step short of the operating speed (0.9934 Ω_op with the default 150
speeds) reads the peak 1.3 % low and at the wrong speed.
About 0.07 s CPU (150 speeds, 10 elements).
"""

from __future__ import annotations

import numpy as np
from test_montecarlo_unbalance_on_a_pinned_tube_reference import D_OUT, PINNED_TUBE, RHO, WALL, E, L

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.montecarlo.samples import ImbalanceDraws, sample_outputs, unit_responses


def _mid_span_compliance(omega: float, terms: int = 2001) -> float:
    """|w(L/2)|/F of the pinned-pinned beam under a harmonic mid-span load [m/N]."""
    area = np.pi / 4 * (D_OUT**2 - (D_OUT - 2 * WALL) ** 2)
    ei = E * np.pi / 64 * (D_OUT**4 - (D_OUT - 2 * WALL) ** 4)
    n = np.arange(1, terms + 1)
    wn2 = (n * np.pi / L) ** 4 * ei / (RHO * area)
    return float(abs(2 / (RHO * area * L) * np.sum(np.sin(n * np.pi / 2) ** 2 / (wn2 - omega**2))))


def test_default_spin_up_peaks_at_the_operating_speed_with_the_operating_orbit():
    model = build_model(loads_design(PINNED_TUBE.replace("shaft_elements = 20", "shaft_elements = 10")))
    omega = model.speed
    units = unit_responses(model, placement="mid_bay")
    assert units.n_bays == 1
    ecc = np.array([[1e-4], [3e-5]])
    draws = ImbalanceDraws(ecc, np.array([[0.3], [2.0]]), np.full((2, 1), 0.5))
    out = sample_outputs(model, units, draws, strength=False)
    mass = RHO * np.pi / 4 * (D_OUT**2 - (D_OUT - 2 * WALL) ** 2) * L
    expected = ecc[:, 0] * mass * omega**2 * _mid_span_compliance(omega)
    np.testing.assert_allclose(out["shaft_peak_speed"], omega, rtol=1e-12)
    np.testing.assert_allclose(out["shaft_peak"], expected, rtol=1e-4)

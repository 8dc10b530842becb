"""The unprojected critical-speed refinement solves the load case that peaks, on the rigid rotor
on three springs of tests/test_critical_search_load_cases_reference.py.

Its ``"worst"`` placement gives two load cases: in phase (case 1) excites only the translation,
anti-phase (case 2) only the rocking about the middle (the structure is symmetric), so the
rocking critical exists in case 2 alone. With ``projected=False`` every refinement step of a
peak is a full solve of the load case and shaft node where the scan's envelope peaks (the
reference path the projected refinement is tested against). Closed forms (derived in that
file): the peaks of the Ω²-forced single-DOF responses
f(ρ) = ρ²/√((1 − ρ²)² + (2ζρ)²) at ρ_p = 1/√(1 − 2ζ²), with ω_r = √(k/(2I)), ζ_r ≈ 0.0128 and
ω_t = √(3k/M), ζ_t = 0.05; each amplification factor is ρ_p/(ρ₂ − ρ₁) with ρ₁, ρ₂ the
half-power points f = f(ρ_p)/√2, solved here by bracketing (scipy's brentq, to 1e-12; 1/(2ζ)
is only its first-order value: 39.14 and 9.90 against 39.16 and 10).

Tolerances: speeds 1e-3 as in that file (the tube's polar inertia moves the rocking frequency
by ~1e-4); AF 5e-3, the resolution the refinement promises (half-power band sampled at a 20th
of its width, :mod:`flexshaft.analyses.sweep_projection`: "its AF to 0.5 %"; measured 6e-4 and
1e-3). CPU: about 0.1 s (61 scan speeds, full solves of a 4-element model).

Written for the mutation h39b-criticals-full-refine-first-case of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import pytest
from scipy.optimize import brentq
from test_critical_search_load_cases_reference import TEXT, W_ROCK, W_TRANS, ZETA_ROCK, ZETA_TRANS

from flexshaft.analyses.criticals import lateral_critical_speeds
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def _amplification_factor(zeta: float) -> float:
    def f(r):
        return r * r / math.hypot(1 - r * r, 2 * zeta * r)

    peak = 1 / math.sqrt(1 - 2 * zeta**2)
    half = f(peak) / math.sqrt(2)
    low = brentq(lambda r: f(r) - half, 0.5, peak, xtol=1e-14)
    high = brentq(lambda r: f(r) - half, peak, 3.0, xtol=1e-14)
    return peak / (high - low)


def test_each_critical_is_refined_on_the_case_that_excites_it():
    model = build_model(loads_design(TEXT))
    found = lateral_critical_speeds(model, n_points=61, projected=False)
    rocking = W_ROCK / math.sqrt(1 - 2 * ZETA_ROCK**2)
    translation = W_TRANS / math.sqrt(1 - 2 * ZETA_TRANS**2)
    assert [c.speed for c in found] == pytest.approx([rocking, translation], rel=1e-3)
    afs = [c.amplification_factor for c in found]
    assert afs == pytest.approx([_amplification_factor(ZETA_ROCK), _amplification_factor(ZETA_TRANS)], rel=5e-3)

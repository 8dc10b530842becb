"""``flexshaft check`` names the operating speed for an imbalance response refused at an
undamped resonance.

Rule (flexshaft/analyses/preflight.py, ``model_guards``): "computes what every command starts
from, each refused error becoming a problem naming the fields that set it: ... the imbalance
response at the operating speed (spin-up, thermal)". The refusal is the harmonic solver's "add
damping or move the frequency" (flexshaft/analyses/banded.py): here no damping is in the design,
so the field that sets it is ``operating.speed_rpm``.

Reference design: the undamped Jeffcott rotor of tests/rotors.py with a nearly massless tube
(density 1e-6 kg/m³, as in tests/test_api_guards.py), balance grade G 6.3 for a non-zero
imbalance, run at its closed-form natural frequency ω_n = sqrt(k / m_e) (k = 48 E I / L³,
m_e the disk plus the tube's effective mass, tests/test_massless_members.py). The synchronous
forward response F / (k − m_e Ω²) of an undamped Jeffcott rotor is unbounded there: the solve is
refused (measured: still refused with the speed 1e-12 below ω_n, reciprocal condition 5e-17,
so the rpm's rounding does not matter; review r120 measured it refused within ±1e-11 of ω_n,
reciprocal condition 5.3e-16, and not at ±1e-10) and nothing else is (the modes and the static
deflection of a pinned-pinned rotor are regular). 0.1 % below ω_n (Ω = ω_n (1 − δ), δ = 1e-3) the response is
finite: k − m_e Ω² = k (2δ − δ²), so it is about 1/(2δ) = 500 times the static one, and the
design has no problem: the refusal is the resonance's.
"""

from __future__ import annotations

import math

import pytest
from rotors import jeffcott_text
from test_api_guards import DENSITY, OMEGA_N

from flexshaft.analyses.preflight import model_guards
from flexshaft.design import loads_design


def undamped_jeffcott_at(speed_rad_s: float):
    rpm = float(speed_rad_s * 30.0 / math.pi)
    text = (
        jeffcott_text(0.0, 0.0)
        .replace("density = 0.1", f"density = {DENSITY!r}")
        .replace("speed_rpm = 0.0", f"speed_rpm = {rpm!r}")
    )
    return loads_design(text + "[loads]\nbalance_grade = 6.3\n")


def test_an_imbalance_response_at_an_undamped_resonance_names_the_operating_speed():
    problems = model_guards(undamped_jeffcott_at(OMEGA_N))
    assert [p.path for p in problems] == ["operating.speed_rpm"]
    assert "imbalance response at the operating speed" in problems[0].message
    assert "singular" in problems[0].message


@pytest.mark.parametrize("delta", [1e-3])
def test_off_the_resonance_the_same_rotor_has_no_problem(delta):
    assert model_guards(undamped_jeffcott_at(OMEGA_N * (1 - delta))) == []

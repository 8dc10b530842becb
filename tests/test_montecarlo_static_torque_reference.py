"""The Monte-Carlo samples' static state carries the transmitted torque, by hand.

:func:`flexshaft.montecarlo.samples.unit_responses` keeps the static response to the external
loads and the torque T = P/Ω (the state the samples' Tsai-Wu check superposes the imbalance
on). On a uniform aluminium tube with the forward twist held and no other load, the tail
rotor's reaction −T at the aft end twists the tube uniformly (Saint-Venant torsion):
θ(x) = −T x/(G J_p), J_p = π(D_o⁴ − D_i⁴)/32.

Tolerance: a direct sparse solve on a 10-element tube whose torsion element is exact for a
linear twist: rel 1e-9.

Written for the mutation h43d-mc-static-without-torque of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_load_patterns_reference import D_O, ECC, WALL, G, L, _text

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.montecarlo.samples import unit_responses

POWER, RPM = 50.0e3, 3000.0


def test_the_static_state_of_the_samples_holds_the_torque_twist():
    base = _text()
    assert "power = 0.0" in base and f"eccentricity = {ECC}" in base  # both edits below take effect
    text = base.replace("power = 0.0", f"power = {POWER}").replace(f"eccentricity = {ECC}", "eccentricity = 0.0")
    model = build_model(loads_design(text))
    units = unit_responses(model, speeds=[100.0, 200.0], refine=False, placement="mid_bay")
    T = POWER / (RPM * 2 * math.pi / 60)
    J = math.pi * (D_O**4 - (D_O - 2 * WALL) ** 4) / 32
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    x = np.asarray(dm.shaft_x, dtype=float)
    assert units.static[dm.shaft(nodes, "theta")] == pytest.approx(-T * x / (G * J), rel=1e-9, abs=1e-15)
    assert x[-1] == pytest.approx(L)

"""Reference: what a design file means when it leaves out a load or a requirement (hunt h40a).

The defaults are the contract of docs/design-reference.md (``[loads]``) and
docs/requirements.md; each is checked through what it does to a number:

* no ``load_factor``: [0, 0, 0] g, so a design without point or line loads carries no static
  load at all (the static load vector is exactly zero); with ``[0, -1, 0]`` the y-forces sum to
  −m g, m = ρ π (D_o² − D_i²) L/4 of the tube by hand, g = 9.80665 m/s²;
* no ``imbalance_placement``: "mid_bay", a point force e_c m Ω² at the middle of each bay (one
  bay here, the whole shaft: no bearing supports it): per unit Ω² exactly e_c m on the
  midspan node's v row and −i e_c m on its w row, nothing on any other degree of freedom
  (the distributed placement puts consistent loads on every node and moment);
* ``balance_grade`` G 4000, the coarsest grade of ISO 21940-11, is accepted and gives
  e_c = G/Ω_max (the standard's e_per = G/Ω; G in mm/s): 4 m/s / Ω;
* the whirl-damping requirement is the user's ``min_log_decrement`` when given, else
  δ = 2πζ/√(1 − ζ²) of ``min_damping_ratio`` (ζ = 0.05: 0.314554…), else API 617's 0.1.

The model: a pinned-pinned steel tube (tests/test_campbell_mode_count_reference.py). Exact but
for round-off: 1e-14 relative.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_campbell_mode_count_reference import DO, OMEGA, RHO, TEXT, L, T

from flexshaft.assembly import build_model
from flexshaft.assembly.balance import design_eccentricity
from flexshaft.assembly.loads import external_static_load, imbalance_loads
from flexshaft.design import DesignError, loads_design
from flexshaft.design.requirements import Requirements

G0 = 9.80665
E_C = 1.0e-5
TUBE_MASS = RHO * math.pi * (DO**2 - (DO - 2 * T) ** 2) / 4 * L


def test_no_load_factor_means_no_static_load():
    model = build_model(loads_design(TEXT + f"\n[loads]\neccentricity = {E_C}\n"))
    assert not np.any(external_static_load(model))
    one_g = build_model(loads_design(TEXT + "\n[loads]\nload_factor = [0.0, -1.0, 0.0]\n"))
    q = external_static_load(one_g)
    v_rows = [one_g.dofs.shaft(n, "v") for n in range(one_g.dofs.shaft_x.size)]
    assert q[v_rows].sum() == pytest.approx(-TUBE_MASS * G0, rel=1e-12)


def test_the_default_imbalance_is_a_point_force_at_mid_bay():
    model = build_model(loads_design(TEXT + f"\n[loads]\neccentricity = {E_C}\n"))
    q = imbalance_loads(model)
    assert q.shape == (model.dofs.size, 1)
    node = model.dofs.node_at("shaft", 0.5 * L)
    v, w = model.dofs.shaft(node, "v"), model.dofs.shaft(node, "w")
    assert q[v, 0] == pytest.approx(E_C * TUBE_MASS, rel=1e-14)
    assert q[w, 0] == pytest.approx(-1j * E_C * TUBE_MASS, rel=1e-14)
    others = np.delete(q[:, 0], [v, w])
    assert not np.any(others)


def test_the_coarsest_iso_balance_grade_is_accepted():
    design = loads_design(TEXT + "\n[loads]\nbalance_grade = 4000.0\n")
    assert design_eccentricity(design) == pytest.approx(4.0 / OMEGA, rel=1e-14)
    with pytest.raises(DesignError):
        loads_design(TEXT + "\n[loads]\nbalance_grade = 4000.5\n")


def test_the_whirl_damping_requirement_is_the_users_when_given():
    assert Requirements(min_log_decrement=0.3).required_log_decrement == 0.3
    assert Requirements(min_log_decrement=0.0).required_log_decrement == 0.0
    zeta = 0.05
    delta = 2 * math.pi * zeta / math.sqrt(1 - zeta**2)
    assert Requirements(min_damping_ratio=zeta).required_log_decrement == pytest.approx(delta, rel=1e-15)
    assert Requirements().required_log_decrement == 0.1

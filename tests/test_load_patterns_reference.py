"""Consistent load vectors, point moments and the worst imbalance pattern, by hand.

* **A uniform line load on a cubic element** (the fixed-end actions of a uniform load,
  integrated here by hand): with the Hermite cubics N₁ = 1 − 3ξ² + 2ξ³,
  N₂ = L(ξ − 2ξ² + ξ³), N₃ = 3ξ² − 2ξ³, N₄ = L(−ξ² + ξ³),
  ∫₀ᴸ q N dx = q (L/2, L²/12, L/2, −L²/12). A uniform q_y over the whole shaft therefore puts
  q L_e/2 on the end nodes' v, q L_e on the interior ones, +q L_e²/12 on the first node's γ
  (γ = dv/dx) and −q L_e²/12 on the last node's, the interior moments cancelling. A one-point
  rule would give L²/8.
* **A point moment about x** is the generalised force on the twist θ (virtual work
  δW = M_x δθ, θ positive about +x): Q_θ = +M_x at the node, and with the forward twist held
  the static twist at x is M_x x/(G J_p) > 0 (a uniform tube in torsion).
* **The worst imbalance pattern** (``placement = "worst"``) enumerates every in-/anti-phase
  combination of the bays' mid-bay forces, the first bay's sign fixed: with two bays (three
  bearings) the two cases F₁ + F₂ and F₁ − F₂, F_b = e_c m/2 per unit Ω² at each bay's
  midpoint (the permissible e_c m shared equally between the bays: flexshaft's convention,
  ``imbalance_loads``' docstring; ISO 21940-11 itself splits by the planes' distances).
  Their resultants are e_c m and 0, their first moments about x = 0 e_c m (x₁ + x₂)/2 and
  e_c m (x₁ − x₂)/2.
* **A point load on the end mass takes no station** (``[[loads.point]]``, docs/design-reference.md):
  one that gives ``x`` is refused rather than its station silently ignored.

Tolerance: sums of a few dozen O(1) products and a direct sparse solve on a 10-element tube:
rel 1e-9 (the solve's conditioning ~1e4 leaves ~1e-12).

Written for the mutations h43d-loads-line-one-gauss-point, h43d-loads-moment-x-sign,
h43d-loads-worst-no-antiphase and h43d-dloads-end-mass-x-accepted of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads, line_load, point_load
from flexshaft.design import loads_design
from flexshaft.design.loads import PointLoad

L, D_O, WALL, RHO, G = 3.0, 0.05, 0.002, 2700.0, 26e9
X_MID_BEARING = 1.2
ECC = 3.0e-5
ELEMENTS = 10


def _text(placement: str = "mid_bay") -> str:
    return f"""
name = "load patterns by hand"
[materials.al]
kind = "isotropic"
E = 70e9
G = {G}
density = {RHO}
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {D_O}
wall_thickness = {WALL}
material = "al"
fixed_start = ["u", "theta"]
[[bearings]]
name = "fore"
kind = "contact"
x = 0.0
stiffness = {{ v = 1e9, w = 1e9 }}
[[bearings]]
name = "mid"
kind = "contact"
x = {X_MID_BEARING}
stiffness = {{ v = 1e9, w = 1e9 }}
[[bearings]]
name = "aft"
kind = "contact"
x = {L}
stiffness = {{ v = 1e9, w = 1e9 }}
[operating]
speed_rpm = 3000.0
power = 0.0
[loads]
eccentricity = {ECC}
imbalance_placement = "{placement}"
[mesh]
shaft_elements = {ELEMENTS}
"""


@pytest.fixture(scope="module")
def tube():
    return build_model(loads_design(_text()))


def test_a_uniform_line_load_puts_the_fixed_end_moments_on_the_end_nodes(tube):
    q = 150.0
    Q = line_load(tube, "shaft", 0.0, L, (0.0, q, 0.0))
    dm = tube.dofs
    x = np.asarray(dm.shaft_x, dtype=float)
    nodes = np.arange(dm.n_shaft_nodes)
    lengths = np.diff(x)
    v, gamma = Q[dm.shaft(nodes, "v")], Q[dm.shaft(nodes, "gamma")]
    expected_v = q * (np.concatenate([lengths, [0.0]]) + np.concatenate([[0.0], lengths])) / 2
    expected_gamma = q * (np.concatenate([lengths, [0.0]]) ** 2 - np.concatenate([[0.0], lengths]) ** 2) / 12
    assert v == pytest.approx(expected_v, rel=1e-9)
    assert gamma[0] == pytest.approx(q * lengths[0] ** 2 / 12, rel=1e-9)
    assert gamma[-1] == pytest.approx(-q * lengths[-1] ** 2 / 12, rel=1e-9)
    assert gamma == pytest.approx(expected_gamma, rel=1e-9, abs=1e-9 * q * lengths.max() ** 2)


def test_a_point_moment_about_x_twists_the_shaft_positively(tube):
    M = 40.0
    dm = tube.dofs
    k = dm.n_shaft_nodes - 1
    x = float(dm.shaft_x[k])
    Q = point_load(tube, "shaft", (0.0, 0.0, 0.0), moment=(M, 0.0, 0.0), x=x)
    assert Q[dm.shaft(k, "theta")] == pytest.approx(M, rel=1e-12)
    J = math.pi * (D_O**4 - (D_O - 2 * WALL) ** 4) / 32
    q = static_response(tube, Q)
    assert q[dm.shaft(k, "theta")] == pytest.approx(M * x / (G * J), rel=1e-9)


def test_the_worst_pattern_holds_the_in_phase_and_the_anti_phase_bays():
    model = build_model(loads_design(_text("worst")))
    Q = imbalance_loads(model)
    assert Q.shape[1] == 2
    m = RHO * math.pi * (D_O**2 - (D_O - 2 * WALL) ** 2) / 4 * L
    F = ECC * m / 2  # per bay, per unit Ω²
    x1, x2 = X_MID_BEARING / 2, (X_MID_BEARING + L) / 2
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    x = np.asarray(dm.shaft_x, dtype=float)
    sums = []
    for column in Q.T:
        v, gamma = column[dm.shaft(nodes, "v")], column[dm.shaft(nodes, "gamma")]
        sums.append((v.sum(), (v * x + gamma).sum()))
        assert column[dm.shaft(nodes, "w")] == pytest.approx(-1j * v, rel=1e-12, abs=1e-20)
    expected = [(2 * F, F * (x1 + x2)), (0.0, F * (x1 - x2))]
    for (resultant, moment), (r_ref, m_ref) in zip(sums, expected):
        assert resultant == pytest.approx(r_ref, abs=1e-9 * F)
        assert moment == pytest.approx(m_ref, rel=1e-9)


def test_a_point_load_on_the_end_mass_refuses_a_station():
    PointLoad(name="tip", on="end_mass", force=(0.0, 1.0, 0.0))
    with pytest.raises(ValueError, match="must be omitted"):
        PointLoad(name="tip", on="end_mass", x=1.0, force=(0.0, 1.0, 0.0))

"""The design's line loads in the static load, and a boom line load on the boom's own elements,
against consistent nodal loads derived here.

A uniform line load q along y on a Hermite element of length L has the consistent nodal loads
(∫ q N over the element, derived here from N_v,a = 1 − 3s² + 2s³ and N_γ,a = L s (1 − s)²,
s = ξ/L, and their mirror images at the aft node; γ = ∂v/∂x, docs/model.md):

    Q_v,a = Q_v,b = q L / 2,      Q_γ,a = + q L² / 12,      Q_γ,b = − q L² / 12.

Summed over the elements of a member this fixes every nodal value; the resultant force is
q (x_end − x_start) and its moment about x = 0 is q (x_end² − x_start²)/2
(Σ x_i Q_v,i + Σ Q_γ,i, as in tests/test_assembly_load_resultants_reference.py).

* **The design's ``[[loads.line]]``** are part of ``external_static_load`` (its docstring: "the
  design's point loads, line loads and load factor"): a shaft line load with no load factor
  gives the resultants above.
* **A boom line load** is integrated element by element on the boom's own stations: the boom
  here is longer than the shaft (2.5 m against 2 m) and its nodes (bearing stations 1.2 and
  1.9 m on the boom) differ from the shaft's, so every boom node's Q_v and Q_γ follows the
  element sums above.

Tolerances: 4-point Gauss integrates the cubic shape functions exactly; the values are sums of
a few terms of order 1 to 100: 1e-12 relative (1e-12 absolute on values that vanish).

Written for the mutations h54c-loads-static-line-loads-dropped and
h54c-loads-boom-line-on-shaft-stations of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from boomed_rotor import shaft_and_boom

from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load, line_load
from flexshaft.design import loads_design

Q_SHAFT, Q_BOOM = 40.0, -25.0  # N/m along y
SHAFT_SPAN = (0.3, 1.6)

BOOMED = f"""
name = "line loads on a boom longer than the shaft"
{shaft_and_boom(2.5)}[[bearings]]
name = "hanger"
kind = "contact"
x = 0.7
x_boom = 1.2
stiffness = {{ v = 1e7, w = 1e7 }}
[[bearings]]
name = "aft"
kind = "contact"
x = 1.9
stiffness = {{ v = 1e7, w = 1e7 }}
[operating]
speed_rpm = 3000.0
power = 0.0
[loads]
eccentricity = 0.0
[[loads.line]]
name = "shaft line"
on = "shaft"
x_start = {SHAFT_SPAN[0]}
x_end = {SHAFT_SPAN[1]}
force_per_length = [0.0, {Q_SHAFT}, 0.0]
[mesh]
shaft_elements = 4
boom_elements = 3
"""


@pytest.fixture(scope="module")
def model():
    return build_model(loads_design(BOOMED))


def _consistent_uniform(xs: np.ndarray, q: float) -> tuple[np.ndarray, np.ndarray]:
    """(Q_v, Q_γ) per node of a uniform q along y over every element of stations xs."""
    qv, qg = np.zeros(xs.size), np.zeros(xs.size)
    for e, length in enumerate(np.diff(xs)):
        qv[e : e + 2] += q * length / 2
        qg[e] += q * length**2 / 12
        qg[e + 1] -= q * length**2 / 12
    return qv, qg


def test_the_design_line_load_is_in_the_static_load(model):
    Q = external_static_load(model)
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    qv, qg = Q[dm.shaft(nodes, "v")], Q[dm.shaft(nodes, "gamma")]
    a, b = SHAFT_SPAN
    assert qv.sum() == pytest.approx(Q_SHAFT * (b - a), rel=1e-12)
    assert (dm.shaft_x * qv).sum() + qg.sum() == pytest.approx(Q_SHAFT * (b**2 - a**2) / 2, rel=1e-12)


def test_a_boom_line_load_follows_the_boom_elements(model):
    dm = model.dofs
    assert dm.boom_x[-1] == pytest.approx(2.5, abs=1e-12)
    assert not np.isin(np.round(dm.boom_x, 9), np.round(dm.shaft_x, 9)).all()  # the meshes differ
    Q = line_load(model, "boom", 0.0, 2.5, (0.0, Q_BOOM, 0.0))
    nodes = np.arange(dm.n_boom_nodes)
    qv, qg = _consistent_uniform(dm.boom_x, Q_BOOM)
    np.testing.assert_allclose(Q[dm.boom(nodes, "v")], qv, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(Q[dm.boom(nodes, "gamma")], qg, rtol=1e-12, atol=1e-12)
    assert np.abs(Q[dm.shaft(np.arange(dm.n_shaft_nodes), "v")]).max() == 0.0

"""Imbalance bays on stations a hair apart and a bay apart: the rule of docs/limits.md §3.

docs/limits.md, "Mesh stations a hair apart": "Stations closer than 5 % of the nominal element
length h = member length / elements are merged into one node [...] Imbalance bays use the same
merged stations, so a bearing 1e-9 m from another adds no bay."

Model: an aluminium tube from 0 to 2 m, 10 elements (h = 0.2 m, merge distance 0.01 m), on
contact bearings at 0 and 2 m and a pair of inner bearings.

* **A pair 0.06 m apart** (six merge distances, 30 % of h) are two nodes and three bays:
  [0, 1.0], [1.0, 1.06], [1.06, 2].
* **A pair 1e-9 m apart** is one station: two bays [0, 0.8] and [0.8, 2]. The mid-bay imbalance
  e_c m is then shared in halves at 0.4 and 1.4 m, so its first moment about x = 0 is
  Σ (x_i Q_v,i + Q_γ,i) = e_c m (0.4 + 1.4)/2 = 0.9 e_c m (the Hermite shape functions hold a
  rigid rotation v = x φ, γ = φ exactly, docs/model.md: γ = ∂v/∂x; derived here). A third,
  1e-9 m bay would make it e_c m (0.4 + 0.8 + 1.4)/3 = 0.867 e_c m.

The stations are asserted to 1e-12 m (they are typed, not computed); the moment, a sum of a
dozen terms of order 1, to 1e-12 relative.

Written for the mutations h53a-bays-merge-whole-span and h53a-bearing-bays-unmerged of
scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.balance import imbalance_bays, rotating_mass
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import design_from_dict

ECC = 1.0e-4


def _model(stations):
    bearing = {"kind": "contact", "stiffness": {"v": 1e7, "w": 1e7}}
    data = {
        "name": "bays",
        "materials": {"al": {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0}},
        "shaft": {"x_start": 0.0, "x_end": 2.0, "outer_diameter": 0.05, "wall_thickness": 0.002, "material": "al"},
        "bearings": [dict(bearing, name=f"b{i}", x=x) for i, x in enumerate(stations)],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": ECC, "imbalance_placement": "mid_bay"},
        "mesh": {"shaft_elements": 10},
    }
    return build_model(design_from_dict(data))


def test_bearings_six_merge_distances_apart_make_a_bay_of_their_own():
    model = _model((0.0, 1.0, 1.06, 2.0))
    assert np.min(np.abs(model.dofs.shaft_x - 1.06)) < 1e-12  # its own node
    np.testing.assert_allclose(imbalance_bays(model), [(0.0, 1.0), (1.0, 1.06), (1.06, 2.0)], atol=1e-12)


def test_a_bearing_a_hair_from_another_adds_no_bay():
    model = _model((0.0, 0.8, 0.8 + 1e-9, 2.0))
    bays = imbalance_bays(model)
    assert len(bays) == 2
    np.testing.assert_allclose(bays, [(0.0, 0.8), (0.8, 2.0)], atol=1e-12)
    Q = imbalance_loads(model)[:, 0].real
    nodes = np.arange(model.dofs.n_shaft_nodes)
    x = model.dofs.shaft_x
    moment = (x * Q[model.dofs.shaft(nodes, "v")]).sum() + Q[model.dofs.shaft(nodes, "gamma")].sum()
    assert moment == pytest.approx(0.9 * ECC * rotating_mass(model), rel=1e-12)

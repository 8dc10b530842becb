"""The balanced rotor's parts on a shaft cut by a coupling, against hand sums.

docs/model.md ("Forced response and strength"): the imbalance force is ``F = e_c m Ω²`` with
m "the mass of the whole balanced rotor: tubes, disks and coupling hubs", and the
Monte-Carlo's per-bay mass m_b takes "tubes between its bearings, its hubs and disks, the
overhangs with the end bays".

Model: an aluminium tube (ρ = 2700 kg/m³, D_o = 0.05 m, wall 2 mm: ρ π/4 (D_o² − D_i²) =
0.814301 kg/m) from 0 to 2 m on contact bearings at 0, 1.2 and 2 m (bays [0, 1.2] and
[1.2, 2]), cut at x = 1.0 m by a flexible coupling whose hub weighs 1.5 kg. The hub sits in
the first bay, behind that bay's middle (0.6 m). Hand sums:

* m = 2 · 0.814301 + 1.5 kg; the mid-bay imbalance per unit Ω², e_c m, is the sum of the
  load vector's v entries (the Hermite v shape functions sum to 1 at any point), and its w
  entries sum to −i e_c m (``Q_w = −iF``);
* m_1 = 1.2 · 0.814301 + 1.5 kg, m_2 = 0.8 · 0.814301 kg;
* a design that gives ``balance_grade`` G = 6.3 mm/s instead of an eccentricity, run over
  0.95-1.05 of 3000 rpm: e_c = G/Ω_max = 6.3e-3 m/s / (1.05 · 100π rad/s) (docs/model.md's
  rule for a balance grade of ISO 21940-11, at the highest operating speed), and the imbalance
  per unit Ω² sums to e_c m.

Sums of a few products: 1e-12 relative (round-off only).

Written for the mutations h53a-coupling-link-mass-zero, h53a-bay-parts-split-at-midbay and
h53a-imbalance-balance-grade-ignored of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.balance import bay_rotating_masses, imbalance_bays, rotating_mass
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import design_from_dict

RHO, DO, WALL = 2700.0, 0.05, 0.002
PER_METRE = RHO * math.pi / 4 * (DO**2 - (DO - 2 * WALL) ** 2)  # 0.814301 kg/m
HUB = 1.5
ECC = 1.0e-4
SPEED_RPM = 3000.0


def _model(loads=None, speed_range=None):
    bearing = {"kind": "contact", "stiffness": {"v": 1e7, "w": 1e7}}
    coupling = {
        "name": "c",
        "x": 1.0,
        "angular_stiffness": 2300.0,
        "axial_stiffness": 2.0e5,
        "torsional_stiffness": 1.0e5,
        "mass": HUB,
        "diametral_inertia": 1.0e-3,
        "polar_inertia": 2.0e-3,
    }
    data = {
        "name": "hub in a bay",
        "materials": {"al": {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": RHO}},
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": DO,
            "wall_thickness": WALL,
            "material": "al",
            "fixed_start": ["u", "theta"],
        },
        "bearings": [dict(bearing, name=f"b{i}", x=x) for i, x in enumerate((0.0, 1.2, 2.0))],
        "couplings": [coupling],
        "operating": {"speed_rpm": SPEED_RPM, "power": 0.0},
        "loads": loads or {"eccentricity": ECC, "imbalance_placement": "mid_bay"},
        "mesh": {"shaft_elements": 10},
    }
    if speed_range is not None:
        data["operating"]["speed_range"] = list(speed_range)
    return build_model(design_from_dict(data))


def test_the_coupling_hub_is_part_of_the_balanced_rotor():
    model = _model()
    m = 2.0 * PER_METRE + HUB
    assert rotating_mass(model) == pytest.approx(m, rel=1e-12)
    Q = imbalance_loads(model)[:, 0]
    nodes = np.arange(model.dofs.n_shaft_nodes)
    assert Q[model.dofs.shaft(nodes, "v")].sum() == pytest.approx(ECC * m, rel=1e-12)
    assert Q[model.dofs.shaft(nodes, "w")].sum() == pytest.approx(-1j * ECC * m, rel=1e-12)


def test_a_hub_behind_its_bays_middle_stays_in_its_bay():
    model = _model()
    np.testing.assert_allclose(imbalance_bays(model), [(0.0, 1.2), (1.2, 2.0)], rtol=1e-12)
    np.testing.assert_allclose(bay_rotating_masses(model), [1.2 * PER_METRE + HUB, 0.8 * PER_METRE], rtol=1e-12)


def test_a_balance_grade_sets_the_runs_eccentricity_at_the_top_speed():
    model = _model(loads={"balance_grade": 6.3, "imbalance_placement": "mid_bay"}, speed_range=(0.95, 1.05))
    e_c = 6.3e-3 / (1.05 * SPEED_RPM * 2.0 * math.pi / 60.0)
    Q = imbalance_loads(model)[:, 0]
    nodes = np.arange(model.dofs.n_shaft_nodes)
    assert Q[model.dofs.shaft(nodes, "v")].sum().real == pytest.approx(e_c * (2.0 * PER_METRE + HUB), rel=1e-12)

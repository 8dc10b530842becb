"""The balance bays' rotating masses (the rotor's mass split per bay, for the Monte-Carlo's
per-bay unbalance U_b = e_b m_b) against hand sums.

Model: an aluminium tube (ρ = 2700 kg/m³, D_o = 0.05 m, wall 2 mm) from x = 0.5 to 2.5 m on
three contact bearings at 0.5, 1.5 and 2.5 m: two bays of 1 m. The tube's mass per metre is
ρ π/4 (D_o² − D_i²) = 2700 · π/4 · (0.05² − 0.046²) = 0.814301 kg/m, typed here from the
dimensions. The shaft starts at x = 0.5 m on purpose: a per-length mass taken over x_end
instead of x_end − x_start is then 20 % low.

* **A hand-built model** (no ``segments``: the ``[shaft]`` tube over its whole length, as a
  model assembled by hand carries) splits the tube mass m_s by bay length: m_s/2 per bay.
* **A part on an inner bearing's station** is counted once: a 3 kg disk at 1.5 m adds to one
  bay (which one is a tie-break: the bay's unbalance acts at its middle), and the bays sum to
  the rotating mass.
* **ISO 21940-11's U = e m of a massless rotor** is 0 (e = G/Ω = 6.3e-3/100 m), not refused;
  a negative mass is.

Sums of a few products, asserted to 1e-12 (round-off only).

Written for the mutations h51b-balance-handbuilt-length-from-origin and
h51b-balance-massless-unbalance-refused of scripts/mutations.toml.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.balance import bay_rotating_masses, imbalance_bays, permissible_unbalance, rotating_mass
from flexshaft.design import design_from_dict

RHO, DO, WALL = 2700.0, 0.05, 0.002
PER_METRE = RHO * math.pi / 4 * (DO**2 - (DO - 2 * WALL) ** 2)


def _design(disks=()) -> dict:
    bearing = {"kind": "contact", "stiffness": {"v": 1e7, "w": 1e7}}
    return {
        "name": "bays",
        "materials": {"al": {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": RHO}},
        "shaft": {"x_start": 0.5, "x_end": 2.5, "outer_diameter": DO, "wall_thickness": WALL, "material": "al"},
        "bearings": [dict(bearing, name=f"b{i}", x=x) for i, x in enumerate((0.5, 1.5, 2.5))],
        "disks": list(disks),
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "mesh": {"shaft_elements": 4},
    }


def test_per_metre_mass_by_hand():
    assert PER_METRE == pytest.approx(0.814301, rel=1e-6)


def test_a_hand_built_shaft_off_the_origin_splits_its_mass_by_bay_length():
    model = build_model(design_from_dict(_design()))
    assert model.shaft_mass == pytest.approx(2.0 * PER_METRE, rel=1e-12)
    np.testing.assert_allclose(imbalance_bays(model), [(0.5, 1.5), (1.5, 2.5)], rtol=1e-12)
    hand_built = dataclasses.replace(model, segments=())
    np.testing.assert_allclose(bay_rotating_masses(hand_built), [PER_METRE, PER_METRE], rtol=1e-12)
    np.testing.assert_allclose(bay_rotating_masses(model), [PER_METRE, PER_METRE], rtol=1e-12)


def test_a_disk_on_an_inner_bearing_counts_in_one_bay():
    disk = {"name": "d", "x": 1.5, "mass": 3.0, "polar_inertia": 0.01, "diametral_inertia": 0.005}
    model = build_model(design_from_dict(_design([disk])))
    masses = bay_rotating_masses(model)
    assert sorted(masses) == pytest.approx([PER_METRE, PER_METRE + 3.0], rel=1e-12)
    assert masses.sum() == pytest.approx(rotating_mass(model), rel=1e-12)
    assert rotating_mass(model) == pytest.approx(2.0 * PER_METRE + 3.0, rel=1e-12)


def test_a_massless_rotor_may_carry_no_unbalance():
    assert permissible_unbalance(6.3, 100.0, 0.0) == 0.0
    assert permissible_unbalance(6.3, 100.0, 2.0) == pytest.approx(6.3e-3 / 100.0 * 2.0, rel=1e-12)
    with pytest.raises(ValueError, match="mass"):
        permissible_unbalance(6.3, 100.0, -1.0)

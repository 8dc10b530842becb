"""Imbalance by ISO 21940-11 (issue 25, point 5): the balance-grade relation and the rotor's mass.

ISO 21940-11:2016 §5.3: e_per Ω = G (G in mm/s at the maximum service speed Ω) and
U_per = e_per m, m the mass of the rotor being balanced. The reference values below are hand
computations of that formula, written out in the tests; the rotating mass of the embedded
``current`` driveline is summed by hand from its design file.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.balance import (
    bay_rotating_masses,
    design_eccentricity,
    imbalance_bays,
    permissible_eccentricity,
    permissible_unbalance,
    rotating_mass,
)
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import DesignError, embedded_design, tuned_design, with_overrides


def test_balance_grade_relation_by_hand():
    """G 6.3 at 3000 rpm: Ω = 100π = 314.159 rad/s, e_per = 6.3 mm/s / 314.159 1/s = 20.05 µm;
    a 100 kg rotor: U_per = 2.005e-3 kg m (2005 g mm). G 2.5 at 4800 rpm (502.65 rad/s): 4.97 µm."""
    assert permissible_eccentricity(6.3, 100 * math.pi) == pytest.approx(20.0535e-6, rel=1e-5)
    assert permissible_unbalance(6.3, 100 * math.pi, 100.0) == pytest.approx(2.00535e-3, rel=1e-5)
    assert permissible_eccentricity(2.5, 4800 * 2 * math.pi / 60) == pytest.approx(4.9736e-6, rel=1e-4)
    for bad in (0.0, -1.0, float("nan")):
        with pytest.raises(ValueError, match="grade_mm_s"):
            permissible_eccentricity(bad, 100.0)
    with pytest.raises(ValueError, match="speed"):
        permissible_eccentricity(6.3, 0.0)


# The `current` driveline's design file: 6061-T6 tube, D_o 0.1016 m, wall 1.651e-3 m, 8.05 m,
# 2700 kg/m³; four couplings of 1.0 kg at 0.79, 2.21, 5.21, 6.63 m; bearings at 0.74, 2.16,
# 3.71, 5.16, 6.58, 8.05 m (the damper at 3.71 is a bearing station).
RHO, DO, T, LENGTH = 2700.0, 0.1016, 1.651e-3, 8.05
PER_METRE = RHO * math.pi / 4 * (DO**2 - (DO - 2 * T) ** 2)  # 1.39971 kg/m
HUBS = 4 * 1.0


def test_rotating_mass_of_the_current_driveline_by_hand():
    """Tubes ρ π/4 (D_o² − D_i²) L = 2700 · π/4 · (0.1016² − 0.09830²) · 8.05 = 11.268 kg, plus
    four 1.0 kg coupling hubs: 15.268 kg. The tube mass alone is 26 % low (11.268/15.268 = 0.738)."""
    model = build_model(embedded_design("current"))
    assert PER_METRE * LENGTH == pytest.approx(11.2677, rel=1e-4)
    assert model.shaft_mass == pytest.approx(PER_METRE * LENGTH, rel=1e-12)
    assert rotating_mass(model) == pytest.approx(PER_METRE * LENGTH + HUBS, rel=1e-12)
    assert 1 - model.shaft_mass / rotating_mass(model) == pytest.approx(0.262, abs=1e-3)


def test_bay_masses_of_the_current_driveline_by_hand():
    """Bays between bearing stations, the overhang 0-0.74 m with the first: tube lengths 2.16,
    1.55, 1.45, 1.42, 1.47 m; hubs at 0.79 (bay 1), 2.21 (bay 2), 5.21 (bay 4), 6.63 (bay 5)."""
    model = build_model(embedded_design("current"))
    bays = [(0.74, 2.16), (2.16, 3.71), (3.71, 5.16), (5.16, 6.58), (6.58, 8.05)]
    np.testing.assert_allclose(imbalance_bays(model), bays, rtol=1e-12)
    lengths = np.array([2.16, 1.55, 1.45, 1.42, 1.47])
    hubs = np.array([1.0, 1.0, 0.0, 1.0, 1.0])
    np.testing.assert_allclose(bay_rotating_masses(model), PER_METRE * lengths + hubs, rtol=1e-12)
    assert bay_rotating_masses(model).sum() == pytest.approx(rotating_mass(model), rel=1e-12)


def _total_force(model, Q) -> complex:
    """Σ of the load over the shaft's v DOFs: the total rotating force per unit Ω² (the
    consistent nodal loads of a point force sum to it)."""
    nodes = np.arange(model.dofs.n_shaft_nodes)
    return complex(np.sum(Q[model.dofs.shaft(nodes, "v")]))


def test_imbalance_force_uses_the_whole_rotating_mass():
    """current: e_c m Ω² with m = 15.268 kg (not the 11.268 kg of tubes); the tuned one-piece
    shaft (no disks, no hubs) keeps e_c m_s Ω², the same numbers as before."""
    for name in ("current", "tuned"):
        model = build_model(embedded_design(name))
        e = model.design.loads.eccentricity
        force = _total_force(model, imbalance_loads(model)[:, 0])
        assert force == pytest.approx(e * rotating_mass(model), rel=1e-12)
    tuned = build_model(tuned_design())
    assert rotating_mass(tuned) == tuned.shaft_mass


def test_balance_grade_gives_the_eccentricity_at_the_highest_operating_speed():
    """[loads] balance_grade = 6.3 with speed_range [0.95, 1.05] of 4800 rpm: e = 6.3e-3/(1.05 ·
    502.655) = 11.94 µm, and the force e m Ω²; giving both keys is refused."""
    design = with_overrides(tuned_design(), {"loads.eccentricity": 0.0, "loads.balance_grade": 6.3})
    assert design.operating.speed_range == (0.95, 1.05)
    assert design_eccentricity(design) == pytest.approx(6.3e-3 / (1.05 * 4800 * 2 * math.pi / 60), rel=1e-12)
    assert design_eccentricity(design) == pytest.approx(11.94e-6, rel=1e-3)
    model = build_model(design)
    force = _total_force(model, imbalance_loads(model)[:, 0])
    assert force == pytest.approx(design_eccentricity(design) * rotating_mass(model), rel=1e-12)
    with pytest.raises(DesignError, match="loads.balance_grade"):
        with_overrides(tuned_design(), {"loads.balance_grade": 6.3})
    with pytest.raises(DesignError, match="operating.speed_range"):
        with_overrides(tuned_design(), {"operating.speed_range": [1.01, 1.05]})

"""Mode labels of hand-made shapes on the Jeffcott rotor's disk node (mutation hunt h52d).

Reference: the definition of the labels (module docstring of flexshaft.analyses.classify): the
*kinetic* energy ``φᴴMφ`` split over the DOF groups, ``"torsional"`` when the shaft's twist
holds more than half of it, component ``"shaft"`` when the shaft (axial + torsion + lateral)
holds more than 90 %, and the whirl ratio ``r = −2 Σ Im(V̄W)/Σ(|V|² + |W|²)``, +1 for the
forward orbit ``W = −iV``. Derived here for shapes with entries at the disk node only, where the
20 kg disk's point mass is the mass matrix's diagonal (u, v and w) and no mass couples u, v and
θ of one node:

* ``φ = e_u + 2 e_v``: axial share m/(m + 4m) = 0.2, lateral 0.8 (the strain energy splits
  them 0.84/0.16: the tube's axial stiffness 2EA/(L/4) = 1.2e9 N/m against the lateral
  5.8e7 N/m at that node);
* ``φ = e_θ``: all its kinetic energy in the shaft's twist: torsional, component shaft, no
  whirl label.

Degenerate pairs: the grouping of eigenvalues into pairs to resolve must not depend on the
unit of time (the module's docstring: DEGENERATE is relative; a double eigenvalue's split by
Newton's 1e-10 relative convergence is relative too): a pair split by 1e-10 of its value is one
pair at 1 rad/s and at 1e4 rad/s alike, and a root 100 DEGENERATE away is none at either scale.

Tolerance 1e-5 on the shares: the near-massless tube adds 1.3e-5 kg to the node's 20 kg
diagonal (6.7e-7 relative).

CPU: one 4-element model, milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import jeffcott_text

from flexshaft.analyses.classify import DEGENERATE, degenerate_groups, label_modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


@pytest.fixture(scope="module")
def model():
    return build_model(loads_design(jeffcott_text(0.0, 0.0, elements=4)))


def _shape(model, **entries) -> np.ndarray:
    dm = model.dofs
    node = dm.node_at("shaft", 0.5)
    q = np.zeros((dm.size, 1), complex)
    for name, value in entries.items():
        q[dm.shaft(node, name), 0] = value
    return q


def test_energy_shares_are_kinetic(model):
    labels = label_modes(model, _shape(model, u=1.0, v=2.0))
    assert labels.shares.shaft_axial[0] == pytest.approx(0.2, abs=1e-5)
    assert labels.shares.shaft_lateral[0] == pytest.approx(0.8, abs=1e-5)
    assert labels.kind[0] == "lateral"


def test_pure_twist_is_a_torsional_shaft_mode(model):
    labels = label_modes(model, _shape(model, theta=1.0))
    assert labels.shares.shaft_torsion[0] == pytest.approx(1.0, abs=1e-12)
    assert labels.kind[0] == "torsional"
    assert labels.component[0] == "shaft"
    assert labels.whirl[0] == "none"


def test_forward_orbit_is_forward(model):
    labels = label_modes(model, _shape(model, v=1.0, w=-1j))
    assert labels.whirl_ratio[0] == pytest.approx(1.0, abs=1e-12)
    assert labels.whirl[0] == "forward"


@pytest.mark.parametrize("scale", [1.0, 1e4])
def test_degenerate_pairs_are_grouped_at_any_frequency_scale(scale):
    """The grouping is relative (classify's docstring and its DEGENERATE: a pair split by
    Newton's 1e-10 relative convergence is one circular pair): the same relative splits give the
    same groups at 1 and 1e4 rad/s, a split of 1e-10 grouped, one of 100 DEGENERATE not."""
    s = scale * np.array([1j, 1j * (1 + 1e-10), 2j, 2j * (1 + 100 * DEGENERATE)]) - scale * 0.01
    groups = degenerate_groups(s)
    assert [list(g) for g in groups] == [[0, 1]]

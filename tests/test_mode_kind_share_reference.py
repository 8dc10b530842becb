"""A mode is axial when the shaft's axial motion holds more than half of its kinetic energy.

Reference: docs/model.md, "the kind (`"torsional"` or `"axial"` when the shaft's twist or axial
motion holds more than half of the mode's kinetic energy, else `"lateral"`)". Hand-made shapes
on the disk node of the Jeffcott rotor of tests/rotors.py (derived here): the 20 kg disk is a
rigid mass in u and in v alike, so a shape u = √a, v = √(1 − a) at the disk carries the kinetic
energies ½ m a and ½ m (1 − a): axial share a, lateral share 1 − a. a = 0.6 is axial, a = 0.4
lateral (planar: w = 0, whirl ratio 0) and a = 0.7 axial too; all are shaft modes (share 1).

Tolerance: the tube's consistent mass adds 3.5e-6 of the disk's to either diagonal entry, so
the shares are exact to ~1e-6; 1e-4 asserted, far from the 0.5 threshold at 0.1 away.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import L, jeffcott

from flexshaft.analyses.classify import label_modes


def test_axial_share_above_half_makes_an_axial_mode():
    model = jeffcott(0.0, 0.0)
    node = model.dofs.node_at("shaft", L / 2)
    u, v = model.dofs.shaft(node, "u"), model.dofs.shaft(node, "v")
    shares = np.array([0.6, 0.4, 0.7])
    shapes = np.zeros((model.dofs.size, shares.size), complex)
    shapes[u, :] = np.sqrt(shares)
    shapes[v, :] = np.sqrt(1 - shares)
    labels = label_modes(model, shapes)
    assert labels.shares.shaft_axial == pytest.approx(shares, abs=1e-4)
    assert labels.shares.shaft_lateral == pytest.approx(1 - shares, abs=1e-4)
    assert list(labels.kind) == ["axial", "lateral", "axial"]
    assert list(labels.whirl) == ["none", "planar", "none"]
    assert list(labels.component) == ["shaft", "shaft", "shaft"]

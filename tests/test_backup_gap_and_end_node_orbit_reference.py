"""Two things the bearing reactions pass on unchanged: the backup-bearing clearance of the
design, and the orbit of every shaft node (the last one included) in the worst-case scan.

* **Backup gap.** src/flexshaft/design/bearings.py documents ``gap`` of an active bearing as the
  radial clearance of its auxiliary (backup) bearing [m], the limit of the orbit. A bearing's
  reaction carries that design value unchanged (5e-4 m given, so 5e-4 m read back exactly: a
  float copied, no arithmetic); a contact bearing has no gap (None).
* **Worst-case orbit over all nodes.** tests/jeffcott_bearing.py's rotor (4 elements, 5 shaft
  nodes from x = 0 to 1 m). Two load cases: case 0 a forward circle of radius 10 µm at the disk
  node only, case 1 a forward circle of radius 30 µm at the LAST shaft node (x = 1 m; the responses are
  synthetic, so the rotor's pin there does not matter to the scan) only.
  A forward circle v = r, w = −ir has major semi-axis r (√((|a|² + |b|² + |a² + b²|)/2) with
  a² + b² = 0), so the orbit table has one row per shaft node, 30 µm at the last node in case 1,
  and the worst case is 1. Sums of two squares of exact inputs: 1e-12 relative asserted
  (round-off of a square root, ~1e-16).

Written for the mutations h61a-reaction-gap-from-wrong-field and
h61a-react-worst-orbit-drops-last-node of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, CONTACT, model_with

from flexshaft.analyses.reactions import bearing_reactions, worst_case_orbits

GAP = 5e-4  # m


def test_the_reaction_carries_the_backup_gap_of_the_design():
    model = model_with(f"{ACTIVE}\ngap = {GAP}")
    (reaction,) = bearing_reactions(model, np.zeros(model.dofs.size), np.zeros(model.dofs.size), speed=100.0).values()
    assert reaction.gap == GAP
    model = model_with(CONTACT)
    (reaction,) = bearing_reactions(model, np.zeros(model.dofs.size), np.zeros(model.dofs.size), speed=100.0).values()
    assert reaction.gap is None


def test_the_worst_case_scan_includes_the_last_shaft_node():
    model = model_with(CONTACT)
    dm = model.dofs
    last = dm.n_shaft_nodes - 1
    disk = dm.node_at("shaft", 0.5)
    assert last != disk
    q = np.zeros((dm.size, 2, 1), complex)
    q[dm.shaft(disk, "v"), 0, 0], q[dm.shaft(disk, "w"), 0, 0] = 10e-6, -10e-6j
    q[dm.shaft(last, "v"), 1, 0], q[dm.shaft(last, "w"), 1, 0] = 30e-6, -30e-6j
    amp, case = worst_case_orbits(model, q)
    assert amp.shape == (dm.n_shaft_nodes, 2, 1)
    assert amp[last, 1, 0] == pytest.approx(30e-6, rel=1e-12)
    assert amp[disk, 0, 0] == pytest.approx(10e-6, rel=1e-12)
    assert list(case) == [1]

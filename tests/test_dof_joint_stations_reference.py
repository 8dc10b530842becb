"""Which node and element a station at a coupling joint belongs to (:class:`~flexshaft.assembly.dofs.DofMap`).

A two-piece shaft by hand: nodes at x = 0, 0.5, 0.5, 1 m, the coupling joint between nodes 1
and 2 (same station, no shaft element between them), so the shaft elements are (0, 1) and
(2, 3). The numbering's contract (its docstrings): a station at or before the joint reads the
forward flange's node (1), one after it the aft flange's (2); a station at the joint lies in the
element after it, (2, 3), at its start (ξ = 0). Its DOFs: node n's field k is 6 n + k, the
boom's follow, then the extra DOFs, so with no boom the "tail_rotor" extra DOF is 6 × 4 = 24.

Exact integer answers. CPU: milliseconds.
"""

from __future__ import annotations

import numpy as np

from flexshaft.assembly.dofs import DofMap


def _two_pieces() -> DofMap:
    return DofMap(
        shaft_x=np.array([0.0, 0.5, 0.5, 1.0]), boom_x=np.zeros(0), shaft_joints=np.array([1]), extra=("tail_rotor",)
    )


def test_a_station_at_the_joint_reads_the_forward_flange_and_after_it_the_aft():
    dofs = _two_pieces()
    assert dofs.node_at("shaft", 0.5) == 1
    assert dofs.node_at("shaft", 0.5 - 1e-6) == 1
    assert dofs.node_at("shaft", 0.5 + 1e-6) == 2
    assert dofs.node_at("shaft", 0.0) == 0 and dofs.node_at("shaft", 1.0) == 3


def test_a_station_at_the_joint_starts_the_element_aft_of_it():
    dofs = _two_pieces()
    np.testing.assert_array_equal(dofs.shaft_element_nodes, [[0, 1], [2, 3]])
    assert dofs.locate("shaft", 0.5) == (1, 0.0, 0.5)
    assert dofs.locate("shaft", 0.25) == (0, 0.5, 0.5)
    assert dofs.extra_dof("tail_rotor") == 24 and dofs.size == 25
    assert dofs.shaft(2, "v") == 13

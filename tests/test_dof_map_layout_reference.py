"""The global DOF numbering against its documented layout, written out by hand.

:mod:`flexshaft.assembly.dofs`: shaft nodes first, 6 DOFs each in (u, v, w, θ, β, γ) order,
so shaft node j's field f is 6 j + f; boom nodes after them, 5 each in (v, w, θ, β, γ) order
(6 n_s + 5 k + f). Node indices follow Python's convention: −n ≤ j < n, −1 the last node; any
other node is refused (an index n must not wrap to node 0, which would put a load or a
bearing on the wrong end of the shaft without a word).

A rigid coupling ties the aft node's DOF to the forward one's; a tied DOF is one unknown, so
:meth:`~flexshaft.assembly.dofs.DofMap.unique` lists it once (a sum over nodes counts it once).

Exact integers: asserted with ==.

Written for the mutations h51b-dofs-index-range-wraps-n and h51b-dofs-unique-counts-tied-twice
of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly.dofs import DofMap


def _map(**kw) -> DofMap:
    return DofMap(shaft_x=np.array([0.0, 1.0, 1.0, 2.0]), boom_x=np.array([0.0, 2.0]), **kw)


def test_indices_follow_the_layout():
    dm = _map()
    assert dm.shaft(2, "theta") == 6 * 2 + 3
    assert dm.shaft(-1, "gamma") == 6 * 3 + 5
    assert dm.shaft(-4, "u") == 0
    assert dm.boom(1, "beta") == 6 * 4 + 5 * 1 + 3
    assert dm.boom(-1, "v") == 6 * 4 + 5


@pytest.mark.parametrize(("component", "node"), [("shaft", 4), ("shaft", -5), ("boom", 2), ("boom", -3)])
def test_a_node_outside_the_member_is_refused(component, node):
    with pytest.raises(IndexError, match="out of range"):
        _map().index(component, node, "v")


def test_a_node_array_reaching_past_the_end_is_refused():
    with pytest.raises(IndexError, match="out of range"):
        _map().shaft(np.arange(5), "w")


def test_a_tied_dof_counts_once():
    """Nodes 1 and 2 share x = 1 m (a coupling); its rigid v and w tie node 2's to node 1's."""
    tied = np.array([[6 * 2 + 1, 6 * 1 + 1], [6 * 2 + 2, 6 * 1 + 2]])
    dm = _map(shaft_joints=np.array([1]), tied=tied)
    v = dm.shaft(np.arange(4), "v")
    assert list(v) == [1, 7, 7, 19]
    assert list(dm.unique(v)) == [1, 7, 19]
    both = np.concatenate([v, dm.shaft(np.arange(4), "w")])
    assert list(dm.unique(both)) == [1, 2, 7, 8, 19, 20]
    assert dm.free.size == dm.size - 2

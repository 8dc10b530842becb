"""Mesh stations of a member not starting at x = 0 and of point loads on shaft and boom, by hand.

The rule of :mod:`flexshaft.assembly.mesh` (its docstring): each member gets a node at every
station, and each segment between stations ``max(1, round(n · L_seg / L))`` equal elements,
``L`` the member's length (end station minus start station, not its end coordinate). A point
load with ``on = "shaft"`` is a station of the shaft mesh, one with ``on = "boom"`` a station of
the boom's (docs/design-reference.md, ``[[loads.point]]``). The node lists below are written out
from that rule; tolerance 1e-12 m (a few roundings of numbers of order 1 m).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from flexshaft.assembly.mesh import design_mesh, segment_mesh

TOL = 1e-12


def test_a_member_starting_at_two_metres_shares_its_elements_by_its_own_length():
    """[2, 3, 5] m with 6 elements: L = 3 m, so round(6 · 1/3) = 2 and round(6 · 2/3) = 4
    elements of 0.5 m (taking L = 5 m would give 1 and 2)."""
    nodes = segment_mesh([2.0, 3.0, 5.0], 6)
    np.testing.assert_allclose(nodes, np.linspace(2.0, 5.0, 7), atol=TOL)


def test_point_loads_are_stations_of_their_own_member():
    """A 1 m shaft of 4 elements with a load at 0.6 m: round(2.4) = 2 elements before it and
    round(1.6) = 2 after. A 2 m boom of 4 elements with a load at 0.3 m: round(0.6) = 1 element
    before it, round(3.4) = 3 after."""
    design = SimpleNamespace(
        shaft=SimpleNamespace(x_start=0.0, x_end=1.0),
        bearings=[SimpleNamespace(x=0.0, boom_x=0.0, kind="contact", sensor_offset=0.0)],
        disks=[],
        loads=SimpleNamespace(point=[SimpleNamespace(x=0.6, on="shaft"), SimpleNamespace(x=0.3, on="boom")]),
        tailboom=SimpleNamespace(length=2.0),
        mesh=SimpleNamespace(shaft_elements=4, boom_elements=4),
    )
    shaft_x, boom_x = design_mesh(design)
    np.testing.assert_allclose(shaft_x, [0.0, 0.3, 0.6, 0.8, 1.0], atol=TOL)
    np.testing.assert_allclose(boom_x, np.concatenate([[0.0], np.linspace(0.3, 2.0, 4)]), atol=TOL)

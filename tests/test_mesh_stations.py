"""Node stations of :mod:`flexshaft.assembly.mesh`, counted by hand.

A member meshed with n requested elements gets a node at every station (ends, bearings, disks,
point loads), ``max(1, round(n · L_seg / L))`` equal elements per segment between them, and
stations closer than 5 % of the nominal element ``L / n`` merged (the module's docstring). The
expected nodes below are written out from that rule; stations and spacings are exact binary
fractions or compared with a tolerance of 1e-12 m (a few roundings of numbers of order 1 m).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.assembly.mesh import design_mesh, merge_stations, merge_tolerance, segment_mesh

TOL = 1e-12


def test_segments_get_their_share_of_the_elements():
    """[0, 1, 2.5] m with 10 elements: 4 of 0.25 m on the first metre, 6 of 0.25 m after."""
    nodes = segment_mesh([0.0, 1.0, 2.5], 10)
    np.testing.assert_allclose(nodes, np.linspace(0.0, 2.5, 11), atol=TOL)


def test_counts_are_rounded_not_truncated():
    """[0, 0.37, 1] m with 10 elements: round(3.7) = 4 and round(6.3) = 6, ten in all."""
    nodes = segment_mesh([0.0, 0.37, 1.0], 10)
    assert nodes.size == 11
    np.testing.assert_allclose(nodes[:5], np.linspace(0.0, 0.37, 5), atol=TOL)
    np.testing.assert_allclose(nodes[4:], np.linspace(0.37, 1.0, 7), atol=TOL)


def test_a_short_segment_keeps_one_element_and_its_end():
    """[0, 0.1, 10] m with 10 elements: round(0.1) = 0 → 1 element on the first segment, 10 after."""
    nodes = segment_mesh([0.0, 0.1, 10.0], 10)
    np.testing.assert_allclose(nodes, np.concatenate([[0.0], np.linspace(0.1, 10.0, 11)]), atol=TOL)


def test_merge_keeps_separate_stations_and_drops_close_ones():
    """Tolerance 0.05 m: 0.3 and 0.7 are kept (the last interior station too); 0.02 (beside the
    start) and 0.97 (beside the end) merge into the ends."""
    np.testing.assert_array_equal(merge_stations([0.0, 0.3, 0.7, 1.0], 0.05), [0.0, 0.3, 0.7, 1.0])
    np.testing.assert_array_equal(merge_stations([0.0, 0.02, 0.3, 0.7, 0.97, 1.0], 0.05), [0.0, 0.3, 0.7, 1.0])


def test_merge_tolerance_is_five_percent_of_one_element():
    """A 2 m member with 10 elements: h = 0.2 m, tolerance 0.05 h = 0.01 m."""
    assert merge_tolerance(2.0, 10) == pytest.approx(0.01, rel=TOL)


def test_a_disk_off_the_grid_is_a_node():
    """A disk at 0.33 m on a 1 m shaft of 4 elements (grid 0.25 m) gets its own node, at its
    station: round(4 · 0.33) = 1 element before it, round(4 · 0.67) = 3 after."""
    design = SimpleNamespace(
        shaft=SimpleNamespace(x_start=0.0, x_end=1.0),
        bearings=[SimpleNamespace(x=0.0, kind="contact", sensor_offset=0.0)],
        disks=[SimpleNamespace(x=0.33)],
        loads=SimpleNamespace(point=[]),
        tailboom=None,
        mesh=SimpleNamespace(shaft_elements=4),
    )
    shaft_x, boom_x = design_mesh(design)
    expected = np.concatenate([[0.0], np.linspace(0.33, 1.0, 4)])
    np.testing.assert_allclose(shaft_x, expected, atol=TOL)
    assert boom_x.size == 0

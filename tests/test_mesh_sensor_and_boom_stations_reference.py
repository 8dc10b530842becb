"""Mesh stations of an offset sensor and of the bearings' tailboom attachments, counted by hand.

The rule of :mod:`flexshaft.assembly.mesh` (its docstring): every bearing, sensor, disk and
point load is a station of its member's mesh, and each segment between stations gets
``max(1, round(n · L_seg / L))`` equal elements. A magnetic bearing's sensor sits at
``x + sensor_offset`` on the shaft and at ``boom_x + sensor_offset`` on the boom
(docs/design-reference.md, ``sensor_offset``, which may be negative: a sensor forward of its
magnet); a bearing's boom station is ``boom_x``. The node lists below are written out from
that rule and the module's merge rule (stations closer than ``0.05 h``, h = member length /
requested elements, are one node, the first kept; ``STATION_MERGE_FRACTION``); tolerance
1e-12 m (a few roundings of numbers of order 1 m).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from flexshaft.assembly.mesh import design_mesh

TOL = 1e-12


def _design(sensor_offset: float) -> SimpleNamespace:
    """A 2 m shaft of 4 elements (h = 0.5 m, merge tolerance 0.025 m) on a contact bearing at
    x = 0 (boom station 0.2 m) and a magnet at x = 1 m (boom station 0.9 m) with its sensor
    ``sensor_offset`` away; a 2 m boom of 4 elements."""
    contact = SimpleNamespace(x=0.0, boom_x=0.2, kind="contact", sensor_offset=0.0)
    magnet = SimpleNamespace(
        x=1.0,
        boom_x=0.9,
        kind="active",
        sensor_offset=sensor_offset,
        sensor_x=1.0 + sensor_offset,
        sensor_boom_x=0.9 + sensor_offset,
    )
    return SimpleNamespace(
        shaft=SimpleNamespace(x_start=0.0, x_end=2.0),
        bearings=[contact, magnet],
        disks=[],
        loads=SimpleNamespace(point=[]),
        tailboom=SimpleNamespace(length=2.0),
        mesh=SimpleNamespace(shaft_elements=4, boom_elements=4),
    )


def test_a_sensor_forward_of_its_magnet_is_a_station_of_shaft_and_boom():
    """Sensor offset −0.3 m: shaft stations 0, 0.7, 1, 2 m → round(1.4) = 1, round(0.6) = 1 and
    round(2) = 2 elements; boom stations 0, 0.2, 0.6 (sensor), 0.9 (magnet), 2 m →
    max(1, round(0.4)) = 1, round(0.8) = 1, round(0.6) = 1, round(2.2) = 2 elements."""
    shaft_x, boom_x = design_mesh(_design(-0.3))
    np.testing.assert_allclose(shaft_x, [0.0, 0.7, 1.0, 1.5, 2.0], atol=TOL)
    np.testing.assert_allclose(boom_x, [0.0, 0.2, 0.6, 0.9, 1.45, 2.0], atol=TOL)


def test_a_sensor_within_the_merge_tolerance_of_its_magnet_is_no_node():
    """Sensor offset +0.02 m, inside the merge tolerance 0.05 · 2 m / 4 = 0.025 m: the sensor's
    stations 1.02 m (shaft) and 0.92 m (boom) merge into the magnet's 1 m and 0.9 m (the first
    station kept), leaving shaft stations 0, 1, 2 m (2 + 2 elements) and boom 0, 0.2, 0.9, 2 m
    (1, round(1.4) = 1, round(2.2) = 2 elements). Unmerged, the shaft would get 0, 1, 1.02, 2 m
    with round(2) = 2, max(1, round(0.04)) = 1, round(1.96) = 2 elements (a 2 cm element)."""
    shaft_x, boom_x = design_mesh(_design(0.02))
    np.testing.assert_allclose(shaft_x, [0.0, 0.5, 1.0, 1.5, 2.0], atol=TOL)
    np.testing.assert_allclose(boom_x, [0.0, 0.2, 0.9, 1.45, 2.0], atol=TOL)


def test_a_sensor_just_beyond_the_merge_tolerance_is_a_node():
    """Sensor offset +0.03 m, beyond 0.025 m: shaft stations 0, 1, 1.03, 2 m → round(2) = 2,
    max(1, round(0.06)) = 1 and round(1.94) = 2 elements; boom stations 0, 0.2, 0.9, 0.93, 2 m →
    1, round(1.4) = 1, max(1, round(0.06)) = 1 and round(2.14) = 2 elements."""
    shaft_x, boom_x = design_mesh(_design(0.03))
    np.testing.assert_allclose(shaft_x, [0.0, 0.5, 1.0, 1.03, 1.515, 2.0], atol=TOL)
    np.testing.assert_allclose(boom_x, [0.0, 0.2, 0.9, 0.93, 1.465, 2.0], atol=TOL)

"""Node stations of the shaft and tailboom meshes.

Every bearing, sensor, disk and point load is a mesh station, and each member gets about the
requested number of near-equal elements between its stations. Stations closer together than
:data:`STATION_MERGE_FRACTION` of the nominal element length ``h = member length / requested
elements`` are merged into one node (the first one kept; the member ends are always kept).

Why merge. An element much shorter than its neighbours makes the stiffness matrix
ill-conditioned (its bending stiffness grows as 1/L³ while its mass shrinks as L): on the
baseline, a magnetic bearing 1e-9 m from the forward hanger gave f1 = 12,640 Hz instead of
4.93 Hz, and an element of 0.5 % of h made the harmonic solver report a singular system.
Merging loses nothing: bearings, sensors and point loads are attached through the element
shape functions at their exact stations (:func:`~flexshaft.elements.relative_rows`), so a
bearing beside a node acts where it is; only a disk, lumped at the nearest node, moves, by at
most ``0.05 h`` (1 cm on the baseline's 0.2 m elements).
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "STATION_MERGE_FRACTION",
    "merge_stations",
    "segment_mesh",
    "design_stations",
    "design_mesh",
    "merge_tolerance",
]

#: Stations closer than this fraction of the nominal element length are one node.
STATION_MERGE_FRACTION = 0.05


def merge_tolerance(span: float, n_elements: int) -> float:
    """Distance [m] below which stations of a member of length ``span`` [m] meshed with about
    ``n_elements`` elements are merged: :data:`STATION_MERGE_FRACTION` × span / n_elements."""
    return STATION_MERGE_FRACTION * span / max(int(n_elements), 1)


def merge_stations(points, tolerance: float) -> np.ndarray:
    """Sorted distinct stations [m], dropping any closer than ``tolerance`` [m] to the previous
    kept one or to the last station (both ends are always kept)."""
    pts = np.unique(np.asarray(points, dtype=float))
    if pts.size < 2:
        return pts
    first, last = pts[0], pts[-1]
    kept = [first]
    for x in pts[1:-1]:
        if x - kept[-1] >= tolerance and last - x >= tolerance:
            kept.append(x)
    kept.append(last)
    return np.array(kept)


def segment_mesh(breakpoints, n_elements: int, merge_fraction: float = STATION_MERGE_FRACTION) -> np.ndarray:
    """Nodes covering ``breakpoints`` [m] with about ``n_elements`` near-equal elements.

    Breakpoints closer than ``merge_fraction × span / n_elements`` are merged first
    (:func:`merge_stations`); every remaining breakpoint is a node, and each segment gets
    ``max(1, round(n · L_seg / L))`` elements.
    """
    raw = np.asarray(breakpoints, dtype=float)
    if raw.size < 2 or not np.all(np.isfinite(raw)):
        raise ValueError(f"breakpoints must be at least two finite stations [m] (got {breakpoints!r})")
    total = float(raw.max() - raw.min())
    if not total > 0:
        raise ValueError(f"breakpoints must span a positive length (got {breakpoints!r})")
    pts = merge_stations(raw, merge_fraction * total / max(int(n_elements), 1))
    nodes = [pts[:1]]
    for a, b in zip(pts[:-1], pts[1:]):
        n = max(1, int(round(n_elements * (b - a) / total)))
        nodes.append(np.linspace(a, b, n + 1)[1:])
    return np.concatenate(nodes)


def design_stations(design) -> tuple[list[float], list[float]]:
    """The shaft and boom stations [m] every mesh of ``design`` has a node at (before merging)."""
    shaft, boom = design.shaft, design.tailboom
    shaft_pts = [shaft.x_start, shaft.x_end]
    shaft_pts += [b.x for b in design.bearings] + [d.x for d in design.disks]
    sensors = [b for b in design.bearings if b.kind == "active" and b.sensor_offset != 0.0]
    shaft_pts += [b.sensor_x for b in sensors]
    shaft_pts += [p.x for p in design.loads.point if p.on == "shaft"]
    if boom is None:
        return shaft_pts, []
    boom_pts = [p.x for p in design.loads.point if p.on == "boom"]
    boom_pts += [0.0, boom.length] + [b.boom_x for b in design.bearings] + [b.sensor_boom_x for b in sensors]
    return shaft_pts, boom_pts


def design_mesh(design) -> tuple[np.ndarray, np.ndarray]:
    """Shaft and tailboom node stations [m] of ``design`` (the boom's empty without a tailboom)."""
    shaft_pts, boom_pts = design_stations(design)
    shaft_x = segment_mesh(shaft_pts, design.mesh.shaft_elements)
    if design.tailboom is None:
        return shaft_x, np.zeros(0)
    return shaft_x, segment_mesh(boom_pts, design.mesh.boom_elements)

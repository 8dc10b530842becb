"""Placing text labels without overprinting, before the figure is drawn.

Text extents are estimated from the font size and the number of characters (no renderer is
needed, so placing labels costs no extra draw); the estimate is generous (0.62 em per
character) so that estimated boxes that do not overlap leave real text apart.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

__all__ = ["spread", "place_point_labels"]


def spread(
    positions: Sequence[float], min_gap: float, low: float | None = None, high: float | None = None
) -> np.ndarray:
    """Move 1-D label positions apart by at least ``min_gap``, as little as possible.

    Positions keep their order; the result stays within ``[low, high]`` when it fits. Used for
    the mode numbers at the end of the Campbell curves (positions in pixels).
    """
    y = np.asarray(positions, dtype=float)
    order = np.argsort(y, kind="stable")
    s = y[order].copy()
    for _ in range(50):  # pool-adjacent-violators style relaxation, converges in a few sweeps
        moved = False
        for i in range(1, s.size):
            overlap = min_gap - (s[i] - s[i - 1])
            if overlap > 1e-9:
                s[i - 1] -= overlap / 2
                s[i] += overlap / 2
                moved = True
        if low is not None and s.size and s[0] < low:
            s += low - s[0]
            moved = True
        if high is not None and s.size and s[-1] > high and (low is None or s[-1] - s[0] <= high - low):
            s -= s[-1] - high
            moved = True
        if not moved:
            break
    out = np.empty_like(s)
    out[order] = s
    return out


_OFFSETS = [
    (6, -16),
    (6, 6),
    (-6, -16),
    (-6, 6),
    (8, -30),
    (8, 20),
    (-8, -30),
    (-8, 20),
    (14, -44),
    (14, 34),
    (-14, -44),
    (-14, 34),
]


def place_point_labels(
    ax,
    x: Sequence[float] | np.ndarray,
    y: Sequence[float] | np.ndarray,
    texts: Sequence[str],
    *,
    fontsize: float = 8.0,
    avoid: Sequence[tuple[float, float]] = (),
    **text_kw,
) -> list:
    """Annotate data points ``(x, y)`` with ``texts`` so that no two labels overlap.

    Each label tries offsets around its point (right-below first) and takes the first whose
    estimated box overlaps no label placed before it, no point (of ``x, y`` and ``avoid``,
    data coordinates) and stays inside the axes; when none is free it takes the least crowded,
    with a leader line. The axes limits must be final. Returns the annotations.
    """
    fig = ax.figure
    to_px = ax.transData.transform
    scale = fig.dpi / 72.0
    pts = (
        np.asarray(to_px(np.column_stack([np.asarray(x, float), np.asarray(y, float)]))) if len(x) else np.zeros((0, 2))
    )
    marks = np.vstack([pts, to_px(np.asarray(avoid, float))]) if len(avoid) else pts
    box = ax.bbox
    placed: list[tuple[float, float, float, float]] = []
    out = []
    radius = 6.0 * scale
    for (px, py), text in sorted(zip(map(tuple, pts), texts), key=lambda item: item[0][0]):
        width = 0.62 * fontsize * scale * max(len(line) for line in text.split("\n"))
        height = 1.25 * fontsize * scale * (text.count("\n") + 1)
        best, best_cost = None, np.inf
        for dx, dy in _OFFSETS:
            x0 = px + dx * scale - (width if dx < 0 else 0.0)
            y0 = py + dy * scale
            rect = (x0, y0, x0 + width, y0 + height)
            cost = sum(_overlap(rect, r) for r in placed)
            cost += sum(_overlap(rect, (mx - radius, my - radius, mx + radius, my + radius)) for mx, my in marks)
            outside = (
                max(0.0, box.x0 - rect[0])
                + max(0.0, rect[2] - box.x1)
                + max(0.0, box.y0 - rect[1])
                + max(0.0, rect[3] - box.y1)
            )
            cost += outside * height * 4
            if cost < best_cost - 1e-9:
                best, best_cost = (dx, dy, rect), cost
            if cost == 0.0:
                break
        assert best is not None  # the first offset always improves on an infinite cost
        dx, dy, rect = best
        placed.append(rect)
        far = abs(dy) > 20 or abs(dx) > 10
        xy = ax.transData.inverted().transform((px, py))
        out.append(
            ax.annotate(
                text,
                xy,
                xytext=(dx, dy),
                textcoords="offset points",
                fontsize=fontsize,
                ha="right" if dx < 0 else "left",
                va="bottom",
                arrowprops={"arrowstyle": "-", "color": "0.45", "lw": 0.7} if far else None,
                **text_kw,
            )
        )
    return out


def _overlap(a, b) -> float:
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    return w * h if w > 0 and h > 0 else 0.0

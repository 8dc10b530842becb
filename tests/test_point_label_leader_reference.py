"""A point label set away from its point is joined to it by a leader line.

`place_point_labels` (plot/labels.py) names the Campbell diagram's critical speeds; its
docstring: each label "tries offsets around its point" and, pushed away, comes "with a leader
line". The reference is what a reader needs to tell which marker a label names: a label whose
drawn text box lies next to its point (closer than one line of its own text) names that point
by proximity; one set farther than two lines of text from it, with other labels in between,
does not, and must carry a line back to its point.

Five labels of one point (coincident critical speeds, the case the helper is for) on open
axes: four fit next to the point (their drawn boxes 16.7 px from it, 1.25 times the 8-pt
text's height of 13.3 px at 120 dpi); the fifth finds those places taken and is set a second
ring away (36.7 px, 2.75 heights). Distances are measured on the drawn text boxes (Agg
renderer; the leader excluded), so the verdict does not rest on the helper's own size
estimate; the threshold of two heights lies far from both (10 px either side).

Not covered (reported by hunter h107b): a sixth label goes to the offset (8, 20) pt, its box
35.9 px (2.7 heights) above the point, and gets no leader: the code's test ``abs(dy) > 20``
is strict, while the label as far below has the offset (8, -30) (va="bottom": a box below
the point is offset by its height as well).
"""

from __future__ import annotations

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.text import Text

from flexshaft.plot.labels import place_point_labels


def test_a_label_set_away_from_its_point_has_a_leader_line():
    fig = Figure(figsize=(5.0, 4.0), dpi=120)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ax.set_xlim(0.0, 10.0)
    ax.set_ylim(0.0, 10.0)
    point = (5.0, 5.0)
    labels = place_point_labels(ax, [point[0]] * 5, [point[1]] * 5, [f"{n} rpm" for n in range(2400, 2405)])
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    px, py = ax.transData.transform(point)
    far = []
    for label in labels:
        box = Text.get_window_extent(label, renderer)  # the text alone, without its leader
        gap = np.hypot(max(0.0, box.x0 - px, px - box.x1), max(0.0, box.y0 - py, py - box.y1))
        if gap > 2.0 * box.height:
            far.append(label.get_text())
            assert label.arrow_patch is not None, f"{label.get_text()!r} is {gap:.0f} px from its point, no leader"
            np.testing.assert_allclose(label.xy, point, rtol=1e-12)  # the leader ends on the point
    assert len(far) == 1  # the arrangement above: four next to the point, one a ring away

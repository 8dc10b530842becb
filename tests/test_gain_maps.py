"""The maps over the actuator gains: the K_d = 0 row on a strip of its own (not on the log
axis), marked points both visible, and the stability margin's sign unmistakable.

Checked on the figure's content (the colours each cell is drawn in, the hatches, markers, tick
labels and the extents of the labels after a draw), never on pixels.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from matplotlib.collections import QuadMesh  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

from flexshaft.plot.gain_maps import gain_label, gain_map_figure, stability_margin_figure  # noqa: E402

KP = np.array([3e5, 2e6, 1e7, 5e7])
KD = np.array([0.0, 300.0, 1170.0, 3000.0])


def _drawn(fig):
    fig.canvas.draw()
    return fig


def _cell_colours(ax) -> np.ndarray:
    (mesh,) = [c for c in ax.collections if isinstance(c, QuadMesh)]
    return mesh.get_facecolors()


def test_gain_labels_are_short_and_exact():
    assert [gain_label(v) for v in (0.0, 300.0, 1172.3, 3000.0, 15.64, 4.2813e5, 5e7)] == [
        "0",
        "300",
        "1170",
        "3000",
        "15.6",
        "4.28e5",
        "5e7",
    ]


def test_stability_map_sign_is_unmistakable():
    """ζ = −2e-4 beside ζ up to +9e-3 (the report's map): the unstable cells are drawn from the
    red half of a scale centred at 0 and hatched; a marginally stable cell (+2e-4) stays light;
    the colour bar carries negative and positive ticks."""
    zeta = np.array(
        [
            [2e-4, 9e-3, 9e-3, 4e-3],  # K_p 3e5: stable, the K_d = 0 cell marginal
            [-1e-4, 1e-4, 5e-4, 2e-3],
            [-2e-4, -2e-4, -2e-4, -1.5e-4],
            [-2e-4, -2e-4, -2e-4, -2e-4],
        ]
    )
    onset = np.where(zeta < 0, 3125.0, np.nan)
    fig = _drawn(stability_margin_figure(KP, KD, zeta, onset, best=(4.28e5, 562.0)))
    main, strip, bar = fig.axes
    # every cell: red for ζ < 0 (red channel above blue by far), light or blue for ζ ≥ 0
    rows = np.flatnonzero(KD > 0)
    colours = _cell_colours(main).reshape(rows.size, KP.size, 4)
    for i in range(KP.size):
        for k, j in enumerate(rows):
            r, g, b, _ = colours[k, i]
            if zeta[i, j] < 0:
                assert r > 0.4 and r > 3 * max(g, b), (i, j, colours[k, i])
            else:
                assert b >= r, (i, j, colours[k, i])
    strip_colours = _cell_colours(strip)
    assert strip_colours[0][0] > 0.85 and strip_colours[0][2] > 0.85  # ζ = +2e-4: near white
    assert strip_colours[1][0] > 3 * max(strip_colours[1][1:3])  # ζ = −1e-4: red, not white
    # unstable cells hatched, one patch each
    hatched = [p for a in (main, strip) for p in a.patches if isinstance(p, Rectangle) and p.get_hatch()]
    assert len(hatched) == int((zeta < 0).sum())
    # the colour bar shows the sign
    ticks = [t for t in bar.get_yticks() if bar.get_ylim()[0] <= t <= bar.get_ylim()[1]]
    assert min(ticks) < 0 < max(ticks)
    # the K_d label is inside the figure (not cut off by the tick labels)
    label = main.yaxis.label.get_window_extent()
    assert main.get_ylabel() == "derivative gain K_d [N s/m]" and label.x0 >= 0
    # cell text: white on the dark (navy, dark red) cells, black on light ones
    texts = {(round(t.get_position()[0], 6), round(t.get_position()[1], 6)): t for t in main.texts}
    dark = texts[(round(np.log10(3e5), 6), round(np.log10(1170.0), 6))]  # ζ = 9e-3, navy
    light = texts[(round(np.log10(2e6), 6), round(np.log10(300.0), 6))]  # ζ = 1e-4, near white
    assert matplotlib.colors.to_rgb(dark.get_color()) == (1.0, 1.0, 1.0)
    assert matplotlib.colors.to_rgb(light.get_color()) == (0.0, 0.0, 0.0)
    assert dark.get_text() == "stable" and texts[(round(np.log10(1e7), 6), round(np.log10(300.0), 6))].get_text() == (
        "onset\n3125 rpm"
    )


def test_gain_map_keeps_kd_zero_off_the_log_axis_and_both_markers_visible():
    rng = np.random.default_rng(3)
    kp = np.geomspace(1e5, 1e8, 12)
    kd = np.concatenate([[0.0], np.geomspace(10.0, 3e4, 11)])
    values = rng.uniform(1e-4, 1e-1, (kp.size, kd.size))
    best = design = (4.28e5, 562.0)  # the design at the best cell: the ring must not hide
    fig = _drawn(gain_map_figure(kp, kd, values, "orbit [mm]", scale=1e3, best=best, other={"design": design}))
    main, strip, bar = fig.axes
    # main axis: the positive gains on their decades only; the zero has its own strip
    assert main.get_ylim()[0] > np.log10(kd[1]) - 0.5  # log10 of K_d, half a cell below 10 N s/m
    labels = [t.get_text() for t in main.get_yticklabels()]
    assert labels == ["10¹", "10²", "10³", "10⁴"]
    assert [t.get_text() for t in strip.get_yticklabels()] == ["0"]
    np.testing.assert_allclose(_cell_colours(strip).shape[0], kp.size)  # one row of cells
    # the star and the ring at the same gains: the ring is larger and drawn above the star
    (star,) = [ln for ln in main.get_lines() if ln.get_marker() == "*"]
    (ring,) = [ln for ln in main.get_lines() if ln.get_marker() == "o"]
    np.testing.assert_allclose(np.column_stack(star.get_data()), np.column_stack(ring.get_data()))
    np.testing.assert_allclose(star.get_xdata()[0], np.log10(4.28e5))  # at its gains, not snapped
    assert ring.get_markersize() > star.get_markersize() + 4 and ring.get_zorder() > star.get_zorder()
    assert ring.get_markerfacecolor() == "none"
    # the legend sits under the x label, away from the map
    legend = main.get_legend().get_window_extent()
    assert legend.y1 < strip.xaxis.label.get_window_extent().y0
    assert bar.get_ylabel() == "orbit [mm]"


def test_gain_map_point_at_kd_zero_goes_on_the_strip():
    fig = _drawn(gain_map_figure(KP, KD, np.ones((4, 4)), "x [-]", best=(1e7, 0.0), log_values=False))
    main, strip, _ = fig.axes
    assert [ln.get_marker() for ln in strip.get_lines()] == ["*"] and not main.get_lines()


def test_gain_map_refuses_gains_a_log_axis_cannot_draw():
    with pytest.raises(ValueError, match="kp: proportional gains must be finite and > 0"):
        gain_map_figure([0.0, 1e6], KD, np.ones((2, 4)), "x")
    with pytest.raises(ValueError, match="kd: derivative gains must be finite and >= 0"):
        gain_map_figure(KP, [-1.0, 0.0, 1.0, 2.0], np.ones((4, 4)), "x")

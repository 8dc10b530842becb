"""The ISO 14839-3 zone bands shaded on the sensitivity panel (plot/loops.py).

Reference, quoted from docs/magnetic-bearings.md (hand-written): the peak sensitivity is
graded "A below 3 (9.5 dB), B below 4 (12 dB), C below 5 (14 dB), D above". With the limits
3, 4, 5 the panel shades one band per zone: A from |S| = 0 to 3, B 3 to 4, C 4 to 5 and D from
5 to the top of the axis, each limit the edge of two bands.

Agg, no file; CPU milliseconds.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from flexshaft.plot.loops import loop_sensitivity_figure  # noqa: E402


def _y_range(patch) -> tuple[float, float]:
    """The |S| interval a horizontal span covers (Rectangle or Polygon alike)."""
    verts = patch.get_patch_transform().transform(patch.get_path().vertices)
    return float(verts[:, 1].min()), float(verts[:, 1].max())


def test_one_band_per_zone_from_zero_to_the_top():
    """Four bands (A, B, C, D) with edges 0, 3, 4, 5 and the axis top.

    The edges are the limits passed in and 0.0, copied into the patch geometry: 1e-12 is only
    for the affine transform's round-off.
    """
    f = np.array([1.0, 10.0, 100.0])
    fig = loop_sensitivity_figure({"a": (f, np.array([0.5, 2.0, 1.0]))}, zone_limits=(3.0, 4.0, 5.0))
    top = fig.axes[0]
    bands = sorted(_y_range(p) for p in top.patches)
    assert len(bands) == 4  # zones A, B, C, D
    edges = [bands[0][0]] + [hi for _, hi in bands]
    np.testing.assert_allclose(edges[:4], [0.0, 3.0, 4.0, 5.0], atol=1e-12)
    np.testing.assert_allclose(edges[4], top.get_ylim()[1], rtol=1e-12)
    for (_, hi), (lo, _) in zip(bands[:-1], bands[1:]):
        assert abs(hi - lo) <= 1e-12 * hi  # contiguous: every limit is the edge of two zones

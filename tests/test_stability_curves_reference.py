"""Stability figures: unstable side of Re(s), the requirement in view, the onset map's axes,
and each whirl branch in its own line style.

Hand-built curves (no model); references derived here:

* an eigenvalue s = σ + iω grows when σ = Re(s) > 0: the red band of the real-part figure
  covers only Re(s) ≥ 0;
* the required log decrement is always in view, also when every curve lies under it;
* the onset map has K_d [N s/m] on the abscissa and the onset speed [rpm] on the ordinate; a
  gain stable over the analysed range is drawn at the range's end, max_rpm [rpm];
* a mode labelled forward at the first two speeds and backward at the last two is drawn as a
  solid segment over speeds 1-3 (joined to the first backward point) and a dashed one over
  speeds 3-4 (solid forward, dashed backward: the project's WHIRL_LINESTYLE convention).

Compared exactly or to rel 1e-12 (no arithmetic beyond copying). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.stability import log_decrement_figure, real_parts_figure, stability_map_figure  # noqa: E402

REL = 1e-12
SPEEDS = np.array([0.0, 2000.0, 4000.0, 6000.0])  # [rpm]


def _span_y(patch) -> np.ndarray:
    """The data y of a horizontal span's corners (a Rectangle or a Polygon, by matplotlib version)."""
    return patch.get_patch_transform().transform(patch.get_path().vertices)[:, 1]


def test_real_parts_band_covers_the_growing_side_only():
    re = np.column_stack([[-3.0, -1.0, 0.5, 2.0], [-4.0, -4.0, -4.0, -4.0]])  # [1/s]
    ax = real_parts_figure(SPEEDS, {"shaft": re}).axes[0]
    (band,) = ax.patches
    y = _span_y(band)
    assert y.min() == 0.0 and y.max() >= 2.0


def test_requirement_in_view_when_every_curve_is_below_it():
    delta = np.full((4, 1), 0.05)
    ax = log_decrement_figure(SPEEDS, {"shaft": delta}, required=0.1).axes[0]
    (req,) = [ln for ln in ax.get_lines() if str(ln.get_label()).startswith("required")]
    low, high = ax.get_ylim()
    assert low < req.get_ydata()[0] == 0.1 < high


def test_whirl_branches_keep_their_line_styles():
    delta = np.array([[0.3], [0.25], [0.2], [0.15]])
    whirl = np.array([["forward"], ["forward"], ["backward"], ["backward"]])
    ax = log_decrement_figure(SPEEDS, {"shaft": delta}, whirl={"shaft": whirl}).axes[0]
    curves = [ln for ln in ax.get_lines() if len(ln.get_xdata()) > 1 and ln.get_transform() == ax.transData]
    drawn = [(list(ln.get_xdata()), ln.get_linestyle()) for ln in curves]
    assert drawn == [([0.0, 2000.0, 4000.0], "-"), ([4000.0, 6000.0], "--")]


def test_onset_map_kd_across_onset_up_and_stable_gains_at_the_range_end():
    kd = np.array([0.0, 100.0, 200.0])  # [N s/m]
    onset = np.array([3000.0, 5000.0, np.nan])  # [rpm]
    ax = stability_map_figure(kd, {"shaft": onset}, max_rpm=7200.0).axes[0]
    line, open_markers = [ln for ln in ax.get_lines() if ln.get_marker() == "o"]
    np.testing.assert_allclose(line.get_xdata(), kd, rtol=REL)
    np.testing.assert_allclose(line.get_ydata(), onset, rtol=REL)
    np.testing.assert_allclose(open_markers.get_xdata(), [200.0], rtol=REL)
    np.testing.assert_allclose(open_markers.get_ydata(), [7200.0], rtol=REL)

"""A stability panel without an onset states the speed range it is stable over.

Hand-built curves (no model). Reference, API contract (log_decrement_figure's docstring,
flexshaft.plot.stability; no docs page states it), the meaning of a missing onset: "None:
stable over the range". The range is the analysed speeds, so the panel must say it is stable
up to the HIGHEST analysed speed. The grid here starts at 1500 rpm (not at rest) and ends at
7500 rpm, so a figure reading the wrong end of the sweep would print 1500. A panel with an onset
says nothing about being stable.

The speed is printed with ``:.0f`` from a copied grid value: the text comparison is exact.
Agg, nothing written.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.stability import log_decrement_figure, real_parts_figure  # noqa: E402

SPEEDS = np.linspace(1500.0, 7500.0, 5)  # [rpm]


def _texts(ax) -> list[str]:
    return [t.get_text() for t in ax.texts]


def test_log_decrement_panel_without_onset_is_stable_to_the_top_speed():
    """Two designs: one stable (onset None, δ > 0 throughout), one with an onset at 4500 rpm."""
    stable = np.column_stack([np.linspace(0.3, 0.1, 5), np.full(5, 0.2)])
    unstable = np.column_stack([np.linspace(0.2, -0.2, 5), np.full(5, 0.2)])
    fig = log_decrement_figure(SPEEDS, {"stable": stable, "unstable": unstable}, {"stable": None, "unstable": 4500.0})
    a_stable, a_unstable = fig.axes[:2]
    assert "stable up to 7500 rpm" in _texts(a_stable)
    assert not any(t.startswith("stable up to") for t in _texts(a_unstable))


def test_real_parts_panel_without_onset_is_stable_to_the_top_speed():
    """Re(s) < 0 at every speed, onset None: the same statement on the real-part figure."""
    re = np.column_stack([np.linspace(-2.0, -0.5, 5)])
    ax = real_parts_figure(SPEEDS, {"shaft": re}, onset_rpm={"shaft": None}).axes[0]
    assert "stable up to 7500 rpm" in _texts(ax)

"""Figures of the whirl-stability analysis (matplotlib imported lazily)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike

from flexshaft.plot.style import mark_operating, new_figure, styled, vector

__all__ = ["real_parts_figure", "stability_map_figure"]


@styled
def real_parts_figure(speeds_rpm: ArrayLike, real_parts: Mapping[str, ArrayLike], operating_rpm: float | None = None):
    """Real parts of the tracked eigenvalues against speed, one panel per shaft (thesis
    figures 4.2-4.4). ``real_parts[name]`` is (n_speeds, n_modes) [1/s]; Re > 0 is unstable."""
    speeds = vector("speeds_rpm", speeds_rpm)
    n = len(real_parts)
    fig, axes = new_figure(n, 1, (8.0, 2.8 * n), sharex=True)
    for ax, (name, re) in zip(axes[:, 0], real_parts.items()):
        re = np.asarray(re, dtype=float)
        if re.shape[0] != speeds.size:
            raise ValueError(f"real_parts[{name!r}]: expected {speeds.size} rows, got {re.shape[0]}")
        ax.plot(speeds, re, lw=1.2)
        ax.axhline(0.0, color="k", lw=1.0)
        ax.fill_between(speeds, 0, max(np.nanmax(re), 0.0) * 1.05 + 1e-12, color="tab:red", alpha=0.08, lw=0)
        mark_operating(ax, operating_rpm, label=False)
        ax.set_ylabel("Re(s) [1/s]")
        ax.set_title(name, fontsize=10)
    axes[-1, 0].set_xlabel("spin speed Ω [rpm]")
    axes[-1, 0].set_xlim(speeds.min(), speeds.max())
    return fig


@styled
def stability_map_figure(kd: ArrayLike, onset_rpm: Mapping[str, ArrayLike], operating_rpm: float | None = None,
                         max_rpm: float | None = None):
    """Onset speed of whirl instability against the actuators' derivative gain K_d [N s/m];
    NaN onsets (stable over the analysed range) are drawn at ``max_rpm`` with open markers."""
    kd = vector("kd", kd)
    fig, axes = new_figure(1, 1, (8.0, 4.2))
    ax = axes[0, 0]
    for name, values in onset_rpm.items():
        v = np.asarray(values, dtype=float)
        line, = ax.plot(kd, v, "o-", label=name)
        if max_rpm is not None and np.any(np.isnan(v)):
            ax.plot(kd[np.isnan(v)], np.full(np.isnan(v).sum(), max_rpm), "o", mfc="none", color=line.get_color())
    if operating_rpm is not None:
        ax.axhline(operating_rpm, color="tab:red", ls="-.", label=f"operating speed {operating_rpm:.0f} rpm")
    if max_rpm is not None:
        ax.axhline(max_rpm, color="0.5", ls=":", label=f"stable to ≥ {max_rpm:.0f} rpm (open markers)")
    ax.set_xlabel("derivative gain K_d [N s/m]")
    ax.set_ylabel("onset speed [rpm]")
    ax.set_title("Whirl-instability onset")
    ax.legend(loc="best")
    return fig

"""Reference: the mode-shape figure draws each plane's translations in that plane's curve.

Reference (derived here): the Jeffcott rotor of tests/jeffcott_bearing.py (disk mass m at
midspan of a near-massless pinned tube of stiffness k) with an undamped contact bearing at the
disk, stiffness k_v in v and k_w in w. At rest there is no gyroscopic coupling and the two
planes decouple into single masses, ω_v = √((k + k_v)/m) < ω_w = √((k + k_w)/m) for
k_v < k_w: mode 1 moves in v only, mode 2 in w only (planar). The figure
(:func:`~flexshaft.plot.shapes.mode_shapes_figure`, its docstring) scales each shape to a unit
largest orbit radius and draws the shaft's v curve ("shaft v (vertical)") and w curve ("shaft w
(lateral)"): in mode 1's panel the v curve reaches ±1 at the disk and the w curve is zero; in
mode 2's the other way round. The mode frequencies in the panel titles confirm which mode is
which (ω_v and ω_w are 8 % apart). With a spin frequency f_s given (``near_rpm`` = 60 f_s), each
title states the mode's multiple of it, "f/f_s× spin" (the Modes.plot_shapes label): at
f_s = f_v/2, 2.00 for mode 1 and f_w/f_s = 2√((k + k_w)/(k + k_v)) for mode 2.

Tolerances: the other plane's curve is round-off of the eigen-solution (~1e-12 of the unit
shape); 1e-6 asserted, far below the 1 the swapped curve would show. The moving plane's peak
is 1 by the normalisation up to round-off (1e-9). The tube's mass (3.5e-6 of the disk's)
shifts the frequencies by ~1e-6 relative; the titles print 2 decimals of Hz (±0.006 Hz) and of
the ratio (±0.006).
"""

from __future__ import annotations

import re

import matplotlib
import numpy as np
import pytest
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK, L

from flexshaft.analyses.modal import modes

matplotlib.use("Agg")

KV, KW = 4.0e5, 8.0e5  # N/m: the v plane is the softer one, so mode 1 is the v mode


OMEGA_V, OMEGA_W = np.sqrt((K_SHAFT + KV) / M_DISK), np.sqrt((K_SHAFT + KW) / M_DISK)


def _panels(**kwargs):
    import matplotlib.pyplot as plt

    m = modes(model_with(f'kind = "contact"\nstiffness = {{ v = {KV}, w = {KW} }}\ndamping = {{}}'), 0.0, n_modes=2)
    fig = m.plot_shapes(modes=[0, 1], **kwargs)
    try:
        out = []
        for ax in fig.axes:
            if not (ax.get_visible() and ax.get_title()):
                continue
            lines = {ln.get_label(): (np.asarray(ln.get_xdata()), np.asarray(ln.get_ydata())) for ln in ax.get_lines()}
            out.append((ax.get_title(), lines))
        return out
    finally:
        plt.close(fig)


def test_each_planar_mode_is_drawn_in_its_own_plane():
    """Mode 1 (ω_v) in the v curve only, mode 2 (ω_w) in the w curve only, each peaking at ±1
    at the disk (midspan)."""
    panels = _panels()
    assert len(panels) == 2
    omegas = {"v": OMEGA_V, "w": OMEGA_W}
    curves = {"v": "shaft v (vertical)", "w": "shaft w (lateral)"}
    for (title, lines), plane, other in zip(panels, ("v", "w"), ("w", "v"), strict=True):
        f = float(re.search(r": ([0-9.e+]+) Hz", title).group(1))
        assert f == pytest.approx(omegas[plane] / (2 * np.pi), abs=0.006)
        x, moving = lines[curves[plane]]
        _, still = lines[curves[other]]
        assert np.max(np.abs(moving)) == pytest.approx(1.0, abs=1e-9)
        assert x[np.argmax(np.abs(moving))] == pytest.approx(L / 2, abs=1e-12)
        assert np.max(np.abs(still)) < 1e-6


def test_the_panel_title_states_the_mode_as_a_multiple_of_the_spin():
    """At f_s = f_v/2: "2.00× spin" for the v mode, f_w/f_s = 2 ω_w/ω_v for the w mode (not the
    inverse, f_s/f)."""
    f_s = OMEGA_V / (2 * np.pi) / 2
    titles = [title for title, _ in _panels(near_rpm=60.0 * f_s)]
    ratios = [float(re.search(r"\(([0-9.]+)× spin", t).group(1)) for t in titles]
    assert ratios == pytest.approx([2.0, 2.0 * OMEGA_W / OMEGA_V], abs=0.006)

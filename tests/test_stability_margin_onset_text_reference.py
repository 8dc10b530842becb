"""The whirl-stability margin map writes each cell's onset speed inside that cell.

Hand-built grids (no analysis); reference derived here: the map's cell (K_p,i, K_d,j) is
centred at (log10 K_p,i, log10 K_d,j) for K_d,j > 0, and at y = 1/2 on the strip under the
map for K_d,j = 0 (plot/gain_maps.py's module docstring, code: log axes, cells centred on the grid values,
the zero-K_d row a strip of its own). So the text drawn at that centre must be the onset given
for (i, j): "onset\\n<n> rpm" with n the onset rounded to whole rpm, "stable" where it is NaN.

Every onset is distinct, so a text read at another cell's gains shows another number.
Positions compared to 1e-9 (log10 of exact powers of ten). Agg, no file.
"""

from __future__ import annotations

import matplotlib
import numpy as np

matplotlib.use("Agg")

from flexshaft.plot.gain_maps import stability_margin_figure  # noqa: E402

TOL = 1e-9


def _texts(ax) -> dict[tuple[float, float], str]:
    return {(round(t.get_position()[0], 6), round(t.get_position()[1], 6)): t.get_text() for t in ax.texts}


def test_onset_written_at_its_own_cell_on_the_map_and_the_strip():
    kp = np.array([1e5, 1e6])  # [N/m]
    kd = np.array([0.0, 1e1, 1e2, 1e3])  # [N s/m]: a zero row and three positive rows
    zeta = np.array([[-0.02, 0.01, 0.03, 0.05], [-0.01, -0.005, 0.02, 0.04]])
    onset = np.array([[1000.0, 2000.0, 3000.0, np.nan], [1500.0, 2500.0, 3500.0, 4500.0]])  # [rpm]
    fig = stability_margin_figure(kp, kd, zeta, onset)
    main, strip = fig.axes[:2]
    on_main, on_strip = _texts(main), _texts(strip)
    assert len(on_main) == kp.size * 3 and len(on_strip) == kp.size
    for i in range(kp.size):
        for j in range(kd.size):
            want = "stable" if np.isnan(onset[i, j]) else f"onset\n{onset[i, j]:.0f} rpm"
            if kd[j] > 0:
                key = (round(np.log10(kp[i]), 6), round(np.log10(kd[j]), 6))
                assert on_main[key] == want, (i, j)
            else:
                key = (round(np.log10(kp[i]), 6), 0.5)
                assert on_strip[key] == want, (i, j)
    # the centres are the grid's own log10 positions (not snapped elsewhere)
    ys = sorted({p[1] for p in on_main})
    np.testing.assert_allclose(ys, np.log10(kd[1:]), atol=TOL)

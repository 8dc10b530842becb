"""Every panel of the multi-panel study figures draws its own case in the axis units.

The gain, wall and response-surface figures are drawn from small hand-built arrays and read back
from their matplotlib artists. References, derived by hand in each test:

* 1 m = 1000 mm: a wall given in metres sits at 1000 times that on every panel's
  "wall thickness [mm]" axis, an actuator displacement given in metres at 1000 times that on
  the "max actuator displacement [mm]" axis;
* each response-surface panel is one case: its title quotes that case's own largest orbit
  (the panels only share the amplitude axis), so two cases with peaks 0.5 mm and 2 mm are
  titled 0.5 mm and 2 mm.

The inputs are short decimals; the figure multiplies each by 1000 once, so the read-back values
are compared at 1e-12 relative, far above one rounding of the mm conversion
(1.1e-16) and far below the factor-1000 slips these tests are for. Agg, no file.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from flexshaft.plot.studies import gain_figure, response_surface_figure, wall_thickness_figure  # noqa: E402


def test_gain_study_displacement_panel_is_in_mm():
    """Displacements 1e-3, 5e-4, 2.5e-4 m are drawn at 1, 0.5, 0.25 on the mm panel; the safety
    factors 2, 3, 4 [-] unchanged on the top panel; both against the gains as given [N/m]."""
    kp = np.array([1e4, 1e5, 1e6])
    displacement = np.array([1e-3, 5e-4, 2.5e-4])
    fig = gain_figure(kp, [2.0, 3.0, 4.0], displacement)
    top, bottom = fig.axes[0], fig.axes[1]
    assert "[mm]" in bottom.get_ylabel()
    (line,) = [ln for ln in bottom.get_lines() if len(ln.get_ydata()) == 3]
    np.testing.assert_allclose(line.get_xdata(), kp, rtol=1e-12)
    np.testing.assert_allclose(line.get_ydata(), [1.0, 0.5, 0.25], rtol=1e-12)
    (sf_line,) = [ln for ln in top.get_lines() if len(ln.get_ydata()) == 3]
    np.testing.assert_allclose(sf_line.get_ydata(), [2.0, 3.0, 4.0], rtol=1e-12)
    plt.close(fig)


def test_wall_study_frequency_panel_sits_at_the_walls_in_mm():
    """Walls 1, 1.5, 2 mm given in metres: the first-mode frequencies (Hz, unchanged) are drawn
    at x = 1, 1.5, 2 on the frequency panel, the same x as the safety factors above them."""
    wall = np.array([1e-3, 1.5e-3, 2e-3])
    frequency = np.array([40.0, 50.0, 60.0])
    fig = wall_thickness_figure(wall, [2.0, 2.5, 3.0], [2.5, 3.0, 3.5], frequency_hz=frequency)
    axes = fig.axes
    assert len(axes) == 2
    (f_line,) = axes[1].get_lines()
    np.testing.assert_allclose(f_line.get_xdata(), [1.0, 1.5, 2.0], rtol=1e-12)
    np.testing.assert_allclose(f_line.get_ydata(), frequency, rtol=1e-12)
    for line in axes[0].get_lines():
        np.testing.assert_allclose(line.get_xdata(), [1.0, 1.5, 2.0], rtol=1e-12)
    plt.close(fig)


def test_response_surface_panels_quote_their_own_peak():
    """Two cases over 2 stations x 3 speeds with largest orbits 5e-4 m and 2e-3 m: the panels are
    titled 'peak 0.5 mm' and 'peak 2 mm' (each its own case), though they share the 2 mm axis."""
    x = np.array([0.0, 1.0])
    speeds = np.array([1000.0, 2000.0, 3000.0])
    small = np.array([[1e-4, 5e-4, 2e-4], [1e-4, 2.5e-4, 1e-4]])
    large = 4.0 * small
    fig = response_surface_figure(x, speeds, {"design": small, "tuned": large})
    titles = [ax.get_title() for ax in fig.axes]
    assert titles == ["design\npeak 0.5 mm", "tuned\npeak 2 mm"]
    for ax in fig.axes:
        assert ax.get_zlim()[1] == pytest.approx(2.0, rel=1e-12)  # shared top: the larger case's 2 mm
    plt.close(fig)

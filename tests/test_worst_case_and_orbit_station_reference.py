"""Which load case and which station the imbalance read-outs pick, on hand-made responses of
the 4-element Jeffcott rotor with a contact bearing (tests/jeffcott_bearing.py; shaft nodes at
x = 0, 0.25, 0.5, 0.75, 1 m).

The responses are written by hand (no solve): at a node, v = a and w = −i a is a forward
circular orbit of radius |a| (derived here: (Re(a e^{iφ}), Re(−i a e^{iφ})) = |a| (cos ψ, sin ψ)
with ψ = φ + arg a), so every orbit's size is known exactly.

* docs/requirements.md: the spin-up deflection is "the orbit envelope (largest over shaft
  stations and imbalance cases)", so ``worst_case_orbits`` takes at each speed the case whose
  largest orbit over the nodes is largest (its docstring: "the worst load case at each speed
  (the largest orbit over the nodes)"). Case 1 has a 1 μm orbit at x = 0.25 m and nothing elsewhere; case 2 has 0.6 μm
  at every node. The largest orbit is case 1's (1 > 0.6), although case 2's orbits summed over
  the 5 nodes (3 μm) exceed case 1's (1 μm): the worst case is case 1 (index 0).
* ``HarmonicResponse.plot_orbit`` documents its default station as "the node of the largest
  orbit" at "the analysed point nearest speed_rpm". At the first speed the largest orbit is
  2 μm at x = 0.25 m (0.5 μm at x = 0.75 m); at the second 3 μm at x = 0.75 m (1 μm at
  x = 0.25 m). Plotted at the first speed, the orbit is x = 0.25 m's, radius 2 μm; the node of
  the largest orbit over the whole sweep (x = 0.75 m) would draw 0.5 μm. The axes are in μm
  for an orbit below 0.1 mm (flexshaft.plot.response.orbit_figure).

Tolerances: the orbit amplitudes are |a| to a few ulps (1e-12 relative); the plotted circle
samples the phase every 3°, so its largest |v| is within 1 − cos 1.5° = 3.4e-4 of the radius
(1e-3 asserted).
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from jeffcott_bearing import CONTACT, model_with

from flexshaft.analyses.reactions import worst_case_orbits
from flexshaft.analyses.response import HarmonicResponse

UM = 1e-6  # m


def _circle(q, dofs, x, a, *index):
    """Write a forward circular orbit of complex radius ``a`` at shaft station ``x``."""
    node = dofs.node_at("shaft", x)
    q[(dofs.shaft(node, "v"),) + index] = a
    q[(dofs.shaft(node, "w"),) + index] = -1j * a


def test_worst_case_is_the_largest_single_orbit_not_the_largest_sum():
    model = model_with(CONTACT)
    dm = model.dofs
    q = np.zeros((dm.size, 2, 1), complex)  # (ndof, cases, speeds)
    _circle(q, dm, 0.25, 1.0 * UM, 0, 0)
    for x in dm.shaft_x:
        _circle(q, dm, float(x), 0.6 * UM * np.exp(0.7j), 1, 0)
    amp, case = worst_case_orbits(model, q)
    node = dm.node_at("shaft", 0.25)
    assert amp[node, 0, 0] == pytest.approx(1.0 * UM, rel=1e-12)
    assert amp[:, 1, 0] == pytest.approx(np.full(dm.n_shaft_nodes, 0.6 * UM), rel=1e-12)
    assert list(case) == [0]


def test_orbit_plot_default_station_is_the_largest_orbit_at_the_plotted_speed():
    import matplotlib.pyplot as plt

    model = model_with(CONTACT)
    dm = model.dofs
    speeds = np.array([100.0, 200.0])  # rad/s
    q = np.zeros((dm.size, speeds.size), complex)  # one load case
    _circle(q, dm, 0.25, 2.0 * UM, 0)
    _circle(q, dm, 0.75, 0.5 * UM, 0)
    _circle(q, dm, 0.25, 1.0 * UM, 1)
    _circle(q, dm, 0.75, 3.0 * UM, 1)
    response = HarmonicResponse(q, speeds, speeds, dm, "imbalance", model.internal_damping)
    fig = response.plot_orbit(speed_rpm=speeds[0] * 60.0 / (2 * np.pi))
    try:
        line = fig.axes[0].get_lines()[0]
        assert "μm" in fig.axes[0].get_ylabel()
        ov = np.asarray(line.get_ydata())  # v [μm]
        assert np.abs(ov).max() == pytest.approx(2.0, rel=1e-3)
    finally:
        plt.close(fig)

"""Reference: which modes Modes.plot_shapes draws by default, and the log decrement its panel
titles print.

API contract (the Modes.plot_shapes docstring; README's figure list says the same: "mode shapes
of the modes nearest the spin frequency"): without ``modes`` it draws "the ``n`` modes nearest the
spin frequency" (``near_rpm`` instead of the result's speed), the lowest ``n`` only at rest; each
panel's title ends in "δ = …", the logarithmic decrement δ = 2πζ/√(1 − ζ²).

The rotor is the Jeffcott rotor of tests/rotors.py (heavy midspan disk m on a near-massless
pinned tube, k = 48 E I / L³) with an external dashpot c at the disk, no material loss. Its
lowest pair (v and w planes) is the disk's bounce at ω_n = √(k/m) with ζ = c/(2√(k m))
(derived here: m ẍ + c ẋ + k x = 0); every other mode lies more than 10 ω_n above it (the disk
bouncing axially on the tube's front half, held axially at x = 0 only: √(2EA/(L m)) =
ω_n √(A L²/(24 I)) ≈ 12.8 ω_n, derived here; then the modes of the 3.5e-6-times lighter tube). So with
the spin frequency far above every mode, the n = 2 nearest are the two highest of the four
computed (modes 3 and 4 in the 1-based numbering of the titles), never the disk's
pair (modes 1 and 2); at rest the default is the lowest two.

Tolerances: the titles print 3 significant figures (δ to ±5e-3 relative, the frequency to 2
decimals); the tube's mass shifts ω_n and ζ by ~1e-6 relative.
"""

from __future__ import annotations

import re

import matplotlib
import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.modal import modes

matplotlib.use("Agg")

ZETA = 0.1


@pytest.fixture(scope="module")
def result():
    c = ZETA * 2 * np.sqrt(K_SHAFT * M_DISK)
    return modes(jeffcott(0.0, c), 0.0, n_modes=4)


def _titles(fig):
    import matplotlib.pyplot as plt

    try:
        return [ax.get_title() for ax in fig.axes if ax.get_visible() and ax.get_title()]
    finally:
        plt.close(fig)


def _numbers(titles):
    return sorted(int(re.match(r"mode (\d+):", t).group(1)) for t in titles)


def test_the_default_panels_at_a_spin_above_every_mode_are_the_highest_modes(result):
    """Spin frequency 1e6 × f_n: the two nearest are the two highest computed (3 and 4), both
    more than 10 f_n; not the disk's pair at f_n."""
    f_n = WN / (2 * np.pi)
    titles = _titles(result.plot_shapes(n=2, near_rpm=60.0 * 1e6 * f_n))
    assert _numbers(titles) == [3, 4]
    for t in titles:
        f = float(re.search(r": ([0-9.e+]+) Hz", t).group(1))
        assert f > 10 * f_n


def test_the_default_panels_at_rest_are_the_disk_pair(result):
    """At rest (no spin frequency) the default is the lowest two: the disk's pair at the
    damped ω_n √(1 − ζ²)."""
    titles = _titles(result.plot_shapes(n=2))
    assert _numbers(titles) == [1, 2]
    f_d = WN * np.sqrt(1 - ZETA**2) / (2 * np.pi)
    for t in titles:
        assert float(re.search(r": ([0-9.e+]+) Hz", t).group(1)) == pytest.approx(f_d, abs=0.006)


def test_the_panel_title_prints_the_log_decrement(result):
    """The disk mode's title: δ = 2πζ/√(1 − ζ²) = 0.6315 for ζ = 0.1 (not ζ itself)."""
    titles = _titles(result.plot_shapes(modes=[0]))
    delta = float(re.search(r"δ = ([-0-9.e+]+)", titles[0]).group(1))
    assert delta == pytest.approx(2 * np.pi * ZETA / np.sqrt(1 - ZETA**2), rel=5e-3)

"""The report's orbit and onset cells (report/run_sections.py; the orbit cell is
plot/response.py's ``orbit_amplitude_mm``, the orbit figure's too) against independent references.

Orbit: a harmonic whirl v(t) = Re(V e^{iωt}), w(t) = Re(W e^{iωt}) traces an ellipse whose
major semi-axis is the largest radius √(v² + w²) over a period; the reference samples the period
at 20 000 points (the radius near its maximum is flat to second order: the sampling error is
below (π/20000)²/2 ~ 1e-8 relative, tolerance 1e-6). Onset: ω [rad/s] as ω·60/(2π) rpm.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.plot.response import orbit_amplitude_mm
from flexshaft.report.run_sections import _onset_text


def _sampled_major_mm(v: complex, w: complex) -> float:
    t = np.linspace(0.0, 2.0 * np.pi, 20_000, endpoint=False)
    phase = np.exp(1j * t)
    return float(np.max(np.hypot((v * phase).real, (w * phase).real)) * 1000.0)


@pytest.mark.parametrize(
    ("v", "w"),
    [
        (1.0e-4, 0.0),  # straight line: major semi-axis |V|
        (1.0e-4, -1.0e-4j),  # circle: radius |V|
        (2.0e-4 * np.exp(0.3j), 0.7e-4 * np.exp(1.9j)),  # a tilted ellipse
    ],
)
def test_orbit_major_semi_axis_in_mm(v, w):
    assert orbit_amplitude_mm(v, w) == pytest.approx(_sampled_major_mm(v, w), rel=1e-6)


def test_onset_and_stable_top_in_rpm():
    """3125 rpm and a whirl map analysed to 7200 rpm, given in rad/s."""
    rpm = 2.0 * math.pi / 60.0
    assert _onset_text(3125.0 * rpm, 7200.0 * rpm) == "3125"
    assert _onset_text(None, 7200.0 * rpm) == "stable to 7200"
    assert _onset_text(float("inf"), 7200.0 * rpm) == "stable to 7200"

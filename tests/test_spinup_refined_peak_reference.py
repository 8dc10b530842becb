"""The spin-up study's refined peak (:func:`flexshaft.thesis.spinup_maps._refined_peak`, thesis
figure 3.17: the peak deflection before and after tuning the gains) against the closed form of
a single resonance.

The receptance is replaced by a damped oscillator's amplification (natural frequency ω0, damping
ratio ζ): A(Ω) = 1/√((1 − r²)² + (2ζr)²), r = Ω/ω0, whose maximum 1/(2ζ√(1 − ζ²)) lies at
Ω* = ω0√(1 − 2ζ²) (any vibrations text, e.g. Rao, Mechanical Vibrations, §3.4). The coarse
grid's largest sample lies below Ω*, its upper neighbour above it: the refinement searches
between both neighbours of the coarse peak, so it finds the maximum above the sample, and keeps
it since it is higher.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.thesis import spinup_maps

OMEGA0, ZETA = 100.0, 0.01  # [rad/s], [-]


def _amplification(speeds):
    r = np.asarray(speeds, dtype=float) / OMEGA0
    return 1.0 / np.sqrt((1 - r**2) ** 2 + (2 * ZETA * r) ** 2)


def test_the_refined_peak_is_the_resonance_maximum(monkeypatch):
    """Coarse speeds 1.5 rad/s apart (99.5 and 101 rad/s beside Ω* = 99.99 rad/s, the sampled
    peak 10 % low); 81 fine speeds between the neighbours, 0.0375 rad/s apart: the peak to
    2e-4 (a Lorentzian of half-width ζω0 = 1 rad/s sampled within 0.019 rad/s of its top:
    (0.019/1)²/2 = 1.8e-4) and its speed to half a fine step."""
    monkeypatch.setattr(spinup_maps, "_receptance", lambda model, speeds: np.frombuffer(speeds))
    monkeypatch.setattr(spinup_maps, "spinup_curves", lambda rec, law: SimpleNamespace(shaft_peak=_amplification(rec)))
    speeds = np.arange(92.0, 108.0, 1.5)
    curve = _amplification(speeds)
    i = int(np.argmax(curve))
    peak_speed = OMEGA0 * np.sqrt(1 - 2 * ZETA**2)
    peak = 1 / (2 * ZETA * np.sqrt(1 - ZETA**2))
    assert speeds[i] < peak_speed < speeds[i + 1] and curve[i] < 0.95 * peak
    value, speed = spinup_maps._refined_peak(None, None, speeds, curve)
    assert value == pytest.approx(peak, rel=2e-4)
    assert speed == pytest.approx(peak_speed, abs=0.5 * 3.0 / 80 + 1e-9)

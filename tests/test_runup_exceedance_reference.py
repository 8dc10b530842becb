"""The run-up Monte-Carlo's exceedance estimate and its standard error, worked by hand.

N independent samples of which k exceed a limit estimate P = k/N, a binomial proportion
with standard error sqrt(P(1 - P)/N): k is binomial with variance N P (1 - P), so k/N has
variance P (1 - P)/N (the same formula as :class:`flexshaft.montecarlo.confidence.Exceedance`,
which the steady study reports).
Four samples 1, 2, 3, 4 mm against a 2.5 mm limit: k = 2, P = 1/2, standard error
sqrt(1/4/4) = 1/4; one of the four above 3.5 mm: P = 1/4, sqrt(3/16/4) = sqrt(3)/8.

The :class:`~flexshaft.montecarlo.runup.RunupSamples` is built directly from those samples
(no transient is run): microseconds. Tolerance: a few floating-point operations on exact
binary fractions, ``REL`` = 1e-14.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.montecarlo.runup import RunupSamples

REL = 1e-14


def _samples(peaks: np.ndarray) -> RunupSamples:
    zeros = np.zeros_like(peaks)
    return RunupSamples(
        shaft_peak=peaks,
        shaft_peak_speed=zeros,
        actuator_orbit_max=zeros,
        actuator_force_max=zeros,
        draws=None,  # type: ignore[arg-type]  # not read by exceedance
        actuator_excursion_max=zeros,
        actuator_load_max=zeros,
    )


def test_exceedance_is_k_over_n_with_the_binomial_standard_error() -> None:
    run = _samples(np.array([1.0, 2.0, 3.0, 4.0]) * 1e-3)
    p, error = run.exceedance("shaft_peak", 2.5e-3)
    assert p == pytest.approx(0.5, rel=REL)
    assert error == pytest.approx(0.25, rel=REL)
    p, error = run.exceedance("shaft_peak", 3.5e-3)
    assert p == pytest.approx(0.25, rel=REL)
    assert error == pytest.approx(math.sqrt(3.0) / 8.0, rel=REL)

"""The run's phase φ = ∫₀ᵗ Ω dτ under a speed quadratic in time.

:func:`~flexshaft.analyses.transient.transient_response` reports the imbalance's angle
φ(t) = ∫₀ᵗ Ω dτ at its output instants by the two-point Gauss-Legendre rule on each output
interval (nodes at the centre ± h/(2√3)), which integrates polynomials up to the third degree
exactly (Abramowitz & Stegun 25.4.29 with n = 2). For Ω(t) = Ω₀ + βt² (a callable profile; a
table is piecewise linear):

    φ(t) = Ω₀ t + β t³/3          (closed form).

Another pair of symmetric nodes ±a integrates t² with the error h(a² − h²/12) per interval of
length h: 0.026 rad over this run for a = (√3/4) h (β = 100 rad/s³, h = 0.05 s, T = 1 s).

The rotor: the Jeffcott disk of tests/rotors.py, two modes, 50 to 150 rad/s (below its 302-rad/s
critical). Tolerance 1e-11 rad absolute on φ ≤ 83.3 rad: the sum of 20 Gauss terms (round-off
about 20 × 1e-16 × 83 = 2e-13). Written for the mutation h35b-transient-gauss-points-outside of
scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
from rotors import jeffcott

from flexshaft.analyses.transient import SpeedProfile, transient_response

W0, BETA, DURATION = 50.0, 100.0, 1.0  # rad/s, rad/s³, s


def test_the_phase_of_a_quadratic_speed_is_its_exact_integral():
    profile = SpeedProfile.from_callable(lambda t: W0 + BETA * t * t, DURATION, lambda t: 2 * BETA * t)
    run = transient_response(jeffcott(0.0, 200.0), profile, basis_size=2, output_step=0.05, initial="rest")
    t = run.time
    assert t.size == 21 and t[-1] == DURATION
    assert np.abs(run.phase - (W0 * t + BETA * t**3 / 3)).max() <= 1e-11

"""A run-up is called unstable by the stability analysis's damping-ratio rule, not by the sign of
a round-off real part.

Rule (docs/model.md, hand-written): the onset "is the first speed where a mode's damping ratio
drops below −1e-9"; docs/transient.md: the run-up's ``unstable`` is that rule on the run's free
vibrations, and ``flexshaft runup`` prints "unstable there" only then. An undamped mode's real
part is round-off (review r112 measured +9.6e-10 1/s on a damped rotor's nearly undamped tube
modes: the command then printed "unstable there" for a stable rotor).

References, derived here:

* the rule itself on hand-made envelope eigenvalues λ = s − iΩ (the frame rotation of the
  run's complex envelopes): s = 1e-12 + 1000i (ζ = −1e-15) does not grow, s = 1e-3 + 1000i
  (ζ = −1e-6) does; a rigid-body root s = 1e-10 beside a mode of |s| = 1e4 is round-off (below
  the eigen-analyses' divergence bound 1e-6 × the largest basis frequency 1e4 = 0.01 1/s),
  s = 0.5 is a divergence, also beside a controller's fast pole (the bound is the structure's);
* a conservative Jeffcott rotor (no loss, no damper): every root on the imaginary axis, so no
  run of it is unstable, whatever the sign of its round-off;
* the Jeffcott rotor with a rotating-frame loss η = 0.02 and no external damping
  (tests/test_rundown_from_unstable_speed_reference.py): the forward whirl's exact root of
  m s² + D (s − iΩ) + k = 0, D = kη/(ω_n + Ω), grows above ω_n and decays below it: a run held
  at 2 ω_n for 1 s (growth e^{1.007}, far below the refusal's 1e3) is unstable, one held at
  ω_n/2 is not, and a ramp from ω_n/2 to 2 ω_n is (its later reference speeds count).

CPU: four Jeffcott runs on a two-mode basis, about 0.2 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.envelope import growing_whirl
from flexshaft.analyses.transient import SpeedProfile, transient_response

ETA = 0.02


@pytest.mark.parametrize(
    ("roots", "scale", "grows"),
    [
        ([-1.0 + 1000j, 1e-12 + 1000j], 1e3, False),
        ([-1.0 + 1000j, 1e-3 + 1000j], 1e3, True),
        ([1e-10 + 0j, -1.0 + 1e4j], 1e4, False),
        ([0.5 + 0j, -1.0 + 1e4j], 1e4, True),
        ([0.5 + 0j, -1.0 + 1e4j, -6.3e6 + 0j], 1e4, True),
    ],
)
def test_the_damping_ratio_rule_on_hand_made_roots(roots, scale, grows):
    """``scale``: the largest basis frequency [rad/s]; the last case adds a 1 MHz amplifier's
    pole, which must not raise the divergence bound over the real root 0.5 1/s (review r116)."""
    speed = 300.0
    lam = np.array(roots) - 1j * speed  # the envelope eigenvalues of these modes
    assert growing_whirl(lam, speed, scale) is grows


def _held(model, speed: float, duration: float = 1.0):
    return transient_response(
        model, SpeedProfile.table([0.0, duration], [speed, speed]), basis_size=2, initial="rest", output_step=0.25
    )


def test_a_conservative_rotor_is_never_called_unstable():
    run = _held(jeffcott(0.0, 0.0), 0.5 * WN)
    assert run.unstable is False
    assert abs(run.max_growth_rate) <= 1e-6 * WN  # round-off of zero real parts, either sign


@pytest.mark.parametrize(("ratio", "unstable"), [(0.5, False), (2.0, True)])
def test_the_rotating_loss_whirls_above_the_critical_only(ratio, unstable):
    speed = ratio * WN
    D = K_SHAFT * ETA / (WN + speed)
    largest = np.roots([M_DISK, D, K_SHAFT - 1j * D * speed]).real.max()
    assert bool(largest > 0) is unstable  # the closed form's verdict
    run = _held(jeffcott(ETA, 0.0, "rotating"), speed)
    assert run.unstable is unstable


def test_a_ramp_into_the_unstable_range_is_unstable():
    """From ω_n/2 (stable) to 2 ω_n (unstable, the closed form above) in 1 s: the run's first
    reference speed is stable, a later one is not; the run is unstable."""
    run = transient_response(
        jeffcott(ETA, 0.0, "rotating"),
        SpeedProfile.table([0.0, 1.0], [0.5 * WN, 2.0 * WN]),
        basis_size=2,
        initial="rest",
        output_step=0.25,
    )
    assert run.refreshes > 1
    assert run.unstable is True

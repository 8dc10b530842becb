"""The Campbell diagram of the damped Jeffcott rotor against its exact roots (derived here).

The Jeffcott rotor of tests/rotors.py: a 20 kg disk at the middle of a near-massless (7e-6 of
the disk's mass) pinned-pinned tube of stiffness k = 48EI/L³, an external dashpot c_e at the
disk and a rotating-frame hysteretic loss factor η of the tube. In the complex coordinate
r = v + i w of the disk a whirl r = e^{st} obeys

    m s² + c_e s + k (1 + i η σ) = 0,    σ = sgn(Im s − Ω) for forward whirl, σ = +1 for backward

(the rotating loss acts on the whirl seen from the rotor, at frequency ω − Ω; the backward whirl
is seen at ω + Ω > 0; the same equations as tests/test_damping.py and tests/test_root_stability.py).
The root of σ = +1 with Im s > 0 is the forward whirl below the spin, its mirror
s₋ = −c_e/m − s̄₊ (the root of σ = −1) above it: one damped frequency ω_d, two real parts. With
η = 0.1 and ζ_e = c_e/(2√(km)) = 0.2, ω_d ≈ 0.981 ω_n, and the forward whirl is damped less above
ω_d (Re s ≈ −0.149 ω_n) than below (−0.251 ω_n); the backward whirl keeps −0.251 ω_n.

Checked against these roots (np.roots of the scalar quadratics):

* the damped frequencies Im s/2π at every speed (the undamped |s|/2π is 1.2-3.2 % higher);
* the mode summary: the forward mode's smallest log decrement δ = 2πζ/√(1 − ζ²) is that of s₋,
  reached above ω_d; the backward mode's is that of s₊;
* the whirl labels: the mode whose damping drops above ω_d is labelled forward at every speed,
  and at rest (where the forward and backward roots coincide, s₊ for both) the labels and whirl
  ratios are those of the modes' continuation.

Tolerance 1e-4 relative: the tube's mass (7e-6 of the disk's) and the modal basis leave about
1e-6 on these roots (the same rotor is asserted at 1e-4 in tests/test_root_stability.py). Eight
tube elements are enough: the disk's equation is exact at any mesh (the stiffness condenses
exactly onto the disk node). Six speeds, two modes: about 0.06 s of CPU.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.campbell import campbell

ETA, ZETA_E = 0.1, 0.2
C_E = 2 * ZETA_E * M_DISK * WN
SPEEDS = np.array([0.0, 0.3, 0.6, 0.9, 1.2, 1.5]) * WN


def _root(sigma: int) -> complex:
    """The root with Im s > 0 of m s² + c_e s + k (1 + i η σ) = 0."""
    roots = np.roots([M_DISK, C_E, K_SHAFT * (1 + 1j * ETA * sigma)])
    return complex(roots[np.argmax(roots.imag)])


def _log_decrement(s: complex) -> float:
    zeta = -s.real / abs(s)
    return 2 * np.pi * zeta / np.sqrt(1 - zeta**2)


@pytest.fixture(scope="module")
def diagram():
    return campbell(jeffcott(ETA, C_E), SPEEDS, n_modes=2)


def _expected(diagram) -> tuple[int, int, np.ndarray]:
    """Columns of the forward and backward mode (by their damping above ω_d, not by label) and
    the expected roots (n_speeds, 2)."""
    below, above = _root(+1), _root(-1)
    wd = below.imag
    assert above.imag == pytest.approx(wd, rel=1e-12)  # the mirror root: one damped frequency
    top = diagram.eigenvalues[-1]
    forward = int(np.argmin(np.abs(top - above)))
    backward = 1 - forward
    expected = np.empty((SPEEDS.size, 2), complex)
    expected[:, backward] = below
    expected[:, forward] = np.where(SPEEDS > wd, above, below)
    return forward, backward, expected


def test_tracked_roots_and_damped_frequencies_are_the_exact_whirl_roots(diagram):
    forward, backward, expected = _expected(diagram)
    assert diagram.eigenvalues == pytest.approx(expected, rel=1e-4)
    assert diagram.frequencies == pytest.approx(expected.imag / (2 * np.pi), rel=1e-4)


def test_mode_summary_reports_the_smallest_log_decrement_and_its_speed(diagram):
    forward, backward, _ = _expected(diagram)
    wd = _root(+1).imag
    rows = diagram.mode_summary()
    assert rows[forward][5] == pytest.approx(_log_decrement(_root(-1)), rel=1e-4)
    rpm_at = rows[forward][6]
    assert rpm_at > wd * 60 / (2 * np.pi)  # reached above the damped frequency
    assert any(rpm_at == pytest.approx(v * 60 / (2 * np.pi), rel=1e-12) for v in SPEEDS[SPEEDS > wd])
    assert rows[backward][5] == pytest.approx(_log_decrement(_root(+1)), rel=1e-4)
    assert rows[forward][1] == pytest.approx(wd / (2 * np.pi), rel=1e-4)  # f first [Hz]: damped
    assert rows[forward][2] == pytest.approx(wd / (2 * np.pi), rel=1e-4)


def test_whirl_labels_follow_the_damping_and_continue_to_rest(diagram):
    forward, backward, _ = _expected(diagram)
    assert list(diagram.whirl[:, forward]) == ["forward"] * SPEEDS.size
    assert list(diagram.whirl[:, backward]) == ["backward"] * SPEEDS.size
    assert diagram.whirl_ratios[0] == pytest.approx(diagram.whirl_ratios[1], abs=1e-9)
    assert diagram.whirl_ratios[:, forward] == pytest.approx(np.ones(SPEEDS.size), abs=1e-6)
    assert diagram.whirl_ratios[:, backward] == pytest.approx(-np.ones(SPEEDS.size), abs=1e-6)

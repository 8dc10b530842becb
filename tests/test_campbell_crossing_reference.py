"""A tracked Campbell curve keeps its mode through a crossing: the conical (tilt) whirl of an
off-centre gyroscopic disk against the exact roots of its two-degree-of-freedom model (derived
here; mutation survivor h33c-campbell-continuation-mac-loose).

The rotor: tests/rotors.py's near-massless pinned-pinned tube (Euler-Bernoulli, length L, EI)
with loss factor η = 0.01, no dashpot, and a rigid disk (m = 20 kg, diametral inertia
I_d = 6 kg m², polar I_p = 2 I_d) at x = a = 0.45 L, off the middle, so its translation r and
tilt φ couple. The unit-load method on the simply supported beam (moment diagrams of a unit force
and a unit moment at a, b = L − a) gives the flexibility at the disk

    F = 1/(3 EI L) [[a² b², a b (b − a)], [a b (b − a), a² − a b + b²]],

K = F⁻¹ (exact condensation: the disk's loads are nodal, the tube's mass is 3.5e-6 of the
disk's). In complex coordinates (r = v + i w, φ likewise) a whirl e^{st} obeys

    det [[m s² + K₁₁ c, K₁₂ c], [K₁₂ c, I_d s² − i I_p Ω s + K₂₂ c]] = 0,

a quartic in s, with c = 1 + i η for a whirl faster than the spin (Im s > Ω: the rotating loss
sees ω − Ω > 0) and c = 1 − i η below it (Im s < Ω, backward whirl included; forward whirl
slower than the spin also sees ω − Ω < 0; tests/test_campbell_jeffcott_reference.py). Roots
with Im s > 0 whirl forward; a backward root is reported as its conjugate.

At rest the tilt pair (0.86 ω_n) lies below the translation pair (1.08 ω_n, ω_n = √(k/m) of the
midspan Jeffcott rotor); with spin the forward tilt rises through the forward translation. Three
tracked modes (the torsion and the tilt pair: the translation is not tracked) at Ω = 0, 0.5, 1.0
ω_n: the first step starts the forward tilt from its rest root 0.86 ω_n, nearer the forward
translation root (1.01 ω_n) than its own (1.56 ω_n), and the translation is in its shape through
the coupling: Newton's method from there lands on the translation root, whose shape is not the
tilt's. The curve must refuse that root (it is the untracked mode) and keep the tilt:

* the forward curve is the tilt-like root of the quartic at every speed (of the family's two
  roots the one with most of the kinetic energy in I_d |φ|²: 0.75 at rest, above 0.94 spinning;
  its partner's 0.25 and below: unambiguous), to 1e-5 relative;
* the backward curve likewise, and the labels stay forward and backward along the curves.

Tolerance 1e-5 relative: the tube's mass share (3.5e-6) and the modal basis (chosen for 1e-6 of
the full problem) leave about 1e-6 on these roots (measured 3e-7). Three speeds, three modes:
about 0.15 s of CPU.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import DI, DO, M_DISK, WN, E, L, jeffcott_text

from flexshaft.analyses.campbell import campbell
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA, A, I_D = 0.01, 0.45 * L, 6.0
I_P = 2 * I_D
SPEEDS = np.array([0.0, 0.5, 1.0]) * WN
EI = E * np.pi * (DO**4 - DI**4) / 64


def _stiffness() -> np.ndarray:
    """The disk's condensed stiffness (translation, tilt) from the unit-load flexibility."""
    b = L - A
    flexibility = np.array([[A**2 * b**2, A * b * (b - A)], [A * b * (b - A), A**2 - A * b + b**2]]) / (3 * EI * L)
    return np.linalg.inv(flexibility)


def _roots(speed: float) -> list[tuple[complex, float]]:
    """Every root of the quartic consistent with its loss side: (s, tilt's kinetic share)."""
    K = _stiffness()
    found = []
    for c in (1 + 1j * ETA, 1 - 1j * ETA):
        poly = [
            M_DISK * I_D,
            -1j * M_DISK * I_P * speed,
            (M_DISK * K[1, 1] + I_D * K[0, 0]) * c,
            -1j * I_P * speed * K[0, 0] * c,
            (K[0, 0] * K[1, 1] - K[0, 1] ** 2) * c * c,
        ]
        for s in np.roots(poly):
            if (s.imag > speed) != (c.imag > 0):
                continue  # the other loss side's root
            r = -K[0, 1] * c / (M_DISK * s * s + K[0, 0] * c)  # translation per unit tilt
            found.append((complex(s), I_D / (I_D + M_DISK * abs(r) ** 2)))
    return found


def _tilt(speed: float, forward: bool) -> complex:
    """The tilt-like root of the whirl direction, as the diagram reports it (Im s > 0)."""
    family = sorted(((share, s) for s, share in _roots(speed) if (s.imag > 0) == forward), key=lambda item: item[0])
    assert [share for share, _ in family] == [pytest.approx(0.0, abs=0.3), pytest.approx(1.0, abs=0.3)]
    s = family[-1][1]  # the tilt, unambiguous: its partner is mostly translation
    return s if forward else s.conjugate()


@pytest.fixture(scope="module")
def diagram():
    text = jeffcott_text(ETA, 0.0).replace(
        f"x = {L / 2}\nmass = {M_DISK}", f"x = {A}\nmass = {M_DISK}\ndiametral_inertia = {I_D}\npolar_inertia = {I_P}"
    )
    return campbell(build_model(loads_design(text)), SPEEDS, n_modes=3)


def test_the_forward_tilt_curve_keeps_its_mode_through_the_translation(diagram):
    forward = list(diagram.whirl[-1]).index("forward")
    expected = np.array([_tilt(speed, True) for speed in SPEEDS])
    translation = [s for s, share in _roots(SPEEDS[1]) if s.imag > 0 and share < 0.1]
    # the rest root is nearer the translation at the first step than the tilt's own root
    assert abs(expected[0] - translation[0]) < abs(expected[0] - expected[1]) / 3
    assert diagram.eigenvalues[:, forward] == pytest.approx(expected, rel=1e-5)
    assert list(diagram.whirl[:, forward]) == ["forward"] * SPEEDS.size


def test_the_backward_tilt_curve_and_its_labels(diagram):
    backward = list(diagram.whirl[-1]).index("backward")
    expected = np.array([_tilt(speed, False) for speed in SPEEDS])
    assert diagram.eigenvalues[:, backward] == pytest.approx(expected, rel=1e-5)
    assert list(diagram.whirl[:, backward]) == ["backward"] * SPEEDS.size
    assert diagram.frequencies[:, backward] == pytest.approx(expected.imag / (2 * np.pi), rel=1e-5)

"""The whirl onset of a barely unstable mode, and the onset refinement's regula falsi (hunt h39a).

References (derived).

1. Weak hysteretic loss. The Jeffcott-like rotor of tests/rotors.py without external damping,
   loss factor η = 1e-5 in the rotating frame: in complex coordinates r = v + i w the forward
   mode obeys m s² + k (1 + i η σ) = 0, σ = sgn(ω − Ω). Above the spin it is stable; once the
   spin passes the whirl frequency (Ω > ω_n) the loss turns circulatory, s = i ω_n √(1 − i η),
   Re s ≈ η ω_n/2 > 0: ζ = −Re s/|s| ≈ −η/2 = −5e-6, a real but weak instability, and the onset
   is Ω* = ω_n (module docstring of flexshaft.analyses.stability: the jump where the consistent
   root changes side). The stability tolerance (ζ < −1e-9 is unstable) must flag it.
   Tolerances: ζ to 1e-3 relative (the tube's 3.5e-6 mass fraction moves it by ~1e-6 of |s|
   times η, far below); Ω* to 1e-5 (ω_n moves ~1e-6 with the tube's mass). Two speeds, 8
   elements: about 0.06 s.

2. The refinement's arithmetic, on a damping ratio given in closed form. ``_refine_onset``
   follows the mode with Newton's method at each trial speed; here Newton is replaced by the
   closed-form root s(Ω) = |s| (−ζ(Ω) + i √(1 − ζ²)) with ζ(Ω) = 0.01 (e^{−3(Ω/W − 1)} − 1),
   stable at Ω = 0, unstable at 2W, and ζ(W) = 0 exactly. ζ is convex, the case where plain
   regula falsi keeps one end fixed and crawls; the Illinois step (halving the stale end's value)
   must reach W to the refinement's 1e-7 of the speed within its 80 evaluations (it does in
   12; plain regula falsi from this bracket ends 2.5e-6 away after 80, and halving the end
   just replaced instead of the stale one 2.4e-3 away).
   When the mode cannot be followed at all (Newton fails at every trial speed and in every
   sub-step of the bracket), the onset is the linear interpolation of ζ between the two grid
   speeds, a + ζ_a/(ζ_a − ζ_b)(b − a) (the documented last resort).
"""

from __future__ import annotations

import importlib
from types import SimpleNamespace

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.stability import stability

stability_module = importlib.import_module("flexshaft.analyses.stability")

ETA = 1e-5


def test_a_weakly_unstable_whirl_above_its_frequency_sets_the_onset():
    result = stability(jeffcott(ETA, 0.0), np.array([0.5, 1.5]) * WN, n_modes=2)
    roots = np.roots([M_DISK, 0.0, K_SHAFT * (1 - 1j * ETA)])  # above the whirl frequency: σ = −1
    forward = roots[np.argmax(roots.imag)]
    zeta = -forward.real / abs(forward)
    assert zeta == pytest.approx(-ETA / 2, rel=1e-4)
    assert result.stability_margin[1] == pytest.approx(zeta, rel=1e-3)
    assert result.onset_kind == "oscillatory"
    assert result.onset_speed == pytest.approx(WN, rel=1e-5)


W, SIZE = 300.0, 100.0


def _zeta(speed: float) -> float:
    return 0.01 * (np.exp(-3.0 * (speed / W - 1.0)) - 1.0)


def _root(speed: float) -> complex:
    z = _zeta(speed)
    return SIZE * complex(-z, np.sqrt(1.0 - z * z))


def _refine(monkeypatch, newton) -> float:
    speeds = np.array([0.0, 2.0 * W])
    y = np.array([1.0, 0.0], complex)
    tracked = SimpleNamespace(
        eigenvalues=np.array([[_root(speeds[0])], [_root(speeds[1])]]), states=[y[:, None], y[:, None]]
    )
    monkeypatch.setattr(stability_module, "newton", newton)
    return stability_module._refine_onset(None, speeds, tracked, 0, 1, lambda c: None)


def test_the_illinois_refinement_reaches_a_convex_crossing(monkeypatch):
    def newton(red, speed, s, y, viscous=None):
        return _root(speed), y, True

    assert _zeta(0.0) > 0 > _zeta(2 * W) and _zeta(W) == 0.0
    assert _refine(monkeypatch, newton) == pytest.approx(W, rel=1e-7)


def test_an_onset_that_cannot_be_followed_is_the_grid_interpolation(monkeypatch):
    def newton(red, speed, s, y, viscous=None):
        return complex(np.nan, np.nan), y, False

    za, zb = _zeta(0.0), _zeta(2 * W)
    expected = 0.0 + za / (za - zb) * (2 * W - 0.0)
    assert abs(expected / W - 1) > 0.5  # far from the true crossing: the fallback is what is read
    assert _refine(monkeypatch, newton) == pytest.approx(expected, rel=1e-12)

"""The whirl onset refinement's regula falsi on damping ratios given in closed form.

References (derived here).

``_refine_onset`` (flexshaft.analyses.stability) finds the speed where the tracked mode's
damping ratio ζ = −Re s/|s| crosses zero between a stable grid speed a and an unstable one b:
an Illinois regula falsi, each trial root solved from the linear interpolation of the two end
roots at the trial speed's place in [a, b] and counted as the mode only when its shape matches
(MAC ≥ 0.8). Here the mode's root is given in closed form, s(Ω) = |s|(Ω) (−ζ(Ω) + i √(1 − ζ²)),
and Newton's method is replaced by a real Newton iteration on p(s) = (s − s₁)(s − s₂) with s₁
the mode and s₂ a neighbouring mode of another shape (MAC 0), so a trial seeded nearer s₂ is
not the mode.

1. A concave ζ(Ω) = 0.01 (1 − e^{3(Ω/W − 1)}), stable at 0, unstable at 2W, ζ(W) = 0 exactly.
   On a concave decreasing ζ the chord's zero always lies on the stable side, so plain regula
   falsi moves only the stable end and keeps the unstable end: its estimate crawls toward W
   linearly and ends 2.5e-6 W short after 80 trials (computed in the test by the same arithmetic).
   The Illinois step halves the stale unstable end's ζ and reaches W within its 80 trials.
   The refinement's stop (bracket width b − a ≤ 1e-7 b, or a trial with ζ = 0 exactly) bounds
   the error only by 1e-7 b ≤ 2e-7 W; the error measured is exactly 0 (the returned onset is
   W itself, plain and with OPENBLAS_CORETYPE=Prescott: scalar arithmetic, no BLAS). Asserted
   to the documented "converged to 1e-7 of the speed", 1e-7 relative: the measured 0 leaves the
   whole of it as margin, and the mutant without the halving (2.5e-6 W short) is 25 times
   outside.

2. The trial root's seed. The mode's root runs on a straight line from s_a = −3 + 100i at 0 to
   s_b = 6 + 150i at 2W (|s_b| ≠ |s_a|), s₁(Ω) = s_a + (Ω/2W)(s_b − s_a), with a second mode
   s₂ = s₁ + 0.02i of another shape just above it (a near-degenerate pair). Re s₁ crosses zero
   at Ω* = 2W · 3/(3 + 6) = 200 rad/s, where ζ = −Re s/|s| does. The product's seed
   (interpolation on the original bracket: the end roots interpolated at the trial speed's
   place in the bracket [0, 2W] they belong to) is s₁ itself (the path is straight), so every
   trial is the mode and the refinement reaches Ω*: the error measured is exactly 0 again
   (returned 200 rad/s), asserted to the documented 1e-7 of the speed as in 1. A seed
   interpolated at the trial's place in the current, shrunk bracket misses s₁ by up to tens of
   rad/s, far beyond the 0.01 rad/s half-gap bounding s₁'s Newton basin: the trial is the other
   mode. Following the mode down from 2W in sub-steps misses it too: its smallest sub-step,
   1/1024 of the bracket (0.59 rad/s), moves s₁ by 0.59 · |s_b − s_a|/600 = 0.05 rad/s, beyond
   the half-gap; so the result falls back to an estimate away from Ω* (the grid interpolation
   of ζ, the documented last resort, lies at 257 rad/s).

Scope: both cases are synthetic root paths (Newton replaced, no model). No real model was shown
where the current-bracket seed (h95a-stab-refine-guess-current-bracket) moves the onset: the
real Jeffcott rotor gives bit-identical onsets with it; and the Illinois mutant
(h95a-stab-illinois-upper-end-kept) moves hysteretic onsets by only 1e-8 to 3.6e-8 relative,
inside the documented 1e-7 (review r111's measurements). These tests pin the refinement's
stated algorithm, not a physics effect seen on a model.
"""

from __future__ import annotations

import importlib
from types import SimpleNamespace

import numpy as np
import pytest

stability_module = importlib.import_module("flexshaft.analyses.stability")

W = 300.0


def _concave(speed: float) -> float:
    return 0.01 * (1.0 - np.exp(3.0 * (speed / W - 1.0)))


def _on_circle(zeta, size):
    """s(Ω) = |s|(Ω) (−ζ(Ω) + i √(1 − ζ²))."""

    def root(speed: float) -> complex:
        z = zeta(speed)
        return size(speed) * complex(-z, np.sqrt(1.0 - z * z))

    return root


def _refine(monkeypatch, root, gap: float) -> float:
    """_refine_onset on [0, 2W] with the mode s₁ = root(Ω) and a mode s₂ = s₁ + i·gap of shape MAC 0."""
    speeds = np.array([0.0, 2.0 * W])
    y = np.array([1.0, 0.0], complex)
    other = np.array([0.0, 1.0], complex)

    def newton(red, speed, s, shape, viscous=None):
        s1 = root(speed)
        s2 = s1 + 1j * gap
        for _ in range(60):  # Newton on p(s) = (s − s1)(s − s2): the root whose basin holds the seed
            s = s - (s - s1) * (s - s2) / (2 * s - s1 - s2)
        return s, (y if abs(s - s1) < abs(s - s2) else other), True

    ends = [root(v) for v in speeds]
    tracked = SimpleNamespace(eigenvalues=np.array([[ends[0]], [ends[1]]]), states=[y[:, None], y[:, None]])
    monkeypatch.setattr(stability_module, "newton", newton)
    return stability_module._refine_onset(None, speeds, tracked, 0, 1, lambda c: None)


def _plain_regula_falsi(zeta, a: float, b: float, trials: int = 80) -> float:
    za, zb = zeta(a), zeta(b)
    c = a
    for _ in range(trials):
        c = a + za / (za - zb) * (b - a)
        zc = zeta(c)
        if zc < 0:
            b, zb = c, zc
        else:
            a, za = c, zc
    return c


def test_the_illinois_refinement_reaches_a_concave_crossing(monkeypatch):
    assert _concave(0.0) > 0 > _concave(2 * W) and _concave(W) == 0.0
    plain = _plain_regula_falsi(_concave, 0.0, 2 * W)
    assert abs(plain / W - 1) > 1e-6  # plain regula falsi stalls here: the case tests the halving
    onset = _refine(monkeypatch, _on_circle(_concave, lambda v: 100.0), gap=1e6)
    assert onset == pytest.approx(W, rel=1e-7)


def test_each_trial_root_is_seeded_on_the_original_bracket(monkeypatch):
    sa, sb = complex(-3.0, 100.0), complex(6.0, 150.0)

    def line(speed: float) -> complex:
        return sa + speed / (2 * W) * (sb - sa)

    crossing = 2 * W * 3.0 / (3.0 + 6.0)
    za, zb = -sa.real / abs(sa), -sb.real / abs(sb)
    grid = 2 * W * za / (za - zb)
    assert abs(grid / crossing - 1) > 1e-3  # the fallback differs from the crossing
    onset = _refine(monkeypatch, line, gap=0.02)
    assert onset == pytest.approx(crossing, rel=1e-7)

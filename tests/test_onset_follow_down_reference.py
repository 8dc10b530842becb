"""The onset refinement's follow-down of a wide bracket, on a closed-form mode (no model).

``_refine_onset`` identifies the crossing mode at each trial speed by its shape at the bracket's
unstable end; when a trial's root is not that mode it follows the mode down the bracket in
sub-steps (``_follow_down``: 1/8 of the bracket, halved on a lost step, at least 1/1024) and
solves the crossing again in the lowest sub-step where the damping ratio changes sign. Here
``_mode_at`` is replaced by a closed form, as tests/test_whirl_onset_refinement_reference.py
replaces Newton's method:

* the root s(Ω) = |s| (−ζ(Ω) + i √(1 − ζ²)), ζ(Ω) given per case (piecewise linear);
* the shape y(Ω) = (cos θ, sin θ), θ = (π/2) Ω/B on the bracket [0, B], B = 600 rad/s, and a
  root counts as the mode only when its MAC with the shape it is checked against is ≥ 0.8, the
  code's test: cos²(Δθ) ≥ 0.8, i.e. |ΔΩ| ≤ 0.295 B. The first trial of the regula falsi, the
  grid's linear interpolation at B/2 (ζ(0) = −ζ(B)), is 45° from the unstable end (MAC 0.5):
  lost, so the follow-down runs. Its sub-steps of B/8 (11.25°, MAC 0.96) all hold, so it visits
  0, 75, 150, ..., 600 rad/s exactly.

References (derived from these closed forms):

1. Two windows of instability, ζ < 0 on (100, 200) and on (425, 600]: the onset is the lowest
   zero, Ω = 100 (ζ linear on [75, 150], so the regula falsi there is exact to its 1e-7 stop).
   The highest window would give a bracket [525, 600] unstable at both ends.
2. The mode followed down is unstable at the bracket's low end too (ζ = −0.01 everywhere, while
   the grid's root at 0 is stable: another mode's): no crossing in the bracket, so the result is
   the documented last resort, the linear interpolation of the grid's ζ, B/2 = 300.
3. The mode lost at every speed: the same last resort, 300.
4. A bracket two ulp wide: B/8 rounds away (Ω − step = Ω), so no sub-step can move: the
   follow-down gives up at once (None) instead of looping on the same speed.
5. The worst case of the step control: a step is only found when it is at most B/1024. The
   mode is followed in 1024 steps of B/1024, each success doubling the step and the next try
   losing it: at most 2 × 1024 + 7 evaluations (the docstring's bound), and the crossing found.
6. The common path (the last test's docstring): a mode found from the regula falsi's
   interpolated guess never runs the follow-down.

Tolerances: 1e-7 relative (the regula falsi's stop), 1e-12 for the interpolation (a few
operations). CPU: ~2300 closed-form evaluations, ~0.05 s.
"""

from __future__ import annotations

import importlib
from types import SimpleNamespace

import numpy as np
import pytest

stability_module = importlib.import_module("flexshaft.analyses.stability")

B, SIZE = 600.0, 100.0


def _root(zeta: float) -> complex:
    return SIZE * complex(-zeta, np.sqrt(1.0 - zeta * zeta))


def _shape(speed: float) -> np.ndarray:
    theta = 0.5 * np.pi * speed / B
    return np.array([np.cos(theta), np.sin(theta)], complex)


def _fake(zeta, found=lambda speed, y: True, calls=None):
    """``_mode_at`` of the closed-form mode: its root and shape, found when MAC ≥ 0.8."""

    def mode_at(red, speed, guess, y, viscous):
        if calls is not None:
            calls.append(speed)
        shape = _shape(speed)
        mac = abs(np.vdot(y, shape)) ** 2 / (np.vdot(y, y).real * np.vdot(shape, shape).real)
        return _root(zeta(speed)), shape, bool(mac >= 0.8 and found(speed, y))

    return mode_at


def _refine(monkeypatch, zeta, found=lambda speed, y: True, grid=(0.01, -0.01)) -> float:
    speeds = np.array([0.0, B])
    tracked = SimpleNamespace(
        eigenvalues=np.array([[_root(grid[0])], [_root(grid[1])]]), states=[None, _shape(B)[:, None]]
    )
    monkeypatch.setattr(stability_module, "_mode_at", _fake(zeta, found))
    return stability_module._refine_onset(None, speeds, tracked, 0, 1, None)


def test_the_onset_is_the_lowest_of_two_windows(monkeypatch):
    knots = [0.0, 75.0, 150.0, 250.0, 400.0, 450.0, B]
    values = [0.01, 0.01, -0.02, 0.02, 0.01, -0.01, -0.01]

    def zeta(speed):
        return float(np.interp(speed, knots, values))

    assert zeta(100.0) == pytest.approx(0.0, abs=1e-17) and zeta(200.0) == pytest.approx(0.0, abs=1e-17)
    assert zeta(425.0) == pytest.approx(0.0, abs=1e-17) and zeta(525.0) < 0
    assert _refine(monkeypatch, zeta) == pytest.approx(100.0, rel=1e-7)


def test_a_mode_unstable_at_the_low_end_falls_back_to_the_grid_interpolation(monkeypatch):
    assert _refine(monkeypatch, lambda speed: -0.01) == pytest.approx(B / 2, rel=1e-12)


def test_a_mode_lost_everywhere_falls_back_to_the_grid_interpolation(monkeypatch):
    assert _refine(monkeypatch, lambda speed: 0.01 - speed / B * 0.02, lambda speed, y: False) == pytest.approx(
        B / 2, rel=1e-12
    )


def test_a_bracket_a_few_ulp_wide_gives_up_at_once(monkeypatch):
    calls: list[float] = []
    monkeypatch.setattr(stability_module, "_mode_at", _fake(lambda speed: -0.01, calls=calls))
    b = B
    a = np.nextafter(np.nextafter(b, 0.0), 0.0)
    assert b - (b - a) / 8 == b  # the sub-step rounds away
    assert stability_module._follow_down(None, a, b, _root(-0.01), _shape(b), None) is None
    assert calls == []


def test_the_follow_down_costs_at_most_two_evaluations_per_smallest_step(monkeypatch):
    calls: list[float] = []
    last = {"speed": B}

    def found(speed, y):  # only a step of at most B/1024 from the last found speed holds the mode
        ok = last["speed"] - speed <= B / 1024 * (1 + 1e-12)
        if ok:
            last["speed"] = speed
        return ok

    def zeta(speed):
        return 0.01 - speed / B * 0.02  # stable at 0, unstable above B/2

    monkeypatch.setattr(stability_module, "_mode_at", _fake(zeta, found, calls))
    bracket = stability_module._follow_down(None, 0.0, B, _root(zeta(B)), _shape(B), None)
    assert bracket is not None
    lo, hi = bracket[:2]
    assert lo <= B / 2 < hi and hi - lo == pytest.approx(B / 1024, rel=1e-9)
    assert len(calls) <= 2 * 1024 + 7


def test_a_mode_found_from_the_interpolated_guess_needs_no_follow_down(monkeypatch):
    """The common path: Newton's method holds the mode only from a guess within 0.5 rad/s of its
    root (a basin), the shape is the same across the bracket, ζ is linear (zero at B/2). The
    regula falsi's guess, the eigenvalue interpolated between the bracket's ends, is within
    |s| ζ²/2 = 5e-3 of the root, so the crossing is found without the follow-down (its sub-steps
    cost up to ~2 × 1024 evaluations); a guess extrapolated away from the unstable end is
    ~2 rad/s off and would need it."""

    def zeta(speed):
        return 0.01 - speed / B * 0.02

    def mode_at(red, speed, guess, y, viscous):
        root = _root(zeta(speed))
        return root, y, bool(abs(guess - root) <= 0.5)

    def follow_down(*args):
        raise AssertionError("the follow-down ran on the common path")

    speeds = np.array([0.0, B])
    y = np.array([1.0, 0.0], complex)
    tracked = SimpleNamespace(eigenvalues=np.array([[_root(zeta(0.0))], [_root(zeta(B))]]), states=[None, y[:, None]])
    monkeypatch.setattr(stability_module, "_mode_at", mode_at)
    monkeypatch.setattr(stability_module, "_follow_down", follow_down)
    assert stability_module._refine_onset(None, speeds, tracked, 0, 1, None) == pytest.approx(B / 2, rel=1e-7)

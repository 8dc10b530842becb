"""The match cost's frequency distance is relative to a damped curve's frequency Im s (hunt h101f).

Reference (rules quoted from the product's docstring and docs/model.md, worked by hand; no
number produced by the code):

* The 0.1 weight and the distance "relative to the curve's frequency" are the product
  docstring's rule, not a hand-written doc's: flexshaft/analyses/screened_match.py, module
  docstring, "1 − MAC of the shapes plus a tenth of the relative frequency distance", and
  match_cost's docstring, "a tenth of the frequency distance relative to the curve's
  frequency" (the cost flexshaft.analyses.campbell's tracking uses). docs/model.md gives only
  what that frequency is, ω = Im s: "A mode s (frequency ω = Im s > 0)" and "Modes are
  numbered by damped frequency Im s". So the distance term of a curve s = −σ + iω to a root at
  iω' is 0.1 |ω' − ω| / ω, not over |s| = √(σ² + ω²).
* A well damped curve s = −30 + 40i rad/s (ζ = 0.6, |s| = 50): a root of the same shape
  (MAC 1) at 48i costs 0.1 · 8/40 = 0.02 (0.016 over |s|); a root at 40i whose shape has
  MAC 0.982 (cos² θ of unit vectors at θ) costs 0.018. The curve's cheapest root is the
  latter; with the distance over |s| it would be the former (0.016 < 0.018).

Exact arithmetic of a few terms: 1e-14. No model; microseconds.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.screened_match import match_cost

CURVE = np.array([-30.0 + 40.0j])  # rad/s: ζ = 0.6, |s| = 50, frequency Im s = 40


def _roots() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    prev = np.array([[1.0], [0.0]], dtype=complex)
    c, s = np.sqrt(0.982), np.sqrt(0.018)
    shapes = np.array([[c, 1.0], [s, 0.0]], dtype=complex)  # MAC 0.982 and 1 with prev
    return prev, np.array([-29.0 + 40.0j, -31.0 + 48.0j]), shapes


def test_the_frequency_distance_is_relative_to_the_curves_damped_frequency():
    prev, lam, shapes = _roots()
    cost = match_cost(CURVE, prev, lam, shapes)
    assert cost == pytest.approx(np.array([[1 - 0.982 + 0.0, 1 - 1 + 0.1 * 8 / 40]]), abs=1e-14)


def test_a_damped_curve_keeps_its_nearer_root_of_a_slightly_different_shape():
    prev, lam, shapes = _roots()
    assert int(np.argmin(match_cost(CURVE, prev, lam, shapes), axis=1)[0]) == 0

"""The two one-dimensional refinements of flexshaft.analyses.local_projection, driven by hand
against functions whose answers are known exactly (derived here).

* golden_maximum: the golden-section search for the largest value of a unimodal f on log ω.
  On the Jeffcott rotor's imbalance response |A|/U = r² / |1 − r² + 2iζr| (r = ω/ω_n) the
  peak is at r = 1/√(1 − 2ζ²) (d|A|²/dr = 0: closed form), and on −(ln ω − ln 3)² it is at
  ω = 3. A golden-section search keeps the maximum inside its bracket and stops when the
  bracket is shorter than tol, so the returned log ω is within tol of the true one. Round-off
  limits that only where f's curvature makes δ²f''/2 comparable with ε f, δ ~ 1e-8: tol = 1e-6
  is 100 times above it.
* illinois_root: the Illinois variant of regula falsi for a root of f between a and b. On the
  concave f = ln ω, plain regula falsi moves the same end at every step (the secant lies
  below the curve) and converges only linearly, the fixed end never approached; the Illinois
  step halves the stale end's value and converges superlinearly. With tol = 1e-12 the root
  ω = 1 must be met to 1e-12 (each iterate is a secant root; in a bracket ~tol wide the secant
  is exact to round-off, 2e-16), and in far fewer evaluations than the 100 the loop allows
  (30 is the bound: the Illinois method gains a digit per one or two steps once close; 14 are
  needed from a six-decade bracket).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.local_projection import golden_maximum, illinois_root


def _drive(refinement):
    """Run a refinement, answering each requested ω with L(iω) = ω; (result, evaluations)."""
    count = 0
    try:
        omega = next(refinement)
        while True:
            count += 1
            omega = refinement.send(complex(omega))
    except StopIteration as stop:
        return stop.value, count


def test_golden_maximum_finds_the_jeffcott_imbalance_peak():
    omega_n, zeta = 100.0, 0.05

    def amplitude(L):
        r = L.real / omega_n
        return r * r / abs(1.0 - r * r + 2j * zeta * r)

    tol = 1e-6
    (log_peak, value), _ = _drive(golden_maximum(amplitude, np.log(50.0), np.log(200.0), tol))
    peak = omega_n / np.sqrt(1.0 - 2.0 * zeta**2)
    assert abs(log_peak - np.log(peak)) <= tol
    assert value == pytest.approx(1.0 / (2.0 * zeta * np.sqrt(1.0 - zeta**2)), rel=1e-9)  # the peak height


def test_golden_maximum_of_a_log_parabola():
    x0 = np.log(3.0)
    tol = 1e-6
    (x, value), _ = _drive(golden_maximum(lambda L: -((np.log(L.real) - x0) ** 2), np.log(0.5), np.log(40.0), tol))
    assert abs(x - x0) <= tol
    assert value <= 0.0 and value >= -(tol**2)


@pytest.mark.parametrize("a, b", [(1e-3, 1e3), (1e-2, 1e2), (0.05, 50.0)])
def test_illinois_root_of_a_concave_function_converges_superlinearly(a, b):
    tol = 1e-12
    (root, value), evaluations = _drive(illinois_root(lambda L: np.log(L.real), a, b, complex(a), complex(b), tol))
    assert abs(root - 1.0) <= tol
    assert value == complex(root)  # L(iω) returned is the one at the returned root (no arithmetic)
    assert evaluations <= 30

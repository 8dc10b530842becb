"""The damping ratio that sorts whirl modes from overdamped roots is −σ/|s|, not −σ/ω_d.

A root s = σ + iω_d of a damped single-degree-of-freedom mode is s = −ζω_n + iω_n√(1 − ζ²), so
|s| = ω_n and ζ = −σ/|s| (the roots of s² + 2ζω_n s + ω_n² = 0 for ζ < 1); −σ/ω_d is
instead ζ/√(1 − ζ²) (both derived here), which reaches 0.99 already at ζ = 0.70.
docs/requirements.md (the `whirl_damping` check) counts "at least `modes` of them, 10 at every
resolution: the torsional and axial modes and the real or overdamped roots of the controllers'
states, ζ ≥ 0.99, do not take their places", so
:func:`~flexshaft.verdict.operating_point.whirl_modes` keeps the lateral roots with ζ < 0.99:

* a lateral root with ζ = 0.8 (−σ/ω_d = 0.8/0.6 = 1.33) is a whirl mode;
* a real root s = −0.5 rad/s (a slow controller state: ζ = 1, while −σ over a zero damped
  frequency is not defined) is not.

Roots written by hand; the mask is exact (comparisons of numbers far from 0.99). CPU: none.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np

from flexshaft.verdict.operating_point import whirl_modes


def test_a_heavily_damped_whirl_is_kept_and_a_slow_real_root_is_not():
    zeta, wn = 0.8, 300.0
    heavy = complex(-zeta * wn, wn * math.sqrt(1.0 - zeta**2))
    assert abs(-heavy.real / abs(heavy) - zeta) < 1e-12
    found = SimpleNamespace(eigenvalues=np.array([-0.5 + 0.0j, heavy]), kind=np.array(["lateral", "lateral"]))
    assert whirl_modes(found).tolist() == [False, True]

"""Which roots the whirl-damping check holds, by the damping ratio of each root, and a point at
rest has no operating speed range.

* **Whirl modes are the roots with ζ < 0.99.** A root s = σ + iω_d of a damped mode has the
  damping ratio ζ = −σ/|s| (s = −ζω_n ± iω_n√(1 − ζ²), |s| = ω_n: Inman, *Engineering
  Vibration*, the underdamped single-degree-of-freedom root); a real negative root (a
  controller's integrator or amplifier state, an overdamped pair) has ζ = 1, an unstable root
  ζ < 0. :func:`~flexshaft.verdict.operating_point.whirl_modes` keeps the lateral roots with
  ζ below :data:`~flexshaft.verdict.operating_point.OVERDAMPED_RATIO` (0.99): a lightly damped
  and an unstable whirl, not a real root nor a pair at ζ = 0.999, nor a torsional root. Written
  by hand for four roots; the mask is exact (a comparison of numbers far from 0.99).
* **At rest there is no operating speed range.** ``[operating] speed_range = [0.9, 1.1]`` is a
  fraction of the operating speed: spinning at 6000 rpm (628.3 rad/s) it is 0.9 and 1.1 ×
  2π·6000/60 rad/s (to 1e-12 relative, one product each); at rest the point has one speed, 0,
  and :func:`~flexshaft.verdict.gather.operating_range` is None (module docstring: "None at
  rest"), so the report and the separation check do not show a (0, 0) range.

Written for the mutations h37a-whirl-zeta-sign and h37a-operating-range-at-rest of
scripts/mutations.toml. CPU: two small design loads, well under 0.1 s.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
from rotors import jeffcott_text

from flexshaft.design import loads_design
from flexshaft.verdict.gather import operating_range
from flexshaft.verdict.operating_point import OVERDAMPED_RATIO, whirl_modes


def _root(zeta: float, wn: float) -> complex:
    return complex(-zeta * wn, wn * math.sqrt(1.0 - zeta**2))


def test_whirl_modes_are_the_lateral_roots_below_the_overdamped_ratio():
    assert OVERDAMPED_RATIO == 0.99
    roots = np.array(
        [
            -150.0 + 0.0j,  # a controller state: real, ζ = 1
            _root(0.02, 300.0),  # a lightly damped whirl
            _root(0.999, 400.0),  # an overdamped pair
            complex(2.0, 500.0),  # an unstable whirl, ζ < 0
            _root(0.02, 600.0),  # lightly damped, but torsional
        ]
    )
    found = SimpleNamespace(eigenvalues=roots, kind=np.array(["lateral"] * 4 + ["torsional"]))
    assert whirl_modes(found).tolist() == [False, True, False, True, False]


def _design(speed_rpm: float):
    text = jeffcott_text(0.0, 0.0).replace("speed_rpm = 0.0", f"speed_rpm = {speed_rpm}\nspeed_range = [0.9, 1.1]")
    return loads_design(text)


def test_a_point_at_rest_has_no_operating_range_and_a_spinning_one_its_fractions():
    spinning = _design(6000.0)
    omega = 2.0 * math.pi * 6000.0 / 60.0
    found = operating_range(SimpleNamespace(design=spinning, operating_speed=omega))
    assert found == pytest.approx((0.9 * omega, 1.1 * omega), rel=1e-12)
    assert operating_range(SimpleNamespace(design=_design(0.0), operating_speed=0.0)) is None

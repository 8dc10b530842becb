"""The controller-law check of :mod:`flexshaft.assembly.checks`: its pole limit by size, and
its remembered verdicts keyed by the current gain, on a 2-element steel tube.

Rule (docs/limits.md, "Checks of several numbers"): the law k_i A(s) C(s) must be finite over
the analysed frequencies, with state-space entries below 1e100 and poles within 1e12 rad/s of
the origin.

Reference values, derived here:

* **A fast pole off the real axis.** C(s) = 1e26/(s² + 1e26) has poles s = ±1e13 i rad/s
  (roots of s² = −1e26 by hand), |s| = 1e13 > 1e12 although their real part is 0: refused.
  Its realization holds 1e26 < 1e100, its static gain C(0) = 1 N/m, and C(iω) is finite below
  1e13 rad/s, so only the pole limit refuses it.
* **k_i scales the law.** C(s) = 6e99 s/(s + 1) has the controllable realization D = 6e99,
  C = −6e99 (numerator minus D times the denominator), A = −1, B = 1: entries at most
  6e99 < 1e100, allowed with k_i = 1 N/A; k_i = 2 N/A doubles D and C to 1.2e100 > 1e100:
  refused. C(0) = 0, so the support-stiffness limit plays no part. Built with k_i = 1 first,
  so that a verdict remembered without k_i would wrongly pass the second build.

CPU: three model builds of a 2-element tube, 0.3 to 0.6 s measured, most of it the first
build's imports.
"""

from __future__ import annotations

import pytest

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, loads_design


def design(active_keys: str):
    return loads_design(
        f"""
name = "actuator law checks"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800.0
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = 0.05
wall_thickness = 0.005
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
[[bearings]]
name = "hanger"
kind = "contact"
x = 0.0
stiffness = {{ v = 1e6, w = 1e6 }}
[[bearings]]
name = "amb"
kind = "active"
x = 1.0
{active_keys}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 2
"""
    )


def controller(numerator, denominator) -> str:
    return f"[bearings.controller]\nnumerator = {list(numerator)!r}\ndenominator = {list(denominator)!r}"


def test_a_pole_beyond_the_limit_on_the_imaginary_axis_is_refused():
    with pytest.raises(DesignError, match=r"bearings\[1\]\.controller.*has a pole at s = .*1e\+13j"):
        build_model(design(controller([1e26], [1.0, 0.0, 1e26])))


def test_the_current_gain_scales_the_law_checked():
    high_pass = controller([6e99, 0.0], [1.0, 1.0])
    build_model(design(high_pass))  # k_i = 1: realization entries 6e99, below 1e100
    with pytest.raises(DesignError, match=r"bearings\[1\]\.controller.*entries up to 1\.2e\+100"):
        build_model(design("ki = 2.0\n" + high_pass))

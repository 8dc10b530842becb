"""The controller-law check of :mod:`flexshaft.assembly.checks` over its documented sweep, its
pole limit by size, and its remembered verdicts, on a 2-element steel tube.

Rule (docs/limits.md, "Checks of several numbers"): the law k_i A(s) C(s) must be finite over
the analysed frequencies, 1 rad/s to 100 times the larger of the operating speed and 1e3 rad/s,
with state-space entries below 1e100 and poles within 1e12 rad/s of the origin.

Reference values, derived here:

* **A law whose slope overflows.** C(s) = 1e100 s⁹ / (1e100 (s¹⁰ + s + 1)) is proper, its
  denominator has no root on the imaginary axis (at s = iω its imaginary part is ω, its real
  part 1 − ω¹⁰) and its poles are near |s| = 1, so its realization holds only ±1 and 1 and
  C(iω) ≈ 1/(iω) is small everywhere. Its slope dC/ds = (N'D − N D')/D², which the Newton
  refinement of the eigenvalues uses (``Controller.derivative``), is evaluated with
  |D(iω)|² ≈ 1e200 ω²⁰: this exceeds the largest double, 1.8e308, once ω > (1.8e108)^(1/20) =
  2.6e5 rad/s, while N'D ≈ 9e200 ω¹⁸ overflows too, so the slope is inf/inf = nan there. At
  rest the sweep ends at 100 × 1e3 = 1e5 rad/s < 2.6e5 (|D|² = 1e300 and N'D = 9e290, finite):
  the law is allowed. At Ω = 1e5 rad/s (955 000 rev/min, inside the 1e6 rev/min cap) it ends
  at 1e7 rad/s > 2.6e5: the law is refused (and only by its slope: C(1e7 i) ≈ −1e-7 i is
  finite). The same law at the two speeds, in that order, also shows that a verdict remembered
  for one speed is not reused at another (the sweep depends on the speed).
* **A fast pole off the real axis.** C(s) = 1e26/(s² + 1e26) has poles s = ±1e13 i rad/s
  (roots of s² = −1e26 by hand), |s| = 1e13 > 1e12 although their real part is 0: refused.
  Its realization holds 1e26 < 1e100, its static gain C(0) = 1 N/m, and C(iω) is finite below
  1e13 rad/s, so only the pole limit refuses it.
* **k_i scales the law.** C(s) = 1e100 s/(s + 1) has the controllable realization D = 1e100,
  C = −1e100 (numerator minus D times the denominator), A = −1, B = 1: entries at most 1e100,
  allowed with k_i = 1 N/A; k_i = 2 N/A doubles D and C to 2e100 > 1e100: refused. C(0) = 0,
  so the support-stiffness limit plays no part. Built with k_i = 1 first, so that a verdict
  remembered without k_i would wrongly pass the second build.

CPU: seven model builds of a 2-element tube, about 0.1 s.
"""

from __future__ import annotations

import pytest

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, loads_design


def design(active_keys: str, operating: str = "speed_rpm = 0.0"):
    return loads_design(
        f"""
name = "actuator law sweep"
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
{operating}
power = 0.0
[mesh]
shaft_elements = 2
"""
    )


def controller(numerator, denominator) -> str:
    return f"[bearings.controller]\nnumerator = {list(numerator)!r}\ndenominator = {list(denominator)!r}"


# 1e100 s⁹ / (1e100 (s¹⁰ + s + 1)): slope overflows above 2.6e5 rad/s (module docstring)
STEEP = controller([1e100] + [0.0] * 9, [1e100] + [0.0] * 8 + [1e100, 1e100])
FAST = "speed = 1e5"  # [rad/s]: the sweep reaches 1e7 rad/s


def test_a_law_whose_slope_overflows_inside_the_sweep_is_refused():
    with pytest.raises(DesignError, match=r"bearings\[1\]\.controller.*not finite.*1e\+07 rad/s"):
        build_model(design(STEEP, FAST))


def test_the_sweep_follows_the_speed_not_a_remembered_verdict():
    build_model(design(STEEP))  # at rest the sweep ends at 1e5 rad/s: |D|² = 1e300, finite
    with pytest.raises(DesignError, match=r"bearings\[1\]\.controller.*not finite"):
        build_model(design(STEEP, FAST))


def test_a_pole_beyond_the_limit_on_the_imaginary_axis_is_refused():
    with pytest.raises(DesignError, match=r"bearings\[1\]\.controller.*has a pole at s = .*1e\+13j"):
        build_model(design(controller([1e26], [1.0, 0.0, 1e26])))


def test_the_current_gain_scales_the_law_checked():
    high_pass = controller([1e100, 0.0], [1.0, 1.0])
    build_model(design(high_pass))  # k_i = 1: realization entries 1e100, at the bound
    with pytest.raises(DesignError, match=r"bearings\[1\]\.controller.*entries up to 2e\+100"):
        build_model(design("ki = 2.0\n" + high_pass))

"""A rotational support against E I/h, and an integrating law accepted (hunt h41a).

References, derived here (the limit's reason is in :mod:`flexshaft.assembly.checks`'s
docstring: a support stiffer than RIGID_RATIO = 1e8 shaft elements is no more rigid):

* **Rotational supports.** One Euler-Bernoulli element of length h has an end-rotation
  stiffness that scales as E I/h [N m/rad] and an end-translation one as E I/h³ [N/m] (the
  project's documented convention for the limit, docs/limits.md: "E I/h³ laterally, E I/h in
  rotation"); the two differ unless h = 1 m.
  A steel tube (E = 210 GPa, D_o = 20 mm, wall 1 mm: I = π(D_o⁴ − D_i⁴)/64 = 2.70e-9 m⁴), 2 m
  in 4 elements (h = 0.5 m): E I/h = 1134 N m/rad, E I/h³ = 4537 N/m, four times more. A
  ``beta`` or ``gamma`` stiffness of 1.25 × 1e8 E I/h is refused, 0.8 × it allowed; judged
  against E I/h³ the refused one would pass. 25 % either side: the physics decides, not the
  digits.
* **An integrating law.** A PID law C(s) = K_p + K_I/s + K_d s is finite at every s = iω, ω > 0
  (its one pole is the integrator's at s = 0, where it is meant to be infinite: zero static
  error). The check of overflowing laws evaluates C at ω = 0 only for a law that does not
  integrate, so a PID magnet (K_p = 1e5 A/m, K_I = 1e6 A/(m s), K_d = 100 A s/m) is built, and
  the model's actuator carries the integrator.

CPU: five builds of an 8-element tube, about 0.05 s. Written for h41a-checks-gamma-as-lateral
and h41a-checks-integrating-law-at-zero of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, loads_design

E, DO, WALL, LENGTH, ELEMENTS = 210e9, 0.02, 0.001, 2.0, 4
RIGID_RATIO = 1e8


def _ei() -> float:
    di = DO - 2 * WALL
    return E * math.pi * (DO**4 - di**4) / 64


def _text(hanger: str, active: str) -> str:
    return f"""
name = "rotational support"
[materials.steel]
kind = "isotropic"
E = {E!r}
G = 80e9
density = 7800.0
[shaft]
x_start = 0.0
x_end = {LENGTH}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "hanger"
kind = "contact"
x = 0.0
stiffness = {{ {hanger} }}
[[bearings]]
name = "amb"
kind = "active"
x = {LENGTH}
{active}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = {ELEMENTS}
"""


PD = "kp = 1e5\nkd = 100.0"


@pytest.mark.parametrize("direction", ["beta", "gamma"])
def test_a_rotational_support_is_judged_against_ei_over_h(direction):
    h = LENGTH / ELEMENTS
    limit = RIGID_RATIO * _ei() / h
    # judged laterally the limit would be RIGID_RATIO E I/h³ = limit / h², 4 times higher
    build_model(loads_design(_text(f"v = 1e5, w = 1e5, {direction} = {0.8 * limit!r}", PD)))
    with pytest.raises(DesignError, match=rf"bearings\[0\]\.stiffness\.{direction}"):
        build_model(loads_design(_text(f"v = 1e5, w = 1e5, {direction} = {1.25 * limit!r}", PD)))


def test_a_pid_magnet_is_built_with_its_integrator():
    model = build_model(loads_design(_text("v = 1e5, w = 1e5", "kp = 1e5\nkd = 100.0\nintegral_gain = 1e6")))
    assert [a.integrates for a in model.actuators] == [True]

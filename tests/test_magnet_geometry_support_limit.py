"""The rigid-support limit counts the magnet's gains when they come from its geometry.

:mod:`flexshaft.assembly.checks` refuses an actuator whose control stiffness k_i K_p, or
negative stiffness k_s, exceeds RIGID_RATIO = 1e8 times one shaft element's bending stiffness
E I/h³ (the limit's reason is in that module's docstring). A bearing may give k_i and k_s, or
its magnet geometry (coil turns N, pole area A, bias current i_0, air gap g_0, pole angle α);
the model is built with the same gains either way, so the limit must be the same.

Reference values, derived here (not read from the code): one horseshoe's gap flux density
B = μ0 N i/(2 g) (two gaps in series), each of its two poles pulls B² A/(2 μ0) at the angle α
to the axis, so f = k i²/g² with k = μ0 N² A cos α/4; the differential pair's current gain
k_i = ∂f/∂i = 4 k i_0/g_0² and negative stiffness k_s = ∂f/∂x = 4 k i_0²/g_0³ (the same as
Schweitzer & Maslen 2009, ch. 2, cited by :mod:`flexshaft.elements.magnetic`). μ0 = 4π·10⁻⁷
H/m. The tube's second moment I = π(D_o⁴ − D_i⁴)/64, h = length/elements.

The gains are put 25 % either side of the limit, far beyond round-off (1e-15) of the few
operations each side computes: the limit is decided by the physics, not by the digits.
Before this test the check read k_i = 1, k_s = 0 for a geometry bearing: a geometry giving
k_i = 2513 N/A passed with k_i K_p 9e8 times the element's stiffness (refused when the same
k_i was given).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, loads_design

MU_0 = 4e-7 * math.pi
RIGID_RATIO = 1e8  # the documented limit, in element stiffnesses


def magnet_gains(turns, area, i0, gap, alpha=0.0):
    k = MU_0 * turns**2 * area * math.cos(alpha) / 4.0
    return 4 * k * i0 / gap**2, 4 * k * i0**2 / gap**3


def design(do, wall, length, elements, active_keys, hanger_v=1e5):
    """The tube's design text: a contact hanger (v stiffness ``hanger_v`` [N/m]) at its start, an
    active bearing of ``active_keys`` at its end (also tests/test_support_limit_law_reference.py)."""
    return f"""
name = "magnet geometry support limit"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800.0
[shaft]
x_start = 0.0
x_end = {length}
outer_diameter = {do}
wall_thickness = {wall}
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
[[bearings]]
name = "hanger"
kind = "contact"
x = 0.0
stiffness = {{ v = {hanger_v!r}, w = 1e5 }}
[[bearings]]
name = "amb"
kind = "active"
x = {length}
{active_keys}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = {elements}
"""


def element_limit(do, wall, length, elements):
    di = do - 2 * wall
    return RIGID_RATIO * 210e9 * math.pi * (do**4 - di**4) / 64 / (length / elements) ** 3


TUBE = (0.1, 0.005, 2.0, 4)  # E I/h³ = 2.84e6 N/m, limit 2.84e14 N/m
GEOMETRY = {"turns": 500.0, "area": 1e-3, "i0": 2.0, "gap": 5e-4}  # k_i = 2513 N/A, k_s = 1.0e7 N/m


def geometry_keys(turns, area, i0, gap):
    return f"coil_turns = {turns}\npole_area = {area}\nbias_current = {i0}\nair_gap = {gap}\npole_angle = 0.0"


@pytest.mark.parametrize("given", [False, True], ids=["from-geometry", "given"])
def test_control_stiffness_ki_kp_is_limited_alike(given):
    k_i, _ = magnet_gains(**GEOMETRY)
    magnet = f"ki = {k_i!r}" if given else geometry_keys(**GEOMETRY)
    kp_limit = element_limit(*TUBE) / k_i
    with pytest.raises(DesignError, match=r"bearings\[1\]\.kp"):
        build_model(loads_design(design(*TUBE, f"kp = {1.25 * kp_limit!r}\nkd = 0.0\n{magnet}")))
    model = build_model(loads_design(design(*TUBE, f"kp = {0.8 * kp_limit!r}\nkd = 0.0\n{magnet}")))
    assert model.actuators[0].current_gain == pytest.approx(k_i, rel=1e-12)


THIN = (0.02, 0.001, 2.0, 2)  # E I/h³ = 567 N/m, limit 5.67e10 N/m
STRONG = {"turns": 500.0, "area": 1e-3, "i0": 20.0, "gap": 1e-4}  # k_i = 6.3e5 N/A, k_s = 1.26e11 N/m


@pytest.mark.parametrize("given", [False, True], ids=["from-geometry", "given"])
def test_negative_stiffness_ks_is_limited_alike(given):
    k_i, k_s = magnet_gains(**STRONG)
    assert k_s > 1.25 * element_limit(*THIN)
    magnet = f"ki = {k_i!r}\nks = {k_s!r}" if given else geometry_keys(**STRONG)
    with pytest.raises(DesignError, match=r"bearings\[1\]\.ks"):
        build_model(loads_design(design(*THIN, f"kp = 0.0\nkd = 0.0\n{magnet}")))

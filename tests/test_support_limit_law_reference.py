"""The rigid-support limit and the controller-pole limit of :mod:`flexshaft.assembly.checks`, at
their edges, on a small steel tube.

Reference values, derived here. The tube: E = 210 GPa, D_o = 20 mm, wall 1 mm, 2 m in 2
elements (h = 1 m), so one element's bending stiffness is E I/h³ with I = π(D_o⁴ − D_i⁴)/64:
567 N/m, and the limit RIGID_RATIO = 1e8 times it, 5.67e10 N/m (the limit's reason is in the
module's docstring; a thin tube so that the limit lies inside the schema's range of a given
stiffness, at most 1e12 N/m).

* **At most the limit.** A support exactly at the limit is allowed ("allowed: at most ..."), the
  next float above it is refused. The limit used is the module's ``element_stiffness`` once it
  is checked against the closed form E I/h³ above (rel 1e-14: a few roundings).
* **A controller's support stiffness is k_i C(0)** [N/m]: C(s) maps the displacement to the coil
  current [A/m] and k_i [N/A] the current to force. With k_i = 100 N/A, a static gain C(0) of
  1.25 limit/k_i is 1.25 limits of support (refused) although C(0) alone is 0.0125 limits; 0.8
  limit/k_i is allowed. 25 % either side: decided by the physics, not the digits.
* **The fastest pole decides.** C(s) = 1/((s/1e13 + 1)(s/100 + 1)) has poles at −1e13 and
  −100 rad/s (by hand, from its factors): the fast one is beyond the documented 1e12 rad/s, so
  the law is refused although its slow pole is fine.

CPU: six model builds of a 2-element tube, about 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_magnet_geometry_support_limit import RIGID_RATIO, element_limit
from test_magnet_geometry_support_limit import design as tube_text

from flexshaft.assembly import build_model
from flexshaft.assembly.checks import element_stiffness
from flexshaft.design import DesignError, loads_design

TUBE = (0.02, 0.001, 2.0, 2)  # outer diameter, wall, length [m], elements: E I/h³ = 567 N/m


def design(hanger_v: float, active_keys: str):
    return loads_design(tube_text(*TUBE, active_keys, hanger_v=hanger_v))


def closed_form_limit() -> float:
    return element_limit(*TUBE)


PD = "kp = 1e5\nkd = 0.0"


def test_a_support_at_the_limit_is_allowed_and_above_it_refused():
    soft = design(1e5, PD)
    reference = element_stiffness(soft, build_model(soft).shaft)["v"]
    assert RIGID_RATIO * reference == pytest.approx(closed_form_limit(), rel=1e-14)
    limit = RIGID_RATIO * reference
    build_model(design(limit, PD))  # exactly at the limit: allowed
    with pytest.raises(DesignError, match=r"bearings\[0\]\.stiffness\.v"):
        build_model(design(float(np.nextafter(limit, np.inf)), PD))


def test_a_controllers_support_stiffness_is_its_static_gain_times_ki():
    k_i, limit = 100.0, closed_form_limit()
    for factor, refused in ((1.25, True), (0.8, False)):
        law = f"ki = {k_i!r}\n[bearings.controller]\nnumerator = [{factor * limit / k_i!r}]\ndenominator = [1.0]"
        if refused:
            with pytest.raises(DesignError, match=r"bearings\[1\]\.controller"):
                build_model(design(1e5, law))
        else:
            build_model(design(1e5, law))


def test_a_law_with_one_pole_beyond_the_limit_is_refused():
    fast, slow = 1e13, 100.0
    denominator = [1.0 / (fast * slow), 1.0 / fast + 1.0 / slow, 1.0]  # (s/fast + 1)(s/slow + 1)
    law = f"[bearings.controller]\nnumerator = [1e5]\ndenominator = {denominator!r}"
    with pytest.raises(DesignError, match=r"has a pole at s = -1e\+13 rad/s"):
        build_model(design(1e5, law))

"""Equivalent diameter of the elliptical tailboom: the circle with the boom's outer perimeter.

References (independent of flexshaft.thermal.tailboom):

* a circle of radius r has perimeter 2 pi r, so a round boom of mid-line radius r and wall t has
  the equivalent diameter 2 (r + t/2): the outer skin, which convects and radiates;
* the exact perimeter of an ellipse of semi-axes a >= b is 4 a E(m), E the complete elliptic
  integral of the second kind with parameter m = 1 - (b/a)^2 (scipy.special.ellipe), taken at
  the length-averaged outer semi-axes (mid-line + t/2) of the linearly tapered boom.

Ramanujan's second approximation is within ~1e-9 of the exact perimeter for b/a >= 0.5
(h = ((a-b)/(a+b))^2 <= 1/9, error of order h^5 ~ 3e-10 relative): tolerance 1e-8.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest
from scipy.special import ellipe

from flexshaft.thermal.tailboom import boom_equivalent_diameter


def test_round_boom_is_its_outer_diameter():
    boom = SimpleNamespace(root_semi_axes=(0.30, 0.30), tip_semi_axes=(0.20, 0.20), wall_thickness=0.004)
    assert boom_equivalent_diameter(boom) == pytest.approx(2 * (0.25 + 0.002), rel=1e-12)


@pytest.mark.parametrize("ratio", [0.8, 0.5])
def test_elliptical_boom_has_the_exact_outer_perimeter(ratio):
    root, tip, t = (0.30, 0.30 * ratio), (0.18, 0.18 * ratio), 0.003
    a = (root[0] + tip[0]) / 2 + t / 2
    b = (root[1] + tip[1]) / 2 + t / 2
    perimeter = 4 * a * ellipe(1 - (b / a) ** 2)
    boom = SimpleNamespace(root_semi_axes=root, tip_semi_axes=tip, wall_thickness=t)
    assert boom_equivalent_diameter(boom) == pytest.approx(perimeter / math.pi, rel=1e-8)

"""Air above the specific-heat table and the convection dispatchers' defaults, by hand.

* c_p of air above 400 K: :mod:`flexshaft.thermal.air` interpolates Incropera & DeWitt
  Table A.4 (250, 300, 350, 400 K → 1006, 1007, 1009, 1014 J/(kg K), typed in the module) and,
  as its docstring says, extends the last interval linearly beyond 400 K:
  c_p(T) = 1014 + (T − 400) (1014 − 1009)/(400 − 350), i.e. 1024 J/(kg K) at 500 K and
  1019 J/(kg K) at 450 K (the module's documented rule, not a datum, is what is checked).
* ``rotating_cylinder_nusselt`` without a method is Becker's fit (docs/thermal.md, the
  ``shaft_convection`` default ``"becker"``): the same value as the named Becker function. Its
  constants (0.133, Pr^{1/3}) are not retyped here: their paper could not be read
  (docs/testing.md, the open ``h17b-becker-prandtl-exponent``), so this is a dispatch check;
* ``forced_cylinder_nusselt`` without a method is Churchill & Bernstein (1977), J. Heat Transfer
  99, 300-306 (the form quoted by Incropera & DeWitt, §7.4), typed here:
  Nu = 0.3 + 0.62 Re^{1/2} Pr^{1/3} / [1 + (0.4/Pr)^{2/3}]^{1/4} · [1 + (Re/282000)^{5/8}]^{4/5}.

Tolerances: a few floating-point operations each (rel 1e-12; the ``ht`` implementation of
Churchill-Bernstein evaluates the same expression, 1e-10 allows a different grouping).
"""

from __future__ import annotations

import pytest

from flexshaft.thermal.air import air_properties
from flexshaft.thermal.correlations import (
    forced_cylinder_nusselt,
    rotating_cylinder_nusselt,
    rotating_cylinder_nusselt_becker,
)


@pytest.mark.parametrize("T, cp", [(450.0, 1019.0), (500.0, 1024.0), (600.0, 1034.0)])
def test_specific_heat_beyond_the_table_continues_its_last_interval(T, cp):
    assert air_properties(T).specific_heat == pytest.approx(cp, rel=1e-12)


def test_specific_heat_inside_the_table_is_linear_between_its_rows():
    # 375 K: halfway between 1009 (350 K) and 1014 (400 K)
    assert air_properties(375.0).specific_heat == pytest.approx(1011.5, rel=1e-12)


@pytest.mark.parametrize("Re, Pr", [(2.0e4, 0.71), (3.0e5, 0.70)])
def test_rotating_cylinder_default_is_becker(Re, Pr):
    nu = rotating_cylinder_nusselt(Re, Pr)
    assert nu.method == "becker"
    assert nu.value == rotating_cylinder_nusselt_becker(Re, Pr).value


@pytest.mark.parametrize("Re, Pr", [(50.0, 0.71), (1.0e4, 0.70), (2.0e5, 0.72)])
def test_forced_cylinder_default_is_churchill_bernstein(Re, Pr):
    by_hand = (
        0.3
        + (0.62 * Re**0.5 * Pr ** (1.0 / 3.0) / (1.0 + (0.4 / Pr) ** (2.0 / 3.0)) ** 0.25)
        * (1.0 + (Re / 282000.0) ** (5.0 / 8.0)) ** 0.8
    )
    nu = forced_cylinder_nusselt(Re, Pr)
    assert nu.method == "churchill_bernstein"
    assert nu.value == pytest.approx(by_hand, rel=1e-10)

"""Specific heat of air inside Incropera & DeWitt's Table A.4 rows.

Incropera & DeWitt, *Fundamentals of Heat and Mass Transfer*, Table A.4 (air at atmospheric
pressure) lists c_p = 1.006, 1.007, 1.009 and 1.014 kJ/(kg K) at 250, 300, 350 and 400 K.
docs/thermal.md ("Air", line 103) takes c_p from Incropera Table A.4, so at a row c_p must be
the row's value. API contract (module docstring of flexshaft.thermal.air: c_p is the linear
interpolation of these rows): half-way between two rows it is their mean (derived here:
1008 J/(kg K) at 325 K, 1006.5 J/(kg K) at 275 K, 1011.5 J/(kg K) at 375 K).

The values are a few additions of numbers near 1e3, exact to a few ulps: rel = 1e-12 leaves
four orders of magnitude of room and still sees a 1 J/(kg K) slip (1e-3 relative) by a factor
1e9. The 1 % property check of the module's docstring would not: an extrapolation from the
400 K row through the whole table moves c_p(300 K) by 0.3 % only.

Microseconds.
"""

from __future__ import annotations

import pytest

from flexshaft.thermal.air import air_properties

INCROPERA_A4_CP = {250.0: 1006.0, 300.0: 1007.0, 350.0: 1009.0, 400.0: 1014.0}  # J/(kg K)


@pytest.mark.parametrize("T", sorted(INCROPERA_A4_CP))
def test_specific_heat_at_the_table_rows(T):
    assert air_properties(T).specific_heat == pytest.approx(INCROPERA_A4_CP[T], rel=1e-12)


@pytest.mark.parametrize(("T", "cp"), [(275.0, 1006.5), (325.0, 1008.0), (375.0, 1011.5)])
def test_specific_heat_half_way_between_rows_is_their_mean(T, cp):
    assert air_properties(T).specific_heat == pytest.approx(cp, rel=1e-12)

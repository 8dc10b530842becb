"""The cylinder correlations at the edges of their published validity ranges.

* Hilpert, cross-flow over a cylinder: Incropera & DeWitt Table 7.2 lists
  Nu_D = C Re_D^m Pr^{1/3} with C = 0.989, m = 0.330 for 0.4 ≤ Re_D ≤ 4 and C = 0.027,
  m = 0.805 for 4e4 ≤ Re_D ≤ 4e5. Both ends of the table are inclusive (docs/thermal.md, "Hover",
  line 88: "valid 0.4 ≤ Re ≤ 4×10⁵"), so at Re_D = 0.4 the
  first row applies, in range: Nu = 0.989 · 0.4^0.330 · 0.7^{1/3} = 0.649 for Pr = 0.7 (the top
  row would give 57 times less), and at Re_D = 4e5 the last row.
* Churchill-Chu, free convection from a horizontal cylinder (Incropera & DeWitt eq. 9.34):
  valid for Rayleigh numbers Ra_D = Gr_D Pr, 1e-5 ≤ Ra ≤ 1e12 (docs/thermal.md, "Parked",
  line 101: "valid 10⁻⁵ ≤ Ra ≤ 10¹²"). The range is on Ra, not on Gr: with Pr = 0.7,
  Gr = 1.2e12 gives Ra = 8.4e11, inside; Gr = 1.2e-5 gives Ra = 8.4e-6, outside.

The Hilpert values are a power and a product, exact to a few ulps: rel = 1e-12. The
Churchill-Chu range flags are booleans with Ra 16 % inside (8.4e11 against 1e12) and 16 %
outside (8.4e-6 against 1e-5) the limits (Gr itself 20 % beyond them), so no rounding can flip
them.

Microseconds.
"""

from __future__ import annotations

import pytest

from flexshaft.thermal.correlations import churchill_chu_nusselt, hilpert_nusselt


def test_hilpert_at_its_lowest_reynolds_number_uses_the_first_row():
    nu = hilpert_nusselt(0.4, 0.7)
    assert nu.in_range
    assert nu.value == pytest.approx(0.989 * 0.4**0.330 * 0.7 ** (1.0 / 3.0), rel=1e-12)


def test_hilpert_at_its_highest_reynolds_number_uses_the_last_row():
    nu = hilpert_nusselt(4e5, 0.7)
    assert nu.in_range
    assert nu.value == pytest.approx(0.027 * 4e5**0.805 * 0.7 ** (1.0 / 3.0), rel=1e-12)


def test_churchill_chu_range_is_on_the_rayleigh_number():
    assert churchill_chu_nusselt(0.7, 1.2e12).in_range  # Ra = 8.4e11 <= 1e12
    assert not churchill_chu_nusselt(0.7, 1.2e-5).in_range  # Ra = 8.4e-6 < 1e-5

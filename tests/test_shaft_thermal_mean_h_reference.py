"""The shaft's reported heat transfer coefficient is the surface average (1/A) ∫ h dA.

For a shaft whose elements have different h (segments of other diameters), the one mean h that
convects the same heat from the same surface at a uniform excess temperature is the
area-weighted mean Σ h_e A_e / Σ A_e, A_e = perimeter_e × length_e (the definition of the
average coefficient, e.g. Incropera & DeWitt, "average convection coefficient" over a surface:
derived here from q = h̄ A ΔT = Σ h_e A_e ΔT). Two elements of lengths 1 m and 2 m, perimeters
0.2 m and 0.4 m, h = 10 and 30 W/m²K: A = 0.2 and 0.8 m², h̄ = (2 + 24)/1 = 26 W/m²K
(the plain mean would be 20). Exact arithmetic: 1e-12.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.thermal.shaft import solve_shaft_temperature


def test_mean_heat_transfer_coefficient_is_area_weighted():
    x = np.array([0.0, 1.0, 3.0])
    result = solve_shaft_temperature(
        x, np.array([5.0, 5.0]), 10.0, 1e-4, np.array([0.2, 0.4]), np.array([10.0, 30.0]), 300.0
    )
    assert result.heat_transfer_coefficient == pytest.approx(26.0, rel=1e-12)

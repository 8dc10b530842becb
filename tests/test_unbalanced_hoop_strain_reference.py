"""The free hoop strain of an UNBALANCED wall (A16, A26 ≠ 0) against classical lamination theory.

N_y = 0 for a tube with a free hoop (thesis eq. 2.46): A12 ε_x + A22 ε_y + A26 γ_xy = 0, so
ε_y = −(A12 ε_x + A26 γ_xy)/A22. A single 30° ply of thickness t has A = t Q̄ with Q̄ from the
explicit forms of Jones (1999, eq. 2.84), written here from the engineering constants:
Q11 = E_L/(1 − ν_LT ν_TL), Q22 = E_T/(1 − ν_LT ν_TL), Q12 = ν_LT E_T/(1 − ν_LT ν_TL), Q66 = G_LT,
ν_TL = ν_LT E_T/E_L (Jones eq. 2.61 and the reciprocal relation). At 30° Q̄16 ≠ Q̄26, so the
shear-hoop coupling must use A26 (the y row), not A16. Closed form: agreement to 1e-12 relative
(a handful of floating-point operations on moduli of similar size).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.laminate import Lamina, Laminate, hoop_strain_free

E_L, E_T, G_LT, NU = 140e9, 10e9, 5e9, 0.3


def _qbar_row_y(angle_deg: float) -> tuple[float, float, float]:
    """(Q̄12, Q̄22, Q̄26) of Jones eq. 2.84 for a ply at ``angle_deg`` from x towards y."""
    nu_TL = NU * E_T / E_L
    d = 1.0 - NU * nu_TL
    Q11, Q22, Q12, Q66 = E_L / d, E_T / d, NU * E_T / d, G_LT
    c, s = np.cos(np.radians(angle_deg)), np.sin(np.radians(angle_deg))
    Q12b = (Q11 + Q22 - 4 * Q66) * s**2 * c**2 + Q12 * (s**4 + c**4)
    Q22b = Q11 * s**4 + 2 * (Q12 + 2 * Q66) * s**2 * c**2 + Q22 * c**4
    Q26b = (Q11 - Q12 - 2 * Q66) * s**3 * c + (Q12 - Q22 + 2 * Q66) * s * c**3
    return Q12b, Q22b, Q26b


@pytest.mark.parametrize("angle_deg", [30.0, -60.0])
def test_free_hoop_strain_of_a_single_off_axis_ply(angle_deg):
    t = 2e-3
    laminate = Laminate(np.radians([angle_deg]), np.array([t]), Lamina(E_L, E_T, G_LT, NU, 1500.0))
    Q12b, Q22b, Q26b = _qbar_row_y(angle_deg)
    eps_x, gamma = 1e-3, 2e-3
    expected = -(Q12b * t * eps_x + Q26b * t * gamma) / (Q22b * t)
    assert float(hoop_strain_free(laminate, eps_x, gamma)) == pytest.approx(expected, rel=1e-12)
    # shear alone: the hoop strain is −Q̄26/Q̄22 γ, nonzero only because the wall is unbalanced
    assert float(hoop_strain_free(laminate, 0.0, gamma)) == pytest.approx(-Q26b / Q22b * gamma, rel=1e-12)

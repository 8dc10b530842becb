"""The endless thin tube's long n = 2 helix, far below the circumferential wavenumber.

Donnell's equation of an isotropic cylinder in torsion, D ∇⁸w + (E t/R²) w,xxxx + 2 τ t ∇⁴ w,xy = 0
(Donnell 1933, NACA Report 479; Timoshenko & Gere 1961, sec. 11.12), with the helix
w = cos(k x + η y), η = n/R, gives

    τ t = [D s⁴ + E t k⁴/R²] / (2 k η s²),   s = k² + η²,   D = E t³/(12(1 − ν²)).

Donnell's kinematics on the endless tube (:func:`flexshaft.buckling.infinite_cylinder_torque`)
is the energy whose Euler-Lagrange equations these are, so its minimum over k at n = 2 is this
formula's minimum exactly. For a thin tube the minimum lies at a long axial wave: for k ≪ η,
k⁴ ≈ η⁸ R² t²/(36(1 − ν²)), so at R/t = 500, R = 1 m, k ≈ 0.075 rad/m, k/η ≈ e^-3.3, a half-wave
π/k of about forty radii. The search over k must reach that far below η = n/R.

The reference minimum is scipy's bounded scalar search of the formula over log k in (−8, 2)
(xatol 1e-10 in log k); the package's golden-section search ends within 5.5e-5 in log k of its
minimum, a relative error of order 1e-9 in T at a smooth minimum, and the rank-two helix solve is
exact to round-off: so the torque is compared to 1e-7 and the wavenumber to 1e-3 (a flat
minimum: a relative error ε in T allows about √ε in k).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.optimize

from flexshaft.buckling import infinite_cylinder_torque
from flexshaft.laminate import Lamina, Laminate

E, NU = 70e9, 0.3
R_OVER_T = 500.0


def test_the_thin_tubes_long_helix_is_donnells_minimum():
    t = 1.0 / R_OVER_T
    D = E * t**3 / (12 * (1 - NU**2))
    eta = 2.0  # n = 2 on R = 1 m

    def tau(log_k: float) -> float:
        k = np.exp(log_k)
        s = k**2 + eta**2
        return (D * s**4 + E * t * k**4) / (2 * k * eta * s**2 * t)

    best = scipy.optimize.minimize_scalar(tau, bounds=(-8.0, 2.0), method="bounded", options={"xatol": 1e-10})
    k_ref = float(np.exp(best.x))
    assert k_ref / eta < np.exp(-3.0)  # the long wave this test is about
    torque_ref = best.fun * 2 * np.pi * t  # T = 2π R² t τ, R = 1 m

    laminate = Laminate([0.0], [t], Lamina.isotropic(E, E / (2 * (1 + NU)), 2700.0))
    found = infinite_cylinder_torque(laminate, 1.0, theory="classical", kinematics="donnell", n_max=3)
    for sense in ("positive", "negative"):  # isotropic: the senses mirror each other
        torque, n, k = found[sense]
        assert n == 2
        assert torque == pytest.approx(torque_ref, rel=1e-7)
        assert abs(k) == pytest.approx(k_ref, rel=1e-3)

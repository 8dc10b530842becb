"""The endless tube's torsional buckling helix of the shear-deformable shell theory: its
minimum over the circumferential wave number n must include the oval n = 2 helix that governs
every long thin tube in torsion (Donnell 1933; Timoshenko & Gere 1961 sec. 11.12).

Independent closed form (the one of tests/test_buckling.py's Mindlin-Donnell test): Donnell's
equation for a helix w = cos(k x + eta y), s = k^2 + eta^2, eta = n/R, gives
tau t = [D s^2 + E t k^4/(R^2 s^2)] / (2 k eta) (Batdorf 1947), and first-order shear
deformation of an isotropic wall replaces D by D / (1 + D s/(k G t)) (Mindlin 1951). Minimised
over k for n = 2 and n = 3, at R/t = 100: n = 2 is the lower by a factor of about 1.5, so a
search that starts at n = 3 returns a torque 50 % too high and the wrong n. Tolerance 1e-6:
the golden-section refinement of the code leaves about 1e-9 relative and scipy's bounded
search is run to 1e-10 in log k (the same accuracy argument as the test it follows).

Written for the mutation h38b-shear-helix-n-from-three of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import scipy.optimize

from flexshaft.buckling import infinite_cylinder_torque
from flexshaft.laminate import Lamina, Laminate

E, NU = 70e9, 0.3
RADIUS, R_OVER_T = 1.0, 100.0


def _reference(n: int) -> float:
    """Lowest helix shear stress [Pa] at wave number n (closed form of the docstring)."""
    t = RADIUS / R_OVER_T
    D = E * t**3 / (12 * (1 - NU**2))
    kGt = 5 / 6 * E / (2 * (1 + NU)) * t

    def tau(log_k: float) -> float:
        k, eta = np.exp(log_k), n / RADIUS
        s = k**2 + eta**2
        D_eff = D / (1 + D * s / kGt)
        return (D_eff * s**2 + E * t * k**4 / (RADIUS**2 * s**2)) / (2 * k * eta * t)

    grid = np.log(n / RADIUS) + np.linspace(-6, 3, 200)
    start = grid[np.argmin([tau(x) for x in grid])]
    return scipy.optimize.minimize_scalar(
        tau, bounds=(start - 0.1, start + 0.1), method="bounded", options={"xatol": 1e-10}
    ).fun


def test_the_shear_theory_endless_tube_buckles_in_the_oval_n2_helix():
    t = RADIUS / R_OVER_T
    tube = Laminate([0.0], [t], Lamina.isotropic(E, E / (2 * (1 + NU)), 2700.0))
    found = infinite_cylinder_torque(tube, RADIUS, theory="shear", kinematics="donnell", n_max=12)
    tau2, tau3 = _reference(2), _reference(3)
    assert tau3 > 1.2 * tau2  # the closed form's own ordering: n = 2 governs
    for sense in ("positive", "negative"):  # an isotropic wall: both senses alike
        torque, n, _ = found[sense]
        assert n == 2
        np.testing.assert_allclose(torque / (2 * np.pi * RADIUS**2 * t), tau2, rtol=1e-6)

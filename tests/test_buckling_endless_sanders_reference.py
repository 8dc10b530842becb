"""The endless tube of the shear-deformable shell with Sanders' kinematics against the long-wave
(semi-membrane) n-lobe helix, derived here.

Helix w = W exp(i(k x + n theta)) on radius R, thickness t, shear flow tau t; u axial, v hoop,
w outward, beta_x = -w_x, beta_y = (v - w_theta)/R (Sanders). For k R << n:
* hoop inextensional and no membrane shear, eps_y = (v_theta + w)/R = 0 and
  gamma = v_x + u_theta/R = 0, give v = i w/n and u = -i k R w/n^2;
* so beta_y = -i (n^2 - 1) w/(n R), the hoop curvature kappa_y = beta_y,theta/R = (n^2 - 1) w/R^2,
  and the axial strain eps_x = u_x = k^2 R w/n^2;
* the hoop force of the mode is of the bending order (N_y ~ 0), so the axial membrane stiffness is
  E t (uniaxial; the small eps_y = -nu eps_x it implies changes v by a relative (k R/n)^2);
* energy balance over a wave (every term's average carries the same factor 1/2), bending
  D |kappa_y|^2/2 + membrane E t |eps_x|^2/2 against the shear flow's work on the nonlinear
  shear strain, tau t Re(beta_x conj beta_y) = tau t k (n^2 - 1)|W|^2/(n R):
  tau t = [D (n^2 - 1)^2/R^4 + E t k^4 R^2/n^4] n R/(2 k (n^2 - 1)) = a/k + b k^3,
  a = D n (n^2 - 1)/(2 R^3), b = E t R^3/(2 n^3 (n^2 - 1)), least at k^4 = a/(3 b) where
  tau t = (4/3) a^(3/4) (3 b)^(1/4);
* at n = 2, with D = E t^3/(12 (1 - nu^2)): k^4 = 4 t^2/((1 - nu^2) R^6) and
  tau = E/(3 sqrt 2 (1 - nu^2)^(3/4)) (t/R)^(3/2) = 0.2357 E/(1 - nu^2)^(3/4) (t/R)^(3/2).
The same formula is quoted from Timoshenko & Gere (1961) sec. 11.12 in tests/test_buckling.py
for the long finite tube, in agreement. Donnell's shallow-shell relations (beta_y = -w_theta/R,
kappa_y = n^2 w/R^2) give a = D n^3/(2 R^3), b = E t R^3/(2 n^5), so at n = 2 a tau
(4/3)^(3/4) (3/4)^(1/4) = 2/sqrt 3 times higher (+15.5 %).

Corrections at R/t = 500: the asymptote drops terms of relative order (k R)^2 =
2 (t/R)/sqrt(1 - nu^2) = 0.42 % (axial bending, twist, the hoop strain above) and thickness
terms O(t/R) = 0.2 %; transverse shear flexibility of an isotropic wall is of order
(n t/R)^2/5, about 3e-6. The code's ratio to the formula is 1 + 0.576 t/R (measured at
R/t = 100..5000; 1.00115 at R/t = 500), so the 1 % tolerance is about 9 times the deviation
while Donnell's kinematics sit at +15.6 %.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.buckling import infinite_cylinder_torque
from flexshaft.laminate import Lamina, Laminate

E, NU = 70e9, 0.3


@pytest.mark.parametrize("sense", ["positive", "negative"])
def test_endless_shear_tube_with_sanders_kinematics_matches_the_semi_membrane_helix(sense):
    """n = 2 and tau within 1 % of E/(3 sqrt 2 (1 - nu^2)^(3/4)) (t/R)^(3/2) (docstring)."""
    radius, thickness = 1.0, 1.0 / 500.0
    tube = Laminate([0.0], [thickness], Lamina.isotropic(E, E / (2 * (1 + NU)), 2700.0))
    torque, n, _ = infinite_cylinder_torque(tube, radius, theory="shear", kinematics="sanders", n_max=12)[sense]
    tau = torque / (2 * np.pi * radius**2 * thickness)
    reference = E / (3 * np.sqrt(2) * (1 - NU**2) ** 0.75) * (thickness / radius) ** 1.5
    assert n == 2
    assert tau == pytest.approx(reference, rel=0.01)

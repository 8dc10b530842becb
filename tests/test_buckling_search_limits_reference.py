"""The user's limits of the torsional buckling search: the number of axial Ritz terms M and the
largest circumferential wave number n_max of :func:`torsional_buckling_torque`.

References (derived here):

* One axial term cannot buckle in torsion. The torque's second-order work in the classical
  shell is proportional to the integral over the length of beta_x beta_y, the products of the
  normal's rotations: beta_x = -w_x is a cosine series and beta_y = (v - w_theta)/R a sine
  series (w, v = sum of sin(m pi x/L)). With M = 1 both carry only m = 1, and
  int_0^L sin(pi x/L) cos(pi x/L) dx = [sin^2(pi x/L) L/(2 pi)]_0^L = 0: the load matrix
  vanishes, no torque buckles the tube (T = inf in both senses), whatever n.
* Rayleigh-Ritz upper bound on nested trial spaces: the M = 2 series is contained in the
  default one (M >= 24, ``default_terms``), so T(M = 2) >= T(default) at every n and so for the
  minimum over n. That inequality is all the reference gives, and all that is asserted. Its
  relative tolerance 1e-9 is the round-off of two eigen-solves of differently sized problems,
  should both spaces give equal values: not a few ulp (1e-12), since the default pencil is
  larger and its stiffness spans the m^4 growth of M >= 24 terms; far below any physical
  difference. At L = 5 R, R/t = 100 the bound is not tight (measured T(M = 2) about
  1.3 T(default)): the default mode (n = 5) has 2 axial half-waves, with |W_1..W_4| = 0.90,
  1.00, 0.48, 0.08 of the largest, more than two sine terms can represent.
* n_max is "the largest circumferential wave number tried" (the docstring): the critical mode
  of a capped search has n <= n_max, and the minimum over the subset n <= n_max is at least
  the minimum over all n. At L = 3 R, R/t = 50 the free search finds n = 5.
"""

from __future__ import annotations

import numpy as np

from flexshaft.buckling import torsional_buckling_torque
from flexshaft.laminate import Lamina, Laminate

E, NU = 70e9, 0.3
ALUMINIUM = Lamina.isotropic(E, E / (2 * (1 + NU)), 2700.0)


def _tube(radius_over_thickness: float) -> Laminate:
    return Laminate([0.0], [1.0 / radius_over_thickness], ALUMINIUM)  # radius 1 m


def test_one_axial_term_carries_no_torque_work_in_the_classical_shell():
    """M = 1: the sin-cos integral of the same half-wave vanishes, so T = inf (docstring)."""
    result = torsional_buckling_torque(_tube(100.0), 1.0, 5.0, theory="classical", n_terms=1)
    assert result.n_terms == 1
    assert np.isinf(result.torque_positive) and np.isinf(result.torque_negative)


def test_two_axial_terms_bound_the_classical_torque_from_above():
    """Nested Ritz spaces: T(M = 2) >= T(default M) up to eigen-solve round-off (docstring)."""
    tube, length = _tube(100.0), 5.0
    default = torsional_buckling_torque(tube, 1.0, length, theory="classical")
    two = torsional_buckling_torque(tube, 1.0, length, theory="classical", n_terms=2)
    assert two.n_terms == 2 and default.n_terms > 2
    for coarse, fine in (
        (two.torque_positive, default.torque_positive),
        (two.torque_negative, default.torque_negative),
    ):
        assert np.isfinite(coarse)
        assert coarse >= fine * (1 - 1e-9)  # round-off of two eigen-solves (docstring)


def test_capped_wave_number_search_stays_below_the_cap_in_shear():
    """n_max = 3 of the shear theory: n <= 3 and T >= the free search's T (docstring)."""
    tube, length = _tube(50.0), 3.0
    free = torsional_buckling_torque(tube, 1.0, length, theory="shear")
    capped = torsional_buckling_torque(tube, 1.0, length, theory="shear", n_max=3)
    assert free.n_positive is not None and free.n_positive > 3  # the cap must bind
    for n in (capped.n_positive, capped.n_negative):
        assert n is not None and 2 <= n <= 3
    # a subset's minimum: relative 1e-12 covers the case of equal values only
    assert capped.torque_positive >= free.torque_positive * (1 - 1e-12)
    assert capped.torque_negative >= free.torque_negative * (1 - 1e-12)

"""The two torque senses of an unbalanced laminated tube against its mirror image (mutation
hunt 23d).

Derived reference (symmetry). Reflect the tube in a plane through its axis (the circumferential
coordinate y → −y): a ply at +θ becomes a ply at −θ, and the shear flow N_xy of a torque T
changes sign, so the reflected tube under −T is the original under +T. Hence the buckling
torques of the two senses swap between a laminate and its mirror image:

    T−(+θ laminate) = T+(−θ laminate),   T+(+θ laminate) = T−(−θ laminate),

for every branch (global helical, crimping) and either shell theory; the discrete problem is
mirror-symmetric too (harmonic n ↔ −n of the same Ritz basis), so the identity holds to
rounding. A tube of one unbalanced angle, (30)_8 carbon/epoxy (E_L 140, E_T 10, G_LT 5 GPa),
R = 50 mm, L = 1 m, t = 1 mm, has senses 8 % apart, each buckling in a global helix (the stiff
matrix keeps crimping far away). The lower global torque of the two senses, and the safety
factor of the weaker sense, then follow from the positive senses of the two laminates alone.
Tolerance 1e-9 relative: rounding of the two eigen-solves, far below the 8 % between senses.
CPU: four buckling searches, about 0.2 s.
"""

from __future__ import annotations

import pytest

from flexshaft.buckling import buckling_safety_factor, torsional_buckling_torque
from flexshaft.laminate import Lamina, Laminate

CARBON = Lamina.from_loss_factors(140e9, 10e9, 5e9, 0.3, 1600.0, 0.0, 0.0, 0.0)
RADIUS, LENGTH, WALL = 0.05, 1.0, 1e-3


@pytest.mark.parametrize("theory", ["classical", "shear"])
def test_the_weaker_global_sense_is_the_mirror_laminates_positive_sense(theory):
    plus = torsional_buckling_torque(Laminate.from_layup("(30/30/30/30)s", WALL, CARBON), RADIUS, LENGTH, theory=theory)
    mirror = torsional_buckling_torque(
        Laminate.from_layup("(-30/-30/-30/-30)s", WALL, CARBON), RADIUS, LENGTH, theory=theory
    )
    negative = mirror.global_torque_positive  # T− of the +30° tube, by the reflection
    assert plus.global_torque_negative == pytest.approx(negative, rel=1e-9)
    weaker = min(plus.global_torque_positive, negative)
    assert abs(plus.global_torque_positive - negative) > 0.05 * weaker  # the senses differ
    assert plus.global_torque == pytest.approx(weaker, rel=1e-9)
    assert plus.governing == "global helical" and plus.critical_torque == pytest.approx(weaker, rel=1e-9)
    torque = 100.0  # [N m], either sense
    assert buckling_safety_factor(plus, -torque, signed=True) == pytest.approx(negative / torque, rel=1e-9)
    assert buckling_safety_factor(plus, torque) == pytest.approx(weaker / torque, rel=1e-9)


def test_the_negative_senses_mode_numbers_are_the_mirror_laminates_positive_ones():
    """By the same reflection, the negative sense's critical mode of the +30° tube is the
    positive sense's mode of the −30° tube: the same circumferential wave number n and axial
    half-wave count m (the index of the largest sine term of w). At L = 1 m the two senses of
    the +30° tube buckle in different helices (n = 3 and 2, m = 2 and 1), so a negative sense
    that repeats the positive sense's numbers is seen. Integers: compared exactly. Written for
    h41b-torque-half-waves-negative-from-positive (one classical search per laminate, 0.05 s)."""
    plus = torsional_buckling_torque(
        Laminate.from_layup("(30/30/30/30)s", WALL, CARBON), RADIUS, LENGTH, theory="classical"
    )
    mirror = torsional_buckling_torque(
        Laminate.from_layup("(-30/-30/-30/-30)s", WALL, CARBON), RADIUS, LENGTH, theory="classical"
    )
    assert (plus.n_negative, plus.axial_half_waves_negative) == (mirror.n_positive, mirror.axial_half_waves_positive)
    assert (plus.n_positive, plus.axial_half_waves_positive) == (mirror.n_negative, mirror.axial_half_waves_negative)
    assert (plus.n_positive, plus.axial_half_waves_positive) != (plus.n_negative, plus.axial_half_waves_negative)

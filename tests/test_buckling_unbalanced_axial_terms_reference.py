"""Default axial resolution of the classical Ritz solution for an unbalanced laminate.

An unbalanced (all +45 degree) soft-matrix wall buckles into helices of very different pitch in
the two torque senses: the endless tube's positive-sense helix (n = 7) has about eight times the
axial wavenumber of the negative-sense one (n = 2). The default number of axial Ritz terms must
resolve the shorter of the two helices, else the Ritz torque of that sense (an upper bound)
comes out too high and at the wrong n.

References, independent of the finite-length Ritz solution:

* the endless tube (:func:`flexshaft.buckling.infinite_cylinder_torque`): one helical harmonic
  exp(i(k x + n theta)) solves the shell equations exactly, minimised over n and k. A simply
  supported tube of finite length is stiffer (its ends hold w = v = 0), so its torque lies above
  the endless tube's and tends to it as L grows (derived here: the end constraints only add
  restraint; the n of the minimum is the endless tube's once the tube holds many half-waves);
* Ritz convergence: the Ritz torque is an upper bound that falls monotonically as terms are
  added, so a converged default must move little when the number of terms is raised by half.

The endless-tube reference and the Ritz code share ``_common.shell_stiffness`` (the laminate
stiffness C), and the Ritz default term count is sized from ``classical_helix_torque``'s k, so
these tests check the axial resolution, not the stiffness. Lower bound T_Ritz ≥ T_endless: the
Ritz admissible field, extended over 2L, is an admissible field of the endless tube. The 2.5 % band
is about twice the measured end effect (1.18 % positive, 1.33 % negative at 1.5 m), which
decays as 1/L² (positive sense: 4.70 % → 1.18 % → 0.29 % at 0.75, 1.5 and 3 m).
About 0.15 s CPU for the file (the 1.5×-terms fixture 0.07 s, where doubled terms took 0.16 s).
"""

from __future__ import annotations

import pytest

from flexshaft.buckling import infinite_cylinder_torque, torsional_buckling_torque
from flexshaft.laminate import Lamina, Laminate

#: carbon fibre in a soft (elastomeric) matrix: the FMC case, transverse and shear moduli 2000x
#: and 5000x below the fibre modulus
_FMC = Lamina(E_L=100e9, E_T=0.05e9, G_LT=0.02e9, nu_LT=0.35, density=1500.0)
_RADIUS = 0.05  # mid-surface radius [m]
_LENGTH = 1.5  # span between the simple supports [m]: about 47 axial half-waves of the n = 7 helix


@pytest.fixture(scope="module")
def unbalanced():
    laminate = Laminate.from_layup([45, 45, 45, 45], 2e-3, _FMC)
    endless = infinite_cylinder_torque(laminate, _RADIUS, theory="classical")
    finite = torsional_buckling_torque(laminate, _RADIUS, _LENGTH, theory="classical")
    return laminate, endless, finite


def test_the_two_senses_buckle_into_helices_of_different_pitch(unbalanced):
    """Premise of the other tests: the positive-sense helix is the short one (|k+| > 4 |k-|), so a
    default taken from the longer helix would under-resolve it."""
    _, endless, _ = unbalanced
    assert abs(endless["positive"][2]) > 4.0 * abs(endless["negative"][2])


@pytest.mark.parametrize("sense", ["positive", "negative"])
def test_default_terms_give_the_endless_tube_torque_and_wave_number(unbalanced, sense):
    """Each sense's finite-tube torque lies above the endless tube's (end restraint) by less than
    2.5 %, at the endless tube's n.

    Tolerance: the simply supported ends of a 1.5 m tube (about 47 half-waves of the positive
    helix, 6 of the negative one) raise the torque by about 1.2 % (positive) and 1.3 % (negative)
    over the endless tube, and that excess shrinks with length (4.7 % at 0.75 m, 2.7 % at 1.0 m);
    2.5 % is about twice the end effect and far below the 17 % excess (at n = 4 instead of 7) of
    a Ritz series that resolves only the longer, negative-sense helix."""
    _, endless, finite = unbalanced
    T_endless, n_endless, _ = endless[sense]
    T = finite.torque_positive if sense == "positive" else finite.torque_negative
    n = finite.n_positive if sense == "positive" else finite.n_negative
    assert T_endless < T < 1.025 * T_endless
    assert n == n_endless


@pytest.fixture(scope="module")
def more_terms(unbalanced):
    laminate, _, finite = unbalanced
    return torsional_buckling_torque(laminate, _RADIUS, _LENGTH, theory="classical", n_terms=3 * finite.n_terms // 2)


@pytest.mark.parametrize("sense", ["positive", "negative"])
def test_default_terms_are_converged(unbalanced, more_terms, sense):
    """Raising the default number of axial terms by half (76 → 114) lowers each sense's Ritz
    torque (an upper bound) by less than 0.3 %.

    Tolerance: the measured drop is 0.057 % (positive) and 0.003 % (negative); 0.3 % is five
    times the larger and well below the 10 % drop (24 → 36 terms) of a series sized for the
    longer helix only."""
    _, _, finite = unbalanced
    T = finite.torque_positive if sense == "positive" else finite.torque_negative
    T2 = more_terms.torque_positive if sense == "positive" else more_terms.torque_negative
    assert T2 <= T * (1.0 + 1e-9)  # Ritz: more terms never raise the bound (1e-9: eigen-solve round-off)
    assert T2 > T * (1.0 - 3e-3)

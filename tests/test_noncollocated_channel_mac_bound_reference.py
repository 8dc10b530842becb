"""The MAC bound of the hysteretic root pairing with a stateless non-collocated bearing channel.

:func:`flexshaft.analyses.hysteretic_roots.mac_bounds` bounds |yᴴv| for the unit null vector y
of ``T(s) = s² I + s D + K`` (modal coordinates) from the roots alone; the pairing of on-line
roots (``_may_pair``) and the screened matching of the tracking exclude every root whose bound
is small. Derived here: whatever its construction, a valid answer is either None (no bound) or a
number at least |yᴴv| for every root and column. A non-collocated PD magnetic bearing (sensor
off its magnet, no controller states) adds ``(k + s d) B_aᵀ B_s`` to T(s) (the force at the
magnet follows the sensed displacement; tests/test_noncollocated_dynamic_stiffness_reference.py),
a coupling of the modes that D and K do not hold; a bound built from D and K alone can then be
far below the true overlap (measured: about 0 where |yᴴy| = 1).

The reference is the bound's own definition applied to the product's T(s): for each root s of
each branch's linear problem (weights of :func:`~flexshaft.analyses.hysteretic_roots.branches`),
the right singular vector of the smallest singular value of T(s) from
:meth:`~flexshaft.analyses.eigen.ReducedModel.newton_terms`, computed here with an SVD (no
eigen-solve of the module), and the overlaps |yᴴv| of those vectors. The roots are cross-checked
by the first-order matrix's own (branch_roots): T(s) is singular at each, its smallest singular
value, the residual ‖T(s) y‖ of the vector, at most 1e-9 of the largest (the dense solve's roots
are accurate to about 1e-13 relative). The vector lies in T's null space: of a double root (the
isotropic rotor's v and w), any unit vector of its plane, which the bound covers too (its
derivation holds for every unit y with T(s) y = 0). The bound is asserted to hold with a 1e-6
margin (the null vectors' error over the gaps to the other roots is far smaller), far below the
overlaps of order 1 it must cover.

With the correct code mac_bounds returns None for this rotor (it has a stateless channel), so
the comparison runs only when a mutation makes it return a bound; that is the point: a valid
answer is None or a true bound, and a bound built without the channel's coupling is not one.

Rotor: the Jeffcott test tube with loss η = 0.05, a dashpot at the disk and the magnet at
x = 0.3 m, sensor 0.1 m further (as in that test). CPU: an 8-mode basis, milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import M_DISK, WN, jeffcott_text

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import branch_roots, branches, mac_bounds
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KI, KP, KD, KS = 100.0, 5.0e3, 2.0, 2.0e5  # [N/A], [A/m], [A s/m], [N/m]


@pytest.fixture(scope="module")
def reduced():
    text = jeffcott_text(0.05, 2 * 0.01 * M_DISK * WN, elements=10)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    magnet = (
        '[[bearings]]\nname = "m"\nx = 0.3\nkind = "active"\nsensor_offset = 0.1\n'
        f"ki = {KI}\nkp = {KP}\nkd = {KD}\nks = {KS}\n"
    )
    model = build_model(loads_design(head + magnet + tail))
    assert not model.actuators[0].collocated
    return reduce(model, 8)


@pytest.mark.parametrize("speed", [0.0, 500.0])
def test_the_bound_holds_or_is_withheld_with_a_noncollocated_channel(reduced, speed):
    red = reduced
    assert any(a.law is None and (a.stiffness or a.damping) for a in red.actuators)  # stateless channels
    for branch in branches(red, speed):
        s, _ = branch_roots(red, speed, branch.weights)
        # the 4 of lowest |s|: the disk pair (322 rad/s), the single axial root (3 854 rad/s) and
        # one root of the 1.28e6 rad/s tube pair (a double root at rest, cut in two); on the lower
        # branch at 500 rad/s a nearly critically damped root (-2.35e5 + 1.2e4i rad/s) comes fourth
        s = s[:4]
        Y = np.empty((red.size, s.size), complex)
        for k, root in enumerate(s):
            T, _ = red.newton_terms(complex(root), speed, branch.weights, np.ones(red.size, complex))
            _, sigma, vh = np.linalg.svd(T)
            assert sigma[-1] <= 1e-9 * sigma[0]  # a null vector (of a double root's plane: any one)
            Y[:, k] = vh[-1].conj()
        bound = mac_bounds(red, speed, branch.weights, s, Y)
        if bound is None:
            continue
        actual = np.abs(Y.conj().T @ Y)
        assert np.all(bound >= actual - 1e-6), (speed, branch)

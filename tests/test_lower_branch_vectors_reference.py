"""The vectors of the roots below the spin (hysteretic_roots.consistent_values_below, lowest_roots).

Reference (derived in tests/test_damping.py and the module docstring of
flexshaft.analyses.hysteretic_roots): on the Jeffcott-like rotor of tests/rotors.py with the
rotating-frame loss, above the first critical speed both whirls of the disk mode lie below the
spin, on the lower branch (loss weights of σ = −1). In r = v + i w the backward whirl solves
``m s² + c_e s + k(1 + iη) = 0`` (root s_b with Im s > 0), the forward one
``m s² + c_e s + k(1 − iη) = 0``, whose root with Im s > 0 is ``s_f = −c_e/m − s̄_b`` (unstable
here: ηω_n > c_e/m). The rotor is axisymmetric, so each vector is a circular whirl of the disk:
the forward one ``(v, w) ∝ (1, −i)`` (forward part (v + iw)/2 only, the convention of
tests/test_damping.py's forward load), the backward one ``∝ (1, +i)``. The two branches share
the backward root but not the forward one (the upper branch's forward root is s_b): a forward
vector found on the upper branch's problem is a mixture of both whirls, and one taken from the
other root has the other whirl.

Tolerances. Roots: the tube's mass (7e-6 of the disk's) and the mesh, 1e-4 relative as in
tests/test_damping.py. Vectors: a backward-stable eigenvalue solve of the first-order matrix A
errs by up to δ = ε‖A‖₂ (ε = 2.2e-16; ‖A‖₂ ≈ 2e13 rad²/s², the tube's stiff modes), which
leaves the inverse-iteration vector a residual ‖T(s) y‖ ≈ δ ‖T'(s)‖ with
``T'(s) = 2 s I + ΩG + C`` and an admixture of the other whirl of about δ/|s_f − s_b|
(|s_f − s_b| ≈ ηω_n); ten times these bounds are asserted (about 30 and 1e-2; a vector from
the upper branch's problem has a residual near 3e3 and equal parts of both whirls). The
residual is taken on the LOWER branch's problem, built in the test from the weights
``(i, 0, 1)`` of σ = −1 (tests/test_stability.py's ``BELOW``). Small model (8 elements, 12
modes: 24 x 24 first-order matrices), well under a second.

The pairing's candidates (``_may_pair``): a lower-branch root above the line gets its vector only
when a bound on its MAC with one of the upper roots below the line reaches half of
SAME_MODE_MAC; the bound must hold for every unit vector, whatever the coupling. Reference: the
roots and vectors of a small quadratic problem by a dense solve of its first-order matrix, built
in the test, with a rank-one dashpot (``c b bᵀ``: a bearing damper seen by every mode) coupling
two close modes so strongly that their vectors nearly coincide (c = 5: MAC 0.95 between the two
roots near 102 rad/s; c = 3 and 10: 0.38 and 0.24): every root must be kept for every vector
(its own included) with which its MAC reaches SAME_MODE_MAC / 2. An exact property (no tolerance).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.eigen import ReducedModel, reduce
from flexshaft.analyses.hysteretic_roots import SAME_MODE_MAC, _may_pair, consistent_values_below, lowest_roots
from flexshaft.analyses.loss import LossCoefficients

ETA = 0.02
C_E = 2 * 0.003 * M_DISK * WN
BELOW = LossCoefficients(1j, 0.0, 1.0)  # weights of F, K_lat, K_lat S below the spin (σ = −1)
EPS = np.finfo(float).eps


@pytest.fixture(scope="module")
def rotor():
    model = jeffcott(ETA, C_E)
    return model, reduce(model, 12)


def _lower_problem(red, speed, s):
    """The lower branch's ``T(s)`` and ``‖T'(s)‖₂``, assembled here from the projected matrices."""
    damping = speed * red.G + red.C
    stiffness = np.diag(red.w2) + BELOW.fixed * red.F + BELOW.lateral * red.L + BELOW.circulatory * red.S
    T = s * s * np.eye(red.size) + s * damping + stiffness
    return T, 2 * abs(s) + np.linalg.norm(damping, 2)


def _first_order_norm(red, speed):
    """‖A‖₂ of the lower branch's first-order matrix [[0, I], [−K, −D]], assembled here."""
    damping = speed * red.G + red.C
    stiffness = np.diag(red.w2) + BELOW.fixed * red.F + BELOW.lateral * red.L + BELOW.circulatory * red.S
    nb = red.size
    A = np.block([[np.zeros((nb, nb)), np.eye(nb)], [-stiffness, -damping]])
    return np.linalg.norm(A, 2)


@pytest.mark.parametrize("solver", ["consistent_values_below", "lowest_roots"])
def test_the_whirls_below_the_spin_carry_their_own_lower_branch_vectors(rotor, solver):
    model, red = rotor
    speed = 1.5 * WN  # both disk whirls below the spin; the tube's modes far above it
    roots = np.roots([M_DISK, C_E, K_SHAFT * (1 + 1j * ETA)])
    s_b = roots[np.argmax(roots.imag)]
    s_f = -C_E / M_DISK - np.conj(s_b)
    assert s_f.real > 0 and s_f.imag < speed  # the reference case: unstable forward whirl below the spin
    if solver == "consistent_values_below":
        s, Y = consistent_values_below(red, speed)
    else:
        s, Y = lowest_roots(red, speed, 2)
    free = list(model.dofs.free)
    rows = [free.index(d) for d in disk_dofs(model)]
    delta = 10 * EPS * _first_order_norm(red, speed)
    for want, whirl in ((s_f, +1), (s_b, -1)):
        near = np.flatnonzero(np.abs(s - want) <= 1e-4 * abs(want))
        assert near.size == 1, (want, s[:4])
        y = Y[:, near[0]]
        assert np.linalg.norm(y) == pytest.approx(1.0, rel=1e-12)
        T, slope = _lower_problem(red, speed, complex(s[near[0]]))
        assert np.linalg.norm(T @ y) <= delta * slope
        v, w = red.shapes(y[:, None])[rows, 0]
        forward, backward = abs(v + 1j * w) / 2, abs(v - 1j * w) / 2
        own, other = (forward, backward) if whirl > 0 else (backward, forward)
        assert other <= delta / abs(s_f - s_b) * own


@pytest.mark.parametrize("c", [3.0, 5.0, 10.0])
def test_a_root_whose_mac_may_reach_the_pairing_threshold_keeps_its_vector(c):
    w2 = np.array([1.0, 1.1, 4.0, 9.0]) * 1e4  # two close modes near 100 rad/s, two far ones
    b = np.array([1.0, 1.0, 0.5, 0.2])
    zero = np.zeros((4, 4))
    loss = np.diag(0.02 * w2)
    red = ReducedModel(np.eye(4), w2, zero, c * np.outer(b, b), loss, zero, zero, "rotating", (), True)
    speed = 1000.0  # every root below it: the lower branch's problem, K = Λ + i F (BELOW)
    A = np.block([[zero, np.eye(4)], [-(np.diag(w2) + BELOW.fixed * loss), -red.C]])
    lam, V = la.eig(A)
    keep = lam.imag > 0
    lam, Y = lam[keep], V[:4, keep] / np.linalg.norm(V[:4, keep], axis=0)
    mac = np.abs(Y.conj().T @ Y) ** 2
    off = mac - np.diag(np.diag(mac))
    assert off.max() >= 0.5 * SAME_MODE_MAC  # the case holds a pair of distinct roots that may match
    for i, j in zip(*np.nonzero(mac >= 0.5 * SAME_MODE_MAC)):
        assert _may_pair(red, speed, BELOW, lam[[i]], Y[:, [j]])[0], (c, lam[i], lam[j], mac[i, j])

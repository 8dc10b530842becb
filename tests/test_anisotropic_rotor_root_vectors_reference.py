"""Roots and vectors of the hysteretic problem on an anisotropic Jeffcott rotor (hysteretic_roots).

The rotor: the Jeffcott-like rotor of tests/rotors.py (disk mass m on a near-massless tube of
stiffness k at the disk, loss factor η) with a bearing at the disk acting in v only: a lossless
spring k_b = 0.2 k and a dashpot c_v = m ω_v, ω_v = √((k + k_b)/m) (ζ_v = 1/2). Derived here:
at rest the rotating-frame loss has no circulatory part (weights (i, i, 0): the code docstring
of flexshaft.analyses.hysteretic_roots, not a hand-written doc), so the two bending planes of
the disk are uncoupled and each obeys its own scalar equation,

    v:  m s² + c_v s + k(1 + iη) + k_b = 0,        w:  m s² + k(1 + iη) = 0.

Their roots with Im s > 0: s_w ≈ i ω_n (|s_w| ≈ ω_n = √(k/m)) and s_v with |s_v| ≈ 1.095 ω_n but
Im s_v ≈ ω_v √(1 − ζ_v²) ≈ 0.949 ω_n: the order by |s| (w, then v) is the reverse of the order
by damped frequency (v, then w), a 5 % difference either way. The distance between the two
roots, |s_v − s_w| ≈ 0.50 |s_v|, is what a relative neighbour window of 0.6 takes in and an
absolute one of 0.6 rad/s does not.

Vectors: a returned unit vector y of a root s must be the null vector of its own branch's
problem T(s) (the branch of Im s: below the spin the lower one, the same code docstring),
which the test finds by a singular value decomposition of T(s) (its right singular vector
of the smallest singular value). Tolerance: both the code's vector and the SVD's are perturbed
by the dense solve's root error δs <= ε‖A‖ ≈ 5e-3 rad/s (ε = 2.2e-16, ‖A‖ ≈ 2e13 the stiffest
tube mode's ω²) by at most δs |T'(s)| / σ₂ ≈ 5e-3 × 600 / 1e5 ≈ 3e-5 (σ₂ ≈ 1e5 the second
smallest singular value of T(s) here), so 1 − MAC <= 1e-9; the other branch's null vector at the
same s differs by the loss the two branches do not share (of order η k: 1 − MAC ≈ 3e-4 here).
1 − MAC <= 1e-6 separates the two. Roots: 1e-4 relative to the closed form, the tube's mass
(3.5e-6 of the disk's) and the mesh, as in tests/test_damping.py.
The SVD check builds T(s) with the product's own ``newton_terms``, so it checks the vectors
against the code's T(s); independently of it, at rest the planes are uncoupled (above), so the
physical shape Φ y of the v-root (the free-DOF vector) lies in the v plane (v, γ) and that of
the w-root in the w plane (w, β): the other plane's part is zero but for round-off. Measured:
‖w part‖/‖Φ y‖ = 1.2e-9 for the v-root (1.5e-9 on Prescott) and ‖v part‖/‖Φ y‖ = 2e-17 for
the w-root. Bound: a round-off coupling of the planes of size ε‖A‖ ≈ 5e-3 rad²/s² (above)
against the other plane's problem at s, whose smallest singular value is about
|s_v² − s_w²| ≈ 1e5, mixes in at most 5e-3/1e5 = 5e-8 of the other plane; 1e-6 is 20 times that,
and a vector of the wrong root (the other plane) has a ratio near 1.
Small model (8 elements, 12 modes): every solve is of a 24 × 24 matrix, well under a second.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import branch_roots, branches, consistent_values_below, lowest_roots, on_branch
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA = 0.02
K_B = 0.2 * K_SHAFT
W_V = np.sqrt((K_SHAFT + K_B) / M_DISK)
C_V = M_DISK * W_V  # ζ_v = c_v / (2 m ω_v) = 1/2


def _upper_root(coefficients) -> complex:
    roots = np.roots(coefficients)
    return complex(roots[np.argmax(roots.imag)])


S_W = _upper_root([M_DISK, 0.0, K_SHAFT * (1 + 1j * ETA)])
S_V = _upper_root([M_DISK, C_V, K_SHAFT * (1 + 1j * ETA) + K_B])


@pytest.fixture(scope="module")
def model():
    text = (
        jeffcott_text(ETA, 0.0)
        .replace("stiffness = {}", f"stiffness = {{ v = {K_B} }}")
        .replace("damping = { v = 0.0, w = 0.0 }", f"damping = {{ v = {C_V} }}")
    )
    assert f"v = {C_V}" in text  # the bearing of the reference was built
    return build_model(loads_design(text))


@pytest.fixture(scope="module")
def red(model):
    return reduce(model, 12)


def _other_plane_fraction(model, red, y, own: tuple[str, str]) -> float:
    """‖part of the physical shape Φ y outside the plane ``own``‖ / ‖Φ y‖ (free DOFs)."""
    dofs = model.dofs
    nodes = np.arange(dofs.n_shaft_nodes)
    other = ("w", "beta") if own == ("v", "gamma") else ("v", "gamma")
    assert own in (("v", "gamma"), ("w", "beta"))
    rows = np.isin(np.asarray(dofs.free), np.concatenate([dofs.index("shaft", nodes, f) for f in other]))
    assert 0 < rows.sum() < rows.size  # the other plane holds free DOFs (16 of the 48 here)
    shape = red.shapes(y)
    return float(np.linalg.norm(shape[rows]) / np.linalg.norm(shape))


def _one_minus_mac_with_null_vector(red, speed, s, y) -> float:
    """1 − MAC of ``y`` with the null vector of its own branch's T(s), found by an SVD."""
    branch = next(b for b in branches(red, speed) if on_branch(b, s.imag, speed))
    T, _ = red.newton_terms(complex(s), speed, branch.weights, y)
    null = np.linalg.svd(T)[2][-1].conj()
    return 1.0 - abs(np.vdot(null, y)) ** 2 / np.vdot(y, y).real


def test_the_reference_orders_disagree():
    """The premise: |s_w| < |s_v| but Im s_v < Im s_w, each by a few per cent."""
    assert abs(S_W) < 0.95 * abs(S_V)
    assert S_V.imag < 0.97 * S_W.imag


def test_roots_at_rest_are_sorted_by_modulus_not_by_frequency(red):
    """branch_roots and consistent_values_below return the roots sorted by |s| (their
    documented order): s_w before s_v although s_v whirls slower."""
    (only,) = branches(red, 0.0)
    for s in (branch_roots(red, 0.0, only.weights)[0], consistent_values_below(red, 0.0)[0]):
        assert np.all(np.diff(np.abs(s)) >= 0)
        assert abs(s[0] - S_W) <= 1e-4 * abs(S_W)
        assert abs(s[1] - S_V) <= 1e-4 * abs(S_V)


def test_the_neighbour_window_is_relative_to_the_modulus(model, red):
    """lowest_roots(…, window=0.6) returns a vector for the wanted mode (the lowest damped
    frequency: s_v) and for every root within 0.6 |s_v| of it (s_w, about 0.5 |s_v| away, far
    more than 0.6 rad/s); each vector is the null vector of T(s)."""
    s, Y = lowest_roots(red, 0.0, 1, window=0.6)
    k_w = int(np.argmin(np.abs(s - S_W)))
    k_v = int(np.argmin(np.abs(s - S_V)))
    assert abs(s[k_w] - S_W) <= 1e-4 * abs(S_W) and abs(s[k_v] - S_V) <= 1e-4 * abs(S_V)
    for k in (k_v, k_w):
        assert np.linalg.norm(Y[:, k]) == pytest.approx(1.0, abs=1e-12)
        assert _one_minus_mac_with_null_vector(red, 0.0, s[k], Y[:, k]) <= 1e-6
    # independent of T(s): at rest each root's shape lies in its own plane (docstring, 1e-6)
    assert _other_plane_fraction(model, red, Y[:, k_v], ("v", "gamma")) <= 1e-6
    assert _other_plane_fraction(model, red, Y[:, k_w], ("w", "beta")) <= 1e-6


def test_roots_below_the_spin_keep_their_own_branch_vectors(red):
    """At Ω = 1.5 ω_n both disk modes whirl below the spin: they are roots of the lower
    branch's problem T₋, and their vectors from lowest_roots must be T₋'s null vectors (not
    those of the upper branch's T₊ at the same s, which differ by the circulatory loss)."""
    speed = 1.5 * WN
    s, Y = lowest_roots(red, speed, 2)
    for k in range(2):
        assert 0.0 < s[k].imag < speed
        assert np.linalg.norm(Y[:, k]) == pytest.approx(1.0, abs=1e-12)
        assert _one_minus_mac_with_null_vector(red, speed, s[k], Y[:, k]) <= 1e-6

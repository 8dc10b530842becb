"""The whirl tracking's match from the vectors of a few roots (analyses/screened_match.py).

Reference: the match of the previous curves to every hysteretic root with every vector, built
here from dense eigen-solutions (scipy.linalg.eig) of the two branches' first-order matrices
``[[0, I], [−K, −D]]``, K = Λ + w_F F + w_L L + w_S S, D = ΩG + C, assembled in the test with the
rotating-frame loss weights of flexshaft.analyses.loss (derived in tests/test_damping.py and the
docstring of flexshaft.analyses.hysteretic_roots): ``(i, i, 0)`` above the spin, ``(i, 0, 1)``
below it; R(Ω) is every root on its own branch's side (0 < Im s <= Ω below, Im s >= Ω above;
the case has no mode near the spin, so no on-line root: checked, one root per mode). Each curve
is assigned by scipy.optimize.linear_sum_assignment on the cost 1 − MAC + 0.1 |Δω|/ω of
flexshaft.analyses.campbell's match (its definition, restated here).

The model: six modal coordinates (Λ = diag ω², ω 100-548 rad/s), gyroscopic pairs, a dashpot
``c b bᵀ`` seen by every mode (a bearing damper: it couples them), loss matrices. Small on
purpose (12 x 12 first-order matrices, milliseconds): the match is a statement about any
model's roots and vectors, not about a mesh.

Tolerances. The roots of a backward-stable dense solve err by about ε‖A‖ (‖A‖ ≈ 3e5 rad²/s²:
7e-11 rad/s, 1e-12 relative to |s| >= 100); the two solves (with and without vectors) differ by
as much, and a vector by that over the distance to the next root (> 2 rad/s here): 1e-9 is
asserted for both, far above round-off, far below any other root.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from scipy.optimize import linear_sum_assignment

from flexshaft.analyses.eigen import ReducedModel
from flexshaft.analyses.hysteretic_roots import mac_bounds
from flexshaft.analyses.loss import LossCoefficients
from flexshaft.analyses.screened_match import screened_match

ABOVE = LossCoefficients(1j, 1j, 0.0)
BELOW = LossCoefficients(1j, 0.0, 1.0)
SPEED, PREVIOUS = 150.0, 135.0
N_CURVES = 4  # the curves near 100, 102, 200, 207 rad/s: the roots near 400 and 548 rad/s are not tracked


def _model() -> ReducedModel:
    w2 = np.array([1.0, 1.05, 4.0, 4.3, 16.0, 30.0]) * 1e4
    G = np.zeros((6, 6))
    for i, g in ((0, 0.3), (2, 0.5), (4, 0.4)):
        G[i, i + 1], G[i + 1, i] = g, -g
    b = np.array([1.0, 0.8, 0.6, 0.5, 0.3, 0.2])
    skew = G / np.abs(G).max()
    S = 0.02 * skew * np.sqrt(np.outer(w2, w2))
    return ReducedModel(
        np.eye(6), w2, G, 20.0 * np.outer(b, b), 0.005 * np.diag(w2), 0.02 * np.diag(w2), S, "rotating", (), True
    )


def _branch(red: ReducedModel, speed: float, w: LossCoefficients):
    """Every root with Im s > 0 of one branch and its unit modal coordinates (dense, here)."""
    K = np.diag(red.w2) + w.fixed * red.F + w.lateral * red.L + w.circulatory * red.S
    D = speed * red.G + red.C
    n = red.size
    lam, V = la.eig(np.block([[np.zeros((n, n)), np.eye(n)], [-K, -D]]))
    keep = lam.imag > 0
    Y = V[:n, keep]
    return lam[keep], Y / np.linalg.norm(Y, axis=0)


def consistent_from(red: ReducedModel, speed: float):
    """R(Ω) with every vector, sorted by |s| (no mode lies near the spin: one root per mode)."""
    lo, Y_lo = _branch(red, speed, BELOW)
    hi, Y_hi = _branch(red, speed, ABOVE)
    keep_lo, keep_hi = lo.imag <= speed, hi.imag >= speed
    s = np.concatenate([lo[keep_lo], hi[keep_hi]])
    Y = np.hstack([Y_lo[:, keep_lo], Y_hi[:, keep_hi]])
    assert s.size == red.size  # no fold, no gap at the line
    order = np.argsort(np.abs(s))
    return s[order], Y[:, order]


def _reference_match(lam_prev, Y_prev, s, Y):
    cost = 1 - np.abs(Y_prev.conj().T @ Y) ** 2
    cost = cost + 0.1 * np.abs(lam_prev.imag[:, None] - s.imag[None, :]) / np.abs(lam_prev.imag)[:, None]
    rows, cols = linear_sum_assignment(cost)
    return cols[np.argsort(rows)]


def test_the_match_from_a_few_vectors_is_the_match_from_every_vector():
    red = _model()
    lam_prev, Y_prev = consistent_from(red, PREVIOUS)
    lam_prev, Y_prev = lam_prev[:N_CURVES], Y_prev[:, :N_CURVES]
    s_ref, Y_ref = consistent_from(red, SPEED)
    cols = _reference_match(lam_prev, Y_prev, s_ref, Y_ref)
    found = screened_match(red, SPEED, lam_prev, Y_prev)
    assert found is not None
    s, Y, index = found
    assert np.any(~np.any(Y, axis=0))  # some roots were left without their vector (the bound excluded them)
    assert np.allclose(s, s_ref, rtol=1e-9, atol=0)
    assert np.allclose(s[index], s_ref[cols], rtol=1e-9, atol=0)
    mac = np.abs(np.einsum("ij,ij->j", Y[:, index].conj(), Y_ref[:, cols])) ** 2
    assert np.all(mac >= 1 - 1e-9)


def test_a_curve_whose_shape_is_a_root_left_out_is_not_matched_from_the_few_vectors():
    """A previous shape equal to a root above the band (near 548 rad/s) costs that root least:
    the screened match must not pick a candidate instead (None: the caller solves every vector)."""
    red = _model()
    lam_prev, Y_prev = consistent_from(red, PREVIOUS)
    s_ref, Y_ref = consistent_from(red, SPEED)
    top = int(np.argmax(np.abs(s_ref)))
    lam, Y = lam_prev[:N_CURVES].copy(), Y_prev[:, :N_CURVES].copy()
    Y[:, -1] = Y_ref[:, top]
    assert _reference_match(lam, Y, s_ref, Y_ref)[-1] == top  # the reference picks the root left out
    found = screened_match(red, SPEED, lam, Y)
    assert found is None or np.isclose(found[0][found[2][-1]], s_ref[top], rtol=1e-9, atol=0)
    assert found is None  # that root is above the candidates' band: no vector, so no match


@pytest.mark.parametrize("speed", [SPEED, 600.0])
def test_the_mac_bound_holds_for_every_root_and_vector(speed):
    """mac_bounds is an upper bound of |yᴴv| for the root's unit null vector y: checked against
    the dense solve's vectors (round-off 1e-12 relative) for the basis vectors and random ones."""
    red = _model()
    rng = np.random.default_rng(7)
    V = np.hstack([np.eye(6), rng.standard_normal((6, 8)) + 1j * rng.standard_normal((6, 8))])
    V /= np.linalg.norm(V, axis=0)
    for weights in (ABOVE, BELOW):
        s, Y = _branch(red, speed, weights)
        mac = np.abs(Y.conj().T @ V) ** 2
        bound = mac_bounds(red, speed, weights, s, V)
        assert bound is not None and bound.shape == mac.shape
        assert np.all(bound**2 >= mac * (1 - 1e-9) - 1e-12)
        assert np.any(bound**2 < 0.5)  # not vacuous: the bound excludes some pairs

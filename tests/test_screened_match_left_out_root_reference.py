"""The screened match must not leave out an upper-branch root that a curve matches best.

Reference: the match of the previous curves to every hysteretic root with every vector, built
from dense eigen-solutions (scipy.linalg.eig; the reference and the match are those of
tests/test_screened_match_reference.py, imported) of the two branches' first-order matrices
``[[0, I], [−K, −D]]``, K = Λ + w_F F + w_L L + w_S S, D = ΩG + C, with the rotating-frame loss
weights derived in tests/test_damping.py and the docstring of
flexshaft.analyses.hysteretic_roots: ``(i, i, 0)`` above the spin, ``(i, 0, 1)`` below it; R(Ω)
is every root on its own branch's side (no mode lies near the spin here: one root per mode,
checked). Each curve is assigned by scipy.optimize.linear_sum_assignment on the cost
1 − MAC + 0.1 |Δω|/ω of flexshaft.analyses.campbell's match (its definition, restated here).

The model: six modal coordinates (Λ = diag ω², ω 100-548 rad/s), gyroscopic pairs in the four
lowest only, a dashpot ``c b bᵀ`` that the top mode barely sees (b₆ = 0.01), loss matrices
F = 0.005 Λ, L = 0.02 Λ (diagonal) and a circulatory S in the gyroscopic pairs. So the top
mode (ω₆ ≈ 548 rad/s) is nearly decoupled: its upper-branch root s₆ is left out of the
screened match's candidates (|s₆| > _BAND × the largest curve's |s| ≈ 2 × 240 rad/s) and only
the bound of its MAC can keep it.

Why the bound must be the upper branch's (derived here). The screen bounds |y₆ᴴv| for the unit
null vector y₆ of the upper branch's ``T₊(s₆)``: its diagonal term T₊,66(s₆) vanishes to first
order in the weak coupling (y₆ ≈ e₆), so the row bound is u₆ = 1 and a curve whose shape is
y₆ may cost s₆ only 0.1 |Δω|/ω ≈ 0.13, below every candidate's ≈ 1: the match is not certain
and the screen returns None (the caller solves every vector). The lower branch's ``T₋(s₆)``
differs on the diagonal by the loss, T₋,66 − T₊,66 = −i·0.02 ω₆² ≈ −6000i rad²/s², against an
off-diagonal row of |s₆| c b₆ ‖b‖ ≈ 548 · 20 · 0.01 · 1.5 ≈ 170 rad²/s², so a bound taken from it
would be u₆ ≤ 0.03 on the first step (2e-4 after the iteration) and would exclude s₆: the
screen would then hand that curve a wrong candidate.

Tolerances: the dense roots err by about ε‖A‖ ≈ 7e-11 rad/s (1e-12 relative to |s| >= 80);
1e-9 relative is asserted on the roots; the match is a set of indices (exact), chosen by cost
margins of 0.8 and more (no ties).
"""

from __future__ import annotations

import numpy as np
from test_screened_match_reference import N_CURVES, PREVIOUS, SPEED, _reference_match, consistent_from

from flexshaft.analyses.eigen import ReducedModel
from flexshaft.analyses.screened_match import _BAND, screened_match


def _model() -> ReducedModel:
    """The model of tests/test_screened_match_reference.py but for b₆ = 0.01 (the dashpot barely
    reaches the top mode) and no third gyroscopic pair (the top mode is not paired)."""
    w2 = np.array([1.0, 1.05, 4.0, 4.3, 16.0, 30.0]) * 1e4
    G = np.zeros((6, 6))
    for i, g in ((0, 0.3), (2, 0.5)):
        G[i, i + 1], G[i + 1, i] = g, -g
    b = np.array([1.0, 0.8, 0.6, 0.5, 0.3, 0.01])
    S = 0.02 * (G / np.abs(G).max()) * np.sqrt(np.outer(w2, w2))
    return ReducedModel(
        np.eye(6), w2, G, 20.0 * np.outer(b, b), 0.005 * np.diag(w2), 0.02 * np.diag(w2), S, "rotating", (), True
    )


def test_a_nearly_decoupled_root_left_out_is_bounded_on_its_own_branch():
    red = _model()
    lam_prev, Y_prev = consistent_from(red, PREVIOUS)
    s_ref, Y_ref = consistent_from(red, SPEED)
    top = int(np.argmax(np.abs(s_ref)))
    assert abs(s_ref[top]) > _BAND * np.abs(lam_prev[:N_CURVES]).max()  # the premise: left out of the candidates
    lam, Y = lam_prev[:N_CURVES].copy(), Y_prev[:, :N_CURVES].copy()
    Y[:, -1] = Y_ref[:, top]  # the last curve has the top root's shape
    cols = _reference_match(lam, Y, s_ref, Y_ref)
    assert cols[-1] == top  # the dense match gives that curve the root left out
    found = screened_match(red, SPEED, lam, Y)
    if found is not None:  # a screened match must be the dense one
        s, _, index = found
        np.testing.assert_allclose(s, s_ref, rtol=1e-9, atol=0)
        assert list(index) == list(cols)
    assert found is None  # s_top has no vector: only the caller's solve with every vector can pick it

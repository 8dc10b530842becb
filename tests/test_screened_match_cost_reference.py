"""The tracking's match cost by its definition, and two curves on one root (hunt h39a).

References.

1. The match cost of flexshaft.analyses.campbell's tracking (restated in the docstring of
   flexshaft.analyses.screened_match): 1 − MAC + 0.1 |Δω|/ω, with the modal assurance criterion
   MAC = |aᴴb|² of unit vectors a, b: the squared cosine of the angle between the shapes. Unit
   vectors built at 60° (MAC = cos² 60° = 1/4) and at 45° with a phase (MAC = 1/2), frequencies
   100 and 110 rad/s (0.1 · 10/100 = 0.01): the costs 0.76 and 0.5 by hand. Exact arithmetic of a
   few terms: 1e-14.

2. Distinct roots. Two previous curves with the same eigenvalue and shape both find the same
   root cheapest; an assignment of distinct roots (scipy.optimize.linear_sum_assignment on the
   cost, tests/test_screened_match_reference.py's reference) gives the second curve another root.
   The screened match may decline (None: the caller solves every vector) or return that
   assignment, never one root for both curves. The six-coordinate model of that file (12 x 12
   first-order matrices): milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_screened_match_reference import PREVIOUS, SPEED, _model, _reference_match, consistent_from

from flexshaft.analyses.screened_match import mac, match_cost, screened_match


def test_the_match_cost_is_one_minus_the_squared_cosine_plus_a_tenth_of_the_frequency_step():
    prev = np.array([[1.0], [0.0], [0.0]], dtype=complex)
    c60, s60 = np.cos(np.pi / 3), np.sin(np.pi / 3)
    roots = np.array([[c60, np.sqrt(0.5)], [s60, 0.0], [0.0, 1j * np.sqrt(0.5)]], dtype=complex)
    assert np.linalg.norm(roots, axis=0) == pytest.approx([1.0, 1.0], abs=1e-15)
    assert mac(prev, roots) == pytest.approx(np.array([[0.25, 0.5]]), abs=1e-14)
    cost = match_cost(np.array([100j]), prev, np.array([110j, 100j]), roots)
    assert cost == pytest.approx(np.array([[1 - 0.25 + 0.01, 1 - 0.5]]), abs=1e-14)


def test_two_curves_on_one_root_are_never_both_given_it():
    red = _model()
    lam_prev, Y_prev = consistent_from(red, PREVIOUS)
    lam = np.repeat(lam_prev[:1], 2)
    Y = np.repeat(Y_prev[:, :1], 2, axis=1)
    s_ref, Y_ref = consistent_from(red, SPEED)
    cols = _reference_match(lam, Y, s_ref, Y_ref)
    assert cols[0] != cols[1]
    # both curves' best root is the same one: the screened match declines (None: its
    # documented fallback, the caller's assignment over every vector, as the reference does)
    # rather than hand one root to two curves
    assert screened_match(red, SPEED, lam, Y) is None

"""Tsai-Wu's interaction term: which given F12 the ply's strengths accept, and what it does.

The criterion's quadratic part in (σ1, σ2) is the form F11 σ1² + 2 F12 σ1σ2 + F22 σ2², whose
matrix [[F11, F12], [F12, F22]] is positive definite, by Sylvester's criterion, exactly when
F11 > 0 and F11 F22 − F12² > 0. Only then is the failure surface closed (an ellipsoid): at
F12 = −√(F11 F22) the direction σ1/σ2 = √(F22/F11) has no quadratic term at all and the
biaxial state never fails in one of its senses. So every |F12| < √(F11 F22) is a valid input
(Tsai & Hahn's default −½√(F11 F22) is one of them, not the limit) and |F12| ≥ √(F11 F22) is
refused. F11 = 1/(X_t X_c), F22 = 1/(Y_t Y_c).

With a strong interaction, F12 = −0.9 √(F11 F22), an equal biaxial stress σ1 = σ2 = s has
a = (F11 + F22 + 2 F12) s², b = (F1 + F2) s, and the safety factor is the positive root of
a R² + b R − 1 = 0, here found by NumPy's companion-matrix `roots` (another code than the
module's cancellation-free form): 1e-12 relative, round-off of a quadratic's roots well apart.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.strength import Strengths, tsai_wu_safety_factor

X_T, X_C, Y_T, Y_C, S = 1500e6, 1200e6, 50e6, 200e6, 70e6
F11, F22 = 1 / (X_T * X_C), 1 / (Y_T * Y_C)
LIMIT = math.sqrt(F11 * F22)


@pytest.mark.parametrize("fraction", [-0.999, -0.9, -0.6, 0.6, 0.999])
def test_every_interaction_inside_the_closed_surface_is_accepted(fraction):
    strengths = Strengths(X_T, X_C, Y_T, Y_C, S, F12=fraction * LIMIT)
    assert strengths.F12 == fraction * LIMIT


@pytest.mark.parametrize("fraction", [-1.001, 1.001, -1.5])
def test_an_interaction_that_opens_the_surface_is_refused(fraction):
    with pytest.raises(ValueError, match="opens the Tsai-Wu surface"):
        Strengths(X_T, X_C, Y_T, Y_C, S, F12=fraction * LIMIT)


def test_a_strong_interaction_sets_the_equal_biaxial_safety_factor():
    """F12 = −0.9 √(F11 F22), σ1 = σ2 = s = 30 MPa: R from a R² + b R − 1 = 0 by np.roots."""
    F12 = -0.9 * LIMIT
    s = 30e6
    a = (F11 + F22 + 2 * F12) * s**2
    b = (1 / X_T - 1 / X_C + 1 / Y_T - 1 / Y_C) * s
    roots = np.roots([a, b, -1.0])
    expected = float(max(roots.real))
    R = float(tsai_wu_safety_factor(s, s, 0.0, Strengths(X_T, X_C, Y_T, Y_C, S, F12=F12)))
    assert R == pytest.approx(expected, rel=1e-12)

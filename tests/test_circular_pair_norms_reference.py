"""Resolved degenerate pairs keep the norms of the columns they replace.

Reference (derived here): take one shaft node whose v and w are the two coordinates of the
vectors, ``Y = a I`` (two columns of norm ``a``) with a double eigenvalue. The whirl ratio of a
combination ``(c1, c2)`` is ``r = −2 Im(c̄1 c2) / (|c1|² + |c2|²)``, stationary at the circular
combinations: ``(1, −i)/√2`` (r = +1, forward) and ``(1, i)/√2`` (r = −1, backward).
:func:`~flexshaft.analyses.classify.circular_pairs` returns them most forward first, each scaled
to the norm ``a`` of the original columns (its documented contract), so column k is
``a (1, ∓i)/√2`` up to a unit phase: ``|Y_0k| = |Y_1k| = a/√2``.
"""

import numpy as np
import pytest

from flexshaft.analyses.classify import circular_pairs


@pytest.mark.parametrize("a", [3.0, 0.25])
def test_resolved_pair_is_circular_with_the_original_norms(a):
    """Both columns are circular orbits of norm ``a``, forward first (closed form above).

    The 2×2 Hermitian eigenproblem is perfectly conditioned (B = a² I), so the results hold to
    a few ulps; 1e-12 relative leaves room for any LAPACK kernel.
    """
    s = np.array([100j, 100j])
    Y = a * np.eye(2, dtype=complex)
    out = circular_pairs(s, Y, Y[0:1], Y[1:2])
    np.testing.assert_allclose(np.linalg.norm(out, axis=0), [a, a], rtol=1e-12)
    np.testing.assert_allclose(np.abs(out), np.full((2, 2), a / np.sqrt(2)), rtol=1e-12)
    v, w = out[0], out[1]
    ratio = -2 * np.imag(np.conj(v) * w) / (np.abs(v) ** 2 + np.abs(w) ** 2)
    np.testing.assert_allclose(ratio, [1.0, -1.0], atol=1e-12)

"""The banded solver's lower and upper half bands on an unsymmetric pattern (mutation hunt 46a).

A non-collocated magnetic bearing adds the pattern B_aᵀB_s (actuation rows × sensing rows),
which need not be symmetric: the permuted matrix may then have kl ≠ ku sub- and
super-diagonals, and ``zgbsv`` must be given them in LAPACK's order (kl, ku). No model of the
design text was found whose ordering gives kl ≠ ku, so the band structure is built from a
hand-made pattern on n = 3 free DOFs: a diagonal "M", a symmetric "K" coupling (0, 1) and
(1, 0), and a feedback "S0" with entries (2, 0) and (2, 1) only.

Reference: LAPACK's definition of a band matrix (zgbsv's documentation): A(i, j) = 0 unless
j − ku ≤ i ≤ j + kl, with kl, ku the smallest such; counted here directly on the dense permuted
matrix with numpy. The pattern is one connected block; whatever the ordering, the half bands
are checked against the ordering the structure reports. Then the matrix is stored as
zgbsv's documentation prescribes, AB(kl + ku + 1 + i − j, j) = A(i, j) (1-based), and the band
solution is compared with numpy.linalg.solve on the dense matrix (tolerance 1e-13 relative: a
3 × 3 diagonally dominant system, condition number below 10, solved to a few ε).

CPU: a few milliseconds.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import lapack

from flexshaft.analyses.banded import _band_structure

N = 3
TERMS = {
    "M": (np.arange(N), np.arange(N), np.array([4.0, 5.0, 6.0])),
    "K": (np.array([0, 1]), np.array([1, 0]), np.array([1.0, 1.5])),
    "S0": (np.array([2, 2]), np.array([0, 1]), np.array([-0.7, 0.9])),
}


def dense_permuted(perm: np.ndarray) -> np.ndarray:
    """The sum of the terms as a dense matrix, rows and columns in the ordering ``perm``."""
    A = np.zeros((N, N))
    for r, c, v in TERMS.values():
        np.add.at(A, (r, c), v)
    return A[np.ix_(perm, perm)]


def test_half_bands_follow_lapacks_definition():
    band = _band_structure(N, TERMS, np.arange(N)[:, None].astype(float))
    A = dense_permuted(np.asarray(band.perm))
    i, j = np.nonzero(A)
    assert (band.kl, band.ku) == (int(np.max(i - j)), int(np.max(j - i)))
    assert band.kl != band.ku  # the case the test is for: an unsymmetric band


def test_a_band_solve_with_the_half_bands_matches_the_dense_solve():
    band = _band_structure(N, TERMS, np.arange(N)[:, None].astype(float))
    kl, ku = band.kl, band.ku
    A = dense_permuted(np.asarray(band.perm)).astype(complex)
    ab = np.zeros((2 * kl + ku + 1, N), dtype=complex, order="F")
    for i, j in zip(*np.nonzero(A)):
        assert -ku <= i - j <= kl, "an entry outside the band the structure reports"
        ab[kl + ku + i - j, j] = A[i, j]
    b = np.array([1.0, -2.0 + 0.5j, 3.0])
    _, _, x, info = lapack.zgbsv(kl, ku, ab, b)
    assert info == 0
    np.testing.assert_allclose(x, np.linalg.solve(A, b), rtol=1e-13, atol=0)

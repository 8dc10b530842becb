"""The negative-sense buckling mode of a classical shell is the eigenvector of the Ritz pencil
at the negative critical torque, against a dense generalized eigen-solve.

``BucklingResult.mode_negative`` is documented (buckling/torque.py) as the Ritz coefficients
W_1..W_M of w, normalised to max |W_m| = 1, of the mode at the critical torque of the negative
sense. The pencil K a = T G a (``classical_galerkin_matrices``, dofs U_0..U_M, V_1..V_M,
W_1..W_M) has that mode's eigenvalue at T = -T_cr^-. For an isotropic tube the two senses have
the same |T| (mirror symmetry theta -> -theta, derived here) but mirror-image modes: the positive
sense leans along the +45 deg tension diagonal, the negative along -45 deg, so the W blocks of
the two eigenvectors differ (here |<W+, W->| / (|W+| |W->|) is far from 1). With
w(x, theta) = Re sum W_m sin(m pi x / L) e^(i n theta), the mirror theta -> -theta maps the
coefficients W_m to conj(W_m): for an isotropic tube W- = conj(W+) up to a complex factor, in
either shell theory (derived here; measured 1 - overlap of 2e-16 by review).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

from flexshaft.buckling import torsional_buckling_torque
from flexshaft.buckling.classical import classical_galerkin_matrices
from flexshaft.laminate import Lamina, Laminate

E, NU = 70e9, 0.3
ALUMINIUM = Lamina.isotropic(E, E / (2 * (1 + NU)), 2700.0)


def _overlap(a: np.ndarray, b: np.ndarray) -> float:
    """|<a, b>| / (|a| |b|): 1 for vectors equal up to a complex factor (phase-free)."""
    return float(abs(np.vdot(a, b)) / (np.linalg.norm(a) * np.linalg.norm(b)))


def test_negative_sense_mode_is_the_pencil_eigenvector_at_minus_the_critical_torque():
    """R/t = 200, L = 5 R (an isolated eigenvalue, as the positive-sense test of
    tests/test_buckling_modes_and_integrals_reference.py): the mode is compared up to a complex
    factor, so the normalisation's tie-break does not matter; 1 - overlap < 1e-10 (the
    eigenvector of a well separated eigenvalue, to rounding), and max |W_m| = 1 to 1e-12."""
    tube = Laminate([0.0], [1.0 / 200.0], ALUMINIUM)
    result = torsional_buckling_torque(tube, 1.0, 5.0, theory="classical")
    assert result.torque_negative == pytest.approx(result.torque_positive, rel=1e-9)  # the mirror symmetry
    M, n = result.n_terms, result.n_negative
    K, G = classical_galerkin_matrices(tube, 1.0, 5.0, n, M)
    values, vectors = scipy.linalg.eig(K, G)
    negative = np.where(np.isfinite(values) & (values.real < 0), -values.real, np.inf)
    i = int(np.argmin(negative))
    assert -values[i].real == pytest.approx(result.torque_negative, rel=1e-9)
    W = vectors[2 * M + 1 : 3 * M + 1, i]
    mode = result.mode_negative
    assert np.max(np.abs(mode)) == pytest.approx(1.0, abs=1e-12)
    assert 1.0 - _overlap(W, mode) < 1e-10
    # and it is the positive sense's mirror image, not that mode itself
    assert 1.0 - _overlap(np.conj(result.mode_positive), mode) < 1e-10
    assert _overlap(result.mode_positive, mode) < 0.1  # measured 1.5e-4


def test_shear_theorys_negative_sense_mode_is_the_mirror_image_of_the_positive():
    """The same tube in the shear-deformable theory (the verdict's): equal torques of both senses
    and W- = conj(W+) up to a complex factor (the mirror symmetry above); both modes are
    eigenvectors of well separated eigenvalues, to rounding: 1e-10."""
    tube = Laminate([0.0], [1.0 / 200.0], ALUMINIUM)
    result = torsional_buckling_torque(tube, 1.0, 5.0, theory="shear")
    assert result.torque_negative == pytest.approx(result.torque_positive, rel=1e-9)
    assert 1.0 - _overlap(np.conj(result.mode_positive), result.mode_negative) < 1e-10
    assert _overlap(result.mode_positive, result.mode_negative) < 0.1

"""A law with a common root of numerator and denominator keeps its gain when the root cancels.

:meth:`Controller.realization` cancels roots shared by num(s) and den(s) (a minimal
realization); the cancelled law must still be C(s). References, by hand (factor, cancel, long
division; no polynomial code shared with the package):

* ``(3s² + 21s + 30)/(s² + 3s + 2) = 3(s + 2)(s + 5)/((s + 2)(s + 1)) = 3(s + 5)/(s + 1)
  = 3 + 12/(s + 1)``: D = 3, E = 0, one state with pole −1 and residue C·B = 12;
* ``(2s² + 14s + 20)/(4s² + 12s + 8) = 2(s + 2)(s + 5)/(4(s + 2)(s + 1)) = ½ + 2/(s + 1)``:
  D = 0.5, one state with pole −1 and residue 2 (a non-monic numerator and denominator: the
  numerator's leading factor must survive the cancellation).

The roots are found numerically (``numpy.roots`` of a quadratic with well-separated roots,
relative error ~1e-15): relative 1e-9 leaves a wide margin on any BLAS.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly.controller import Controller

S = np.array([1j * 3.0, 2.0 + 5.0j, 1j * 400.0])


@pytest.mark.parametrize(
    ("num", "den", "D", "residue"),
    [((3.0, 21.0, 30.0), (1.0, 3.0, 2.0), 3.0, 12.0), ((2.0, 14.0, 20.0), (4.0, 12.0, 8.0), 0.5, 2.0)],
)
def test_a_cancelled_common_root_keeps_the_laws_gain(num, den, D, residue):
    A, B, C, d, E = Controller(num, den).realization()
    assert A.shape == (1, 1) and A[0, 0] == pytest.approx(-1.0, rel=1e-9)
    assert E == 0.0 and d == pytest.approx(D, rel=1e-9)
    assert (C @ B).item() == pytest.approx(residue, rel=1e-9)
    realized = [d + (C @ np.linalg.solve(s * np.eye(1) - A, B)).item() for s in S]
    np.testing.assert_allclose(realized, D + residue / (S + 1.0), rtol=1e-9)

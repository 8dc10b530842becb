"""The eigenvalue tolerance and estimate that a tracked analysis's ``to_dataset()`` writes.

References:

* API contract (flexshaft.analyses.eigen_error.with_error_estimate, which writes the dataset
  attributes; docs/model.md does not name them): with_error_estimate writes the result's
  tolerance as ``eigenvalue_tolerance``, i.e. the tolerance the caller passed in, not the
  largest estimate reached, and the estimates as ``eigenvalue_error``.
* docs/model.md (*Accuracy of the reduced eigenvalues*): the basis doubles while the largest
  estimate exceeds the tolerance, so the estimates of the returned result lie below it (what
  justifies ``errors < tolerance``).
* ``attrs["basis_size"] == result.basis_size`` is a wiring check only (the dataset carries the
  result's own number; no independent reference).

The model is the Jeffcott rotor of tests/rotors.py (8 elements): cheap, and its first basis
passes a loose tolerance by many orders of magnitude, so the two numbers differ widely.
"""

from __future__ import annotations

import numpy as np
from rotors import jeffcott

from flexshaft.analyses import campbell


def test_campbell_dataset_tolerance_is_the_one_asked_for_not_the_estimate():
    """With a loose tolerance 1e-3, which the first basis passes by far (its estimates are at
    round-off, below 1e-20, for the two disk modes of this small model), the dataset's
    ``eigenvalue_tolerance`` is 1e-3 exactly (a float copied, no arithmetic; API contract),
    ``basis_size`` the basis the result reports (wiring), and ``eigenvalue_error`` holds the
    (speed, mode) estimates, each below the tolerance (docs/model.md's doubling rule)."""
    tolerance = 1e-3
    result = campbell(jeffcott(0.0, 0.0), [0.0, 150.0], n_modes=2, tolerance=tolerance)
    ds = result.to_dataset()
    assert ds.attrs["eigenvalue_tolerance"] == tolerance
    assert ds.attrs["basis_size"] == result.basis_size
    errors = np.asarray(ds["eigenvalue_error"])
    assert errors.shape == (2, 2)
    assert np.all(errors < tolerance)

"""The lateral whirl modes of an operating point, from one solve of a few more modes, against the
modal analysis asked for exactly that many.

:func:`~flexshaft.verdict.operating_point.lateral_modes` solves the lowest ``n + 1`` damped
modes (more when needed) and keeps the shortest prefix holding ``n`` lateral whirl modes. The
reference is :func:`~flexshaft.analyses.modal.modes` for that prefix's length: the same modes
in the same order, each eigenvalue within the sum of the two solutions' a-posteriori error
estimates (each bounds its distance from the full model's eigenvalue, so their distance from
each other is at most the sum; a factor 3 and 1e-12 for the estimate's own accuracy,
tests/test_eigen_accuracy.py).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.modal import modes
from flexshaft.assembly import build_model
from flexshaft.design.io import embedded_design
from flexshaft.verdict.operating_point import lateral_modes, whirl_modes


@pytest.mark.parametrize("name", ["baseline", "tuned"])
@pytest.mark.parametrize("n_lateral", [4, 10])
def test_lateral_modes_are_the_shortest_prefix_of_the_full_modal_analysis(name, n_lateral):
    model = build_model(embedded_design(name).model_copy(update={"envelope": None}))
    found = lateral_modes(model, model.speed, n_lateral)
    whirl = whirl_modes(found)
    assert int(whirl.sum()) == n_lateral and whirl[-1]  # n whirl modes, the last one a whirl mode
    reference = modes(model, model.speed, found.eigenvalues.size)
    assert list(found.kind) == list(reference.kind)
    bound = 3 * (found.error_estimate + reference.error_estimate) + 1e-12
    error = np.abs(found.eigenvalues - reference.eigenvalues) / np.abs(reference.eigenvalues)
    assert np.all(error <= bound)
    assert found.shapes.shape == reference.shapes.shape
    assert found.shares.shaft.shape == (found.eigenvalues.size,)

"""The enriched basis with the circulatory loss on anisotropic bearings (mutation hunt 46a).

:func:`~flexshaft.analyses.reduced_basis.enrich_basis` adds the static corrections
``K_σ⁻¹ X φ_j`` of every non-zero coupling X, the circulatory loss ``K_lat S`` among them (the
term that destabilises supercritical whirl). On isotropic bearings that vector lies in the span
of the others (S turns a lateral plane into the other, and each mode's partner in the other plane
is a target too), so the rotor here is tests/test_eigen_accuracy.py's steel tube, 8 elements
(52 free DOFs), with bearings of stiffness 1e7 N/m in v and 3e6 N/m in w, loss factor η = 0.2,
at Ω = 2500 rad/s (above the second critical speed), on an 8-mode basis with the corrections of
its 4 lowest modes (``reduce(model, 8, enrich=4)``).

Reference: each of the four lowest reduced roots against the full root, Newton's method on the
full dense ``T(s)`` with the loss weights of the root's own side of the synchronous line
(tests/test_eigen_accuracy.py's ``_full_root``, started from the reduced root and its expanded
vector; good to about 3e-11 relative, that file's docstring; restarting it from its own result
moves these roots by at most 7e-14).

Bar 1e-10 relative: three times the reference's stated accuracy. With every correction the four
roots agree with the full ones to 5e-13 (measured); without the circulatory correction roots 3
and 4 err by 7.1e-10 and 1.0e-9 (the bar is 7-10 times below; a larger basis, (12, enrich=8),
gave a smaller margin: 1.5e-12 against 2e-10).

CPU: one 52-DOF model, four dense Newton solves: about 0.05 s.
"""

from __future__ import annotations

import warnings

import numpy as np
import scipy.linalg as la
from test_eigen_accuracy import SHAFT, _dense, _full_root

import flexshaft
from flexshaft.analyses.campbell import track_modes
from flexshaft.analyses.eigen import reduce
from flexshaft.design import loads_design

ETA = 0.2
SPEED = 2500.0  # rad/s


def test_the_enriched_roots_with_circulatory_loss_on_anisotropic_bearings():
    text = SHAFT.replace("shaft_elements = 30", "shaft_elements = 8")
    text = text.replace("stiffness = { v = 1e7, w = 1e7 }", "stiffness = { v = 1e7, w = 3e6 }")
    assert text.count("w = 3e6") == 2  # both bearings anisotropic
    text = text.replace("density = 7810.0", f"density = 7810.0\nloss_factor = {ETA}")
    model = flexshaft.build_model(loads_design(text))
    assert model.internal_damping == "rotating"
    assert model.loss_circulatory.nnz
    matrices = (model.M, model.G, model.C, model.K, model.loss_fixed, model.loss_lateral, model.loss_circulatory)
    dense = np.stack([_dense(model, A) for A in matrices])
    red = reduce(model, 8, enrich=4)
    tracked = track_modes(model, red, np.array([SPEED]), 4)
    s, X = tracked.eigenvalues[0], red.Phi @ tracked.states[0]
    full = np.empty(s.size, complex)
    with warnings.catch_warnings():  # T(s) is singular at the root by design: inverse iteration
        warnings.simplefilter("ignore", la.LinAlgWarning)
        for m in range(s.size):
            full[m] = _full_root(model, dense, s[m], X[:, m] / np.linalg.norm(X[:, m]), SPEED)
    np.testing.assert_array_less(np.abs(full - s) / np.abs(s), 1e-10)

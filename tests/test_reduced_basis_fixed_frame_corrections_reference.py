"""The enriched basis with bearing dampers, and with a lossy tailboom: their static corrections
(mutation hunt 101c).

:mod:`flexshaft.analyses.reduced_basis` (module docstring): the exact mode at speed Ω has
components on every higher undamped mode for each coupling X the undamped modes do not
diagonalise — "the dampers C + K_d, the hysteretic loss matrices F, K_lat, K_lat S" — and the
basis holds them through the span of ``K_σ⁻¹ X Φ_t`` "for each coupling X". Two couplings are
checked here, each on a rotor where its correction lies in no other correction's span:

* the dampers D = C: a shaft on two damped bearings, no actuators (so no actuator flexibility
  ``K_σ⁻¹ Bᵀ`` carries a damper's point force) and no loss;
* the fixed-frame loss F: the shaft over a lossy aluminium tailboom (loss factor 0.05 on the
  boom only: F is the boom's loss stiffness, not proportional to the whole K, so
  ``K_σ⁻¹ F φ`` is not φ itself; the steel shaft has no loss, K_lat = 0).

Reference: each of the four lowest reduced roots against the full root, Newton's method on the
full dense ``T(s)`` with the loss weights of the root's own side (tests/test_eigen_accuracy.py's
``_full_root``, started from the reduced root and its expanded vector; good to about 3e-11
relative, that file's docstring).

Bar: test_eigen_accuracy.py's RESOLVED, 1e-9 relative, thirty times the reference's accuracy.
Measured (relative error of the worst of the four roots):

* dampers — tests/test_eigen_accuracy.py's steel tube (bearings 1e7 N/m, dampers 1e3 N s/m),
  8 elements (52 free DOFs), Ω = 2500 rad/s, ``reduce(model, 8, enrich=4)``: 1.2e-10 with
  every correction; 2.3e-8 without the dampers' (23 times the 1e-9 bar);
* boom — tests/boomed_rotor.py's 2 m shaft over its 2 m boom, contact bearings at 0.7 m
  (1e7, 2e7 N/m) and 1.55 m (1e7 N/m), 5 shaft and 3 boom elements (49 free DOFs), Ω = 314
  rad/s, ``reduce(model, 12, enrich=6)``: 1.8e-10 with every correction; 5.6e-6 to 2.6e-5
  without the fixed loss's (above even the modal analyses' 1e-6). The smaller (8, enrich=4)
  basis reaches only 7.9e-9 on this rotor: hence 12 modes.

CPU: two models of about 50 DOFs, eight dense Newton solves: about 0.2 s.
"""

from __future__ import annotations

import warnings

import numpy as np
import scipy.linalg as la
from boomed_rotor import shaft_and_boom
from test_eigen_accuracy import RESOLVED, SHAFT, _dense, _full_root

import flexshaft
from flexshaft.analyses.campbell import track_modes
from flexshaft.analyses.eigen import reduce
from flexshaft.design import loads_design

BOOM_LOSS = 0.05
LOSSY_BOOM = shaft_and_boom(2.0).replace("density = 2700.0", f"density = 2700.0\nloss_factor = {BOOM_LOSS}")
BOOMED = f"""
name = "shaft over a lossy tailboom"
{LOSSY_BOOM}
[[bearings]]
name = "hanger"
kind = "contact"
x = 0.7
stiffness = {{ v = 1e7, w = 2e7 }}
[[bearings]]
name = "mount"
kind = "contact"
x = 1.55
stiffness = {{ v = 1e7, w = 1e7 }}
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 5
boom_elements = 3
"""


def _reduced_and_full_roots(model, speed: float, basis: int, enrich: int) -> tuple[np.ndarray, np.ndarray]:
    """The four lowest roots of ``reduce(model, basis, enrich=enrich)`` at ``speed`` and the full
    roots Newton's method converges to from each (module docstring)."""
    matrices = (model.M, model.G, model.C, model.K, model.loss_fixed, model.loss_lateral, model.loss_circulatory)
    dense = np.stack([_dense(model, A) for A in matrices])
    red = reduce(model, basis, enrich=enrich)
    tracked = track_modes(model, red, np.array([speed]), 4)
    s, X = tracked.eigenvalues[0], red.Phi @ tracked.states[0]
    full = np.empty(s.size, complex)
    with warnings.catch_warnings():  # T(s) is singular at the root by design: inverse iteration
        warnings.simplefilter("ignore", la.LinAlgWarning)
        for m in range(s.size):
            full[m] = _full_root(model, dense, s[m], X[:, m] / np.linalg.norm(X[:, m]), speed)
    return s, full


def test_the_enriched_roots_with_bearing_dampers_match_the_full_roots():
    text = SHAFT.replace("shaft_elements = 30", "shaft_elements = 8")
    assert text.count("damping = { v = 1e3, w = 1e3 }") == 2  # both bearings damped
    model = flexshaft.build_model(loads_design(text))
    assert model.C.nnz and not model.actuators and not model.has_loss
    s, full = _reduced_and_full_roots(model, 2500.0, 8, 4)
    assert np.all(s.real < 0)  # damped roots: the dampers act on them
    np.testing.assert_array_less(np.abs(full - s) / np.abs(s), RESOLVED)


def test_the_enriched_roots_with_a_lossy_tailboom_match_the_full_roots():
    assert LOSSY_BOOM.count("loss_factor") == 1  # the aluminium boom's only
    model = flexshaft.build_model(loads_design(BOOMED))
    assert model.loss_fixed.nnz and not model.loss_lateral.nnz and not model.C.nnz and not model.actuators
    s, full = _reduced_and_full_roots(model, 314.0, 12, 6)
    assert np.all(s.real < 0)  # damped by the boom's loss alone
    np.testing.assert_array_less(np.abs(full - s) / np.abs(s), RESOLVED)

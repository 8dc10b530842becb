"""The modes of :func:`~flexshaft.analyses.modal.modes` against the full (unreduced) model solved
directly, and the shape normalisation its docstring states.

Reference (the unreduced model, solved here with dense LAPACK): a 12-element pinned-pinned steel
tube (78 free DOFs) with a disk (polar inertia: gyroscopic) and a viscous dashpot, no material
loss, so the exact damped modes at spin Ω are the roots of the *linear* quadratic eigenproblem
``(s² M + s (Ω G + C) + K) φ = 0`` on the free DOFs. It is solved in first-order form through
its inverse: with ``x = (φ, sφ)``, ``A⁻¹ = [[−K⁻¹(ΩG + C), −K⁻¹M], [I, 0]]`` has eigenvalues
μ = 1/s, so the lowest modes are its largest, obtained to about ε κ(K) relative; with the DOFs
Jacobi-scaled first (``D K D``, ``D = diag(K)^(-1/2)``: the same roots) κ ≈ 1.5e4, so the
reference's own error is below ε κ ≈ 3e-12 (it moved by 7e-14 against the unscaled solve).
At rest and with ``damped=False`` the modes are ``s = ± i ω`` with ω² the eigenvalues of
``K φ = ω² M φ`` (``scipy.linalg.eigh``).

What is checked:

* ``damped=False`` drops the dashpot: the roots at rest are ``i ω`` exactly (ζ = 0) with ω of the
  undamped symmetric problem (the damped roots have ζ ≈ 1e-2 here, far outside 1e-10).
* The default (enriched) basis honours its ``tolerance``: at a tolerance of 1e-12, the first
  basis :func:`~flexshaft.analyses.eigen_error.accurate_basis` tries for 4 modes (16 modes + 8
  corrections) errs by 7.5e-11 on the fourth mode, so the loop must double it; the returned
  eigenvalues are asserted within 1e-11 of the full model's (the tolerance plus the reference's
  3e-12, with a factor 2 for an estimate that is not a strict bound).
* At the default tolerance the first basis is kept and :attr:`Modes.error_estimate` is an
  estimate of the true error: below the tolerance, and within a factor 3 of the true error of
  the fourth mode, whose truncation error (7.5e-11) stands well above the reference's round-off
  (the estimate is first-order in the residual: its ratio to the true error is 1 ± O(error)).
* "Unit maximum translation" (the :class:`~flexshaft.analyses.modal.Modes` docstring): each
  shape divided by its largest translation, over the shaft's u, v, w **and** the boom's v, w, so
  that entry is exactly 1 (real): checked on the damped, spinning tube (complex shapes) and on a
  shaft with a 6 m tailboom whose bending modes hardly move the shaft.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from test_boom_torsion import design_text as boom_design

from flexshaft.analyses import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

TUBE = """
name = "damped spinning tube"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.05
wall_thickness = 0.005
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "damper"
kind = "contact"
x = 0.6
stiffness = {}
damping = { v = 800.0, w = 800.0 }
[[disks]]
name = "disk"
x = 1.2
mass = 5.0
diametral_inertia = 0.05
polar_inertia = 0.1
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 12
"""


@pytest.fixture(scope="module")
def tube():
    return build_model(loads_design(TUBE))


def _free(model, A):
    free = model.dofs.free
    return A.toarray()[np.ix_(free, free)]


def _full_damped_roots(model, speed: float, n: int) -> np.ndarray:
    """The ``n`` lowest roots (Im s > 0, by Im s) of the unreduced quadratic eigenproblem."""
    M, K, G, C = (_free(model, A) for A in (model.M, model.K, model.G, model.C))
    d = 1.0 / np.sqrt(np.diag(K))  # Jacobi scaling: the same roots, κ(K) from 1.5e6 to 1.5e4
    M, K, G, C = (d[:, None] * X * d[None, :] for X in (M, K, G, C))
    size = M.shape[0]
    Kinv_D = la.solve(K, speed * G + C)
    Kinv_M = la.solve(K, M)
    A_inv = np.block([[-Kinv_D, -Kinv_M], [np.eye(size), np.zeros((size, size))]])
    s = 1.0 / la.eigvals(A_inv)
    s = s[s.imag > 0]
    return s[np.argsort(s.imag)][:n]


def _relative(a, b):
    return np.abs(a - b) / np.abs(b)


def test_undamped_modes_at_rest_are_the_symmetric_eigenproblem(tube):
    w2 = la.eigh(_free(tube, tube.K), _free(tube, tube.M), eigvals_only=True)[:4]
    m = modes(tube, 0.0, n_modes=4, damped=False)
    np.testing.assert_array_equal(m.eigenvalues.real, 0.0)
    np.testing.assert_allclose(m.eigenvalues.imag, np.sqrt(w2), rtol=1e-10)
    damped = modes(tube, 0.0, n_modes=4)
    assert damped.damping_ratios[0] > 1e-3  # the dashpot is felt when damped


def test_a_tight_tolerance_is_reached_against_the_full_model(tube):
    speed = float(tube.speed)
    exact = _full_damped_roots(tube, speed, 4)
    m = modes(tube, speed, n_modes=4, tolerance=1e-12)
    assert np.all(_relative(m.eigenvalues, exact) < 1e-11)


def test_the_error_estimate_is_the_true_error_at_the_default_tolerance(tube):
    speed = float(tube.speed)
    exact = _full_damped_roots(tube, speed, 4)
    m = modes(tube, speed, n_modes=4)
    true = _relative(m.eigenvalues, exact)
    assert np.all(true < 1e-6)
    assert np.all(m.error_estimate <= 1e-6)
    assert true[3] > 1e-11  # truncation, not the reference's round-off, dominates this mode
    assert true[3] / 3 < m.error_estimate[3] < 3 * true[3]


def _translations(dofs):
    rows = [dofs.shaft(np.arange(dofs.n_shaft_nodes), f) for f in ("u", "v", "w")]
    if dofs.n_boom_nodes:
        rows += [dofs.boom(np.arange(dofs.n_boom_nodes), f) for f in ("v", "w")]
    return np.concatenate(rows)


def _assert_unit_maximum_translation(m):
    idx = _translations(m.dofs)
    T = m.shapes[idx]
    largest = np.abs(T).max(axis=0)
    np.testing.assert_allclose(largest, 1.0, rtol=1e-12)
    at = T[np.argmax(np.abs(T), axis=0), np.arange(T.shape[1])]
    np.testing.assert_allclose(at, 1.0, rtol=0, atol=1e-12)


def test_damped_spinning_shapes_have_a_real_unit_maximum_translation(tube):
    m = modes(tube, float(tube.speed), n_modes=6)
    assert np.abs(m.shapes.imag).max() > 0.1  # the shapes are complex (whirl, damping)
    _assert_unit_maximum_translation(m)


def test_boom_modes_are_scaled_by_the_boom_translation():
    model = build_model(loads_design(boom_design(elements=4, tip_inertia=None)))
    m = modes(model, 0.0, n_modes=6, damped=False)
    dm = model.dofs
    shaft = np.abs(m.shapes[_translations(dm)[: 3 * dm.n_shaft_nodes]]).max(axis=0)
    assert np.any(shaft < 0.1)  # a boom mode: the shaft hardly moves
    _assert_unit_maximum_translation(m)

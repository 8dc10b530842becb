"""Newton's method of :func:`~flexshaft.analyses.eigen.newton` against the reduced (Galerkin)
eigenproblem solved here directly.

Reference (derived here): on the basis Φ of :func:`~flexshaft.analyses.eigen.reduce` the
reduced problem is ``T(s) y = (s² Φᵀ M Φ + s Φᵀ D Φ + Φᵀ K Φ) y = 0`` with the full matrices
projected in this test, ``D = Ω G + C (+ w_F F + w_L K_lat)`` and ``K (+ w_S K_lat S)`` for the
viscous internal-damping method's real weights ``w`` (the docstring of
:func:`~flexshaft.analyses.loss.viscous_equivalent`: damping ``(F + K_lat)/ω_ref``,
circulatory stiffness ``(Ω/ω_ref) K_lat S``). M_r = I (Φ is mass-orthonormal, checked). Its
roots are the eigenvalues of the companion matrix in the scaled state ``[Λ^½ y, s y]``,
``[[0, Λ^½], [−K_r Λ^-½, −D_r]]`` with ``Λ = diag K_r`` (the unscaled ``[[0, I], [−K_r, −D_r]]``
has ‖A‖₂ ≈ 7.5e6 against roots of 150-2750 rad/s, an a-priori bound ε‖A‖₂κ/|s| of 1e-9; the
scaled one has ‖A‖₂ ≈ 3e3 and eigenvalue condition numbers κ ≤ 1.04, so dense LAPACK on this
16 × 16 matrix is accurate to ε‖A‖₂κ/|s| ≤ 5e-15 relative, measured).

Newton's method is started 1e-3 off the root with an eigenvector spoiled by 1e-2 and must
return the root (Newton's own relative step tolerance is 1e-10 and quadratic convergence puts
the returned root far below it; measured agreement with the reference 2e-14 (bending roots)
and 4e-15 (torsion), the round-off of Newton's last solve; 1e-9 is asserted, ten times
Newton's step tolerance, five orders above the reference's bound) and a vector with a small
residual ``‖T(s) y‖ / ‖T(s)‖₂`` (the start vector's is 2-4e-3; the converged vector's is
round-off, measured 1e-16 to 1e-15; 1e-8 is asserted).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la

from flexshaft.analyses.eigen import newton, reduce
from flexshaft.analyses.loss import viscous_equivalent
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import loads_design

TUBE = """
name = "damped spinning tube"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800
loss_factor = LOSS
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
shaft_elements = 8
"""

SPEED = 500.0  # rad/s
BASIS = 8


def _model(loss: float):
    return build_model(loads_design(TUBE.replace("LOSS", repr(loss))))


def _projected(model, red, A):
    return red.Phi.T @ (restrict(A.tocsr(), model.dofs.free).toarray() @ red.Phi)


def _reduced_problem(model, red, speed, weights=None):
    """(M_r, D_r, K_r) of the reduced problem, projected here from the full matrices."""
    M = _projected(model, red, model.M)
    D = speed * _projected(model, red, model.G) + _projected(model, red, model.C + model.Kd)
    K = _projected(model, red, model.K + model.Kp)
    if weights is not None:
        D = D + weights.fixed * _projected(model, red, model.loss_fixed)
        D = D + weights.lateral * _projected(model, red, model.loss_lateral)
        K = K + weights.circulatory * _projected(model, red, model.loss_circulatory)
    return M, D, K


def _roots(M, D, K):
    n = M.shape[0]
    np.testing.assert_allclose(M, np.eye(n), atol=1e-12)  # Φ is mass-orthonormal
    root = np.sqrt(np.diag(K))  # Λ^½, Λ = diag K_r > 0
    A = np.block([[np.zeros((n, n)), np.diag(root)], [-K / root[None, :], -D]])
    s, X = la.eig(A)
    keep = s.imag > 0
    order = np.argsort(s[keep].imag)
    return s[keep][order], X[n:, keep][:, order]  # the lower block s y: an eigenvector y


def _residual(M, D, K, s, y):
    T = s * s * M + s * D + K
    return np.linalg.norm(T @ y) / (np.linalg.norm(T, 2) * np.linalg.norm(y))


def _spoiled(y, seed):
    rng = np.random.default_rng(seed)
    noise = rng.standard_normal(y.size) + 1j * rng.standard_normal(y.size)
    return y / np.linalg.norm(y) + 1e-2 * noise / np.linalg.norm(noise)


@pytest.mark.parametrize("mode", [0, 3])
def test_newton_returns_the_root_and_its_own_eigenvector(mode):
    """Loss-free tube (gyroscopic disk, dashpot) at Ω = 500 rad/s: from a spoiled start Newton
    returns the reduced root to 1e-9 and a vector whose residual is round-off; the start
    vector's residual is 2-4e-3 (asserted above 1e-5, so the check has teeth). Modes 0 and 3
    are bending roots (150 and 697 rad/s), moved by the disk's gyroscopic moment and the
    dashpot; mode 2 would be the torsion root, which neither touches (‖D y‖ ≈ 0)."""
    model = _model(0.0)
    red = reduce(model, BASIS)
    M, D, K = _reduced_problem(model, red, SPEED)
    s_ref, Y = _roots(M, D, K)
    start = _spoiled(Y[:, mode], seed=mode)
    assert _residual(M, D, K, s_ref[mode], start) > 1e-5
    s, y, converged = newton(red, SPEED, complex(s_ref[mode] * (1 + 1e-3)), start)
    assert converged
    assert abs(s - s_ref[mode]) / abs(s_ref[mode]) < 1e-9
    assert _residual(M, D, K, s, y) < 1e-8


@pytest.mark.parametrize("mode", [0, 1])
def test_viscous_newton_keeps_the_circulatory_stiffness(mode):
    """Tube of loss factor 0.02 with the viscous method's weights at ω_ref = 300 rad/s and
    Ω = 500 rad/s (circulatory weight Ω/ω_ref = 1.67): Newton's root is the reduced root of
    the problem *with* the circulatory stiffness ``w_S K_lat S``, to 1e-9. Without it the root
    moves by 1.7e-2 relative (measured; asserted above 1e-6, so the check has teeth)."""
    model = _model(0.02)
    red = reduce(model, BASIS)
    weights = viscous_equivalent(300.0, SPEED)
    M, D, K = _reduced_problem(model, red, SPEED, weights)
    s_ref, Y = _roots(M, D, K)
    _, _, K_free = _reduced_problem(model, red, SPEED)
    s_without, _ = _roots(M, D, K_free)
    assert abs(s_without[mode] - s_ref[mode]) / abs(s_ref[mode]) > 1e-6
    start = _spoiled(Y[:, mode], seed=10 + mode)
    s, y, converged = newton(red, SPEED, complex(s_ref[mode] * (1 + 1e-3)), start, viscous=weights)
    assert converged
    assert abs(s - s_ref[mode]) / abs(s_ref[mode]) < 1e-9
    assert _residual(M, D, K, s, y) < 1e-8

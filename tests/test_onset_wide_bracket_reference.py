"""Viscous whirl onset of an anisotropic overhung rotor: the same on a wide bracket as on a fine grid.

The rotor of tests/test_onset_refinement_anisotropic_reference.py (a steel tube clamped at x = 0,
L = 0.5 m, a rigid tip disk of 20 kg, a tip bearing k_v = 2e5, k_w = 2e6 N/m) with anisotropic
tip damping c_v = 50, c_w = 5 N s/m and the shaft's loss η = 0.05 as the thesis's viscous
internal damping (``damping_model="viscous"``, ω_ref = 200 rad/s).

Reference (another computation, independent of the mode tracking): the full unreduced state
matrix on the 24 free DOFs, written here from the model's matrices and the viscous model's
definition (Zorzi & Nelson 1977, module docstring of flexshaft.analyses.stability):

    M q'' + (C + Ω G + (F + K''_lat)/ω_ref) q' + (K + (Ω/ω_ref) K''_lat S) q = 0,

F the fixed-frame loss (axial, torsion), K''_lat S the rotating lateral loss seen from the fixed
frame. S is built here from the DOF map, not taken from the model: the rotating damping force
on a node is −C_i q̇_r in the rotating frame, q_r = R(−Ωt) q with R(φ) = exp(φ J), J = [[0, −1],
[1, 0]] on (v, w) (positive rotation about x, v → w), so q̇_r = R(−Ωt)(q̇ − Ω J q) and in the
fixed frame F = −C_i (q̇ − Ω J q): on the left of the equation C_i q̇ + Ω C_i S q with S = −J,
(v, w) → (w, −v). The slopes (β, γ) = (−w', v') = J (v', w') turn with the same R (J commutes
with it), so S is (β, γ) → (γ, −β) on them too; with C_i = K''_lat/ω_ref the circulatory term
is (Ω/ω_ref) K''_lat S. The onset is the first speed with an eigenvalue Re s > 0 of the
generalized 48 × 48 pencil A x = s B x, A = [[0, I], [−K_t, −D]], B = diag(I, M)
(scipy.linalg.eigvals(A, B), without inverting M: the tube's density is 0.1 kg/m³, so M is
nearly singular, cond 1.3e10, and the first-order matrix with M⁻¹ written out moves Re s by up to
3e-8 1/s near the onset and the onset by 8e-9 relative: that form's own error, 30 times the
agreement measured with the pencil). A scan at 40 speeds shows one crossing in [0, 4000] rad/s (stable below,
unstable above), and bisection finds it to 1e-9 relative.

The grids [0, 4000], [0, 2000, 4000], [0, 3000, 4000] bracket the crossing (676 rad/s) between
speeds 676-3324 rad/s away. On them the mode's shape at the first trial speed of the onset's
regula falsi differs from the unstable end's (overlaps 0.66, 0.77, 0.69 < 0.8), so the
refinement cannot identify the mode there; it must follow the mode down the bracket in sub-steps
instead of falling back to the linear interpolation of the grid's damping ratios (242, 306 and
252 rad/s: where the model is stable, 64 %, 55 %, 63 % below the onset). A fine grid (81
speeds: the mode found at once, the common path) is checked too.

Tolerance 1e-6 relative: the refinement stops at 1e-7 of the speed, the bisection at 1e-9, the
reference's own round-off (the two first-order forms above) ~1e-8; the reduced basis spans all
24 free DOFs (26 vectors of rank 24 when this test was written), so the reduced eigenvalues are
the full ones to round-off (~1e-13 |s|, |s| = 362 rad/s at the onset), which over the slope
dRe(s)/dΩ = 0.0117 of the crossing root moves it by ~3e-9 rad/s. (Even a basis at the default
eigenvalue tolerance, 1e-6 |s|, would move it by 0.03 rad/s, 5e-5 relative; the
grid-interpolation fallback is off by more than 0.5.) Measured: 2.4e-10 on all four grids (8e-9
against the form with M⁻¹). CPU: four stability runs of a 4-element model and ~70 dense 48 × 48
eigen-solves, 0.12-0.32 s (test phases, measured on a busy 2-core VM).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from test_onset_refinement_anisotropic_reference import K_V, K_W, design_text

import flexshaft as fs
from flexshaft.analyses.stability import stability
from flexshaft.design import loads_design

C_V, C_W = 50.0, 5.0
ETA, W_REF = 0.05, 200.0
TOP = 4000.0


@pytest.fixture(scope="module")
def model():
    plain = f"stiffness = {{ v = {K_V}, w = {K_W} }}"
    text = design_text(ETA)
    assert text.count(plain) == 1
    return fs.build_model(loads_design(text.replace(plain, f"{plain}\ndamping = {{ v = {C_V}, w = {C_W} }}")))


@pytest.fixture(scope="module")
def dense_onset(model) -> float:
    free = model.dofs.free

    def dense(A):
        return A.tocsr()[free][:, free].toarray()

    M, K, C, G = dense(model.M), dense(model.K), dense(model.C), dense(model.G)
    F, K_lat = dense(model.loss_fixed), dense(model.loss_lateral)
    n = free.size
    assert n == 24 and not model.actuators and not len(model.dofs.tied)
    S = np.zeros((model.dofs.size, model.dofs.size))  # (v, w) → (w, −v), (β, γ) → (γ, −β) per node
    for node in range(model.dofs.n_shaft_nodes):
        v, w, beta, gamma = (int(model.dofs.shaft(node, name)) for name in ("v", "w", "beta", "gamma"))
        for first, second in ((v, w), (beta, gamma)):
            S[first, second], S[second, first] = 1.0, -1.0
    K_lat_S = K_lat @ S[np.ix_(free, free)]
    zero, unit = np.zeros((n, n)), np.eye(n)
    B = np.block([[unit, zero], [zero, M]])

    def largest_real_part(speed: float) -> float:
        damping = C + speed * G + (F + K_lat) / W_REF
        stiffness = K + speed / W_REF * K_lat_S
        roots = la.eigvals(np.block([[zero, unit], [-stiffness, -damping]]), B)
        assert np.isfinite(roots).all()  # M is nonsingular: 48 finite roots
        return float(roots.real.max())

    scan = [largest_real_part(speed) for speed in np.linspace(0.0, TOP, 40)]
    signs = np.sign(scan)
    assert signs[0] < 0 < signs[-1] and np.count_nonzero(np.diff(signs)) == 1  # one crossing
    a, b = 0.0, TOP
    while b - a > 1e-9 * b:
        c = 0.5 * (a + b)
        a, b = (a, c) if largest_real_part(c) > 0 else (c, b)
    return b


@pytest.mark.parametrize("grid", [[0.0, TOP], [0.0, 2000.0, TOP], [0.0, 3000.0, TOP], list(np.linspace(0.0, TOP, 81))])
def test_the_onset_does_not_depend_on_the_bracket(model, dense_onset, grid):
    result = stability(model, np.array(grid), n_modes=4, damping_model="viscous", reference_frequency=W_REF)
    assert result.onset_kind == "oscillatory"
    assert result.onset_speed == pytest.approx(dense_onset, rel=1e-6)

"""The error estimate of several speeds at once against the full eigenvalues of each speed (hunt h32b).

:func:`~flexshaft.analyses.eigen_error.tracked_errors` puts the columns of several speeds through
one call of the estimate (``_GROUP_BYTES`` of temporaries a group): each column must take its own
speed's spin Ω (the gyroscopic term ΩsG of the full residual and of the reduced ``T(s)`` whose
left null vector it solves for) and, with the thesis's viscous internal damping, its own speed's
weights (circulatory (Ω/ω_ref) K_lat S). Here the viscous method on the 8-element steel tube of
tests/test_eigen_error_reference.py (52 free DOFs; loss factor 0.02 added) at rest, 1250 and
2500 rad/s (2.1x its second critical speed: a large gyroscopic split), 4 modes of an 8-mode
basis, all three speeds in one group and one speed a group.

Reference: at each speed the full problem ``s²M + s(ΩG + C + F/ω_ref + K_lat/ω_ref) + K +
(Ω/ω_ref) K_lat S`` on every free DOF, its roots from a dense eigen-solve of the first-order
companion matrix (independent of the reduction and of the estimate) and a second solution from
the uninverted pencil, whose distance measures the references' round-off. The true relative
error e of a tracked eigenvalue s is its distance to the nearest full root over |s|. The estimate
is first order (eigen_error's module docstring): it neglects the second Neumann term, relative size
ε² with ``ε = (|s|/ω_c)² + η(|s| + Ω)/ω_ref`` (ω_c the lowest frequency of the complement, the
9th undamped mode, 3382 rad/s; η = 0.02 the loss factor, whose viscous damping ``s η K/ω_ref`` and
circulatory ``Ω η K/ω_ref`` terms are the complement's loss beside its stiffness), and the
quadratic term, relative size e/gap (gap to the nearest other full root, relative to |s|). The bar
is 3 times their sum, as tests/test_eigen_error_reference.py holds δ (measured: the deviation is
at most 0.17 of the bar; estimating a column at its group's first speed, rest, moves it to 6.3).
Checked where the true error is 100 times above the references' round-off (1e-10 to 6e-10
relative; the basis errs by 1.4e-6 to 6.3e-4). A degenerate pair at rest has gap 0: no bar there.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from test_eigen_accuracy import SHAFT

import flexshaft
from flexshaft.analyses import eigen_error
from flexshaft.analyses.campbell import track_modes
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.loss import viscous_equivalent
from flexshaft.assembly.sparse import restrict
from flexshaft.design import loads_design

REFERENCE = 600.0  # ω_ref [rad/s] of the viscous weights
LOSS_FACTOR = 0.02  # η of the steel tube
SPEEDS = np.array([0.0, 1250.0, 2500.0])  # rad/s: to 2.1x the second critical speed (gyroscopic split)


def _viscous(speed: float):
    return viscous_equivalent(REFERENCE, speed)


@pytest.fixture(scope="module")
def lossy_tube():
    """The lossy tube's 8-mode basis, 4 tracked modes over :data:`SPEEDS`, at each speed the
    full roots by two dense solutions, and ω_c, the 9th undamped frequency [rad/s]."""
    text = SHAFT.replace("shaft_elements = 30", "shaft_elements = 8").replace(
        "density = 7810.0", f"density = 7810.0\nloss_factor = {LOSS_FACTOR}"
    )
    model = flexshaft.build_model(loads_design(text))

    def dense(A):
        return restrict(A.tocsr(), model.dofs.free).toarray()

    M, K, G, C = dense(model.M), dense(model.K + model.Kp), dense(model.G), dense(model.C + model.Kd)
    F, L, S = dense(model.loss_fixed), dense(model.loss_lateral), dense(model.loss_circulatory)
    n = M.shape[0]
    full = []
    for speed in SPEEDS:
        w = _viscous(speed)
        damping = speed * G + C + w.fixed * F + w.lateral * L
        stiffness = K + w.circulatory * S
        companion = np.zeros((2 * n, 2 * n))
        companion[:n, n:] = np.eye(n)
        companion[n:, :n] = -la.solve(M, stiffness, assume_a="pos")
        companion[n:, n:] = -la.solve(M, damping, assume_a="pos")
        roots = la.eigvals(companion)
        A = np.block([[np.zeros((n, n)), np.eye(n)], [-stiffness, -damping]])
        B = np.block([[np.eye(n), np.zeros((n, n))], [np.zeros((n, n)), M]])
        pencil = la.eigvals(A, B)
        full.append((roots[roots.imag > 0], pencil[np.isfinite(pencil) & (pencil.imag > 0)]))
    red = reduce(model, 8)
    tracked = track_modes(model, red, SPEEDS, 4, refine_loss=False, viscous=_viscous)
    omega_c = float(np.sqrt(la.eigh(K, M, eigvals_only=True)[red.size]))
    return red, tracked, full, omega_c


def _true_errors(tracked, full):
    """(speeds, modes) true relative errors, the references' round-off and the gap from the
    nearest full root to the next one, both relative to |s|."""
    true, roundoff, gap = (np.empty(tracked.eigenvalues.shape) for _ in range(3))
    for k, (roots, other) in enumerate(full):
        for m, s in enumerate(tracked.eigenvalues[k]):
            nearest = roots[np.argmin(np.abs(roots - s))]
            true[k, m] = abs(nearest - s) / abs(s)
            roundoff[k, m] = float(np.min(np.abs(other - nearest))) / abs(s)
            gap[k, m] = np.sort(np.abs(roots - nearest))[1] / abs(s)
    return true, roundoff, gap


@pytest.mark.parametrize("group_bytes", [2**62, 1], ids=["all speeds in one group", "one speed a group"])
def test_each_column_is_estimated_at_its_own_speed(lossy_tube, monkeypatch, group_bytes):
    red, tracked, full, omega_c = lossy_tube
    monkeypatch.setattr(eigen_error, "_GROUP_BYTES", group_bytes)
    estimate = eigen_error.tracked_errors(red, SPEEDS, tracked.eigenvalues, tracked.states, _viscous)
    s = tracked.eigenvalues
    true, roundoff, gap = _true_errors(tracked, full)
    eps = (np.abs(s) / omega_c) ** 2 + LOSS_FACTOR * (np.abs(s) + SPEEDS[:, None]) / REFERENCE
    with np.errstate(divide="ignore"):
        bar = 3 * (eps**2 + true / gap)
    checked = (true > 100 * roundoff) & np.isfinite(bar)
    assert checked[1:].all()  # every point above rest: the columns after the group's first
    deviation = np.abs(estimate - true)[checked] / true[checked]
    assert np.all(deviation <= bar[checked]), np.max(deviation / bar[checked])

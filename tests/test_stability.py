"""Whirl stability with internal damping against closed forms (issue: thesis chapter 4).

Jeffcott-like rotor: heavy midspan disk (m), near-massless pinned-pinned shaft (7e-6 of the disk mass; lighter
makes the first-order problem ill-conditioned) with loss factor
η, an external dashpot c_e at the disk. The shaft's C_i ∝ K' condenses exactly onto the disk, so
in complex coordinates r = v + iw the forward mode obeys

    m s² + c_e s + c_i (s − iΩ) + k = 0,      c_i = η k / ω_ref   (viscous equivalent)
    m s² + c_e s + k (1 + iη sgn(ω − Ω)) = 0                      (hysteretic, ω = Im s)

and the backward mode m s² + c_e s + k(1 + iη) = 0 on both sides of the spin (tests/test_damping.py
derives both).
"""

import numpy as np
import pytest
import scipy.linalg as la
from conftest import shared_result
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.loss import LossCoefficients, eigen_coefficients
from flexshaft.analyses.stability import rotation_generator, stability
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import baseline_design, with_overrides


def forward_root(speed, c_e, c_i):
    """Root with Im(s) > 0 of m s² + (c_e + c_i) s + k − iΩc_i = 0 near the forward mode."""
    roots = np.roots([M_DISK, c_e + c_i, K_SHAFT - 1j * speed * c_i])
    return roots[np.argmax(roots.imag)]


def test_viscous_internal_damping_threshold_is_wn_times_one_plus_ce_over_ci():
    eta, zeta_e = 0.02, 0.005
    c_e = 2 * zeta_e * M_DISK * WN
    c_i = eta * K_SHAFT / WN  # ω_ref = ω_n
    model = jeffcott(eta, c_e)
    speeds = np.linspace(0.5, 2.0, 301) * WN
    res = stability(model, speeds, n_modes=2, damping_model="viscous", reference_frequency=WN)
    # the forward mode's real part against the closed-form root at every speed
    fwd = np.array([forward_root(s, c_e, c_i) for s in speeds])
    tracked = res.eigenvalues[:, np.argmax(res.eigenvalues[-1].real)]
    assert np.allclose(tracked.real, fwd.real, rtol=1e-4, atol=1e-6 * WN)
    expected = WN * (1 + c_e / c_i)
    assert expected == pytest.approx(WN * (1 + 2 * zeta_e / eta))
    # linear interpolation of Re(s) on a 0.5 % speed grid: error far below 1e-3
    assert res.onset_speed == pytest.approx(expected, rel=1e-3)
    assert res.whirl[-1, res.unstable_mode] == "forward"


@pytest.mark.parametrize("basis_size", [4, 8])
def test_overdamped_internal_roots_never_take_the_whirl_roots_places(basis_size):
    """Was: with the viscous model every shaft mode above 2 ω_ref/η is damped past critical and
    whirls at about Ω/2, below the disk's modes; among the 2n roots of lowest |s| those took the
    places of the disk's forward or backward root (by LAPACK's round-off: numpy 1.26 / scipy
    1.16 at the default basis, every build at a basis of 8), and the onset was missed. Reference:
    the closed-form forward root, as above, and the onset W_N (1 + c_e/c_i)."""
    eta, zeta_e = 0.02, 0.005
    c_e = 2 * zeta_e * M_DISK * WN
    c_i = eta * K_SHAFT / WN
    speeds = np.linspace(0.5, 2.0, 61) * WN
    res = stability(
        jeffcott(eta, c_e), speeds, n_modes=2, damping_model="viscous", reference_frequency=WN, basis_size=basis_size
    )
    assert sorted(res.whirl[-1]) == ["backward", "forward"]
    tracked = res.eigenvalues[:, list(res.whirl[-1]).index("forward")]
    fwd = np.array([forward_root(s, c_e, c_i) for s in speeds])
    assert np.allclose(tracked.real, fwd.real, rtol=1e-4, atol=1e-6 * WN)
    # linear interpolation of Re(s) on a 2.5 % speed grid of a nearly linear Re(s): 1e-3
    assert res.onset_speed == pytest.approx(WN * (1 + c_e / c_i), rel=1e-3)


def test_lowest_modes_put_overdamped_roots_last_and_a_divergence_first():
    """Constructed roots: two vibration modes (ζ 0.01, 0.3), two overdamped stable ones below them
    in Im s (ζ 0.99995, and a real root), and a real divergent root (Re s > 0)."""
    from flexshaft.analyses.eigen import lowest_modes

    vib1, vib2 = complex(-3.0, 300.0), complex(-0.3 * 520 / np.sqrt(1 - 0.09), 520.0)
    over, real_root, divergent = complex(-1.5e4, 150.0), complex(-200.0, 0.0), complex(5.0, 0.0)
    s = np.array([over, vib2, real_root, vib1])
    assert list(s[lowest_modes(s, 2)]) == [vib1, vib2]
    assert list(s[lowest_modes(s, 3)]) == [vib1, vib2, real_root]  # fewer vibration modes than asked
    s = np.append(s, divergent)
    assert list(s[lowest_modes(s, 2)]) == [divergent, vib1]  # Im s = 0 first, as before


def hysteretic_roots(c_e, eta):
    """Closed-form Jeffcott roots (module docstring): the forward roots of the two sides of the
    spin, s₊ (σ = +1) and s₋ (σ = −1), and the backward root (its loss sign is always +)."""
    roots = np.roots([M_DISK, c_e, K_SHAFT * (1 + 1j * eta)])
    s_plus = roots[np.argmax(roots.imag)]
    roots = np.roots([M_DISK, c_e, K_SHAFT * (1 - 1j * eta)])
    s_minus = roots[np.argmax(roots.imag)]
    return s_plus, s_minus, s_plus  # the backward root solves the σ = +1 equation on both sides


def basis_round_off():
    """Relative round-off of the test rotor's frequencies. The dense basis eigen-solve errs by
    ε‖K‖ in ω² (backward stability), i.e. by ε κ relative at ω_n with κ = ω_max²/ω_n² (the
    near-massless shaft's stiffest basis mode against the disk mode, about 4e10); the frequency
    by half that. Ten times ε κ / 2 is asserted: about 4e-5 (different BLAS kernels move the
    frequencies by 5e-6)."""
    w2_max = reduce(jeffcott(0.02, 0.0), 48).w2.max()
    return 10 * np.finfo(float).eps * (w2_max / WN**2) / 2


def test_hysteretic_forward_mode_above_wn_has_real_part_eta_wn_minus_ce_over_m_over_two():
    """Reference: the closed-form roots of m s² + c_e s + k(1 + iησ), σ = sgn(ω − Ω). The forward
    roots of the two sides share one frequency ω_d (s₋ = −c_e/m − s̄₊ exactly), so below ω_d only
    the damped s₊ is an eigenvalue, above it only s₋ with Re s₋ = (ηω_n − c_e/m)/2 + O(η²) > 0:
    the onset is ω_d itself, whatever the speed grid. The set of tracked eigenvalues is checked
    at every speed of the scan, which no choice of branch by round-off can pass by accident."""
    eta, zeta_e = 0.02, 0.005
    c_e = 2 * zeta_e * M_DISK * WN
    model = jeffcott(eta, c_e)
    s_plus, s_minus, backward = hysteretic_roots(c_e, eta)
    w_d = s_plus.imag
    assert s_minus == pytest.approx(-c_e / M_DISK - np.conj(s_plus), rel=1e-14)
    assert s_minus.real == pytest.approx((eta * WN - c_e / M_DISK) / 2, rel=eta)
    tol = basis_round_off()
    speeds = np.array([0.6, 0.9, 1.2, 1.6, 2.0, 3.0]) * WN
    res = stability(model, speeds, n_modes=2, damping_model="hysteretic")
    res_scan = stability(model, np.linspace(0.9, 1.1, 81) * WN, n_modes=2, damping_model="hysteretic")
    for r in (res, res_scan):
        for speed, got in zip(r.speeds, r.eigenvalues):
            if abs(speed / w_d - 1) < tol:
                continue  # on the line within round-off: either side is right
            forward = s_plus if speed < w_d else s_minus
            want = np.sort_complex(np.array([forward, backward]))
            # each root to the frequencies' round-off: |Δs| ≈ ω_d · tol
            np.testing.assert_allclose(np.sort_complex(got), want, rtol=0, atol=tol * w_d)
    assert res.onset_speed is not None and res_scan.onset_speed is not None
    assert res_scan.onset_speed == pytest.approx(w_d, rel=tol)  # the jump itself, not the grid
    assert res.onset_speed == pytest.approx(w_d, rel=tol)
    assert res_scan.whirl[-1, res_scan.unstable_mode] == "forward"


def test_a_given_basis_without_the_estimate_keeps_the_closed_form_onset():
    """``stability(..., reduced=red, estimate=False)`` (the gain map's call) on the Jeffcott rotor:
    the onset is still ω_d of the closed-form roots (the estimate only reports, it changes no
    eigenvalue), and no estimate is made."""
    eta, zeta_e = 0.02, 0.005
    c_e = 2 * zeta_e * M_DISK * WN
    model = jeffcott(eta, c_e)
    w_d = hysteretic_roots(c_e, eta)[0].imag
    res = stability(model, np.array([0.6, 0.9, 1.2, 1.6]) * WN, 2, reduced=reduce(model, 8), estimate=False)
    assert res.error_estimate is None
    assert res.onset_speed == pytest.approx(w_d, rel=basis_round_off())


def pencil_roots(red, speed, weights, bounds=False):
    """Roots with Im s > 0 of the branch problem [s² I + s D + K + W] y = 0 on the modal basis,
    by QZ on the linearisation A z = s B z, A = [[−K, 0], [0, I]], B = [[D, I], [I, 0]],
    z = (y, s y): another linearisation and another algorithm than the package's QR of its
    companion matrix. PD bearings only (no controller states).

    With ``bounds``, also returns each root's error bound [rad/s]: first-order perturbation theory, an
    eigenvalue of a backward-stable solve errs by ε‖data‖ κ, κ = ‖x‖‖y‖/|yᴴ B x| from the
    right and left eigenvectors; the bound adds that of the QZ root (data ‖A‖ + |s|‖B‖) and
    that of the companion matrix [[0, I], [−K, −D]] a QR solver sees, ten times over."""
    assert all(a.A.size == 0 for a in red.actuators)
    fixed, lateral, circulatory = weights
    K = np.diag(red.w2) + fixed * red.F + lateral * red.L + circulatory * red.S
    D = speed * red.G + red.C
    for a in red.actuators:
        K = K + a.stiffness * a.coupling
        D = D + a.damping * a.coupling
    n = red.size
    I, Z = np.eye(n), np.zeros((n, n))
    A, B = np.block([[-K, Z], [Z, I]]), np.block([[D, I], [I, Z]])
    if not bounds:
        lam = la.eigvals(A, B)
        return lam[np.isfinite(lam) & (lam.imag > 0)]
    lam, left, right = la.eig(A, B, left=True, right=True)
    keep = np.isfinite(lam) & (lam.imag > 0)
    lam, left, right = lam[keep], left[:, keep], right[:, keep]
    kappa = np.linalg.norm(left, axis=0) * np.linalg.norm(right, axis=0) / np.abs(np.sum(left.conj() * (B @ right), 0))
    bound = kappa * (la.norm(A, 2) + np.abs(lam) * la.norm(B, 2))
    C = np.block([[Z, I], [-K, -D]])
    mu, cleft, cright = la.eig(C, left=True, right=True)
    kc = np.linalg.norm(cleft, axis=0) * np.linalg.norm(cright, axis=0) / np.abs(np.sum(cleft.conj() * cright, 0))
    nearest = np.argmin(np.abs(mu[None, :] - lam[:, None]), axis=1)
    bound = bound + kc[nearest] * la.norm(C, 2)
    return lam, 10 * np.finfo(float).eps * bound


#: The loss weights of F, K_lat and K_lat S for a mode of frequency ω > 0 at spin Ω > 0,
#: typed from L(ω, Ω) = i F + i (σ_B + σ)/2 K_lat + (σ_B − σ)/2 K_lat S with σ_B = 1
#: (tests/test_damping.py derives the Jeffcott case): above the spin and below it.
ABOVE, BELOW = (1j, 1j, 0.0), (1j, 0.0, 1.0)


def damped_baseline():
    return build_model(with_overrides(baseline_design(), {"bearings[1].kd": 200.0, "bearings[2].kd": 200.0}))


def consistent(solver: str, red, speed):
    """The eigenvalues R(Ω) by ``solver``: ``consistent_roots`` (with every vector) or
    ``consistent_values`` (the vectors only where the on-line pairing reads them)."""
    from flexshaft.analyses import hysteretic_roots

    if solver == "consistent_roots":
        return hysteretic_roots.consistent_roots(red, speed)[0]
    return hysteretic_roots.consistent_values(red, speed)


SOLVERS = ["consistent_roots", "consistent_values"]


def _branch_roots_on_their_own_side() -> dict[float, tuple[np.ndarray, np.ndarray]]:
    """For the damped baseline at rest and at four speeds: each side's roots by QZ
    (:func:`pencil_roots`) filtered by their own side (Im s ≥ Ω above the spin, ≤ Ω below),
    with their perturbation bounds: {speed: (roots, bounds)}."""
    red = reduce(damped_baseline(), 48)
    out = {}
    for speed in (0.0, 150.0, 327.3, 430.0, 600.0):
        sides = [(ABOVE, +1)] if speed == 0 else [(ABOVE, +1), (BELOW, -1)]
        want, tol = [], []
        for weights, sign in sides:
            lam, bound = pencil_roots(red, speed, weights, bounds=True)
            mine = sign * (lam.imag - speed) >= -1e-9 * speed
            want.append(lam[mine])
            tol.append(bound[mine])
        out[speed] = (np.concatenate(want), np.concatenate(tol))
    return out


@pytest.fixture(scope="module")
def branch_roots(tmp_path_factory) -> dict[float, tuple[np.ndarray, np.ndarray]]:
    """:func:`_branch_roots_on_their_own_side`, the reference of both solvers' test below: the
    same QZ solves with their bounds for each (9 of them, 0.2 s of CPU), computed once a session
    (tests/conftest.py's ``shared_result``; CPU budget, issue 23)."""
    return shared_result(tmp_path_factory, "stability_branch_roots", _branch_roots_on_their_own_side)


@pytest.mark.parametrize("solver", SOLVERS)
def test_hysteretic_eigenvalues_are_exactly_the_branch_roots_on_their_own_side(solver, branch_roots):
    """The eigenvalues of the hysteretic problem (piecewise linear in s: one linear problem
    above the spin, one below) are the roots of the problem above the spin with Im s ≥ Ω and
    of the one below with Im s ≤ Ω, nothing else. Reference: each side's roots by QZ
    (:func:`pencil_roots`), filtered by their own side in the test
    (:func:`_branch_roots_on_their_own_side`, shared by both solvers). Both inclusions are
    checked on the damped baseline (gyroscopic, PD bearings, shaft and boom loss) at rest and at
    four speeds, so the set cannot depend on which root an iteration reaches. Tolerance: each
    root's perturbation bound (:func:`pencil_roots`)."""
    red = reduce(damped_baseline(), 48)
    for speed, (want, tol) in branch_roots.items():
        got = consistent(solver, red, speed)
        band = 1e-6 * speed  # a root this close to the line may fall on either side of it
        for s in got:  # every eigenvalue found is a root on its own side
            k = np.argmin(np.abs(want - s))
            assert abs(want[k] - s) <= tol[k], (speed, s, tol[k])
        for s, bound in zip(want, tol):  # and every such root is found
            if abs(s.imag - speed) > band:
                assert np.min(np.abs(got - s)) <= bound, (speed, s, bound)
        assert got.size == want.size


def test_consistent_values_without_an_inverse_iteration_take_the_dense_vectors(monkeypatch):
    """When the inverse iteration of the upper branch's roots below the line fails (T(s)
    singular to working precision), ``consistent_values`` takes every vector of that branch
    from its dense solve: then it repeats ``consistent_roots``' computation, to round-off."""
    from flexshaft.analyses import hysteretic_roots

    red = reduce(damped_baseline(), 48)
    monkeypatch.setattr(
        hysteretic_roots, "_null_vectors", lambda red, speed, weights, roots: np.full((red.size, roots.size), np.nan)
    )
    for speed in (150.0, 430.0):
        want = hysteretic_roots.consistent_roots(red, speed)[0]
        np.testing.assert_allclose(hysteretic_roots.consistent_values(red, speed), want, rtol=1e-14)


def _synchronous_pairs() -> list[tuple[complex, complex, float]]:
    """Each forward mode's roots above and below the spin (s₊, s₋) by QZ (:func:`pencil_roots`)
    near the synchronous line of the damped baseline, and the speed between their frequencies
    (fixed-point iteration: the frequencies move with the speed): (s₊, s₋, Ω) for each pair."""
    red = reduce(damped_baseline(), 48)
    speed = 430.0
    above, below = pencil_roots(red, speed, ABOVE), pencil_roots(red, speed, BELOW)
    pairs = [(p, below[np.argmin(np.abs(below - p))]) for p in above if 0.5 * speed < p.imag < 2 * speed]
    # the loss moves a forward root by ~ηω/2 in its real part and far less in frequency
    pairs = [(p, q) for p, q in pairs if 1e-6 < abs(p.imag - q.imag) / p.imag < 1e-3 and abs(p - q) < 0.05 * abs(p)]
    out = []
    for p, q in pairs:
        for _ in range(4):  # the speed between the pair's frequencies, which move with the speed
            speed = 0.5 * (p.imag + q.imag)
            above, below = pencil_roots(red, speed, ABOVE), pencil_roots(red, speed, BELOW)
            p, q = above[np.argmin(np.abs(above - p))], below[np.argmin(np.abs(below - q))]
        out.append((complex(p), complex(q), float(speed)))
    return out


@pytest.fixture(scope="module")
def synchronous_pairs(tmp_path_factory) -> list[tuple[complex, complex, float]]:
    """:func:`_synchronous_pairs`, the reference of both solvers' test below: the same QZ solves
    for each (58 of them, 0.4 s of CPU), computed once a session (tests/conftest.py's
    ``shared_result``; CPU budget, issue 23)."""
    return shared_result(tmp_path_factory, "stability_synchronous_pairs", _synchronous_pairs)


@pytest.mark.parametrize("solver", SOLVERS)
def test_a_mode_near_the_synchronous_line_has_one_root_in_a_gap_and_two_in_a_fold(solver, synchronous_pairs):
    """A forward mode's roots above and below the spin (s₊, s₋) differ by the shaft loss, their
    frequencies by O(η²)ω: where ω₊ < Ω < ω₋ neither is consistent and the eigenvalue sits on
    the line (Im s = Ω, the loss sign set-valued at 0, its real part between those of s₊ and
    s₋); where ω₋ < Ω < ω₊ both are eigenvalues. Reference: s₊, s₋ by QZ (:func:`pencil_roots`);
    the crossing speed of each pair solved in the test by fixed-point iteration
    (:func:`_synchronous_pairs`, shared by both solvers)."""
    red = reduce(damped_baseline(), 48)
    seen = set()
    for p, q, speed in synchronous_pairs:
        got = consistent(solver, red, speed)
        near = got[np.abs(got - p) < 2 * abs(p - q)]
        tol = 1e-7 * abs(p)  # QZ against QR (previous test), with the fixed-point residual
        if p.imag < speed < q.imag:  # gap: one root, on the line
            seen.add("gap")
            assert near.size == 1
            assert near[0].imag == pytest.approx(speed, rel=1e-9)  # the synchronous band
            assert min(p.real, q.real) - tol <= near[0].real <= max(p.real, q.real) + tol
        elif q.imag < speed < p.imag:  # fold: both
            seen.add("fold")
            assert near.size == 2
            np.testing.assert_allclose(np.sort_complex(near), np.sort_complex(np.array([p, q])), rtol=0, atol=tol)
    assert seen == {"gap", "fold"}  # the baseline has both (its modes 8 and 9 near 414 and 418 rad/s)


@pytest.mark.parametrize("damping_model", ["viscous", "hysteretic"])
def test_no_internal_damping_is_stable_at_all_speeds(damping_model):
    model = jeffcott(0.0, 2 * 0.005 * M_DISK * WN)
    res = stability(model, np.linspace(0, 4, 41) * WN, n_modes=2, damping_model=damping_model, reference_frequency=WN)
    assert res.onset_speed is None
    assert np.all(res.eigenvalues.real < 0)


def test_modal_basis_matches_direct_state_space_at_speed():
    """The reduced fast path against the full first-order problem on the baseline."""
    model = build_model(baseline_design())
    speed, ref = 450.0, 300.0
    res = stability(model, [speed], n_modes=10, damping_model="viscous", reference_frequency=ref)
    f = model.dofs.free
    Ci = model.shaft_loss_stiffness / ref
    Cb = model.boom_loss_stiffness / ref
    D = restrict((speed * model.G + model.C + model.Kd + Ci + Cb).tocsr(), f).toarray()
    K = restrict((model.K.real + model.Kp + speed * Ci @ rotation_generator(model)).tocsr(), f).toarray()
    M = restrict(model.M, f).toarray()
    n = M.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-la.solve(M, K), -la.solve(M, D)]])
    lam = la.eigvals(A)
    lam = lam[lam.imag > 1e-6]
    lam = lam[np.argsort(lam.imag)][:10]
    fast = res.eigenvalues[0][np.argsort(res.eigenvalues[0].imag)]
    assert np.allclose(fast.imag, lam.imag, rtol=1e-5)
    assert np.allclose(fast.real, lam.real, rtol=1e-3, atol=1e-4)


def test_circulatory_matrix_is_skew_symmetric():
    model = build_model(baseline_design())
    Kc = (model.shaft_loss_stiffness @ rotation_generator(model)).toarray()
    assert np.abs(Kc + Kc.T).max() < 1e-9 * np.abs(Kc).max()


def test_onset_speed_converges_with_mesh():
    """The onset moves by less than 2e-3 from the 2x to the 4x mesh, and less than from the 1x.
    35 speeds (CPU budget, issue 23): the onset is solved between the grid speeds, and on 18, 35
    or 86 speeds it agrees to 1e-8 relative, far below the 3e-5 to 3e-4 the meshes move it."""
    base = with_overrides(baseline_design(), {"bearings[1].kd": 200.0, "bearings[2].kd": 200.0})
    onsets = []
    for factor in (1, 2, 4):
        d = with_overrides(base, {"mesh.shaft_elements": 12 * factor, "mesh.boom_elements": 8 * factor})
        model = build_model(d)
        res = stability(model, np.linspace(0.3, 2.0, 35) * model.speed, n_modes=10)
        assert res.onset_speed is not None
        onsets.append(res.onset_speed)
    onsets = np.array(onsets)
    assert abs(onsets[1] / onsets[2] - 1) < 2e-3
    assert abs(onsets[1] - onsets[2]) <= abs(onsets[0] - onsets[2]) + 1e-9 * onsets[2]


def test_mode_assignment_is_scipys_linear_sum_assignment():
    """Reference: scipy.optimize.linear_sum_assignment (the Hungarian/LAPJV solver the tracking
    used before). ``assignment`` must give the same columns on random rectangular costs, on
    costs whose row minima collide (the matching path) and where they do not (the shortcut)."""
    import importlib

    from scipy.optimize import linear_sum_assignment

    assignment = importlib.import_module("flexshaft.analyses.campbell").assignment
    rng = np.random.default_rng(7)
    shortcut = matching = 0
    for _ in range(400):
        p = int(rng.integers(1, 25))
        cost = rng.random((p, p + int(rng.integers(0, 12)))) * 10.0 ** rng.integers(-3, 4)
        if rng.random() < 0.3:  # a near-permutation: each row's own minimum is distinct
            cost[np.arange(p), rng.permutation(cost.shape[1])[:p]] -= cost.max()
        distinct = np.unique(cost.argmin(axis=1)).size == p
        shortcut, matching = shortcut + distinct, matching + (not distinct)
        np.testing.assert_array_equal(assignment(cost), linear_sum_assignment(cost)[1])
    assert shortcut > 50 and matching > 50


def test_shaft_whirl_on_one_model_equals_separate_analyses():
    """Reference: each damping model's stability on its own freshly built model (its own modal
    basis), as the thesis-shaft comparison ran before. One model and one basis for both damping
    models must give the same eigenvalues and onsets exactly (the basis does not depend on the
    damping, and no analysis may leave state behind for the other)."""
    from flexshaft.thesis.whirl import shaft_stability, shaft_whirl

    design = baseline_design()
    speeds = np.linspace(0.0, 1.5 * design.operating.speed_rad_s, 13)
    both = shaft_whirl(design, speeds, n_modes=6)
    assert list(both) == ["viscous", "hysteretic"]
    for damping, result in both.items():
        alone = shaft_stability(design, speeds, damping, 6)
        assert np.array_equal(result.eigenvalues, alone.eigenvalues)
        assert result.onset_speed == alone.onset_speed


def test_newton_terms_vanish_at_the_state_matrix_roots_and_give_the_derivative_of_T():
    """``ReducedModel.newton_terms`` (what Newton's method of the hysteretic stability solves)
    for a lagged, non-collocated magnet pair (PID with states, sensor offsets, negative
    stiffness) and for PD bearings with and without sensor offsets, against two independent
    references: T(s) is singular at every eigenvalue of the first-order state matrix (which
    realises the laws with controller states), smallest singular value below 1e-9 of the
    largest (round-off of the eigen-solve); and dT/ds · y is the central difference of T(s) y,
    step 1e-5 |s|, to 1e-7 (truncation ~1e-10, round-off ~1e-11 of |dT/ds · y|)."""
    lagged = {}
    for i, offset in ((1, 0.04), (2, -0.03)):
        lagged.update(
            {
                f"bearings[{i}].{k}": v
                for k, v in (
                    ("ks", 8.5e5),
                    ("ki", 177.0),
                    ("kp", 1.6e4),
                    ("kd", 11.0),
                    ("integral_gain", 1e5),
                    ("derivative_cutoff", 500.0),
                    ("amplifier_bandwidth", 1000.0),
                    ("sensor_offset", offset),
                )
            }
        )
    pd = {"bearings[1].kd": 300.0, "bearings[2].kd": 300.0}
    offset_pd = {**pd, "bearings[1].sensor_offset": 0.04, "bearings[2].sensor_offset": -0.03}
    rng = np.random.default_rng(7)
    for overrides in (lagged, pd, offset_pd):
        model = build_model(with_overrides(baseline_design(), overrides))
        red = reduce(model, 24)
        speed = model.speed
        lam = la.eigvals(red.state_matrix(speed))
        lam = lam[lam.imag > 1.0]
        lam = lam[np.argsort(np.abs(lam))][:10]
        none = LossCoefficients(0.0, 0.0, 0.0)
        y = rng.standard_normal(red.size) + 1j * rng.standard_normal(red.size)
        for s in lam:
            T, _ = red.newton_terms(s, speed, none, y)
            sv = la.svdvals(T)
            assert sv[-1] <= 1e-9 * sv[0]
        for s in (lam[0], lam[-1], 3.0 + 400.0j):
            loss = eigen_coefficients(model.internal_damping, abs(s.imag), speed, 1.0)
            for weights in (none, loss):
                _, dTy = red.newton_terms(s, speed, weights, y)
                h = 1e-5 * abs(s)
                ahead, _ = red.newton_terms(s + h, speed, weights, y)
                behind, _ = red.newton_terms(s - h, speed, weights, y)
                np.testing.assert_allclose(dTy, (ahead - behind) @ y / (2 * h), rtol=0, atol=1e-7 * np.abs(dTy).max())

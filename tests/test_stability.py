"""Whirl stability with internal damping against closed forms (issue: thesis chapter 4).

Jeffcott-like rotor: heavy midspan disk (m), near-massless pinned-pinned shaft (7e-6 of the disk mass; lighter
makes the first-order problem ill-conditioned) with loss factor
η, an external dashpot c_e at the disk. The shaft's C_i ∝ K' condenses exactly onto the disk, so
in complex coordinates r = v + iw the forward mode obeys

    m s² + c_e s + c_i (s − iΩ) + k = 0,      c_i = η k / ω_ref   (viscous equivalent)
    m s² + c_e s + k (1 + iη sgn(ω − Ω)) = 0                      (hysteretic)
"""

import numpy as np
import pytest
import scipy.linalg as la
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


def test_hysteretic_forward_mode_above_wn_has_real_part_eta_wn_minus_ce_over_m_over_two():
    eta, zeta_e = 0.02, 0.005
    c_e = 2 * zeta_e * M_DISK * WN
    model = jeffcott(eta, c_e)
    speeds = np.array([0.6, 0.9, 1.2, 1.6, 2.0, 3.0]) * WN
    res = stability(model, speeds, n_modes=2, damping_model="hysteretic")
    re_fwd = res.eigenvalues.real.max(axis=1)
    expected = (eta * WN - c_e / M_DISK) / 2
    # first-order result; the viscous-equivalent's residual term ηkσ/|ω − Ω| is O(σ/ω) ≈ 1 %
    assert np.allclose(re_fwd[speeds > 1.1 * WN], expected, rtol=0.02)
    # below ω_n both whirls are damped: Re(s) = −(ηω_n + c_e/m)/2 for the forward mode
    assert np.all(re_fwd[speeds < WN] < 0)
    res_scan = stability(model, np.linspace(0.9, 1.1, 81) * WN, n_modes=2, damping_model="hysteretic")
    assert res_scan.onset_speed == pytest.approx(WN, rel=5e-3)  # unstable at every Ω > ω_n


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
    base = with_overrides(baseline_design(), {"bearings[1].kd": 200.0, "bearings[2].kd": 200.0})
    onsets = []
    for factor in (1, 2, 4):
        d = with_overrides(base, {"mesh.shaft_elements": 12 * factor, "mesh.boom_elements": 8 * factor})
        model = build_model(d)
        res = stability(model, np.linspace(0.3, 2.0, 86) * model.speed, n_modes=10)
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

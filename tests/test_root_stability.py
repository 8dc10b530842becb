"""Every root of the closed loop (flexshaft.analyses.root_stability) against references derived here.

* Jeffcott rotor with rotating hysteretic damping (tests/rotors.py): above ω_n the forward root
  solves m s² + c_e s + k (1 − iη) = 0 (σ = sgn(ω − Ω) = −1), below it m s² + c_e s + k (1 + iη) = 0;
  the check finds the first unstable above the spin and stable below, with those roots.
* A rigid rotor on two PID magnetic bearings with filtered derivative and amplifier lag
  (tests/test_amb.py: the closed loop of one lateral plane written out by hand, 10 states): with
  a destabilising integral gain the unstable roots of the hand-built matrix are among the
  check's, and with the stable gains the least-damped root is the hand-built one.
* The passive route (ideal PD bearings: only the roots below the spin are solved, the rest stable
  by the energy argument; a basis chosen for a stated accuracy by an a-posteriori estimate)
  against the exact full-basis route on the tuned driveline.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from rotors import K_SHAFT, M_DISK, WN, jeffcott
from test_amb import E_RIGID, F_A, F_D, KD, KI, KP, KS, hand_state_matrix, rotor

from flexshaft.analyses import root_stability as rs
from flexshaft.analyses.hysteretic_roots import consistent_values
from flexshaft.analyses.root_stability import root_stability
from flexshaft.assembly import build_model
from flexshaft.design import tuned_design


def test_jeffcott_forward_root_turns_unstable_above_the_first_critical():
    """η = 0.02, ζ_e = 0.005: Re s = (η ω_n − c_e/m)/2 > 0 above ω_n. The check's least-damped
    root at 1.6 ω_n is the root of m s² + c_e s + k (1 − iη) = 0 (the near-massless shaft, 7e-6 of
    the disk mass, and the modal truncation leave ~1e-5: 1e-4 asserted), and at 0.6 ω_n every root
    is stable, the forward one that of m s² + c_e s + k (1 + iη) = 0."""
    eta, zeta_e = 0.02, 0.005
    c_e = 2 * zeta_e * M_DISK * WN
    model = jeffcott(eta, c_e)
    result = root_stability(model, [0.6 * WN, 1.6 * WN])
    above = np.roots([M_DISK, c_e, K_SHAFT * (1 - 1j * eta)])
    unstable = above[np.argmax(above.real)]
    assert unstable.real > 0
    assert [r.speed for r in result.unstable] == [pytest.approx(1.6 * WN)]
    (root,) = result.unstable
    assert root.kind == "oscillatory" and root.refined
    assert root.root == pytest.approx(unstable, rel=1e-4)
    assert result.least_damped[1] == pytest.approx(unstable, rel=1e-4)
    assert result.onset_speed == pytest.approx(1.6 * WN)
    below = np.roots([M_DISK, c_e, K_SHAFT * (1 + 1j * eta)])
    forward = below[np.argmax(below.imag)]
    assert any(abs(s - forward) < 1e-4 * abs(forward) for s in result.roots[0])
    assert result.worst_at(0.6 * WN) is None and result.method == "passive"


def test_without_internal_loss_the_jeffcott_rotor_is_stable_at_every_speed():
    model = jeffcott(0.0, 2 * 0.005 * M_DISK * WN)
    result = root_stability(model, np.array([0.0, 1.0, 2.0, 4.0]) * WN)
    assert result.stable and result.onset_speed is None


#: The rigid-body and controller roots of the rotor lie below this [rad/s]; its bending modes
#: (E = 2.1e15) above 2e5 rad/s: undamped (no material loss), the lagged loops leave them
#: ζ ~ −1e-7, a property of the model that the hand-built rigid plane does not have.
RIGID = 1e4


def _hand_roots(**changes) -> np.ndarray:
    """Eigenvalues of the hand-built plane (both planes of the rotor have them)."""
    return la.eigvals(hand_state_matrix(**changes))


def test_rigid_rotor_with_a_destabilising_integrator_matches_the_hand_built_closed_loop():
    """Integral gain 6e7 A/(m s) (300 times the stable one): the hand-built plane has a complex
    pair with Re s > 0. Both planes of the FE rotor have it: the check's unstable roots at rest
    are those of the hand-built matrix (5e-6: the FE rotor's flexibility error ∝ 1/E, measured
    1e-6 at E = 2.1e15 in tests/test_amb.py; here 6e-6 for this fast pair: 1e-5 asserted)."""
    integral = 6.0e7
    keys = (
        f"kp = {KP}\nkd = {KD}\nintegral_gain = {integral}\nderivative_cutoff = {F_D}\n"
        f"amplifier_bandwidth = {F_A}\nks = {KS}\nki = {KI}"
    )
    hand = _hand_roots(integral=integral)
    hand_unstable = hand[(hand.real > 0) & (hand.imag > 0)]
    assert hand_unstable.size  # the reference is unstable
    result = root_stability(rotor(keys), [0.0])
    assert result.method == "full" and result.exact
    found = np.array([r.root for r in result.unstable if abs(r.root) < RIGID])
    for s in hand_unstable:
        matches = np.abs(found - s) <= 1e-5 * abs(s)
        assert matches.sum() == 2, (s, found)  # one per lateral plane
    assert len(found) == 2 * hand_unstable.size


def test_rigid_rotor_with_stable_gains_has_the_hand_built_least_damped_root():
    keys = (
        f"kp = {KP}\nkd = {KD}\nintegral_gain = 2.0e5\nderivative_cutoff = {F_D}\n"
        f"amplifier_bandwidth = {F_A}\nks = {KS}\nki = {KI}"
    )
    hand = _hand_roots()
    oscillatory = hand[hand.imag > 1e-6 * np.abs(hand)]
    least = oscillatory[np.argmax(oscillatory.real / np.abs(oscillatory))]
    result = root_stability(rotor(keys), [0.0])
    rigid = result.roots[0][np.abs(result.roots[0]) < RIGID]
    zeta = -rigid.real / np.abs(rigid)
    assert zeta.min() > 0
    assert rigid[np.argmin(zeta)] == pytest.approx(least, rel=1e-5)


def _low_roots(result, speed):
    """The oscillatory roots below the spin at the result's first speed, by frequency."""
    s = result.roots[0][result.roots[0].imag < speed]
    return s[np.argsort(s.imag)]


def test_passive_route_equals_the_full_basis_on_the_tuned_driveline(monkeypatch):
    """Ideal PD bearings: the roots below the spin from the passive route (a reduced basis chosen
    for 1e-6, the rest stable by the energy argument) against the exact full-basis route at
    4800 rpm (every mode of the model, no reduction error); the least-damped root of the full
    route is an undamped high mode (Re s = 0 to round-off), never unstable.

    The passive basis's accuracy is estimated, not bounded (flexshaft.analyses.eigen_error: the
    estimate is held within a factor 3 of the true error, tests/test_eigen_accuracy.py), so the
    true error is asserted within 3 × the tolerance, and the reported estimate within a factor 3
    of the largest true error. The plain modal basis of every mode below twice the top speed
    that this route used before moved the PD-damped bay modes near 54 Hz (ζ = 0.14) by 1.6e-4
    of |s|: this test would fail on it."""
    model = build_model(tuned_design())
    passive = root_stability(model, [model.speed])
    assert passive.method == "passive" and passive.stable
    assert passive.tolerance == 1e-6 and passive.error_estimate <= passive.tolerance

    monkeypatch.setattr(rs, "_is_passive", lambda m: False)
    full = root_stability(model, [model.speed])
    assert full.method == "full" and full.exact and full.stable and full.basis_size > passive.basis_size
    assert full.error_estimate is None
    low_passive, low_full = _low_roots(passive, model.speed), _low_roots(full, model.speed)
    assert low_passive.size == low_full.size > 0
    true = np.max(np.abs(low_passive - low_full) / np.abs(low_full))
    assert true <= 3 * passive.tolerance
    assert true / 3 <= passive.error_estimate <= 3 * true
    assert full.least_damping_ratio[0] > -1e-12
    # the passive check's least-damped root is among those its basis resolves (not a static
    # correction's Ritz root at kHz, zeta 4e-4): the least-damped of the full model's exact
    # loss-consistent roots up to that frequency (the full route keeps loss-free values above
    # the spin, so it is not the reference here); on the tuned design it lies below the spin,
    # where the basis is held to the tolerance
    exact = consistent_values(rs._lateral_basis(model, rs.reduce(model, model.dofs.free.size)), model.speed)
    exact = exact[np.abs(exact) <= passive.highest_frequency]
    least = exact[np.argmin(-exact.real / np.abs(exact))]
    assert least.imag < model.speed and abs(passive.least_damped[0]) <= passive.highest_frequency
    assert passive.least_damped[0] == pytest.approx(least, rel=3 * passive.tolerance)


def test_a_tighter_tolerance_takes_a_larger_passive_basis_and_meets_it(monkeypatch):
    """The passive route's basis is enlarged until the estimate meets the tolerance: at 1e-9 the
    tuned driveline's roots below the spin need more than the 1e-6 basis, and then agree with
    the full-basis route's to 3e-9 (the estimate's factor 3)."""
    model = build_model(tuned_design())
    coarse = root_stability(model, [model.speed])
    fine = root_stability(model, [model.speed], tolerance=1e-9)
    assert fine.method == "passive" and fine.error_estimate <= 1e-9 < coarse.error_estimate
    assert fine.basis_size > coarse.basis_size
    monkeypatch.setattr(rs, "_is_passive", lambda m: False)
    exact = _low_roots(root_stability(model, [model.speed]), model.speed)
    assert np.max(np.abs(_low_roots(fine, model.speed) - exact) / np.abs(exact)) <= 3e-9
    with pytest.raises(ValueError, match="tolerance"):
        root_stability(model, [model.speed], tolerance=0.0)


def test_the_torsional_subspace_is_left_out_only_when_decoupled():
    """The tuned driveline's twist DOFs (shaft θ and the tail rotor) are decoupled: the full
    basis leaves them out, and what remains has no mode with twist."""
    model = build_model(tuned_design())
    full = rs.reduce(model, model.dofs.free.size)
    lateral = rs._lateral_basis(model, full)
    twist = rs.torsional_system(model).dofs
    assert lateral.size == full.size - twist.size
    position = np.searchsorted(model.dofs.free, twist)
    share = np.sum(lateral.Phi[position] ** 2, axis=0) / np.sum(lateral.Phi**2, axis=0)
    assert share.max() < 1e-12


def test_bad_speeds_are_refused():
    model = rotor(f"kp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}", modulus=E_RIGID)
    with pytest.raises(ValueError, match="speeds"):
        root_stability(model, [-1.0])

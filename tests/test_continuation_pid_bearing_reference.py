"""The continuation's batched Newton step with a PID bearing (a law with a state *and* an ideal
derivative), against the closed-loop Jeffcott rotor's cubic.

The rotor of tests/jeffcott_bearing.py (``PID``: a 20 kg disk at mid-span of a near-massless
pinned-pinned tube, k = 48EI/L³, with the bearing k_i (k_p + k_d s + K_I/s) − k_s at the disk,
no lag). Per plane, at rest, m s² + k + k_i(k_p + k_d s + K_I/s) − k_s = 0; times s (derived,
as tests/test_eigen_pid_and_undamped_reference.py):

    m s³ + k_i k_d s² + (k + k_i k_p − k_s) s + k_i K_I = 0,

its root with Im s > 0 the disk mode's. The law's ideal derivative E = k_i k_d sits in the
modal damping (``damping_in_basis``), so T(s) takes ``L(s) − k_a − s E`` and Newton's tangent
``L'(s) − E``: :func:`~flexshaft.analyses.continuation.mode_roots` starts 1 % off on the
reduced model's two disk roots (a pair: isotropic) and must come back to the cubic's root,
flagged converged.

Newton's tangent is checked by its rate: with the exact tangent T'(s) y Newton's method
converges quadratically near a simple root (Taylor: e_{k+1} ≈ K e_k²; measured here e₁ ≈ 1e-4
from e₀ = 1.4e-2, K ≈ 0.5), so two steps from a
start 1.4 % off leave about (1e-2)⁴ of |s|, far below the 9e-7 the tube's mass moves the root;
the step is capped at two (``NEWTON_MAX_STEPS``) and the root must already be the cubic's to
2e-6 (the mass effect plus margin). A tangent without −E is a secant-like iteration, linear
only: 5e-6 off after two steps on this rotor.

Tolerance 5e-6 relative, as tests/test_continuation_filtered_bearing_reference.py: the tube's
3.5e-6 mass ratio moves the root by about 1e-6 (measured 9e-7 by the eigen-solver's test on
this rotor); Newton stops at 1e-10 |s|.
"""

from __future__ import annotations

import numpy as np
from jeffcott_bearing import K_INT, KD, KI, KP, KS, PID, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses import continuation
from flexshaft.analyses.continuation import branches, mode_roots, newton_many
from flexshaft.analyses.eigen import candidates, reduce


def test_continuation_with_a_pid_bearing_gives_the_closed_loop_cubic_root():
    roots = np.roots([M_DISK, KI * KD, K_SHAFT + KI * KP - KS, KI * K_INT])
    expected = roots[np.argmax(roots.imag)]
    red = reduce(model_with(PID), 8)
    assert red.actuators[0].law is not None and red.actuators[0].damping_in_basis == KI * KD
    s0, Y0 = candidates(red, 0.0)
    s, _, found = mode_roots(red, 0.0, s0[:2] * (1 + 0.01 - 0.01j), Y0[:, :2])
    assert np.all(found)
    np.testing.assert_allclose(s, [expected, expected], rtol=5e-6)


def test_two_newton_steps_from_one_percent_off_reach_the_root(monkeypatch):
    roots = np.roots([M_DISK, KI * KD, K_SHAFT + KI * KP - KS, KI * K_INT])
    expected = roots[np.argmax(roots.imag)]
    red = reduce(model_with(PID), 8)
    s0, Y0 = candidates(red, 0.0)
    monkeypatch.setattr(continuation, "NEWTON_MAX_STEPS", 2)
    s, _, _ = newton_many(red, 0.0, s0[:2] * (1 + 0.01 - 0.01j), Y0[:, :2], weights=branches(red, 0.0)[0].weights)
    np.testing.assert_allclose(s, [expected, expected], rtol=2e-6)

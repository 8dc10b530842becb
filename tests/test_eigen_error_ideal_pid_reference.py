"""The a-posteriori eigenvalue correction with a PID magnetic bearing whose derivative is ideal
(mutation hunt 46a).

tests/test_eigen_error_reference.py checks the correction δ on the flexible steel rotor of
tests/test_amb.py with its PID bearings' filtered derivative (a proper law: no feedthrough
``E s``). Here the same rotor with the PID law i = −(k_p + k_d s + k_I/s) d, the derivative
ideal: its part ``k_i k_d s`` is in the projected damping C̃ = Φᵀ(C + K_d)Φ, and the channel's
gain in the full residual is the law's minus what K and D already hold,
``L(s) − k_a − s k_i k_d`` (:func:`~flexshaft.analyses.eigen_error._actuator_gains`, the same
split as :meth:`~flexshaft.analyses.eigen.ReducedModel.newton_terms`).

Reference: each full root s* by Newton's method on the full dense
``T(s) = s²M + s(ΩG + C) + K + Σ B_aᵀ(G_a(s) − k_s)B_a`` (the model's controller matrix, the
law's own transfer function), started from the reduced root (tests/test_eigen_error_reference.py's
``_full_root``: round-off floor 1.4e-12 |s|). Bar (eigen_error's docstring): δ is first order;
what it neglects is the second Neumann term, ``(|s|/ω_c)⁴``, and the quadratic term ``|δ|/gap``
(the gap to the nearest other tracked root); three times their sum relative to |s* − s|, as the
filtered-law test asserts. Four modes of an 8-mode basis at 300 rad/s.

CPU: one 8-element rotor, 4 full Newton solves on about 50 DOFs: about 0.1 s.
"""

from __future__ import annotations

from test_amb import K_INT, KD, KI, KP, KS, rotor
from test_eigen_error_reference import assert_corrections_reach_the_full_roots

IDEAL_PID = f"kp = {KP}\nkd = {KD}\nintegral_gain = {K_INT}\nks = {KS}\nki = {KI}"


def test_correction_with_an_ideal_derivative_pid_is_the_distance_to_the_full_root():
    model = rotor(IDEAL_PID, 0.0, 2.1e11)  # a steel shaft: flexible modes above the rigid ones
    assert model.Kd.nnz > 0  # the ideal derivative sits in the damping
    assert_corrections_reach_the_full_roots(model)

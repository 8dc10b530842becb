"""Undamped modes of a rotor on a magnetic bearing whose law has a state (an amplifier lag), and
the whirl ratio of the Campbell labeler on a circular orbit (mutation hunt h52d).

1. ``modes(..., damped=False)`` keeps only the gyroscopic terms and at rest gives the undamped
   natural frequencies of ``(K + K_p) φ = ω² M φ`` (flexshaft.analyses.modal's docstring;
   docs/model.md, *Modal analysis*: the basis of ``(K + K_a) φ = ω² M φ``), K_p holding each law's
   static stiffness. The Jeffcott rotor of tests/jeffcott_bearing.py with the magnet at its disk
   and an amplifier lag of bandwidth ω_a: the law ``G(s) − k_s = k_i (k_p + k_d s)/(1 + s/ω_a) − k_s``
   has the static stiffness ``k_i k_p − k_s`` = 3e5 N/m, so, derived here, the disk's pair is
   ``s = ±i √((k + k_i k_p − k_s)/m)`` with k = 48EI/L³ the tube's stiffness at midspan, purely
   imaginary (no damping: the lag's dynamics, whose phase moves the pair off the imaginary axis,
   are left out). Tolerance 1e-5 relative on the frequency (the tube's 3.5e-6 mass share) and
   |Re s| below 1e-8 |s|: at rest the undamped first-order matrix [[0, I], [−M⁻¹K, 0]] splits
   into 2×2 blocks whose roots LAPACK returns with Re s = 0 exactly on both kernels tried
   (review r52d); with the lag's state kept, Re s = +7.3 rad/s (2.2e-2 |s|: the lag on
   k_i k_p outweighs k_d's lead).

2. :class:`flexshaft.analyses.classify.ModalLabeler` (the Campbell diagram's labels): a basis
   holding the disk node's v and w alone and the modal coordinates ``(1, −i)``, the forward
   circular orbit ``W = −iV``, has the whirl ratio ``r = −2 Im(V̄W)/(|V|² + |W|²) = +1`` exactly
   (classify's module docstring), ``(1, +i)`` has −1.

CPU: one 4-element model, a 16-state eig, milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, KI, KP, KS, disk, model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.classify import ModalLabeler
from flexshaft.analyses.modal import modes

F_A = 150.0  # Hz: amplifier bandwidth


def test_undamped_modes_leave_the_amplifier_lag_out():
    model = model_with(ACTIVE + f"\namplifier_bandwidth = {F_A}")
    assert model.actuators[0].feedback.realization()[0].shape == (1, 1)  # the law has a state
    omega = np.sqrt((K_SHAFT + KI * KP - KS) / M_DISK)
    s = modes(model, 0.0, n_modes=2, damped=False, basis_size=8).eigenvalues
    np.testing.assert_allclose(s.imag, [omega, omega], rtol=1e-5)
    assert np.all(np.abs(s.real) < 1e-8 * np.abs(s))


@pytest.mark.parametrize(("w", "ratio"), [(-1j, 1.0), (1j, -1.0)])
def test_labeler_whirl_ratio_of_a_circular_orbit(w, ratio):
    model = model_with(ACTIVE)
    free = list(model.dofs.free)
    v_dof, w_dof = disk(model)
    Phi = np.zeros((len(free), 2))
    Phi[free.index(v_dof), 0] = 1.0
    Phi[free.index(w_dof), 1] = 1.0
    labels = ModalLabeler(model, Phi)(np.array([[1.0], [w]]))
    assert labels.whirl_ratio[0] == pytest.approx(ratio, abs=1e-12)
    assert labels.whirl[0] == ("forward" if ratio > 0 else "backward")

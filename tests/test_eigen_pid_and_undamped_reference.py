"""The eigen-solver's law with states and ideal derivative, and its gyroscopic-only model, by hand.

Rotors: the Jeffcott disk of tests/rotors.py (m = 20 kg at midspan of a near-massless
pinned-pinned tube, k = 48EI/L³, ω_n = √(k/m) = 302.1 rad/s), at rest (no gyroscopic term).

* **A PID bearing at the disk** (tests/jeffcott_bearing.py's ``PID``: k_i (k_p + k_d s +
  K_I/s) − k_s, an integral state and an ideal derivative). The disk obeys, per plane,
  m s² r + k r + [k_i(k_p + k_d s + K_I/s) − k_s] r = 0; times s:

      m s³ + k_i k_d s² + (k + k_i k_p − k_s) s + k_i K_I = 0,

  whose complex pair is the mode :func:`~flexshaft.analyses.modal.modes` reports (twice: the
  v and w planes). The law's ideal derivative k_i k_d sits once in the projected damping (the
  model's K_d) and must not be added again through the law C(s) in T(s) (module docstring of
  :mod:`flexshaft.analyses.eigen`: ``L(s) − k_a − s E_basis``).
* **The undamped modes** (``damped=False``: "no viscous damping, no loss, no controller
  dynamics") of the Jeffcott disk on an external dashpot c_e = 400 N s/m are ±iω_n, not the
  damped pair −c_e/(2m) ± iω_n√(1 − ζ²) (Re s = −10 1/s).

Tolerance: the tube's mass (3.5e-6 of the disk's) moves the roots by about 1e-6 relative
(measured 9e-7 on both): asserted to 1e-5 relative; the real part of the undamped root to
1e-6 ω_n (round-off of a dense solve), far below the dashpot's 10 1/s.

Written for the mutations h35b-eigen-kd-twice-with-states and h35b-eigen-undamped-keeps-c of
scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import K_INT, KD, KI, KP, KS, PID, model_with
from rotors import K_SHAFT, M_DISK, WN, jeffcott

from flexshaft.analyses.modal import modes


def test_a_pid_bearing_with_an_ideal_derivative_gives_the_cubic_roots():
    roots = np.roots([M_DISK, KI * KD, K_SHAFT + KI * KP - KS, KI * K_INT])
    pair = roots[roots.imag > 0]
    assert pair.size == 1
    s = modes(model_with(PID), 0.0, n_modes=2).eigenvalues
    assert s == pytest.approx(np.full(2, pair[0]), rel=1e-5)


def test_the_undamped_modes_leave_out_the_dashpot():
    c_e = 400.0
    model = jeffcott(0.0, c_e)
    undamped = modes(model, 0.0, n_modes=2, damped=False).eigenvalues
    assert undamped.imag == pytest.approx(np.full(2, WN), rel=1e-5)
    assert np.abs(undamped.real).max() <= 1e-6 * WN
    damped = modes(model, 0.0, n_modes=2).eigenvalues  # the dashpot is in the damped model
    assert damped.real == pytest.approx(np.full(2, -c_e / (2 * M_DISK)), rel=1e-5)

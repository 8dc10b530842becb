"""The whirl-stability result's onset shape and the data file's unstable-mode number, on the
Jeffcott rotor of tests/rotors.py (mutation hunt h43b).

* The onset shape is the unstable mode's shape at the first unstable speed
  (:class:`~flexshaft.analyses.stability.StabilityResult`'s ``onset_shape``). Internal damping
  destabilises the forward whirl only (Zorzi & Nelson 1977; the Jeffcott rotor's forward root of
  m s² + (c_e + c_i) s + k − iΩ c_i = 0, tests/test_stability_onset_bookkeeping_reference.py).
  On the isotropic rotor the spinning modes are circular: the forward whirl has W = −iV at the
  disk (the convention of tests/test_modes_table_and_campbell_kinds_reference.py's forward
  orbit). On a grid of two speeds, rest and 2 ω_n (unstable), the shape at rest is no help: the
  pair is double there and its tracked vector may be planar (it is on this rotor with the
  viscous method: W/V = −0.85). Tolerance 1e-4 on |W/V + i|: the model is isotropic, but the
  shape is the reduced model's (its basis chosen for a relative eigenvalue accuracy of 1e-6,
  EIGENVALUE_TOLERANCE), measured 1.1e-6 off the circle; the planar shape is off by order 1.
* The data file numbers the unstable mode from 1, as the tables do (docs/design-reference.md's
  mode tables, the text's "mode n"): the mode whose root has Re s > 0 at the unstable speed,
  found here from the eigenvalues, column j, is mode j + 1.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import M_DISK, WN, L, jeffcott

from flexshaft.analyses.stability import stability

ETA, ZETA_E = 0.02, 0.005
C_E = 2 * ZETA_E * M_DISK * WN


@pytest.fixture(scope="module")
def model():
    return jeffcott(ETA, C_E)


@pytest.fixture(scope="module")
def result(model):
    return stability(model, np.array([0.0, 2.0]) * WN, n_modes=2, damping_model="viscous", reference_frequency=WN)


def test_the_onset_shape_is_the_forward_circular_whirl_at_the_first_unstable_speed(model, result):
    assert result.onset_speed is not None and result.onset_kind == "oscillatory"
    dm = model.dofs
    node = dm.node_at("shaft", L / 2)
    v, w = result.onset_shape[dm.shaft(node, "v")], result.onset_shape[dm.shaft(node, "w")]
    assert abs(v) > 0
    assert abs(w / v + 1j) < 1e-4


def test_the_data_file_numbers_the_unstable_mode_from_one(result):
    unstable = np.flatnonzero(result.eigenvalues[-1].real > 0)
    assert unstable.size == 1  # the forward mode only
    ds = result.to_dataset()
    assert ds.attrs["unstable_mode"] == int(unstable[0]) + 1

"""The spin-up response adds only positive speeds (hunt h45a).

:func:`flexshaft.analyses.spinup_response.with_speeds` adds the full solutions at the refined
critical speeds to a spin-up scan. Reference (definition): the speeds added are run-up spin
speeds Ω > 0 (at Ω = 0 the imbalance force m e Ω² vanishes, no resonance is there; a negative Ω
is a reversed spin, not a run-up). Asked to add
Ω = 0 or Ω < 0, the response is returned unchanged (the same object: exact). The scan of the
damped Jeffcott rotor of tests/rotors.py at three speeds, solved in full. CPU: a few
milliseconds.
"""

from __future__ import annotations

import numpy as np
from rotors import M_DISK, WN, jeffcott

from flexshaft.analyses.spinup_response import spinup_response, with_speeds


def test_zero_and_negative_speeds_are_not_added():
    model = jeffcott(0.0, 2 * 0.01 * M_DISK * WN)
    response = spinup_response(model, np.array([0.5, 1.0, 1.5]) * WN, projected=False)
    assert with_speeds(model, response, [0.0, -0.8 * WN]) is response
    added = with_speeds(model, response, [-0.8 * WN, 0.8 * WN])  # the control: a positive one is added
    assert np.array_equal(added.speeds, np.array([0.5, 0.8, 1.0, 1.5]) * WN)

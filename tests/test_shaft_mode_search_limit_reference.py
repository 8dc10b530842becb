"""The wall study's shaft-mode search stops at ``max_modes``: NaN when the shaft's first bending
mode lies above the lowest ``max_modes`` modes.

The short aluminium tube of tests/test_shaft_mode_above_twelve_modes_reference.py (0.7 m between
stiff hangers on the baseline's tailboom with a 2000 kg end mass), whose lowest 12 modes are the
boom's and whose shaft bending mode is found only beyond them. Reference (documented rule of
:func:`~flexshaft.thesis.wall.shaft_first_lateral_frequency`: "NaN when none of the lowest
``max_modes`` modes is one"), with the premise checked by an independent call of
:func:`~flexshaft.analyses.modal.modes`: none of the lowest 14 modes has more than
:data:`~flexshaft.thesis.wall.SHAFT_MODE_SHARE` of its kinetic energy in the shaft's bending,
so with ``max_modes = 14`` the answer is NaN (a search widened past 14 modes would return the
finite frequency the twelve-mode file checks against the pinned tube).
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("xarray")

from test_shaft_mode_above_twelve_modes_reference import _short_tube_model  # noqa: E402

from flexshaft.analyses.modal import modes  # noqa: E402
from flexshaft.thesis.wall import SHAFT_MODE_SHARE, shaft_first_lateral_frequency  # noqa: E402

MAX_MODES = 14


def test_no_shaft_mode_within_max_modes_gives_nan():
    _, model = _short_tube_model()
    low = modes(model, 0.0, MAX_MODES)
    assert low.frequencies.size == MAX_MODES
    assert not np.any((low.kind == "lateral") & (low.shares.shaft_lateral > SHAFT_MODE_SHARE))
    assert np.isnan(shaft_first_lateral_frequency(model, max_modes=MAX_MODES))

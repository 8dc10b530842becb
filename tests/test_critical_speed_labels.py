"""The lateral critical speed of the Jeffcott rotor (tests/rotors.py) labelled with its Campbell mode.

Reference: a critical speed's label names the Campbell diagram's tracked mode whose 1× critical
speed is nearest, numbered as the Campbell table numbers its modes: from 1
(:meth:`~flexshaft.analyses.campbell.Campbell.to_dataframe`; ``CriticalSpeed.mode`` is the
0-based index), with that mode's whirl. The Jeffcott rotor's only bending pair below 1.6 ω_n is
its disk's (the tube's own modes are far above): the two lowest modes, 1 and 2.
"""

from __future__ import annotations

import numpy as np
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.criticals import lateral_critical_speeds
from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.units import rad_s_to_rpm


def _jeffcott_with_imbalance(c_e: float):
    """The Jeffcott rotor operated at 1.2 ω_n with a mass eccentricity (its imbalance)."""
    text = jeffcott_text(0.0, c_e).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(1.2 * WN)}")
    return build_model(loads_design(text + "\n[loads]\neccentricity = 1e-5\n"))


def test_critical_speed_is_labelled_with_the_campbell_mode_numbered_from_one():
    """A damped Jeffcott rotor (ζ = 0.05): the peak's label is the nearest Campbell critical's
    mode number + 1 and whirl, the first bending pair's (modes 1 and 2 of four tracked)."""
    zeta = 0.05
    model = _jeffcott_with_imbalance(2 * zeta * np.sqrt(K_SHAFT * M_DISK))
    diagram = campbell(model, np.linspace(0.0, 1.6 * WN, 5), n_modes=4)
    (critical,) = lateral_critical_speeds(model, diagram)
    nearest = min(diagram.critical_speeds, key=lambda c: abs(c.speed - critical.speed))
    assert abs(nearest.speed - critical.speed) <= 0.03 * critical.speed
    assert critical.location["mode"] == f"{nearest.mode + 1} ({nearest.whirl})"
    number = int(critical.location["mode"].split()[0])
    assert 1 <= number <= 2  # the first bending pair: the two lowest modes

"""Each bearing's amplifier lag in the spin-up feedback (:meth:`ActuatorReceptance.feedback`).

docs/magnetic-bearings.md: "`A(s)`: the amplifier (current loop) as a first-order lag of
bandwidth `ω_a`", the feedback law is "`G(s) = k_i A(s) C(s)`", the table gives
`amplifier_bandwidth` in Hz with "none (ideal)" as default, and the spin-up maps "keep each
bearing's magnet (`k_i`, `k_s`), amplifier and sensor position"; its key table gives `ki`
[N/A] a default of 1. So, derived here, the feedback at the synchronous s = iΩ multiplies the
controller values C(iΩ) [A/m] of a bearing with current gain k_i and bandwidth f_a by

    k_i A(iΩ) = k_i / (1 + iΩ / (2π f_a)),

and leaves those of a bearing with the default k_i = 1 and an ideal amplifier (no bandwidth
given) as they are: a design mixing the two must still lag (and scale) the one that has a lag.

Model: the Jeffcott rotor of tests/rotors.py (4 elements) with two active bearings, one with the
defaults k_i = 1 N/A and an ideal amplifier at x = 0.25 and one with k_i = 100 N/A and a 50 Hz
amplifier at x = 0.75; speeds 0.3, 0.6 and 1.4 ω_n (ω_n = 302 rad/s), where Ω/ω_a is 0.29 to
1.35 (lags of 16° to 53°, none lost in rounding). The expected values are one complex division
each (relative rounding 1e-16), so rtol 1e-12 leaves four orders for the product's own
arithmetic. CPU: about 0.06 s.
"""

from __future__ import annotations

import numpy as np
from jeffcott_bearing import KD, KI, KP, KS
from rotors import WN, jeffcott_text

from flexshaft.analyses.receptance import actuator_receptance
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

F_A = 50.0  # Hz: the lagged bearing's amplifier bandwidth


def _two_active_bearings():
    text = jeffcott_text(0.0, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    magnet = f'kind = "active"\nkp = {KP}\nkd = {KD}\nks = {KS}'
    bearings = (
        f'[[bearings]]\nname = "ideal"\nx = 0.25\n{magnet}\n'
        f'[[bearings]]\nname = "lagged"\nx = 0.75\n{magnet}\nki = {KI}\namplifier_bandwidth = {F_A}\n'
    )
    return build_model(loads_design(f"{head}{bearings}{tail}"))


def test_a_lagged_amplifier_keeps_its_lag_beside_an_ideal_one():
    model = _two_active_bearings()
    speeds = np.array([0.3, 0.6, 1.4]) * WN
    rec = actuator_receptance(model, speeds)
    assert sorted(rec.actuator_names) == ["ideal", "lagged"]
    ideal, lagged = rec.actuator_names.index("ideal"), rec.actuator_names.index("lagged")
    laws = (KP + 1j * speeds[:, None] * KD) * np.ones((1, rec.n_actuators))  # C(iΩ) [A/m]
    gains = rec.feedback(laws)
    lag = 1.0 / (1.0 + 1j * speeds / (2 * np.pi * F_A))  # A(iΩ)
    assert np.all(np.abs(np.angle(lag, deg=True)) > 15.0)  # the lag is there to be lost
    np.testing.assert_allclose(gains[:, lagged], laws[:, lagged] * KI * lag, rtol=1e-12)
    np.testing.assert_allclose(gains[:, ideal], laws[:, ideal], rtol=1e-12)

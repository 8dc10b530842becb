"""Two design inputs against what they mean, derived by hand.

* **The unfiltered PID law** (``kp``, ``kd``, ``integral_gain``, no ``derivative_cutoff``):
  ``C(s) = k_p + k_d s + k_int/s`` (parallel PID, Åström & Murray, *Feedback Systems*, 2008,
  ch. 10), one pole at s = 0: |C(iω)| grows as k_int/ω at low frequency (the integral action
  that holds the static offset at zero) and C(iω) → k_p + i k_d ω at high frequency. The
  fraction the bearing returns is evaluated here at a few s against that sum; a few operations
  on numbers of order 1 to 1e7: relative 1e-12.
* **The main rotor's excitation lines** (``main_rotor_speed_rpm`` n [rev/min], ``main_rotor_blades``
  N): the rotor turns at n/60 rev/s, so its 1/rev line is at n/60 Hz and its blade-passage
  line at N n/60 Hz, for any N >= 2 (a two-bladed teetering rotor, the commonest light
  helicopter, has the strong 2/rev); one blade has only the 1/rev. Exact decimal arithmetic:
  relative 1e-15.
"""

from __future__ import annotations

import pytest

from flexshaft.design.bearings import ActiveBearing
from flexshaft.design.loads import Operating

KP, KD, KINT = 2.0e6, 900.0, 3.0e7  # k_p [A/m], k_d [A s/m], k_int [A/(m s)]


def _value(coefficients, s):
    return sum(c * s ** (len(coefficients) - 1 - k) for k, c in enumerate(coefficients))


def test_unfiltered_pid_keys_give_kp_plus_kd_s_plus_kint_over_s():
    bearing = ActiveBearing(kind="active", name="amb", x=0.5, kp=KP, kd=KD, integral_gain=KINT)
    num, den = bearing.transfer_function()
    for s in (1j * 1.0, 1j * 50.0, -30.0 + 400.0j, 1j * 1.0e5):
        assert _value(num, s) / _value(den, s) == pytest.approx(KP + KD * s + KINT / s, rel=1e-12)
    assert _value(den, 0.0) == 0.0  # the integrator's pole at the origin


@pytest.mark.parametrize("blades", [1, 2, 3, 4, 5])
def test_main_rotor_lines_are_once_and_n_per_rev_in_hz(blades):
    rpm = 289.0  # [rev/min], within the 150-500 of helicopter main rotors
    operating = Operating(speed_rpm=4863.0, power=0.0, main_rotor_speed_rpm=rpm, main_rotor_blades=blades)
    lines = operating.main_rotor_frequencies()
    expected = {"1/rev": rpm / 60.0}
    if blades > 1:
        expected[f"{blades}/rev"] = blades * rpm / 60.0
    assert lines.keys() == expected.keys()
    for key, value in expected.items():
        assert lines[key] == pytest.approx(value, rel=1e-15)

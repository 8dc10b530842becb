"""The lateral critical speeds are searched to the scan's top above the highest operating speed,
not above the nominal one.

API 684 measures the separation of a critical above the operating speed range from its highest
speed (the maximum continuous speed), up to 26 % above it; the resolution scans the spin-up to
``scan_top`` (1.3) × the highest operating speed (:meth:`Resolution.spin_speeds`), and the
critical-speed search must end there too. On the Jeffcott rotor (tests/rotors.py) with light
external damping ζ = 0.01 turning at Ω_op = ω_n/1.36 with ``speed_range = [0.9, 1.1]``, the one
critical lies at 1.36 Ω_op: above 1.3 Ω_op (the top without the range) and below
1.3 × 1.1 Ω_op = 1.43 Ω_op, and it is 24 % above the highest speed 1.1 Ω_op, inside API's
26 % cap: the critical a separation check must see. The unbalance peak of a damped one-DOF
oscillator is at ω_n/√(1 − 2ζ²) (the displacement amplitude UΩ²/|k − mΩ² + icΩ| peaks there:
Den Hartog, *Mechanical Vibrations*, the rotating-unbalance response), 1.0001 ω_n; the tube's
mass (7e-6 of the disk's) moves it by less (tests/test_point_tasks_reference.py measured 6e-7
on this rotor) and the refined critical is measured 1.7e-7 from the peak: 5e-6 is asserted, 20
times below the peak's 1e-4 above ω_n, so a search that reported ω_n itself would fail. The
search's top, which the separation check's note quotes,
is 1.3 × 1.1 Ω_op to round-off (1e-12).

Written for the mutation h37a-scan-top-without-range of scripts/mutations.toml. CPU: the spin-up
of the 8-element rotor at the screening resolution, about 0.2 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import M_DISK, WN, jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.resolution import SCREENING
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict import point_tasks

ZETA = 0.01


def test_a_critical_above_the_nominal_scan_top_but_within_the_ranges_is_found():
    c_e = 2.0 * ZETA * M_DISK * WN  # the damper at the disk: ζ = c/(2 m ω_n)
    operating = WN / 1.36
    text = jeffcott_text(0.0, c_e).replace(
        "speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(operating)}\nspeed_range = [0.9, 1.1]"
    )
    model = build_model(loads_design(text + "\n[loads]\neccentricity = 1.0e-5\n"))
    assert SCREENING.scan_top == 1.3
    assert 1.3 * model.speed < WN < 1.3 * 1.1 * model.speed
    _, found = point_tasks._spinup(model, SCREENING)
    assert found.search_top == pytest.approx(1.3 * 1.1 * model.speed, rel=1e-12)
    speeds = [c.speed for c in found.criticals]
    peak = WN / np.sqrt(1.0 - 2.0 * ZETA**2)
    assert len(speeds) >= 1 and min(abs(s / peak - 1.0) for s in speeds) < 5e-6, speeds

"""The critical-speed search of a fresh scan reaches the top speed it is asked for.

Reference (closed form): the Jeffcott rotor of tests/rotors.py (a 20 kg midspan disk on a
near-massless pinned-pinned tube, k = 48 E I / L³, ω_n = √(k/m)) with an isotropic dashpot c at
the disk, ζ = c/(2√(km)) = 0.05. Under the imbalance force m e Ω² e^{iΩt} the disk's orbit is
e Ω²/√((ω_n² − Ω²)² + (2ζω_nΩ)²), largest at Ω_p = ω_n/√(1 − 2ζ²): the one lateral critical
speed. The operating speed is put at Ω_p/1.6, so the critical lies at 1.6 × the operating
speed: above the default search (REPORT.scan_top = 1.3 of it) and below a requested top of 2.
:func:`~flexshaft.analyses.criticals.scan_critical_speeds` documents "the lateral critical
speeds up to ``top`` × the operating speed, from a spin-up scan when it reaches that high, else
from a new scan": without a scan it must find this critical.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.criticals import scan_critical_speeds
from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.resolution import REPORT
from flexshaft.units import rad_s_to_rpm

ZETA = 0.05
ECCENTRICITY = 1e-5
PEAK = WN / np.sqrt(1 - 2 * ZETA**2)


def _rotor():
    c = 2 * ZETA * np.sqrt(K_SHAFT * M_DISK)
    text = jeffcott_text(0.0, c).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(PEAK / 1.6)}")
    return build_model(loads_design(text + f"\n[loads]\neccentricity = {ECCENTRICITY}\n"))


def test_a_new_scan_to_twice_the_operating_speed_finds_the_critical_at_1_6():
    """One critical, at Ω_p to a 20th of its half-power bandwidth 2ζΩ_p (the refinement's
    vertex resolution), and the search reported as reaching 2 Ω_op. The default top (1.3) is
    below it: the test is meaningful only because 1.6 > REPORT.scan_top."""
    assert REPORT.scan_top < 1.6 < 2.0
    model = _rotor()
    result = scan_critical_speeds(model, np.zeros(1), None, top=2.0)
    assert result.search_top == pytest.approx(2.0 * model.speed, rel=1e-12)
    assert result.criticals is not None and len(result.criticals) == 1
    assert result.criticals[0].speed == pytest.approx(PEAK, abs=2 * ZETA * PEAK / 20)

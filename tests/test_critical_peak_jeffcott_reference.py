"""The unbalance-response critical speed of a damped Jeffcott rotor, its peak orbit and where the
search looks for it, against the single-mass closed form (derived here).

The Jeffcott rotor of tests/rotors.py (20 kg disk at the middle of a near-massless pinned-pinned
tube, k = 48EI/L³, ω_n = √(k/m) ≈ 302 rad/s) with its dashpot c = 2ζ√(km), ζ = 0.02, at the
disk, an eccentricity e of the whole rotating mass M (disk + tube, one bay: the mid-bay unbalance
U = e M sits at the disk) and an operating speed Ω_op = 2500 rpm ≈ 262 rad/s. In complex
coordinates the disk obeys m r̈ + c ṙ + k r = U Ω² e^{iΩt}, so its orbit radius is

    |r|(Ω) = (U/m) ρ² / √((1 − ρ²)² + (2ζρ)²),   ρ = Ω/ω_n,

whose maximum (d|r|/dρ = 0) lies at ρ_p = 1/√(1 − 2ζ²) with |r|_max = (U/m)/(2ζ√(1 − ζ²)).
The critical speed N_c = ω_n ρ_p ≈ 1.16 Ω_op lies above the operating speed and below the
search's top, 1.3 Ω_op (:data:`flexshaft.resolution.REPORT`'s ``scan_top``).

* The critical's ``peak_orbit`` (the verdict's spin-up peak when it exceeds the sampled one) is
  that maximum: the refined peak, not the scan's sample near it (41 samples from 0.02 to 1.3
  Ω_op are 8.4 rad/s apart against a half-power bandwidth 2ζω_n ≈ 12 rad/s).
* A spin-up scan that stops at Ω_op cannot show that critical: the search scans again up to
  1.3 Ω_op and finds it.

Tolerance 1e-4: the tube's mass (7e-6 of the disk's) and its flexibility between the disk and
the dashpot (none: both at the middle) move the single-mass values by ~1e-5; the refined peak's
vertex of 1/A² through samples 1/20 of the bandwidth apart is exact to ~1e-6 (measured 1e-6).
The 4-element tube is exact for a point load at its middle (a cubic per element).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.criticals import lateral_critical_speeds, scan_critical_speeds
from flexshaft.analyses.spinup_response import spinup_response
from flexshaft.assembly import build_model
from flexshaft.assembly.balance import rotating_mass
from flexshaft.design import loads_design

ZETA, ECCENTRICITY = 0.02, 1e-5
PEAK_SPEED = WN / np.sqrt(1 - 2 * ZETA**2)


@pytest.fixture(scope="module")
def rotor():
    c = 2 * ZETA * np.sqrt(K_SHAFT * M_DISK)
    text = jeffcott_text(0.0, c, elements=4).replace("speed_rpm = 0.0", "speed_rpm = 2500.0")
    return build_model(loads_design(f"{text}\n[loads]\neccentricity = {ECCENTRICITY}\n"))


def test_the_critical_carries_the_refined_peak_orbit(rotor):
    (critical,) = lateral_critical_speeds(rotor, n_points=41)
    u = ECCENTRICITY * rotating_mass(rotor)
    assert critical.speed == pytest.approx(PEAK_SPEED, rel=1e-4)
    peak = (u / M_DISK) / (2 * ZETA * np.sqrt(1 - ZETA**2))
    assert critical.location["peak_orbit"] == pytest.approx(peak, rel=1e-4)


def test_a_scan_that_stops_at_the_operating_speed_is_not_the_search(rotor):
    speeds = np.linspace(0.05, 1.0, 21) * rotor.speed
    scan = spinup_response(rotor, speeds, projected=False)
    found = scan_critical_speeds(rotor, speeds, scan.orbits)
    assert found.search_top == pytest.approx(1.3 * rotor.speed, rel=1e-12)
    assert [c.speed for c in found.criticals] == pytest.approx([PEAK_SPEED], rel=1e-4)

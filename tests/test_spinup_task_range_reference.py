"""Reference: what the spin-up task of an operating point scans, at both ends of its range.

The Jeffcott rotor of tests/rotors.py (a 20 kg disk at midspan of a near-massless pinned-pinned
tube, k = 48 EI/L³, ω_n = √(k/m)) with an external dashpot at the disk, ζ = c/(2 m ω_n) = 0.01.
Den Hartog's rotating-unbalance response (*Mechanical Vibrations*, the forced vibration of a
mass with rotating unbalance; one line of algebra from m r̈ + c ṙ + k r = m e Ω² e^{iΩt}): the
disk whirls at r = Ω/ω_n with the orbit

    e r² / √((1 − r²)² + (2ζr)²),

which peaks at ω_n/√(1 − 2ζ²) = 1.0001 ω_n. The tube's mass, 3.5e-6 of the disk's, moves ω_n by
2e-6 and the orbit near resonance by about ten times that (tests/rotors.py).

* **A design without imbalance is searched as far as one with imbalance.** ``eccentricity = 0``
  (no ``[loads]`` table) makes the spin-up response zero; the critical speeds are then found
  with a unit eccentricity (the response is linear in it), over the same search range as a
  design with imbalance: to ``scan_top`` × the highest operating speed (docs/requirements.md:
  the scan runs "to 130 % of the highest operating speed"; API 684's separation margins reach
  26 % above it). With ω_n = 2 Ω_op no peak lies in that range, and the separation check's pass
  says how far it looked.
* **The spin-up checks end at the highest operating speed, sampled there.** docs/requirements.md
  defines the spin-up orbit "from 2 % of the operating speed to the highest operating speed (the
  top of ``[operating] speed_range`` …; the scan's speeds, each refined critical speed's peak,
  the operating speed and the highest one)". With Ω_op = ω_n/1.36, ``speed_range = [0.9, 1.1]``
  and ``[loads] eccentricity`` = e = 1e-5 m (``ECC``) the response still rises at 1.1 Ω_op
  (r = 0.809, below the resonance), so the largest orbit up to it is the one at 1.1 Ω_op, by the
  closed form above; the screening scan has no sample there: its nearest lies 7.3e-4 below in
  relative speed, where the orbit is smaller by
  d ln(orbit)/d ln r × 7.3e-4 = (2 + 2r²/(1 − r²)) × 7.3e-4 ≈ 5.8 × 7.3e-4 = 4.2e-3 (ζ → 0;
  measured 4.2e-3), four times the 1e-3 asserted.
"""

from __future__ import annotations

import numpy as np
from rotors import M_DISK, WN, jeffcott_text

import flexshaft as fs
from flexshaft.assembly import build_model
from flexshaft.assembly.balance import design_eccentricity
from flexshaft.design import loads_design
from flexshaft.resolution import SCREENING
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict import point_tasks

ZETA, ECC = 0.01, 1.0e-5


def _text(ratio: float, extra: str = "") -> str:
    """The Jeffcott rotor at Ω_op = ω_n/ratio with ζ = 0.01 at the disk."""
    return jeffcott_text(0.0, 2.0 * ZETA * M_DISK * WN).replace(
        "speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(WN / ratio)}{extra}"
    )


def test_a_design_without_imbalance_is_searched_to_the_scan_top():
    """ω_n = 2 Ω_op, ``speed_range = [0.9, 1.1]``: no critical below 1.3 × 1.1 Ω_op = 1.43 Ω_op,
    and the search range the critical speeds report (the separation check's pass prints it:
    "no resonance peak in the unbalance response up to … rpm") is that, not Ω_op."""
    design = loads_design(_text(2.0, "\nspeed_range = [0.9, 1.1]"))
    model = build_model(design)
    assert model.design is not None and design_eccentricity(model.design) == 0.0
    _, criticals = point_tasks._spinup(model, SCREENING)
    top = SCREENING.scan_top * 1.1 * model.speed
    assert criticals.criticals == () and top < WN
    assert abs(criticals.search_top / top - 1.0) < 1e-12, criticals.search_top / model.speed


def test_the_spinup_orbit_is_read_at_the_top_of_the_speed_range():
    """The verdict's spin-up orbit is the closed form's at 1.1 Ω_op, to 1e-3 (the tube's mass
    shifts it by about 1e-5: 6.8e-6 measured), at the speed 1.1 Ω_op; the check passes (1.9e-5 m
    against a 5 mm limit)."""
    text = _text(1.36, "\nspeed_range = [0.9, 1.1]")
    text += f"\n[requirements]\nmax_spinup_deflection = 0.005\n[loads]\neccentricity = {ECC}\n"
    design = loads_design(text)
    omega = build_model(design).speed
    grid = SCREENING.spin_speeds(omega, 1.1)
    assert np.min(np.abs(grid / (1.1 * omega) - 1.0)) > 1e-4  # the scan alone has no sample there
    check = fs.assess(design, SCREENING).verdict.check("spinup_deflection")
    r = 1.1 * omega / WN
    expected = ECC * r**2 / np.hypot(1.0 - r**2, 2.0 * ZETA * r)
    assert check.value is not None
    assert abs(check.value / expected - 1.0) < 1e-3, check.value / expected
    assert abs(check.location["speed"] / (1.1 * omega) - 1.0) < 1e-12, check.location
    assert check.status == "pass"

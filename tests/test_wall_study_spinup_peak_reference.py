"""The wall study's spin-up peak (:func:`flexshaft.thesis.wall._wall_outputs`, "peak shaft orbit
during spin-up") on a Jeffcott rotor with a PD magnetic bearing, against the resonance maximum
derived here.

The rotor is the one of tests/jeffcott_bearing.py: a disk of mass m = 20 kg at midspan of a
near-massless pinned-pinned steel tube (stiffness k = 48EI/L³ at the disk), and the ACTIVE
bearing at the disk (collocated, no lag) with the law k_i (k_p + iΩ k_d) − k_s. A mass
eccentricity e ([loads] eccentricity) puts the force m e Ω² e^{iΩt} on the disk. In complex
coordinates r = v + i w the disk obeys

    m r̈ + k_i k_d ṙ + (48EI/L³ + k_i k_p − k_s) r = m e Ω² e^{iΩt},

a forward circle of radius |r| = e s² / √((1 − s²)² + (2ζs)²), s = Ω/ω_n, with
ω_n = √((48EI/L³ + k_i k_p − k_s)/m) and ζ = k_i k_d / (2 m ω_n). Setting d|r|²/d(s²) = 0 gives
s² = 1/(1 − 2ζ²) and the largest orbit over speed

    r_max = e / (2ζ √(1 − ζ²)).

Here ω_n = 326.02 rad/s, ζ = 0.01534 and r_max = 3.2606e-4 m. The tube deflects as a
midspan-loaded beam (the disk's inertia, the imbalance and the bearing all act at midspan): its
largest orbit is the disk's, so the shaft's peak orbit is r. The operating speed is 1.5 ω_n, so
the scan (0.02 to 1 × the operating speed) contains the peak at 1.0002 ω_n.

Tolerance 1 %: the tube's mass (3.5e-6 of the disk's) and its 4-element mesh change the orbit by
3e-5 at every scanned speed (measured against |r| at the same speeds); the study's 100 even
speeds are 4.84 rad/s apart, about the resonance's half-width ζω_n = 5.0 rad/s, and the 17 fine
speeds between the neighbours of the coarse peak are 0.61 rad/s apart, so the refined sample
lies within 0.30 rad/s of the top of the peak: at most (0.30/5.0)²/2 = 1.8e-3 below it (5e-4
on this grid). The even speeds alone fall 5.1 % short (the h64g-wall-spinup-peak-unrefined
mutation of scripts/mutations.toml). Under 0.2 s of CPU: one tiny model, 115 banded
solves and a few modes.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, KD, KI, KP, KS
from rotors import K_SHAFT, M_DISK, jeffcott_text

from flexshaft.design import loads_design
from flexshaft.sweep.study import Point
from flexshaft.thesis.wall import _wall_outputs

ECCENTRICITY = 1e-5  # [m]
STIFFNESS = K_SHAFT + KI * KP - KS  # [N/m]
OMEGA_N = np.sqrt(STIFFNESS / M_DISK)  # [rad/s]
ZETA = KI * KD / (2 * M_DISK * OMEGA_N)


def _design():
    """The Jeffcott rotor with the ACTIVE bearing at the disk, spinning at 1.5 ω_n, eccentricity e."""
    head, tail = jeffcott_text(0.0, 0.0, elements=4).split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :].replace("speed_rpm = 0.0", f"speed_rpm = {1.5 * OMEGA_N * 30 / np.pi}")
    text = f'{head}[[bearings]]\nname = "b"\nx = 0.5\n{ACTIVE}\n{tail}[loads]\neccentricity = {ECCENTRICITY}\n'
    return loads_design(text)


def test_spinup_peak_is_the_resonance_maximum():
    peak = ECCENTRICITY / (2 * ZETA * np.sqrt(1 - ZETA**2))
    assert ZETA == pytest.approx(0.01534, rel=1e-3) and peak == pytest.approx(3.2606e-4, rel=1e-4)
    out = _wall_outputs(Point(0, {}, {}, _design()))
    assert out["spinup_peak_deflection"] == pytest.approx(peak, rel=1e-2)

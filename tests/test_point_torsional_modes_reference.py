"""The operating point's torsional analysis holds every torsional mode below twice the highest
excitation, not only the lowest one, against the closed form of a two-inertia torsional system.

Model (tests/test_torsional_checks_reference.py's, derived there): tests/test_torsional.py's
near-massless steel tube (k = G J_p/L over L = 2 m, forward twist held) meshed in two elements,
a disk J₁ = 2 kg m² on the middle node and the tail rotor's reflected inertia J₂ = J_tr/n²
(J_tr = 4 kg m², n = 2, N = 3 blades) on the aft twist, P = 100 kW at 3000 rpm. Each half of the
shaft is a spring 2k, so the squared natural frequencies are the roots of

    J₁J₂ω⁴ − (J₁·2k + J₂·4k)ω² + 4k² = 0,

44.8 and 108.1 Hz. The excitations are the tail rotor's 1/rev (25 Hz), the shaft's 1/rev (50 Hz)
and the tail rotor's 3/rev (75 Hz, the highest), so both modes lie below twice the highest excitation (150 Hz) and the
point's separation holds both (docs/requirements.md, the `torsional_separation` row: "margin of
each torsional mode (below twice the highest excitation) to its nearest excitation"); the second
lies above the 3/rev, margin f₂/75 Hz − 1. Frequencies to 3e-7 (the lumped closed form against
the shaft's own 1e-7 inertia and the dense solve's round-off, measured in
tests/test_torsional_checks_reference.py). The margin m = f₂/f_top − 1 amplifies the relative
error of f₂ by dm/m = (f₂/f_top)/(f₂/f_top − 1) · df₂/f₂ = (1.441/0.441) · df₂/f₂ ≈ 3.3 · df₂/f₂,
so its tolerance is 3.3 × 3e-7 ≈ 1e-6.

The point is analysed through the public ``analyse_point`` at the smallest resolution the tests
use (``conftest.SMALLEST``), 0.05 s of CPU.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import SMALLEST
from test_torsional import K_SHAFT, shaft_text

from flexshaft.design import loads_design
from flexshaft.verdict.operating_point import analyse_point

RPM = 3000.0  # tests/test_torsional.py's operating point
OMEGA = RPM * 2 * np.pi / 60


def test_the_point_holds_every_torsional_mode_below_twice_the_highest_excitation():
    J1, J_tr, n, blades = 2.0, 4.0, 2.0, 3
    disk = '[[disks]]\nname = "disk"\nx = 1.0\nmass = 1.0\npolar_inertia = 2.0\ndiametral_inertia = 1.0\n'
    rotor = f"[tail_rotor]\nblades = {blades}\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n"
    p = analyse_point(loads_design(shaft_text(disk + rotor, elements=2)), SMALLEST, detail=False)
    separation = p.torsional_separation
    assert separation is not None and p.torsional_modes is not None
    J2, k_half = J_tr / n**2, 2 * K_SHAFT  # each half of the shaft: a spring 2k
    a, b, c = J1 * J2, J1 * k_half + J2 * 2 * k_half, k_half * k_half
    disc = np.sqrt(b * b - 4 * a * c)
    f1, f2 = np.sqrt([(b - disc) / (2 * a), (b + disc) / (2 * a)]) / (2 * np.pi)
    f_top = blades / n * OMEGA / (2 * np.pi)  # 75 Hz, the highest excitation
    assert f_top < f2 < 2 * f_top
    assert list(p.torsional_modes.natural_frequencies) == pytest.approx([f1, f2], rel=3e-7)
    assert [s.natural_frequency for s in separation] == pytest.approx([f1, f2], rel=3e-7)
    assert [s.mode for s in separation] == [0, 1]
    assert separation[1].margin == pytest.approx(f2 / f_top - 1.0, rel=1e-6)  # 3.3 × 3e-7, see above

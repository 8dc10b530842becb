"""Each torsional mode's separation is held to the design's own required margin.

docs/requirements.md: ``min_torsional_separation`` (default 0.10) is the separation every torsional
natural frequency keeps from every excitation over the speed range, and the
``torsional_separation`` check compares each mode's margin with it. The analysis's entries
(:class:`~flexshaft.analyses.torsional.TorsionalSeparation`, read by notebooks from an operating
point's ``torsional_separation``) carry that requirement and say whether the mode meets it; until
the twenty-fifth session they carried 10 % whatever the design asked for.

Model: tests/test_torsional_checks_reference.py's two-inertia system (a 2 kg m² disk at midspan
of tests/test_torsional.py's near-massless steel tube, k₁ = k₂ = 2k, a tail rotor of 4 kg m²
through n = 2, three blades, 3000 rpm). Its first mode, the lower root of
J₁J₂ω⁴ − (J₁k₂ + J₂(k₁ + k₂))ω² + k₁k₂ = 0, lies at 44.8 Hz, below the shaft's 1/rev of 50 Hz:
margin m₁ = 1 − f₁/50 Hz = 0.104 (the separation rule below a band, docs/requirements.md). It
meets 10 % and misses 30 %. The closed form holds the computed frequency to 3e-7
(tests/test_torsional_checks_reference.py's bound on the round-off); the margin's 0.004 distance
from 10 % and 0.196 from 30 % are far outside it.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import K_SHAFT, shaft_text

from flexshaft.analyses.torsional import torsional_separation
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

J1, J_TR, N, BLADES, RPM = 2.0, 4.0, 2.0, 3, 3000.0


def _text(requirements: str) -> str:
    disk = '[[disks]]\nname = "disk"\nx = 1.0\nmass = 1.0\npolar_inertia = 2.0\ndiametral_inertia = 1.0\n'
    rotor = f"[tail_rotor]\nblades = {BLADES}\npolar_inertia = {J_TR}\ngearbox_ratio = {N}\n"
    text = shaft_text(disk + rotor + requirements, elements=2)
    assert f"speed_rpm = {RPM}" in text
    return text


def _first_margin() -> float:
    J2, k = J_TR / N**2, 2 * K_SHAFT
    a, b, c = J1 * J2, J1 * k + J2 * 2 * k, k * k
    f1 = np.sqrt((b - np.sqrt(b * b - 4 * a * c)) / (2 * a)) / (2 * np.pi)
    return 1.0 - f1 / (RPM / 60.0)


THIRTY = "[requirements]\nmin_torsional_separation = 0.3\n"


@pytest.mark.parametrize(("requirements", "required"), [("", 0.10), (THIRTY, 0.3)])
def test_each_mode_carries_the_designs_required_separation(requirements, required):
    first = torsional_separation(build_model(loads_design(_text(requirements))))[0]
    margin = _first_margin()
    assert 0.10 < margin < 0.3  # the case separates the two requirements
    assert first.excitation == "shaft 1/rev"
    assert first.margin == pytest.approx(margin, rel=5e-6)  # 3e-7 on f₁ times (1 − m₁)/m₁ ≈ 8.6
    assert first.required == required
    assert first.passed == (margin >= required)

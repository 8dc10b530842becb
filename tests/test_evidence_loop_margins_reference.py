"""A loop's missing gain margin is no finding: the evidence's default for a crossover that does
not exist, against docs/requirements.md.

docs/requirements.md (``loop_gain_margin``): "gain margin of each axis, for a gain rise and a
gain fall (each a finding; none without a phase crossover)"; ``min_gain_margin_db`` = 6 dB: "A
loop with no phase crossover in the 0.1 Hz-2 kHz range has no finite gain margin and is not a
finding". :class:`~flexshaft.verdict.evidence.LoopEvidence` leaves ``gain_margin_lower`` and
``gain_margin_upper`` out (None) when the loop has no phase crossover of that kind.

By hand: a loop around a magnet with an upper margin of 12 dB and no crossover for a gain fall
has one finding, 12 dB against 6 dB (margin +6 dB): the check passes. The same loop with a lower
margin of -4 dB (a gain fall of 4 dB puts it on -1) fails by 2 dB: |-4| - 6. A loop with neither
crossover passes with no finding.
"""

from __future__ import annotations

import pytest

from flexshaft.design.requirements import Requirements
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.evidence import Evidence, LoopEvidence

LIMIT_DB = 6.0


def _check(**margins):
    loop = LoopEvidence(actuator="amb", axis="v", speed=500.0, peak_sensitivity=2.0, peak_frequency=300.0, **margins)
    requirements = Requirements(min_gain_margin_db=LIMIT_DB)
    return evaluate(Evidence(operating_speed=500.0, loops=(loop,)), requirements).check("loop_gain_margin")


def test_a_loop_without_a_lower_crossover_is_judged_on_its_upper_margin_alone():
    check = _check(gain_margin_upper=12.0)
    assert check.status == "pass"
    assert check.value == pytest.approx(12.0, abs=1e-12)
    assert check.margin == pytest.approx(12.0 - LIMIT_DB, abs=1e-12)
    assert len(check.findings) == 1 and check.findings[0].location["case"] == "gain rise"


def test_a_lower_margin_that_exists_is_judged_by_its_size():
    check = _check(gain_margin_upper=12.0, gain_margin_lower=-4.0)
    assert check.status == "fail"
    assert check.value == pytest.approx(4.0, abs=1e-12)
    assert check.margin == pytest.approx(4.0 - LIMIT_DB, abs=1e-12)
    # both directions are findings, and the governing one is the gain fall
    assert sorted(f.location["case"] for f in check.findings) == ["gain fall", "gain rise"]
    assert check.location["case"] == "gain fall"


def test_a_loop_without_any_crossover_has_no_finding():
    check = _check()
    assert check.status == "pass" and not check.findings

"""Each trace of the interactive figures carries its own data: a Campbell mode's hover shows that
mode's log decrement, and each requirement's margin bar is coloured by that requirement's own
status, not by the verdict as a whole: ``margins_figure``'s docstring (public API): "Every
check's normalised margin (...: negative fails) as a bar, green pass, red fail, grey not
evaluated", as the static report's caption says ("green pass, red fail"); docs/explorer.md lists
"the normalised margins" among the explorer's figures, and docs/requirements.md defines the
normalised margin as "the margin over the limit".

References (derived, by hand): stand-ins with values chosen here (no model, no analysis). The
Campbell log decrements are rounded by the figure to 4 significant digits, and the values chosen
here have at most 3, so they read back exactly. The statuses of the hand-built checks follow from
value against limit by hand (2.0 ≥ 1.5 passes, 1.2 ≥ 1.5 fails). About 10 ms.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.report.interactive import campbell_figure, margins_figure
from flexshaft.verdict.result import Check, Verdict

RPM = 2.0 * math.pi / 60.0  # rad/s per rpm


def _campbell_assessment() -> SimpleNamespace:
    speeds = np.array([1000.0, 3000.0, 6000.0]) * RPM
    campbell = SimpleNamespace(
        speeds=speeds,
        frequencies=np.array([[20.0, 40.0], [21.0, 42.0], [22.0, 44.0]]),
        # mode 1 lightly damped, mode 2 ten times more: a hover of the wrong mode reads 10x off
        log_decrements=np.array([[0.010, 0.100], [0.020, 0.200], [0.030, 0.300]]),
        whirl=np.array([["forward", "backward"]] * 3),
        kind=None,
    )
    return SimpleNamespace(
        campbell=campbell,
        evidence=SimpleNamespace(critical_speeds=None),
        operating_speed=4800.0 * RPM,
        design=SimpleNamespace(
            requirements=SimpleNamespace(separation="off"), operating=SimpleNamespace(speed_limits=(0.0, 0.0))
        ),
    )


def test_each_campbell_mode_hovers_its_own_log_decrement():
    """Mode 1's trace carries (0.01, 0.02, 0.03), mode 2's (0.1, 0.2, 0.3): the stand-in's columns."""
    fig = campbell_figure(_campbell_assessment())
    modes = {t["name"]: t for t in fig["data"] if t["name"].startswith("mode ")}
    assert modes["mode 1 (forward)"]["customdata"] == [0.01, 0.02, 0.03]
    assert modes["mode 2 (backward)"]["customdata"] == [0.1, 0.2, 0.3]
    # and the frequencies of the same trace are that mode's [Hz]
    assert modes["mode 2 (backward)"]["y"] == [40.0, 42.0, 44.0]


def _rgb(hex_colour: str) -> tuple[int, int, int]:
    h = hex_colour.lstrip("#")
    return int(h[0:2], 16), int(h[2:4], 16), int(h[4:6], 16)


def test_each_margin_bar_is_coloured_by_its_own_status():
    """A failing verdict (one check fails) with a passing check and one not evaluated: the passing
    bar is green (green channel the largest), the failing one red (red channel the largest), the
    not-evaluated one grey (equal channels)."""
    passing = Check("strength", "strength safety factor", "ratio", "at least", "pass", 2.0, 1.5, 0.5)
    failing = Check("buckling", "buckling safety factor", "ratio", "at least", "fail", 1.2, 1.5, -0.3)
    missing = Check("actuator_orbit", "actuator excursion", "length", "at most", "not evaluated", note="no actuators")
    verdict = Verdict(checks=(passing, failing, missing))
    assert not verdict.passed
    fig = margins_figure(SimpleNamespace(verdict=verdict))
    bars = fig["data"][0]
    assert bars["y"] == ["strength safety factor", "buckling safety factor", "actuator excursion"]
    green, red, grey = (_rgb(c) for c in bars["marker"]["color"])
    assert green[1] > max(green[0], green[2])
    assert red[0] > max(red[1], red[2])
    assert max(grey) - min(grey) <= 16  # a grey: channels within 16 of 255
    # the bars' lengths are the normalised margins: 0.5/1.5 = 1/3 and −0.3/1.5 = −0.2 (by hand),
    # none for the missing one; abs 5e-7: half a unit in the 6th significant digit the page keeps
    assert bars["x"][0] == pytest.approx(1.0 / 3.0, abs=5e-7)
    assert bars["x"][1] == pytest.approx(-0.2, abs=5e-7)
    assert bars["x"][2] == 0.0

"""The interactive figures of ``flexshaft run --interactive`` put each number on the axis of its
unit: speeds in rpm, frequencies in Hz, orbits and gaps in mm, forces in N on the force panel,
and each limit line at the requirement it names.

References (derived, by hand): a stand-in assessment with values chosen here (no model, no
analysis; plotly itself is not needed: the figures are plain JSON data). The unit factors are
written out beside each expectation: rpm = rad/s · 60/(2π), Hz = rpm/60, mm = m · 1e3. The
numbers are rounded by the figure to 6 significant digits, hence rel=1e-6. About 0.1 s.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.report import interactive
from flexshaft.report.interactive import actuator_figure, campbell_figure, spinup_figure, stability_figure

RPM = 2.0 * math.pi / 60.0  # rad/s per rpm
OMEGA = 4800.0 * RPM  # operating speed 4800 rpm = 502.6548 rad/s
SPEEDS = np.array([1000.0, 3000.0, 6000.0]) * RPM  # 1000, 3000, 6000 rpm


def _no_check(key: str):
    """Verdict.check of a verdict without checks."""
    raise KeyError(key)


def _assessment() -> SimpleNamespace:
    actuator = SimpleNamespace(name="amb_1", link=SimpleNamespace(x_shaft=1.0))
    # the actuator sits at shaft node 2 (its index among the actuators is 0)
    model = SimpleNamespace(actuators=[actuator], dofs=SimpleNamespace(node_at=lambda member, x: {1.0: 2}[x]))
    spinup = SimpleNamespace(
        speeds=SPEEDS,
        shaft_peak=np.array([1.0e-4, 4.0e-4, 2.0e-4]),
        # rows: shaft nodes 0..2 [m]; row 0 (the actuator's index) is not its station
        envelope=np.array([[9.0e-4, 9.0e-4, 9.0e-4], [8.0e-4, 8.0e-4, 8.0e-4], [1.0e-5, 3.0e-5, 2.0e-5]]),
        actuator_displacement={"amb_1": np.array([5.0e-5, 2.0e-4, 1.0e-4])},
        actuator_force={"amb_1": np.array([10.0, 40.0, 20.0])},
    )
    evidence = SimpleNamespace(
        name="amb_1",
        static_offset=1.0e-4,
        static_force=50.0,
        orbit_speed=3000.0 * RPM,
        peak_orbit=2.0e-4,
        force_speed=3000.0 * RPM,
        peak_force=40.0,
    )
    point = SimpleNamespace(analyses=SimpleNamespace(spinup=spinup), evidence=SimpleNamespace(actuators=[evidence]))
    requirements = SimpleNamespace(
        max_spinup_deflection=5.0e-4, required_log_decrement=0.1, min_onset_margin=0.15, separation="api684"
    )
    return SimpleNamespace(
        model=model,
        spinup=spinup,
        operating_speed=OMEGA,
        governing_point="nominal",
        point=lambda name: point,
        verdict=SimpleNamespace(checks=[], check=_no_check),
        # the speed range 0.9 to 1.1 of the operating speed: 4320 to 5280 rpm
        design=SimpleNamespace(
            operating=SimpleNamespace(speed_limits=(0.9 * OMEGA, 1.1 * OMEGA)), requirements=requirements
        ),
        campbell=SimpleNamespace(
            speeds=SPEEDS,
            frequencies=np.array([[20.0], [21.0], [22.0]]),  # Hz
            log_decrements=np.array([[0.3], [0.2], [0.1]]),
            whirl=np.array([["forward"]] * 3),
            kind=None,
        ),
        criticals=None,
        stability=SimpleNamespace(
            speeds=SPEEDS,
            log_decrements=np.array([[0.3], [0.2], [0.1]]),
            whirl=np.array([["forward"]] * 3),
            kind=None,
            onset_speed=None,
        ),
        evidence=SimpleNamespace(
            modes_at_operating=(),
            operating_speed=OMEGA,
            operating_range=(0.9 * OMEGA, 1.1 * OMEGA),
            critical_speeds=None,  # no critical speed found (tests set their own)
        ),
    )


def _trace(figure: dict, name: str) -> dict:
    (trace,) = [t for t in figure["data"] if t["name"] == name]
    return trace


def _band(figure: dict) -> tuple[float, float]:
    (rect,) = [s for s in figure["layout"]["shapes"] if s["type"] == "rect"]
    return rect["x0"], rect["x1"]


def test_campbell_speeds_in_rpm_frequencies_in_hz_and_the_speed_band():
    figure = campbell_figure(_assessment())
    assert _trace(figure, "mode 1 (forward)")["x"] == pytest.approx([1000.0, 3000.0, 6000.0], rel=1e-6)
    one = _trace(figure, "1× spin")
    # the 1× line ends at the top speed, 6000 rpm, and its frequency 6000/60 = 100 Hz
    assert one["x"] == pytest.approx([0.0, 6000.0], rel=1e-6)
    assert one["y"] == pytest.approx([0.0, 100.0], rel=1e-6)
    (line,) = [s for s in figure["layout"]["shapes"] if s["type"] == "line"]
    assert line["x0"] == pytest.approx(4800.0, rel=1e-9)
    # 0.9 · 4800 = 4320 rpm, 1.1 · 4800 = 5280 rpm
    assert _band(figure) == pytest.approx((4320.0, 5280.0), rel=1e-9)


def test_spinup_orbits_and_the_deflection_limit_in_mm():
    figure = spinup_figure(_assessment())
    # largest over the shaft: 1e-4, 4e-4, 2e-4 m · 1e3 = 0.1, 0.4, 0.2 mm
    assert _trace(figure, "largest over the shaft")["y"] == pytest.approx([0.1, 0.4, 0.2], rel=1e-6)
    # at the actuator: the envelope of its station's node (row 2), 1e-5, 3e-5, 2e-5 m = 0.01, 0.03, 0.02 mm
    station = _trace(figure, "shaft at amb_1 (x = 1.00 m)")
    assert station["y"] == pytest.approx([0.01, 0.03, 0.02], rel=1e-6)
    # the limit 5e-4 m = 0.5 mm across the speeds 1000 to 6000 rpm
    limit = _trace(figure, "spin-up orbit limit")
    assert limit["y"] == pytest.approx([0.5, 0.5], rel=1e-9)
    assert limit["x"] == pytest.approx([1000.0, 6000.0], rel=1e-9)
    assert figure["layout"]["yaxis"]["title"]["text"] == "orbit [mm]"


def test_actuator_excursion_adds_the_static_offset_and_each_limit_is_on_its_panel(monkeypatch):
    limits = {"amb_1": SimpleNamespace(gap=4.0e-4, force_capacity=800.0)}
    monkeypatch.setattr(interactive, "actuator_limits", lambda model: limits)
    figure = actuator_figure(_assessment())
    top, bottom = [t for t in figure["data"] if t["name"] == "amb_1: static + spin-up"]
    assert (top["yaxis"], bottom["yaxis"]) == ("y", "y2")
    # excursion = static 1e-4 m + orbit (5e-5, 2e-4, 1e-4) m = (0.15, 0.30, 0.20) mm
    assert top["y"] == pytest.approx([0.15, 0.3, 0.2], rel=1e-6)
    # force = static 50 N + dynamic (10, 40, 20) N
    assert bottom["y"] == pytest.approx([60.0, 90.0, 70.0], rel=1e-6)
    assert top["x"] == pytest.approx([1000.0, 3000.0, 6000.0], rel=1e-6)
    gap = _trace(figure, "amb_1: gap")
    assert gap["y"] == pytest.approx([0.4, 0.4], rel=1e-9)  # 4e-4 m = 0.4 mm, on the excursion panel
    assert "yaxis" not in gap or gap["yaxis"] == "y"
    capacity = _trace(figure, "amb_1: force capacity")
    assert capacity["y"] == [800.0, 800.0] and (capacity["xaxis"], capacity["yaxis"]) == ("x2", "y2")
    # the checked peaks: 1e-4 + 2e-4 m = 0.3 mm and 50 + 40 = 90 N, both at 3000 rpm
    peaks = [t for t in figure["data"] if t["name"] == "amb_1: checked peak"]
    assert [(p["yaxis"], p["x"][0], p["y"][0]) for p in peaks] == [
        ("y", pytest.approx(3000.0, rel=1e-6), pytest.approx(0.3, rel=1e-6)),
        ("y2", pytest.approx(3000.0, rel=1e-6), pytest.approx(90.0, rel=1e-6)),
    ]
    assert figure["layout"]["yaxis"]["title"]["text"] == "excursion [mm]"
    assert figure["layout"]["yaxis2"]["title"]["text"] == "force [N]"


def test_stability_limit_is_the_required_log_decrement():
    figure = stability_figure(_assessment())
    required = _trace(figure, "required log decrement")
    assert required["y"] == [0.1, 0.1]  # requirements.required_log_decrement, not another requirement
    assert required["x"] == pytest.approx([1000.0, 6000.0], rel=1e-9)
    assert _band(figure) == pytest.approx((4320.0, 5280.0), rel=1e-9)

"""What ``flexshaft run`` prints after the analyses: each field under its own name and unit.

``_print_run`` is given a results dict whose numbers are chosen distinct and exact, and a
verdict with no checks (an empty table), so every printed number can be traced to its field by
hand: moduli Pa -> GPa is /1e9 (E* 100e9 Pa -> 100 GPa, G* 5e9 Pa -> 5 GPa), the orbit m -> mm
is x1000 (1.5e-4 m -> 0.15 mm); the rest and operating-speed mode tables hold their own rows
(12.5 Hz at rest, 37.5 Hz at speed); the Tsai-Wu and buckling safety factors are their own
(2.5 and 7.25). Nothing is computed: a few ms.
"""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import pytest

from flexshaft.cli.run import _print_run
from flexshaft.verdict.result import Verdict


def _mode(frequency_hz: float) -> dict:
    return {
        "mode": 1,
        "frequency_Hz": frequency_hz,
        "frequency_rpm": 60.0 * frequency_hz,
        "damping_ratio": 0.01,
        "log_decrement": 0.0628,
        "kind": "bending",
        "whirl": "forward",
        "component": "shaft",
    }


def _data() -> dict:
    return {
        "summary": {
            "name": "stand-in",
            "shaft_mass_kg": 3.0,
            "shaft_E_storage_Pa": 100e9,
            "shaft_E_loss_factor": 0.01,
            "shaft_G_storage_Pa": 5e9,
            "shaft_G_loss_factor": 0.02,
            "torque_Nm": 150.0,
            "free_dofs": 120,
            "operating_speed_rpm": 4800.0,
        },
        "modes_at_rest": [_mode(12.5)],
        "modes_at_operating_speed": [_mode(37.5)],
        "strength_static_plus_imbalance": {
            "safety_factor": 2.5,
            "x_m": 0.75,
            "ply": 1,
            "ply_angle_deg": 45.0,
            "dominant_stress": "sigma_2",
        },
        "buckling": {"safety_factor": 7.25},
        "imbalance": {"max_shaft_orbit_spin_up_m": 1.5e-4, "speed_of_max_rpm": 4200.0},
    }


def test_each_printed_number_is_its_own_field(capsys: pytest.CaptureFixture) -> None:
    assessment = SimpleNamespace(verdict=Verdict(checks=()), design=SimpleNamespace(envelope=None))
    _print_run(assessment, _data(), Path("report.html"), 1.0, None)
    printed = capsys.readouterr().out
    assert "E* = 100 GPa (loss factor 0.01), G* = 5 GPa (loss factor 0.02)" in printed
    assert "spin-up peak shaft orbit 0.15 mm at 4200 rpm" in printed
    assert "Tsai-Wu safety factor 2.5 at x = 0.75 m" in printed and "buckling safety factor 7.25" in printed
    rest, at_speed = printed.index("natural frequencies at rest"), printed.index("natural frequencies at 4800 rpm")
    assert rest < at_speed
    rest_table, speed_table = printed[rest:at_speed], printed[at_speed:]
    assert "12.5" in rest_table and "37.5" not in rest_table  # 12.5 Hz = 750 rev/min at rest
    assert "37.5" in speed_table and "12.5" not in speed_table


def test_with_an_envelope_each_headline_names_the_point_it_is_at(capsys: pytest.CaptureFixture) -> None:
    """With an envelope the headline numbers are the governing point's analyses, while the
    verdict table holds each check's worst point: a Tsai-Wu factor of the cold day printed bare
    above the hot day's smaller one in the table reads as a contradiction. Each headline (both
    mode tables, the moduli, the strength and the spin-up lines) names the governing point, here the second
    of two stand-in points; a design without an envelope names none (the test above)."""
    point = SimpleNamespace(name="cold_day", verdict=Verdict(checks=()))
    other = SimpleNamespace(name="hot_day", verdict=Verdict(checks=()))
    assessment = SimpleNamespace(
        verdict=Verdict(checks=()),
        design=SimpleNamespace(envelope=object()),
        points=(other, point),
        governing_point="cold_day",
        point=lambda name: {"cold_day": point, "hot_day": other}[name],
    )
    _print_run(assessment, _data(), Path("report.html"), 1.0, None)
    printed = capsys.readouterr().out
    assert "120 free DOFs [cold_day]" in printed  # E* and G* at the point's temperature
    assert "natural frequencies at rest [cold_day]" in printed
    assert "natural frequencies at 4800 rpm [cold_day]" in printed
    assert "buckling safety factor 7.25 [cold_day]" in printed
    assert "spin-up peak shaft orbit 0.15 mm at 4200 rpm [cold_day]" in printed
    assert "[hot_day]" not in printed.split("governed by")[-1]

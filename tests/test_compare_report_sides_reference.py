"""The ``flexshaft compare`` report keeps each design's numbers on its own side (report/compare.py),
beside tests/test_compare_report_reference.py: the mass without actuators, the parts table, the
lower-bound marks of the key numbers, the critical speeds of ``results.json``, the coupling
table's static and whirl angles, and the overlaid Campbell diagrams' speed axis.

References (derived, by hand): a stand-in comparison whose designs A and B have distinct inputs
(so a value taken from the other design, or from a neighbouring column, is seen); 1 rad =
180/π°, so π/180 rad shows as 1°; rpm = 60·Ω/(2π). Figures are replaced by stubs that draw
nothing. CPU about 0.01 s.
"""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.comparison import PART_KINDS
from flexshaft.report import compare


def _inventory(scale, actuators):
    """Counts 1..5 and masses 1..5 kg times ``scale`` by kind; the actuators' mass given."""
    mass = {kind: scale * (k + 1.0) for k, kind in enumerate(PART_KINDS)}
    mass["actuators"] = actuators
    count = {kind: k + 1 for k, kind in enumerate(PART_KINDS)}
    return NS(mass=mass, count=count, total_mass=sum(mass.values()), total_count=15, mass_not_given=[])


def _comparison(**extra):
    runs = (
        NS(model=NS(design=NS(name="alpha")), verdict=NS(summary="PASS", to_dict=lambda: {"v": "A"}), notes=[]),
        NS(model=NS(design=NS(name="beta")), verdict=NS(summary="FAIL", to_dict=lambda: {"v": "B"}), notes=[]),
    )
    # A: 1 + 2 + 3 + 4 + 6 = 16 kg with 6 kg of actuators; B: 10 + 20 + 30 + 40 + 2 = 102 kg with 2 kg
    fields = {"labels": ("A", "B"), "runs": runs, "inventories": (_inventory(1.0, 6.0), _inventory(10.0, 2.0))}
    fields.update(critical_speeds=lambda d: [], metrics=list)
    fields.update(extra)
    return NS(**fields)


def test_mass_without_actuators_subtracts_each_designs_own():
    """A: 16 − 6 = 10.0 kg; B: 102 − 2 = 100.0 kg."""
    section = compare._summary_section(_comparison())
    (text,) = [p for p in section.paragraphs if p.startswith("Driveline mass")]
    assert "Driveline mass 16.0 kg (A) against 102.0 kg (B)" in text
    assert text.endswith("Without the actuators: 10.0 kg against 100.0 kg.")


def test_parts_table_each_designs_count_and_mass(monkeypatch, tmp_path):
    monkeypatch.setattr(compare, "save_figure", lambda fig, folder, stem: {"png": Path(folder) / f"{stem}.png"})
    monkeypatch.setattr(compare, "mass_breakdown_figure", lambda masses: None)
    (table,) = compare._parts_section(_comparison(), tmp_path).tables
    assert table.rows[0] == ["segments", 1, 1.0, 1, 10.0]
    assert table.rows[3] == ["dampers", 4, 4.0, 4, 40.0]
    assert table.rows[4] == ["actuators", 5, 6.0, 5, 2.0]
    assert table.rows[-1] == ["total", 15, 16.0, 15, 102.0]


def test_key_numbers_mark_only_the_design_whose_value_is_a_lower_bound():
    """Whirl onset: A stable to the top of its scan, 6000 rpm ("> 6000 rpm"); B's onset found at
    5400 rpm (no mark)."""
    rpm = 2.0 * math.pi / 60.0
    metric = NS(
        key="whirl_onset",
        title="whirl onset",
        unit="rad/s",
        values=(6000.0 * rpm, 5400.0 * rpm),
        lower_bounds=(True, False),
        notes=("", ""),
    )
    table = compare._metrics_table(_comparison(metrics=lambda: [metric]))
    assert table.rows == [["whirl onset", "> 6000 rpm", "5400 rpm", "", ""]]


def test_results_json_gives_each_design_its_own_critical_speeds():
    crit = {0: [{"speed": 300.0}], 1: [{"speed": 450.0}, {"speed": 700.0}]}
    out = compare.comparison_json(_comparison(critical_speeds=crit.__getitem__))
    assert out["designs"]["A"]["critical_speeds"] == [{"speed": 300.0}]
    assert out["designs"]["B"]["critical_speeds"] == [{"speed": 450.0}, {"speed": 700.0}]
    assert out["designs"]["B"]["name"] == "beta" and out["designs"]["B"]["total_mass_kg"] == 102.0


def test_coupling_table_static_then_whirl_angle_in_degrees(monkeypatch, tmp_path):
    """A coupling at x = 1.5 m: static angle π/180 rad = 1°, whirl angle π/360 rad = 0.5°,
    allowable 3π/180 rad = 3°; moment 12 N m, axial force 40 N, torque 250 N m."""
    monkeypatch.setattr(compare, "save_figure", lambda fig, folder, stem: {"png": Path(folder) / f"{stem}.png"})
    monkeypatch.setattr(compare, "static_deflection_overlay_figure", lambda shapes, joints: None)
    dofs = NS(shaft_x=np.zeros(2), values=lambda q, member, which: np.zeros(2))
    cm = NS(
        names=["c1"],
        stations=[1.5],
        static_angle=[math.pi / 180.0],
        dynamic_angle=[math.pi / 360.0],
        allowable_angle=[3.0 * math.pi / 180.0],
        static_moment=[12.0],
        axial_force=[40.0],
        torque=[250.0],
    )
    run = NS(model=NS(dofs=dofs, couplings=[NS(x=1.5)]), static_displacement=np.zeros(2), coupling_misalignment=cm)
    other = NS(model=NS(dofs=dofs, couplings=[]), static_displacement=np.zeros(2), coupling_misalignment=None)
    (table,) = compare._deflection_section(NS(labels=("A", "B"), runs=(run, other)), tmp_path).tables
    assert list(table.columns)[2:4] == ["static angle [°]", "whirl angle at Ω_op [°]"]
    ((name, x, static, whirl, allowable, *loads),) = table.rows
    assert (name, x) == ("c1", 1.5)
    assert (static, whirl, allowable) == pytest.approx((1.0, 0.5, 3.0), rel=1e-12)
    assert loads == [12.0, 40.0, 250.0]


def test_campbell_overlay_against_rpm_each_design_its_own(monkeypatch, tmp_path):
    """A's Campbell samples at Ω = 2π·1200/60 and 2π·4800/60 rad/s are drawn at 1200 and
    4800 rpm, B's at 2π·1500/60 and 2π·5400/60 rad/s at 1500 and 5400 rpm, each with its own
    frequencies (A 10 Hz, B 20 Hz) and whirl; the operating speeds 4800 and 5400 rpm."""
    monkeypatch.setattr(compare, "save_figure", lambda fig, folder, stem: {"png": Path(folder) / f"{stem}.png"})
    calls = {}
    monkeypatch.setattr(compare, "campbell_overlay_figure", lambda curves, op: calls.update(curves=curves, op=op))
    monkeypatch.setattr(compare, "spinup_overlay_figure", lambda *args: None)

    def run(rpm, hz, whirl):
        speeds = np.array(rpm) * 2.0 * math.pi / 60.0
        return NS(
            model=NS(speed=speeds[1], design=NS(requirements=NS(max_spinup_deflection=1e-3))),
            campbell=NS(speeds=speeds, frequencies=np.full((2, 1), hz), whirl=[[whirl]] * 2),
            spinup=NS(speeds=speeds, shaft_peak=np.zeros(2)),
        )

    runs = (run([1200.0, 4800.0], 10.0, "forward"), run([1500.0, 5400.0], 20.0, "backward"))
    compare._dynamics_section(_comparison(runs=runs), tmp_path)
    for label, rpm, hz, whirl in (("A", [1200.0, 4800.0], 10.0, "forward"), ("B", [1500.0, 5400.0], 20.0, "backward")):
        speeds, frequencies, whirls = calls["curves"][label]
        assert speeds == pytest.approx(rpm, rel=1e-12)
        assert frequencies.tolist() == [[hz], [hz]] and whirls == [[whirl]] * 2
    assert calls["op"] == pytest.approx({"A": 4800.0, "B": 5400.0}, rel=1e-12)

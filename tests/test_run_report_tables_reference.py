"""The run report's tables and figure data (report/driveline.py) beside those of
tests/test_run_report_pages_reference.py: the bearings table, the key numbers' total mass, the
natural-frequency tables' columns, the main rotor's lines and the verdict's critical speeds
handed to the Campbell diagram, and the static deflection's two planes.

References (derived, by hand) on that file's stand-in assessment (SI values, every value
distinct): rpm = 60·Ω/(2π), so Ω = 2π·N/60 rad/s is N rpm; f [Hz] = Ω/(2π) = N/60; a main-rotor
line of ratio r to the shaft is r·N/60 Hz. The figures are only recorded as jobs (never drawn).
CPU about 0.01 s.
"""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace as NS

import numpy as np
import pytest
from test_run_report_pages_reference import _assessment, _plan, _rad_s


def _section(plan, title):
    (section,) = [s for s in plan.sections if s.title == title]
    return section


def test_bearings_table_shaft_then_boom_station_and_the_total_mass(monkeypatch, tmp_path):
    """A hanger at x = 1.2 m on the shaft, 1.25 m on the boom, h = 0.08 m; a ground bearing at
    3.9 m ("ground" under x boom). Key numbers: shaft 9 kg, total 60 kg (DATA)."""
    a = _assessment()
    a.model.bearings = [
        NS(name="hanger", kind="passive", x_shaft=1.2, x_boom=1.25, offset=0.08),
        NS(name="gearbox", kind="passive", x_shaft=3.9, x_boom=None, offset=0.0),
    ]
    a.model.dofs.n_boom_nodes = 2  # a hanger on the boom: the model has one
    a.model.dofs.boom_x = np.zeros(2)
    summary = _section(_plan(monkeypatch, a, tmp_path), "Design summary")
    key, bearings = summary.tables
    assert list(bearings.columns) == ["name", "kind", "x shaft [m]", "x boom [m]", "offset h [m]"]
    assert bearings.rows == [["hanger", "passive", 1.2, 1.25, 0.08], ["gearbox", "passive", 3.9, "ground", 0.0]]
    rows = {row[0]: row[1] for row in key.rows}
    assert rows["shaft mass [kg]"] == 9.0 and rows["total mass (shaft, boom, end mass) [kg]"] == 60.0


def test_without_a_tailboom_no_boom_is_named_in_the_mass_or_the_deflection(monkeypatch, tmp_path):
    """A model without boom nodes (no ``[tailboom]``: bearings on ground) has no boom nor end
    mass in its total, and its static deflection is the shaft's alone: the key numbers and the
    figure's caption must not name a tailboom (the Jeffcott rotor's report did)."""
    a = _assessment()
    assert a.model.dofs.n_boom_nodes == 0
    plan = _plan(monkeypatch, a, tmp_path)
    key = _section(plan, "Design summary").tables[0]
    rows = {row[0]: row[1] for row in key.rows}
    assert rows["total mass (no tailboom) [kg]"] == 60.0
    assert not any("boom" in str(name) for name in rows if name != "total mass (no tailboom) [kg]")
    figures = [f for section in plan.sections for f in section.figures]
    assert [f.caption for f in figures if Path(f.path_png).name == "static_deflection.png"] == [
        "Static deflection of the shaft"
    ]


def test_natural_frequency_table_hz_then_rpm(monkeypatch, tmp_path):
    """A mode at 50 Hz = 50·60 = 3000 rpm: 50 under "frequency [Hz]", 3000 under "[rpm]"."""
    a = _assessment()
    a.modes_at_rest = "modes at rest"  # the stub table ignores what it is given
    row = {"mode": 1, "frequency_Hz": 50.0, "frequency_rpm": 3000.0, "damping_ratio": 0.02}
    row.update(whirl="forward", component="shaft")
    plan = _plan(monkeypatch, a, tmp_path, modes_rows=[row])
    tables = _section(plan, "Natural frequencies and Campbell diagram").tables
    for table in tables[:2]:  # at rest and at speed
        assert list(table.columns)[:3] == ["mode", "frequency [Hz]", "[rpm]"]
        assert table.rows == [[1, 50.0, 3000.0, 0.02, "forward", "shaft"]]


def test_campbell_job_gets_main_rotor_lines_in_hz_and_criticals_in_rpm(monkeypatch, tmp_path):
    """Shaft at 6000 rpm = 100 Hz: the main rotor's 1/rev at ratio 0.05 is 5 Hz, its 4/rev
    (ratio 0.2) 20 Hz; the tail rotor's 1/rev (ratio 1/1.17) is an order, passed as it is. The
    verdict's critical speeds Ω = 2π·3300/60 and 2π·7000/60 rad/s are 3300 and 7000 rpm, with
    their AF 8 and 2.5. With the operating speed range 5700-6300 rpm (shaded), their separation
    readings, worked by hand from API 684's rule (docs/requirements.md; the check measures a
    critical below the range from its lowest speed, one above from its highest): 3300 rpm is
    (5700 − 3300)/5700 = 42.1 % below 5700 and needs min(16, 17 (1 − 1/(8 − 1.5))) = 14.38 %;
    7000 rpm is 700/6300 = 11.1 % above 6300 and needs min(26, 10 + 17 (1 − 1/(2.5 − 1.5))) = 10 %."""
    a = _assessment()
    a.evidence = NS(
        critical_speeds=[
            NS(speed=_rad_s(3300.0), amplification_factor=8.0),
            NS(speed=_rad_s(7000.0), amplification_factor=2.5),
        ],
        operating_speed=_rad_s(6000.0),
        operating_range=(_rad_s(5700.0), _rad_s(6300.0)),
        torsional_modes=(),
    )
    excitations = [
        NS(name="main rotor 1/rev", source="main_rotor", order=1, ratio=0.05),
        NS(name="main rotor 4/rev", source="main_rotor", order=4, ratio=0.2),
        NS(name="tail rotor 1/rev", source="tail_rotor", order=1, ratio=1.0 / 1.17),
    ]
    plan = _plan(monkeypatch, a, tmp_path, excitations=excitations)
    (job,) = [j for j in plan.jobs if j.stem == "campbell"]
    kw = job.kwargs
    assert kw["main_rotor_hz"] == pytest.approx({"1/rev": 5.0, "4/rev": 20.0}, rel=1e-12)
    assert kw["excitation_orders"] == {"tail rotor 1/rev": 1.0 / 1.17}
    assert kw["operating_rpm"] == pytest.approx(6000.0, rel=1e-12)
    assert kw["max_critical_rpm"] == pytest.approx(7500.0, rel=1e-12)  # 1.25 · 6000
    (c1, af1), (c2, af2) = kw["response_criticals"]
    assert (c1, c2) == (pytest.approx(3300.0, rel=1e-12), pytest.approx(7000.0, rel=1e-12))
    assert (af1, af2) == (8.0, 2.5)
    assert kw["speed_range_rpm"] == pytest.approx((5700.0, 6300.0), rel=1e-12)
    below, above = kw["separation"]
    needs = 0.17 * (1.0 - 1.0 / 6.5)
    assert below == pytest.approx((5700.0, 5700.0 * (1.0 - needs), 2400.0 / 5700.0, needs), rel=1e-12)
    assert above == pytest.approx((6300.0, 6300.0 * 1.10, 700.0 / 6300.0, 0.10), rel=1e-12)
    # with the separation check off ([requirements] separation = "off": not evaluated), no bars
    a.design.requirements.separation = "off"
    plan = _plan(monkeypatch, a, tmp_path, excitations=excitations)
    (job,) = [j for j in plan.jobs if j.stem == "campbell"]
    assert job.kwargs["separation"] == () and len(job.kwargs["response_criticals"]) == 2


def test_static_deflection_figure_vertical_then_lateral(monkeypatch, tmp_path):
    """The shaft's v (vertical) and w (lateral) of the static displacement go to the figure in
    that order, each its own plane's values (stand-in DOF values v = 1, 2 mm, w = −3, −4 mm),
    with the bearings' stations. The stand-in's values exist only for the assessment's static
    displacement (a sentinel): any other vector raises."""
    a = _assessment()
    a.static_displacement = static = object()
    planes = {"v": np.array([1e-3, 2e-3]), "w": np.array([-3e-3, -4e-3])}

    def values(q, member, which):
        if q is not static:
            raise AssertionError(f"the deflected shape drawn from {q!r}, not the static displacement")
        return planes[which]

    a.model.dofs = NS(shaft_x=np.array([0.0, 4.0]), n_boom_nodes=0, values=values)
    a.model.bearings = [NS(name="b", kind="passive", x_shaft=2.0, x_boom=None, offset=0.0)]
    plan = _plan(monkeypatch, a, tmp_path)
    (job,) = [j for j in plan.jobs if j.stem == "static_deflection"]
    x, v, w, boom_x, boom_v, boom_w, bearing_x = job.args
    assert list(v) == [1e-3, 2e-3] and list(w) == [-3e-3, -4e-3]
    assert boom_x is None and boom_v is None and boom_w is None and bearing_x == [2.0]

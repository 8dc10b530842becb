"""The run report's own sections (report/driveline.py, :func:`plan_run_report`) on a hand-built
assessment.

A stand-in of the assessment (plain namespaces with the attributes the page reads, SI values,
every value distinct); the sections other modules write (verdict, inputs, imbalance,
stability; their own reference tests cover them) and the key-number dictionary of
``results.json`` are replaced by stubs, so what is checked is this module's text and tables.
Displayed values are converted by hand from the unit definitions (derived): 1 m = 1000 mm;
1 kW = 1e3 W; 1 GPa = 1e9 Pa; 1 MPa = 1e6 Pa; rpm = 60·Ω/(2π), so Ω = 2π·N/60 rad/s shows
as N rpm. Modes and plies are numbered from 1 in the report (mode 1 is the lowest; ply 1 the
first of the layup), while the results count them from 0. Figures are only recorded as jobs
(never drawn). CPU about 0.01 s.
"""

from __future__ import annotations

import math
from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.report import driveline
from flexshaft.report.html import Section


def _rad_s(rpm: float) -> float:
    return 2.0 * math.pi * rpm / 60.0


def _strength(safety_factor, x, ply, stresses):
    return NS(
        safety_factor=safety_factor,
        x=x,
        ply=ply,
        ply_angle_deg=-55.0,
        phase_deg=90.0,
        dominant_stress="σ2",
        stresses=stresses,
    )


def _assessment(points=("operating point",), point_power=150e3):
    design = NS(
        name="stand-in",
        shaft=NS(x_start=0.0, x_end=4.0, outer_diameter=0.1016, wall_thickness=0.00325, layup="(55/-55)s"),
        operating=NS(main_rotor_frequencies=dict, speed_rad_s=_rad_s(6000.0), power=150e3),
        requirements=NS(min_safety_factor=1.5, separation="api684"),
    )
    dofs = NS(shaft_x=np.zeros(2), n_boom_nodes=0, values=lambda q, member, which: np.zeros(2))
    # the design at the governing point (another object, as the verdict's design_at_point makes)
    at_point = design if point_power == 150e3 else NS(**{**vars(design), "name": "stand-in at the point"})
    model = NS(
        design=at_point,
        dofs=dofs,
        speed=_rad_s(6000.0),
        power=point_power,  # the governing point's (150 kW: the design's own)
        bearings=[],
        internal_damping="thesis",
    )
    criticals = [
        NS(speed=_rad_s(3000.0), speed_rpm=3000.0, mode=0, whirl="forward"),  # 50 %: listed
        NS(speed=_rad_s(7200.0), speed_rpm=7200.0, mode=2, whirl="backward"),  # 120 %: listed
        NS(speed=_rad_s(7800.0), speed_rpm=7800.0, mode=3, whirl="forward"),  # 130 %: beyond 125 %
    ]
    buckling = {
        "theory": "Donnell",
        "critical_torque_positive_Nm": 5000.0,
        "wave_number_positive": 2,
        "critical_torque_negative_Nm": 3000.0,
        "wave_number_negative": 3,
        "torque_Nm": 1000.0,
        "safety_factor": 3.0,
    }
    analyses = NS(
        # static alone: R 4 at x 1.5 m, outer ply 0; with imbalance: R 2.5 at x 2.5 m, ply 2
        strength_static=_strength(4.0, 1.5, 0, (20e6, 3e6, 1e6)),
        strength_total=_strength(2.5, 2.5, 2, (40e6, 5e6, 2e6)),
        buckling=NS(to_dict=lambda: buckling),
        torque_factor=1.0,
        bearing_loops=None,  # no magnetic bearing: no loop section
    )
    judged = [NS(name=name, analyses=analyses) for name in points]
    return NS(
        design=design,
        model=model,
        verdict=NS(check=_no_check),
        campbell=NS(critical_speeds=criticals),
        modes_at_rest=None,
        modes_at_speed=None,
        evidence=NS(critical_speeds=(), operating_speed=_rad_s(6000.0), operating_range=None, torsional_modes=()),
        points=judged,
        point=lambda name: next(p for p in judged if p.name == name),
        governing_point=points[-1],
        static_displacement=None,
        strength_static=analyses.strength_static,
        strength_total=analyses.strength_total,
        buckling=analyses.buckling,
        thermal=None,
    )


def _no_check(key):
    raise KeyError(key)


DATA = {
    "summary": {
        "shaft_mass_kg": 9.0,
        "total_mass_kg": 60.0,
        "shaft_E_storage_Pa": 30e9,
        "shaft_E_loss_factor": 0.01,
        "shaft_G_storage_Pa": 4e9,
        "shaft_G_loss_factor": 0.02,
        "torque_Nm": 1000.0,
        "free_dofs": 400,
    },
    "static": {"boom_tip_v_m": 0.0123, "boom_tip_w_m": -0.0045},
    "notes": [],
}


def _plan(monkeypatch, a, tmp_path, modes_rows=(), excitations=()):
    """``plan_run_report`` of ``a`` with the sections other modules write and the key numbers of
    ``results.json`` stubbed (this module's own text is what the tests read); the modes tables'
    rows and the torsional excitations are ``modes_rows`` and ``excitations``."""
    monkeypatch.setattr(driveline, "results_json", lambda a, thesis: DATA)
    for name, title in (
        ("verdict_section", "Verdict"),
        ("inputs_section", "Inputs"),
        ("imbalance_section", "Imbalance"),
        ("stability_section", "Stability"),
    ):
        monkeypatch.setattr(driveline, name, lambda *args, title=title, **kwargs: Section(title))
    monkeypatch.setattr(driveline, "report_title", lambda design: design.name)
    monkeypatch.setattr(driveline, "modes_table", lambda modes: list(modes_rows))
    monkeypatch.setattr(driveline, "torsional_excitations", lambda design: list(excitations))
    return driveline.plan_run_report(a, tmp_path, design_text="")


@pytest.fixture()
def sections(monkeypatch, tmp_path):
    return {s.title: s for s in _plan(monkeypatch, _assessment(), tmp_path).sections}


def test_design_summary_in_mm_and_kw(sections):
    """D_o 0.1016 m = 101.6 mm, wall 0.00325 m = 3.25 mm, 6000 rpm, 150e3 W = 150 kW; E* 30e9 Pa =
    30 GPa, G* 4e9 Pa = 4 GPa."""
    summary = sections["Design summary"]
    (paragraph,) = summary.paragraphs
    assert "D_o = 101.6 mm, wall 3.25 mm, layup (55/-55)s; 6000 rpm, 150 kW." in paragraph
    key = {row[0]: row[1] for row in summary.tables[0].rows}
    assert key["E* storage [GPa] / loss factor"] == "30.000 / 0.0100"
    assert key["G* storage [GPa] / loss factor"] == "4.000 / 0.0200"


def test_the_summary_gives_the_designs_own_speed_and_power_and_names_the_governing_point(monkeypatch, tmp_path):
    """Was: the summary (and the title) gave the governing point's power as the design's (the
    tuned design's hot-soak start, a 75 kW ground run, titled its 246 kW design "75 kW"). The
    design's 150 kW heads the summary; the point's 75 kW is named with the point, and the key
    numbers read at it say so."""
    a = _assessment(points=("cruise", "ground_run"), point_power=75e3)
    summary = {s.title: s for s in _plan(monkeypatch, a, tmp_path).sections}["Design summary"]
    (paragraph,) = summary.paragraphs
    assert "layup (55/-55)s; 6000 rpm, 150 kW. " in paragraph
    assert paragraph.endswith("The analyses below are at the governing point, ground_run: 6000 rpm, 75 kW.")
    key = {row[0]: row[1] for row in summary.tables[0].rows}
    assert key["torque at ground_run [N m]"] == 1000.0 and "E* storage at ground_run [GPa] / loss factor" in key
    assert _plan(monkeypatch, a, tmp_path).title == "flexshaft report: stand-in"


def test_critical_speeds_up_to_125_percent_with_modes_from_1(sections):
    """Criticals at 50 % and 120 % of 6000 rpm listed (tracked modes 0 and 2 shown as 1 and 3),
    the one at 130 % not."""
    section = sections["Natural frequencies and Campbell diagram"]
    (table,) = [t for t in section.tables if t.caption.startswith("Critical speeds")]
    assert table.rows == [[3000.0, 1, "forward"], [7200.0, 3, "backward"]]


def test_boom_tip_deflection_in_mm(sections):
    """v 0.0123 m = 12.30 mm, w −0.0045 m = −4.50 mm."""
    (paragraph,) = sections["Deflected shape under static loads"].paragraphs
    assert paragraph.endswith(" Boom tip: v = 12.30 mm, w = -4.50 mm.")


def test_critical_ply_rows_by_case_in_mpa(sections):
    """Static: R 4 at 1.5 m in ply 1 (index 0), σ 20 / 3 / 1 MPa; with imbalance: R 2.5 at 2.5 m in
    ply 3 (index 2), σ 40 / 5 / 2 MPa. Buckling: +5000 N m (n = 2), −3000 N m (n = 3)."""
    section = sections["Strength and torsional buckling"]
    (table,) = section.tables
    assert list(table.columns)[-3:] == ["σ1 [MPa]", "σ2 [MPa]", "τ12 [MPa]"]
    static, total = table.rows
    assert static[:4] == ["static", 4.0, 1.5, 1] and static[-3:] == pytest.approx([20.0, 3.0, 1.0], rel=1e-12)
    assert total[:4] == ["static + imbalance", 2.5, 2.5, 3] and total[-3:] == pytest.approx([40.0, 5.0, 2.0], rel=1e-12)
    assert "T_cr = 5000 N m (positive, n = 2), 3000 N m (negative, n = 3); applied 1000 N m" in section.paragraphs[1]


def test_strength_section_shows_the_points_where_its_checks_govern(monkeypatch, tmp_path):
    """An envelope of two points: the Tsai-Wu check governs at "hot" (R 1.6 with imbalance, ply 2
    at x 3.0 m), the buckling check at "cold" (+4000 N m, n = 4), while the assessment's
    governing point "cold" has R 2.5. The section's rows, its sentences, and the figure (its
    result, its caption, and the required factor 1.5 from [requirements]) are the verdict's:
    hot's strength and cold's buckling, each named."""
    a = _assessment()
    cold = a.points[0]
    cold.name = "cold"
    hot_buckling = {"theory": "Donnell", "critical_torque_positive_Nm": 9000.0, "wave_number_positive": 5}
    cold_buckling = dict(
        a.buckling.to_dict(), critical_torque_positive_Nm=4000.0, wave_number_positive=4, safety_factor=2.4
    )
    cold.analyses.buckling = NS(to_dict=lambda: cold_buckling)
    cold.analyses.torque_factor = 1.25  # the torsional response's peak torque over the steady one
    hot = NS(
        name="hot",
        analyses=NS(
            strength_static=_strength(3.0, 1.0, 1, (10e6, 2e6, 1e6)),
            strength_total=_strength(1.6, 3.0, 2, (60e6, 4e6, 3e6)),
            buckling=NS(to_dict=lambda: hot_buckling),
            torque_factor=1.0,
            bearing_loops=None,
        ),
    )
    governs = {"tsai_wu": "hot", "buckling": "cold"}
    a.points = [cold, hot]
    a.point = {"cold": cold, "hot": hot}.__getitem__
    a.governing_point = "cold"
    a.verdict = NS(check=lambda key: NS(location={"point": governs[key]}))
    plan = _plan(monkeypatch, a, tmp_path)
    section = next(s for s in plan.sections if s.title == "Strength and torsional buckling")
    static, total = section.tables[0].rows
    assert static[:4] == ["static", 3.0, 1.0, 2] and total[:4] == ["static + imbalance", 1.6, 3.0, 3]
    assert "at hot, where the Tsai-Wu check governs" in section.paragraphs[0]
    assert "at cold, where the buckling check governs" in section.paragraphs[1]
    assert "T_cr = 4000 N m (positive, n = 4)" in section.paragraphs[1]
    # the check divides by the torque factor: 2.4 / 1.25 = 1.92
    assert "applied 1000 N m × 1.25 (torsional response); buckling safety factor 1.92." in section.paragraphs[1]
    assert "classical shell ignores transverse shear" in section.paragraphs[1]  # a Donnell shell
    (figure,) = section.figures
    assert "at hot, where the Tsai-Wu check governs" in figure.caption
    (job,) = [j for j in plan.jobs if j.stem == "safety_factor"]
    assert job.args[0] is hot.analyses.strength_total and job.kwargs == {"required": 1.5}


def test_a_shear_shell_crimps_without_waves_and_needs_no_caveat(monkeypatch, tmp_path):
    """The shear shell's crimping mode has no circumferential wave number (None): "n = ∞ (shear
    crimping)"; the caveat on the classical shell's missing transverse shear is not printed."""
    a = _assessment()
    shear = dict(a.buckling.to_dict(), theory="shear", wave_number_positive=None, wave_number_negative=None)
    a.points[0].analyses.buckling = NS(to_dict=lambda: shear)
    plan = _plan(monkeypatch, a, tmp_path)
    section = next(s for s in plan.sections if s.title == "Strength and torsional buckling")
    text = section.paragraphs[1]
    assert "(positive, n = ∞ (shear crimping))" in text and "(negative, n = ∞ (shear crimping))" in text
    assert "classical shell" not in text and "buckling safety factor 3.00." in text


def _campbell_caption(plan) -> str:
    (caption,) = [f.caption for s in plan.sections for f in s.figures if f.caption.startswith("Campbell diagram")]
    return caption


def test_the_campbell_caption_names_the_tail_rotors_lines_only_where_the_design_has_them(monkeypatch, tmp_path):
    """Was: the caption promised "brown: the tail rotor's 1/rev and N/rev" on every design,
    although the diagram draws them only from the design's ``[tail_rotor]`` (a design without one
    has none). Without tail-rotor excitations (the stub: none at all) the caption says nothing
    of them; with the tail rotor's 1/rev and 4/rev (at 1/1.17 and 4/1.17 of the shaft's speed)
    it names them."""
    plan = _plan(monkeypatch, _assessment(), tmp_path)
    assert "tail rotor" not in _campbell_caption(plan)
    rotor = [
        NS(name="tail rotor 1/rev", source="tail_rotor", order=1, ratio=1.0 / 1.17),
        NS(name="tail rotor 4/rev", source="tail_rotor", order=4, ratio=4.0 / 1.17),
    ]
    monkeypatch.setattr(driveline, "torsional_excitations", lambda design: rotor)
    plan = driveline.plan_run_report(_assessment(), tmp_path, design_text="")
    assert "brown: the tail rotor's 1/rev and N/rev" in _campbell_caption(plan)

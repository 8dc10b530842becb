"""Assemble the ``flexshaft run`` report from an :class:`~flexshaft.verdict.assess.Assessment`
and the thesis studies beside it (:class:`~flexshaft.thesis.report_studies.ThesisStudies`).

The report computes nothing: every number and curve comes from the assessment (bearing reactions
included); SI is converted to engineering units (rpm, Hz, mm, °C) only here, at the edge, through
:mod:`flexshaft.units`. ``results.json`` is :mod:`flexshaft.report.results_json`; the sections on
the spin-up response, whirl stability and thermal results are :mod:`flexshaft.report.run_sections`.

Writing is in two steps: :func:`plan_run_report` builds the sections and a list of
:class:`~flexshaft.plot.output.FigureJob` (figure functions and their plain-array arguments,
or a result and its ``.plot`` kind), then :func:`write_run_report` renders the figures
(serially, or in forked worker processes) and writes the page.
"""

from __future__ import annotations

import datetime as dt
import json
import math
from collections.abc import Mapping
from concurrent.futures import Executor
from dataclasses import dataclass, replace
from pathlib import Path

from flexshaft.analyses.modal import Modes
from flexshaft.analyses.summary import modes_table
from flexshaft.analyses.torsional import torsional_excitations
from flexshaft.design import baseline_design, baseline_text
from flexshaft.files import atomic_write_text
from flexshaft.plot.driveline import deflected_shape_figure
from flexshaft.plot.output import render_figures, start_figures
from flexshaft.report.html import Section, Table, write_report
from flexshaft.report.inputs import inputs_section, report_title
from flexshaft.report.results_json import json_ready, results_json
from flexshaft.report.run_sections import Figures, imbalance_section, loops_section, stability_section, thermal_section
from flexshaft.report.studies_section import studies_section_and_jobs
from flexshaft.report.verdict import separation_readings, verdict_section
from flexshaft.thesis.design_studies import save_study_data
from flexshaft.thesis.report_studies import ThesisStudies
from flexshaft.units import m_to_mm, rad_s_to_rpm, rpm_to_hz
from flexshaft.verdict.assess import Assessment, check_point

__all__ = ["RunReportPlan", "plan_run_report", "write_run_report"]


def _modes_table(modes: Modes, caption: str) -> Table:
    rows = modes_table(modes)
    return Table(
        caption,
        ["mode", "frequency [Hz]", "[rpm]", "damping ratio", "whirl", "component"],
        [
            [r["mode"], r["frequency_Hz"], r["frequency_rpm"], r["damping_ratio"], r["whirl"], r["component"]]
            for r in rows
        ],
    )


@dataclass(frozen=True)
class RunReportPlan:
    """The report's sections (figures referenced by their future PNG paths), the figures to
    draw, and the key numbers (``results.json``)."""

    sections: list
    jobs: list
    data: dict
    title: str
    design_name: str


def plan_run_report(
    a: Assessment,
    folder: str | Path,
    design_text: str | None = None,
    design_source: str = "design file",
    thesis: ThesisStudies | None = None,
) -> RunReportPlan:
    """Sections, figure jobs and key numbers of the report of the assessment ``a`` and the
    ``thesis`` studies beside it (nothing is drawn or written; see :func:`write_run_report`)."""
    folder = Path(folder)
    figs = Figures(folder)
    model = a.model
    dm = model.dofs
    design = model.design
    data = results_json(a, thesis)
    op_rpm = rad_s_to_rpm(model.speed)
    s = data["summary"]
    sections = []
    section = verdict_section(a.verdict, op_rpm, a)
    ref = figs.result(
        "verdict_margins",
        "Normalised margin of each requirement: its margin divided by its limit, the shaft temperature's "
        "by the allowable's rise above 15 °C (green pass, red fail)",
        a.verdict,
        "margins",
    )
    sections.append(replace(section, figures=[*section.figures, ref]))
    if design_text is None:
        if a.design == baseline_design():
            design_text, design_source = baseline_text(), "embedded thesis baseline"
    sections.append(inputs_section(a.design, design_text, design_source))

    bearings = [
        [b.name, b.kind, b.x_shaft, b.x_boom if b.x_boom is not None else "ground", b.offset] for b in model.bearings
    ]
    # the design as written heads the summary; the analyses below are the governing point's
    at_point, where = "", ""
    if len(a.points) > 1:
        where = f" at {a.governing_point}"
        at_point = (
            f" The analyses below are at the governing point, {a.governing_point}: {op_rpm:.0f} rpm, "
            f"{model.power / 1e3:.0f} kW."
        )
    sections.append(
        Section(
            "Design summary",
            paragraphs=[
                f"{a.design.name}. Shaft {a.design.shaft.x_start:g}–{a.design.shaft.x_end:g} m, "
                f"D_o = {m_to_mm(a.design.shaft.outer_diameter):.1f} mm, "
                f"wall {m_to_mm(a.design.shaft.wall_thickness):.2f} mm, "
                f"layup {a.design.shaft.layup or 'isotropic'}; "
                f"{rad_s_to_rpm(a.design.operating.speed_rad_s):.0f} rpm, {a.design.operating.power / 1e3:.0f} kW."
                + at_point
            ],
            tables=[
                Table(
                    "Key numbers",
                    ["quantity", "value"],
                    [
                        ["shaft mass [kg]", s["shaft_mass_kg"]],
                        [
                            # the model's rigid-body mass: no boom nor end mass without a tailboom
                            "total mass (shaft, boom, end mass) [kg]"
                            if dm.n_boom_nodes
                            else "total mass (no tailboom) [kg]",
                            s["total_mass_kg"],
                        ],
                        [
                            f"E* storage{where} [GPa] / loss factor",
                            f"{s['shaft_E_storage_Pa'] / 1e9:.3f} / {s['shaft_E_loss_factor']:.4f}",
                        ],
                        [
                            f"G* storage{where} [GPa] / loss factor",
                            f"{s['shaft_G_storage_Pa'] / 1e9:.3f} / {s['shaft_G_loss_factor']:.4f}",
                        ],
                        [f"torque{where} [N m]", s["torque_Nm"]],
                        ["free DOFs", s["free_dofs"]],
                    ],
                ),
                Table("Bearings", ["name", "kind", "x shaft [m]", "x boom [m]", "offset h [m]"], bearings),
            ],
        )
    )

    camp = a.campbell
    crit = [c for c in camp.critical_speeds if c.speed <= model.speed * 1.25] if camp is not None else []
    main_rotor = main_rotor_lines(model)
    tail_rotor = campbell_orders(model)
    bearing_x = [b.x_shaft for b in model.bearings]
    f_spin = rpm_to_hz(op_rpm)
    campbell_figure = []
    verdict_criticals = a.evidence.critical_speeds or ()
    judged_off = a.design.requirements.separation == "off"  # the check not evaluated: no bars
    low, high = a.evidence.operating_range or (a.evidence.operating_speed,) * 2
    speed_range_rpm = (rad_s_to_rpm(low), rad_s_to_rpm(high)) if low < high else None
    torsional = (
        torsional_readings(a.evidence, a.design.requirements.min_torsional_separation)
        if a.evidence.torsional_modes
        else []
    )
    if camp is not None:
        campbell_figure.append(
            figs.result(
                "campbell",
                "Campbell diagram"
                + (f" ({a.governing_point})" if len(a.points) > 1 else "")
                + ": whirl as line style and marker, log decrement as colour; every mode up to 1.1 × the "
                "highest excitation the checks use at 130 % of the operating speed; circles: where the lateral "
                "modes cross 1×; red squares: the critical speeds of the verdict (unbalance-response peaks, "
                "with their AF"
                + (
                    ")"
                    if judged_off
                    else " and separation margin); grey bars: the margin API 684 requires of each, from "
                    + (
                        "the end of the operating speed range (shaded) its margin is measured from"
                        if speed_range_rpm
                        else "the operating speed"
                    )
                )
                + ("; brown: the tail rotor's 1/rev and N/rev (torsional separation)" if tail_rotor else "")
                + (
                    "; brown bars: the speeds where each torsional mode's nearest excitation (◇: where it "
                    "crosses the mode) comes within the required torsional separation ("
                    + ", ".join(f"{name} {m:.1%}, needs {r:.1%}" for _, _, m, r, name in torsional)
                    + ")"
                    if torsional
                    else ""
                )
                + (
                    "; purple: the main rotor's 1/rev to N/rev (geared to the shaft; the boom modes' forcing "
                    "and the torsional separation's)"
                    if main_rotor
                    else ""
                ),
                camp,
                "campbell",
                operating_rpm=op_rpm,
                max_critical_rpm=1.25 * op_rpm,
                main_rotor_hz=main_rotor or None,
                excitation_orders=tail_rotor or None,
                response_criticals=[(rad_s_to_rpm(c.speed), c.amplification_factor) for c in verdict_criticals],
                separation=() if judged_off else separation_readings(a.evidence, verdict_criticals),
                speed_range_rpm=speed_range_rpm,
                torsional=torsional,
            )
        )
    sections.append(
        Section(
            "Natural frequencies and Campbell diagram",
            paragraphs=[
                f"Damped eigenvalues of the linear model (gyroscopic terms, bearing damping and actuator K_d, and "
                "the hysteretic loss of every member at each mode's own frequency; the shaft's internal loss "
                f"{_damping_text(model.internal_damping)}). Modes are tracked across speed "
                "by the modal assurance criterion; whirl direction comes from the shaft orbits (forward: same sense "
                "as the spin). The colour of each point is its logarithmic decrement (red: unstable)."
            ],
            tables=[
                *(
                    [_modes_table(a.modes_at_rest, "Natural frequencies at rest")]
                    if a.modes_at_rest is not None
                    else []
                ),
                _modes_table(a.modes_at_speed, f"Natural frequencies at {op_rpm:.0f} rpm"),
                Table(
                    "Critical speeds (1× excitation) up to 125 % of the operating speed",
                    ["speed [rpm]", "tracked mode", "whirl"],
                    [[c.speed_rpm, c.mode + 1, c.whirl] for c in crit],
                ),
            ],
            figures=[
                *campbell_figure,
                figs.result(
                    "mode_shapes",
                    f"Mode shapes at {op_rpm:.0f} rpm of the modes nearest the spin frequency "
                    f"{f_spin:.1f} Hz (v vertical, w lateral; a torsional mode its twist θ, an axial one u; "
                    "▲ bearings)",
                    a.modes_at_speed,
                    "shapes",
                    bearings_x=bearing_x,
                ),
            ],
        )
    )

    sections.append(imbalance_section(a, figs, data, op_rpm))

    qs = a.static_displacement
    st = data["static"]
    deflection = figs.add(
        "static_deflection",
        "Static deflection of shaft and tailboom" if dm.n_boom_nodes else "Static deflection of the shaft",
        deflected_shape_figure,
        dm.shaft_x,
        dm.values(qs, "shaft", "v"),
        dm.values(qs, "shaft", "w"),
        dm.boom_x if dm.n_boom_nodes else None,
        dm.values(qs, "boom", "v") if dm.n_boom_nodes else None,
        dm.values(qs, "boom", "w") if dm.n_boom_nodes else None,
        bearing_x,
    )
    sections.append(
        Section(
            "Deflected shape under static loads",
            paragraphs=[
                "External point and line loads, the manoeuvre load factor on every mass and the transmitted torque."
                + (
                    f" Boom tip: v = {m_to_mm(st['boom_tip_v_m']):.2f} mm, w = {m_to_mm(st['boom_tip_w_m']):.2f} mm."
                    if st["boom_tip_v_m"] is not None
                    else ""
                )
            ],
            figures=[deflection],
        )
    )

    # the three are computed together, for a laminated shaft (verdict.operating_point); shown at the
    # point where the Tsai-Wu check governs, the buckling paragraph at the buckling check's: the
    # verdict's numbers (the governing point's only where it is theirs)
    strength = a.point(check_point(a, "tsai_wu"))
    buckling = a.point(check_point(a, "buckling"))
    several = len(a.points) > 1
    if (
        strength.analyses.strength_total is not None
        and strength.analyses.strength_static is not None
        and buckling.analyses.buckling is not None
    ):
        rows = []
        for name, rr in (
            ("static", strength.analyses.strength_static),
            ("static + imbalance", strength.analyses.strength_total),
        ):
            rows.append(
                [
                    name,
                    rr.safety_factor,
                    rr.x,
                    rr.ply + 1,
                    rr.ply_angle_deg,
                    rr.phase_deg,
                    rr.dominant_stress,
                    rr.stresses[0] / 1e6,
                    rr.stresses[1] / 1e6,
                    rr.stresses[2] / 1e6,
                ]
            )
        b = buckling.analyses.buckling.to_dict()
        at_strength = f" at {strength.name}, where the Tsai-Wu check governs" if several else ""
        at_buckling = f" at {buckling.name}, where the buckling check governs" if several else ""
        # the check divides the steady torque's factor by the torsional response's torque factor
        factor = float(buckling.analyses.torque_factor)
        factor_text = f" × {factor:.4g} (torsional response)" if factor != 1.0 else ""
        sections.append(
            Section(
                "Strength and torsional buckling",
                paragraphs=[
                    "Tsai-Wu safety factor of every ply at both ends of every shaft element, for the static response "
                    "superposed with the imbalance response at the operating speed over the phase φ ∈ [0, 2π) and "
                    f"both signs of the bending strain{at_strength}.",
                    f"Torsional buckling{at_buckling} ({b['theory']} shell, simply supported, both torque senses): "
                    f"T_cr = {b['critical_torque_positive_Nm']:.0f} N m "
                    f"(positive, {_waves(b['wave_number_positive'])}), "
                    f"{b['critical_torque_negative_Nm']:.0f} N m (negative, {_waves(b['wave_number_negative'])}); "
                    f"applied {b['torque_Nm']:.0f} N m{factor_text}; buckling safety factor "
                    f"{b['safety_factor'] / factor:.2f}."
                    + (
                        ""
                        if b["theory"] == "shear"
                        else " The classical shell ignores transverse shear of the soft matrix and is unconservative "
                        "for FMC walls."
                    ),
                ],
                tables=[
                    Table(
                        "Critical ply",
                        [
                            "case",
                            "R",
                            "x [m]",
                            "ply",
                            "angle [°]",
                            "φ [°]",
                            "dominant",
                            "σ1 [MPa]",
                            "σ2 [MPa]",
                            "τ12 [MPa]",
                        ],
                        rows,
                    )
                ],
                figures=[
                    figs.result(
                        "safety_factor",
                        f"Minimum Tsai-Wu safety factor along the shaft{at_strength}, against failure (R = 1) and "
                        "the required factor (dashed)",
                        strength.analyses.strength_total,
                        "along_shaft",
                        required=design.requirements.min_safety_factor,
                    )
                ],
            )
        )
    if a.thermal is not None:
        sections.append(thermal_section(a, figs))
    sections.append(stability_section(a, thesis, figs, op_rpm))
    loops = loops_section(a, figs)
    if loops is not None:
        sections.append(loops)
    if thesis is not None and thesis.design_studies is not None:
        section, jobs = studies_section_and_jobs(thesis.design_studies, folder)
        figs.jobs.extend(jobs)
        sections.append(section)
    if data["notes"]:
        sections.append(Section("Notes", paragraphs=list(data["notes"])))
    return RunReportPlan(sections, figs.jobs, data, f"flexshaft report: {report_title(a.design)}", a.design.name)


def torsional_readings(evidence, required: float) -> list[tuple[float, float, float, float, str]]:
    """The torsional separation check's reading of each torsional mode for the Campbell diagram:
    (natural frequency [Hz], the order of its nearest excitation on the shaft speed, its margin,
    the required margin, "mode × excitation"). The excitation's band spans the operating speed
    range, so its order is the band's top over the range's top speed."""
    modes = evidence.torsional_modes or ()
    low, high = evidence.operating_range or (evidence.operating_speed,) * 2
    return [
        (m.frequency / (2.0 * math.pi), m.band[1] / high, m.margin, required, f"{m.label} × {m.excitation}")
        for m in modes
        if high > 0
    ]


def main_rotor_lines(model) -> dict[str, float]:
    """The main rotor's excitations the torsional separation check uses, 1/rev to N/rev, as
    frequencies at the operating speed [Hz] (the Campbell diagram draws each as a ray geared to
    the shaft): name → frequency. Was 1/rev and N/rev only, so the tuned design's governing
    torsional excitation, the main rotor's 2/rev, was on no figure."""
    if model.design is None or not model.speed > 0:
        return {}
    shaft_hz = model.speed / (2.0 * math.pi)
    return {
        f"{e.order}/rev": e.ratio * shaft_hz for e in torsional_excitations(model.design) if e.source == "main_rotor"
    }


def campbell_orders(model) -> dict[str, float]:
    """The tail rotor's excitations as orders of the shaft speed (the torsional separation
    check's, beside the shaft's 1× and the main rotor's lines): name → order."""
    if model.design is None:
        return {}
    return {e.name: e.ratio for e in torsional_excitations(model.design) if e.source == "tail_rotor"}


#: What the first section of a report without figures says (:func:`without_figures`).
NO_FIGURES_NOTE = (
    "The figures of this report were not drawn (flexshaft run --no-figures): every section has its "
    "text and tables, and results.json holds the numbers the figures would show."
)


def without_figures(plan: RunReportPlan) -> RunReportPlan:
    """``plan`` with no figure to draw and none referenced by its sections; its first section
    says so (:data:`NO_FIGURES_NOTE`)."""
    sections = [replace(section, figures=()) for section in plan.sections]
    if sections:
        sections[0] = replace(sections[0], paragraphs=[*sections[0].paragraphs, NO_FIGURES_NOTE])
    return replace(plan, sections=sections, jobs=[])


def write_run_report(
    a: Assessment,
    folder: str | Path,
    generated: dt.datetime | dt.date | None = None,
    design_text: str | None = None,
    design_source: str = "design file",
    timings: Mapping[str, float] | None = None,
    *,
    thesis: ThesisStudies | None = None,
    svg: bool = False,
    figures: bool = True,
    processes: int = 1,
    executor: Executor | None = None,
) -> Path:
    """Write ``report.html``, the PNG figures (and SVG when ``svg``), ``results.json`` and
    ``timings.json`` of the assessment ``a`` (and the ``thesis`` studies beside it) into
    ``folder``; returns the page's path.

    ``design_text`` is the design file as read (embedded verbatim, with its assumed values
    listed); ``design_source`` says where it came from. The verdict comes first. ``timings``
    (stage -> seconds, e.g. from the CLI's progress display) go to ``timings.json`` with the
    design studies' own, never to ``results.json``. ``processes`` > 1 draws the figures in
    that many forked worker processes; an ``executor`` (e.g.
    :func:`flexshaft.parallel.pool.worker_pool`) draws them in its workers while the data files are
    written here. Without ``figures`` none is drawn: the page has the same sections, text and
    tables, and says that its figures were not drawn (``flexshaft run --no-figures``).
    """
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    plan = plan_run_report(a, folder, design_text, design_source, thesis)
    if not figures:
        plan = without_figures(plan)
    if executor is not None:
        figures_done = start_figures(plan.jobs, folder, executor, svg=svg)
    else:

        def figures_done():
            return render_figures(plan.jobs, folder, svg=svg, processes=processes)

    atomic_write_text(folder / "results.json", json.dumps(json_ready(plan.data), indent=2, allow_nan=False))
    studies = thesis.design_studies if thesis is not None else None
    studies_timings = studies.timings if studies is not None else {}
    atomic_write_text(
        folder / "timings.json",
        json.dumps(
            {
                "note": "wall-clock seconds of this run; they vary from run to run (results.json does not)",
                "stages_s": {k: float(v) for k, v in (timings or {}).items()},
                "design_studies_s": {k: float(v) for k, v in studies_timings.items()},
            },
            indent=2,
        ),
    )
    if studies is not None:
        save_study_data(studies, folder / "studies")
    figures_done()
    return write_report(folder, plan.title, plan.sections, design_name=plan.design_name, generated=generated)


def _damping_text(internal_damping: str) -> str:
    """How the shaft's internal loss acts, in words (the report says which model it used)."""
    if internal_damping == "rotating":
        return (
            'acts in the rotating frame (internal_damping = "rotating"): it does not damp synchronous forward '
            "whirl and drives forward whirl above its natural frequency unstable"
        )
    return (
        'acts as a fixed-frame complex stiffness (internal_damping = "thesis", thesis eqs. 2.39-2.40): it '
        "damps every whirl and never destabilises"
    )


def _waves(n) -> str:
    """The buckling mode's circumferential wave number, "n = ∞ (shear crimping)" for none."""
    return "n = ∞ (shear crimping)" if n is None else f"n = {n}"

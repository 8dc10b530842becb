"""Assemble the ``flexshaft run`` report from a :class:`flexshaft.studies.run.RunResults`.

Duck-typed on the results' plain attributes (arrays, dicts, small dataclasses); converts SI to
engineering units (rpm, Hz, mm) only here, at the edge. The report computes nothing: every
number and curve comes from the results (bearing reactions included).

Writing is in two steps: :func:`plan_run_report` builds the sections and a list of
:class:`~flexshaft.plot.output.FigureJob` (figure functions and their plain-array arguments,
or a result and its ``.plot`` kind), then :func:`write_run_report` renders the figures
(serially, or in forked worker processes) and writes the page.
"""

from __future__ import annotations

import datetime as dt
import json
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from flexshaft.plot.output import FigureJob, render_figures, start_figures
from flexshaft.report.html import FigureRef, Section, Table, write_report
from flexshaft.units import kelvin_to_celsius

__all__ = ["RunReportPlan", "json_ready", "plan_run_report", "results_json", "write_run_report"]

_RPM = 60 / (2 * np.pi)


def _bearing_dict(res) -> dict | None:
    """Static lateral and axial force and the imbalance force amplitude at the operating speed
    (from ``res.bearing_reactions``, computed by the run)."""
    reactions = getattr(res, "bearing_reactions", None)
    if not reactions:
        return None
    return {
        name: {
            "static_lateral_N": r.static_lateral,
            "static_axial_N": r.static_axial,
            "imbalance_lateral_amplitude_N": r.imbalance_lateral_amplitude,
        }
        for name, r in reactions.items()
    }


def _strength_dict(r) -> dict | None:
    if r is None:
        return None
    return {
        "safety_factor": r.safety_factor,
        "x_m": r.x,
        "element": r.element,
        "ply": r.ply + 1,
        "ply_angle_deg": r.ply_angle_deg,
        "phase_deg": r.phase_deg,
        "bending_sign": r.bending_sign,
        "dominant_stress": r.dominant_stress,
        "sigma1_Pa": r.stresses[0],
        "sigma2_Pa": r.stresses[1],
        "tau12_Pa": r.stresses[2],
    }


def results_json(res) -> dict:
    """The key numbers of a run, JSON-ready: SI units, each unit in its key (``_m``, ``_N``,
    ``_Pa``, ``_Hz``; speeds ``_rpm``, temperatures ``_c`` [°C]), non-finite numbers as None.

    Nothing here depends on when or how fast the run went (no timestamp, no timings: those go
    to ``timings.json``), so two runs of one design give byte-identical ``results.json``.
    """
    model = res.model
    dm = model.dofs
    qs = res.static_displacement
    camp = res.campbell
    op = model.speed
    i_op = int(np.argmin(np.abs(res.speeds - op)))
    studies = _studies_json(res)
    if studies is not None:
        studies = {k: v for k, v in studies.items() if k not in ("elapsed_s", "timings_s")}
    return json_ready(
        {
            "design": res.summary["name"],
            "verdict": res.verdict.to_dict() if res.verdict is not None else None,
            "summary": res.summary,
            "modes_at_rest": res.modes_at_rest,
            "modes_at_operating_speed": res.modes_at_speed,
            "critical_speeds": [
                {"speed_rpm": c.speed_rpm, "tracked_mode": c.mode + 1, "harmonic": c.harmonic, "whirl": c.whirl}
                for c in camp.critical_speeds
            ],
            "imbalance": {
                # the spin-up proper (to the operating speed, peaks refined): the verdict's number
                **_spinup_peak(res),
                "max_shaft_orbit_scan_m": float(res.shaft_peak.max()),
                "speed_of_max_scan_rpm": float(res.speeds[np.argmax(res.shaft_peak)] * _RPM),
                "max_shaft_orbit_at_operating_m": float(res.shaft_peak[i_op]),
                "actuator_max_displacement_m": {k: float(v.max()) for k, v in res.actuator_displacement.items()},
                "actuator_max_force_N": {k: float(v.max()) for k, v in res.actuator_force.items()},
            },
            "static": {
                "boom_tip_v_m": float(qs[dm.boom(-1, "v")]) if dm.n_boom_nodes else None,
                "boom_tip_w_m": float(qs[dm.boom(-1, "w")]) if dm.n_boom_nodes else None,
                "max_shaft_deflection_m": float(
                    np.max(np.hypot(dm.values(qs, "shaft", "v"), dm.values(qs, "shaft", "w")))
                ),
            },
            "bearings": _bearing_dict(res),
            "strength_static": _strength_dict(res.strength_static),
            "strength_static_plus_imbalance": _strength_dict(res.strength_total),
            "buckling": res.buckling,
            "stability": _stability_dict(res),
            "thermal": _thermal_dict(res),
            "design_studies": studies,
            "notes": res.notes,
        }
    )


def _spinup_peak(res) -> dict:
    """Peak shaft orbit of the spin-up to the operating speed and its speed: the verdict's
    ``spinup_deflection`` check (refined between the sampled speeds) when it was evaluated,
    else the largest sampled value up to the operating speed."""
    check = next((c for c in res.verdict.checks if c.key == "spinup_deflection"), None) if res.verdict else None
    if check is not None and check.value is not None and "speed" in check.location:
        return {
            "max_shaft_orbit_spin_up_m": float(check.value),
            "speed_of_max_rpm": float(check.location["speed"]) * _RPM,
        }
    up = np.flatnonzero(res.speeds <= res.model.speed * (1 + 1e-9))
    up = up if up.size else np.arange(res.speeds.size)
    k = up[int(np.argmax(res.shaft_peak[up]))]
    return {"max_shaft_orbit_spin_up_m": float(res.shaft_peak[k]), "speed_of_max_rpm": float(res.speeds[k] * _RPM)}


def json_ready(value):
    """Plain JSON data of ``results_json``: numpy scalars/arrays as Python, tuples as lists,
    NaN and infinities as None (strict JSON has neither)."""
    if isinstance(value, dict):
        return {str(k): json_ready(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_ready(v) for v in value]
    if value is None or isinstance(value, (bool, str, int)):
        return value
    if isinstance(value, float):
        return value if np.isfinite(value) else None
    if hasattr(value, "tolist"):
        return json_ready(value.tolist())
    return json_ready(float(value))


def _modes_table(rows, caption) -> Table:
    return Table(
        caption,
        ["mode", "frequency [Hz]", "[rpm]", "damping ratio", "whirl", "component"],
        [
            [r["mode"], r["frequency_Hz"], r["frequency_rpm"], r["damping_ratio"], r["whirl"], r["component"]]
            for r in rows
        ],
    )


def plot_result(result, kind: str | None = None, **kwargs):
    """``result.plot(kind, **kwargs)``: a picklable figure function for :class:`FigureJob`."""
    return result.plot(kind, **kwargs)


@dataclass(frozen=True)
class RunReportPlan:
    """The report's sections (figures referenced by their future PNG paths), the figures to
    draw, and the key numbers (``results.json``)."""

    sections: list
    jobs: list
    data: dict
    title: str
    design_name: str


class _Figures:
    """Collects figure jobs and hands out their :class:`FigureRef`."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self.jobs: list[FigureJob] = []

    def add(self, stem: str, caption: str, function, *args, **kwargs) -> FigureRef:
        self.jobs.append(FigureJob(stem, function, args, kwargs))
        return FigureRef(self.folder / f"{stem}.png", caption)

    def result(self, stem: str, caption: str, result, kind: str | None = None, **kwargs) -> FigureRef:
        return self.add(stem, caption, plot_result, result, kind, **kwargs)


def plan_run_report(
    res, folder: str | Path, design_text: str | None = None, design_source: str = "design file"
) -> RunReportPlan:
    """Sections, figure jobs and key numbers of the report of ``res`` (nothing is drawn or
    written; see :func:`write_run_report`)."""
    from flexshaft.plot.driveline import deflected_shape_figure
    from flexshaft.report.inputs import inputs_section, report_title
    from flexshaft.report.verdict import verdict_section

    folder = Path(folder)
    figs = _Figures(folder)
    model = res.model
    dm = model.dofs
    design = model.design
    data = results_json(res)
    op_rpm = model.speed * _RPM
    s = res.summary
    sections = []
    if res.verdict is not None:
        section = verdict_section(res.verdict, op_rpm)
        ref = figs.result(
            "verdict_margins",
            "Margin of each requirement divided by its limit (green pass, red fail)",
            res.verdict,
            "margins",
        )
        sections.append(replace(section, figures=[*section.figures, ref]))
    if design_text is None:
        from flexshaft.design import baseline_design, baseline_text

        if design == baseline_design():
            design_text, design_source = baseline_text(), "embedded thesis baseline"
    sections.append(inputs_section(design, design_text, design_source))

    bearings = [
        [b.name, b.kind, b.x_shaft, b.x_boom if b.x_boom is not None else "ground", b.offset] for b in model.bearings
    ]
    sections.append(
        Section(
            "Design summary",
            paragraphs=[
                f"{design.name}. Shaft {design.shaft.x_start:g}–{design.shaft.x_end:g} m, "
                f"D_o = {design.shaft.outer_diameter * 1e3:.1f} mm, wall {design.shaft.wall_thickness * 1e3:.2f} mm, "
                f"layup {design.shaft.layup or 'isotropic'}; {op_rpm:.0f} rpm, {model.power / 1e3:.0f} kW."
            ],
            tables=[
                Table(
                    "Key numbers",
                    ["quantity", "value"],
                    [
                        ["shaft mass [kg]", s["shaft_mass_kg"]],
                        ["total mass (shaft, boom, end mass) [kg]", s["total_mass_kg"]],
                        [
                            "E* storage [GPa] / loss factor",
                            f"{s['shaft_E_storage_Pa'] / 1e9:.3f} / {s['shaft_E_loss_factor']:.4f}",
                        ],
                        [
                            "G* storage [GPa] / loss factor",
                            f"{s['shaft_G_storage_Pa'] / 1e9:.3f} / {s['shaft_G_loss_factor']:.4f}",
                        ],
                        ["torque [N m]", s["torque_Nm"]],
                        ["free DOFs", s["free_dofs"]],
                    ],
                ),
                Table("Bearings", ["name", "kind", "x shaft [m]", "x boom [m]", "offset h [m]"], bearings),
            ],
        )
    )

    camp = res.campbell
    crit = [c for c in camp.critical_speeds if c.speed <= model.speed * 1.25]
    main_rotor = model.design.operating.main_rotor_frequencies() if model.design is not None else {}
    bearing_x = [b.x_shaft for b in model.bearings]
    f_spin = op_rpm / 60.0
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
                _modes_table(res.modes_at_rest, "Natural frequencies at rest"),
                _modes_table(res.modes_at_speed, f"Natural frequencies at {op_rpm:.0f} rpm"),
                Table(
                    "Critical speeds (1× excitation) up to 125 % of the operating speed",
                    ["speed [rpm]", "tracked mode", "whirl"],
                    [[c.speed_rpm, c.mode + 1, c.whirl] for c in crit],
                ),
            ],
            figures=[
                figs.result(
                    "campbell",
                    "Campbell diagram: whirl as line style and marker, log decrement as colour"
                    + (
                        "; the main rotor's 1/rev and N/rev lines (geared to the shaft) for the boom modes"
                        if main_rotor
                        else ""
                    ),
                    camp,
                    "campbell",
                    operating_rpm=op_rpm,
                    max_critical_rpm=1.25 * op_rpm,
                    main_rotor_hz=main_rotor or None,
                ),
                figs.result(
                    "mode_shapes",
                    f"Mode shapes at {op_rpm:.0f} rpm of the modes nearest the spin frequency "
                    f"{f_spin:.1f} Hz (v vertical, w lateral; ▲ bearings)",
                    res.mode_shapes,
                    "shapes",
                    bearings_x=bearing_x,
                ),
            ],
        )
    )

    sections.append(_imbalance_section(res, figs, data, op_rpm))

    qs = res.static_displacement
    st = data["static"]
    deflection = figs.add(
        "static_deflection",
        "Static deflection of shaft and tailboom",
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
                    f" Boom tip: v = {st['boom_tip_v_m'] * 1e3:.2f} mm, w = {st['boom_tip_w_m'] * 1e3:.2f} mm."
                    if st["boom_tip_v_m"] is not None
                    else ""
                )
            ],
            figures=[deflection],
        )
    )

    if res.strength_total is not None:
        rows = []
        for name, rr in (("static", res.strength_static), ("static + imbalance", res.strength_total)):
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
        b = res.buckling
        sections.append(
            Section(
                "Strength and torsional buckling",
                paragraphs=[
                    "Tsai-Wu safety factor of every ply at both ends of every shaft element, for the static response "
                    "superposed with the imbalance response at the operating speed over the phase φ ∈ [0, 2π) and "
                    "both signs of the bending strain.",
                    f"Torsional buckling ({b['theory']} shell, simply supported, both torque senses): "
                    f"T_cr = {b['critical_torque_positive_Nm']:.0f} N m (positive, n = {b['wave_number_positive']}), "
                    f"{b['critical_torque_negative_Nm']:.0f} N m (negative, n = {b['wave_number_negative']}); "
                    f"applied {b['torque_Nm']:.0f} N m; buckling safety factor {b['safety_factor']:.2f}. "
                    "The classical shell ignores transverse shear of the soft matrix and is unconservative for FMC walls.",
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
                        "Minimum Tsai-Wu safety factor along the shaft",
                        res.strength_total,
                        "along_shaft",
                    )
                ],
            )
        )
    if res.thermal is not None:
        sections.append(_thermal_section(res, figs))
    if res.stability is not None:
        sections.append(_stability_section(res, figs, op_rpm))
    if res.design_studies is not None:
        from flexshaft.report.studies_section import studies_section_and_jobs

        section, jobs = studies_section_and_jobs(res.design_studies, folder)
        figs.jobs.extend(jobs)
        sections.append(section)
    if res.notes:
        sections.append(Section("Notes", paragraphs=list(res.notes)))
    return RunReportPlan(sections, figs.jobs, data, f"flexshaft report: {report_title(design)}", design.name)


def _imbalance_section(res, figs: _Figures, data: dict, op_rpm: float) -> Section:
    from flexshaft.plot.driveline import actuator_figure, bode_figure, imbalance_response_figure, orbit_figure

    model = res.model
    dm = model.dofs
    design = model.design
    rpm = res.speeds * _RPM
    gaps = {b.name: getattr(b, "gap", None) for b in design.bearings}
    act_gaps = [g for a in model.actuators if (g := gaps.get(a.name)) is not None]
    amps = {"max over shaft": res.shaft_peak}
    amps.update(
        {f"shaft at {a.name}": res.shaft_envelope[dm.node_at("shaft", a.link.x_shaft)] for a in model.actuators}
    )
    figures = [
        figs.add(
            "imbalance_response",
            "Synchronous imbalance response during spin-up (orbit major semi-axis)",
            imbalance_response_figure,
            rpm,
            amps,
            op_rpm,
            log_y=True,
        )
    ]
    q = getattr(res, "imbalance_spinup", None)
    if q is not None and np.ndim(q) == 3 and q.shape[2] == rpm.size:
        i_op = int(np.argmin(np.abs(res.speeds - model.speed)))
        stations = {
            f"{a.name} (x = {a.link.x_shaft:.2f} m)": dm.node_at("shaft", a.link.x_shaft) for a in model.actuators
        }
        peak = int(np.argmax(res.shaft_envelope[:, i_op]))
        stations.setdefault(f"largest orbit at {op_rpm:.0f} rpm (x = {dm.shaft_x[peak]:.2f} m)", peak)
        curves = {}
        for label, node in stations.items():
            v = np.asarray(q[dm.shaft(node, "v")])  # (ncases, n_speeds)
            case = int(np.argmax(np.abs(v[:, i_op])))
            curves[f"{label}, v" + (f", case {case + 1}" if v.shape[0] > 1 else "")] = v[case]
        figures.append(
            figs.add(
                "imbalance_bode",
                "Bode plot of the vertical imbalance response (phase relative to the imbalance force)",
                bode_figure,
                rpm,
                curves,
                op_rpm,
                min(act_gaps) if act_gaps else None,
                title="Imbalance response at the actuators (Bode)",
            )
        )
    reactions = getattr(res, "bearing_reactions", None) or {}
    if reactions:
        orbits = {f"{name} (x = {r.x_shaft:.2f} m)": r.orbit for name, r in reactions.items()}
        orbit_gaps = {f"{name} (x = {r.x_shaft:.2f} m)": r.gap for name, r in reactions.items() if r.gap is not None}
        figures.append(
            figs.add(
                "bearing_orbits",
                f"Shaft orbits relative to each bearing at {op_rpm:.0f} rpm (worst load "
                "case; dashed: auxiliary-bearing gap; viewed along +x, forward whirl "
                "clockwise)",
                orbit_figure,
                orbits,
                orbit_gaps,
                title=f"Orbits at the bearings, {op_rpm:.0f} rpm",
            )
        )
    if model.actuators:
        caps = [c for a in design.bearings if (c := getattr(a, "force_capacity", None)) is not None]
        figures.append(
            figs.add(
                "actuators",
                "Actuator relative displacement and force during spin-up",
                actuator_figure,
                rpm,
                res.actuator_displacement,
                res.actuator_force,
                min(act_gaps) if act_gaps else None,
                operating_rpm=op_rpm,
                force_capacity=min(caps) if caps else None,
            )
        )
    imb = data["imbalance"]
    tables = [
        Table(
            "Actuators (spin-up maxima)",
            ["actuator", "max relative displacement [mm]", "max force [N]"],
            [
                [k, imb["actuator_max_displacement_m"][k] * 1e3, imb["actuator_max_force_N"][k]]
                for k in res.actuator_force
            ],
        )
    ]
    if reactions:
        tables.append(
            Table(
                f"Bearing loads: static, and imbalance at {op_rpm:.0f} rpm (worst load case)",
                [
                    "bearing",
                    "kind",
                    "x shaft [m]",
                    "static lateral [N]",
                    "static axial [N]",
                    "imbalance force amplitude [N]",
                    "relative orbit [mm]",
                    "gap [mm]",
                ],
                [
                    [
                        n,
                        r.kind,
                        r.x_shaft,
                        r.static_lateral,
                        r.static_axial,
                        r.imbalance_lateral_amplitude,
                        _orbit_mm(r.orbit),
                        None if r.gap is None else r.gap * 1e3,
                    ]
                    for n, r in reactions.items()
                ],
            )
        )
    return Section(
        "Imbalance response over speed",
        paragraphs=[
            f"Rotating imbalance e_c m_s Ω² ({design.loads.imbalance_placement} placement), "
            f"steady state at each speed from 2 % to 130 % of the operating speed. Peak shaft orbit of "
            f"the spin-up to the operating speed {imb['max_shaft_orbit_spin_up_m'] * 1e3:.3f} mm at "
            f"{imb['speed_of_max_rpm']:.0f} rpm (refined between the sampled speeds); "
            f"{imb['max_shaft_orbit_at_operating_m'] * 1e3:.4f} mm at the operating speed; "
            f"largest over the whole scan {imb['max_shaft_orbit_scan_m'] * 1e3:.3f} mm at "
            f"{imb['speed_of_max_scan_rpm']:.0f} rpm."
        ],
        tables=tables,
        figures=figures,
    )


def _orbit_mm(pair) -> float:
    """Major semi-axis of the orbit of a (v, w) amplitude pair [m], in mm."""
    v, w = pair
    return float(np.sqrt(0.5 * (abs(v) ** 2 + abs(w) ** 2 + abs(v * v + w * w)))) * 1e3


def write_run_report(
    res,
    folder: str | Path,
    generated: dt.datetime | dt.date | None = None,
    design_text: str | None = None,
    design_source: str = "design file",
    timings: dict | None = None,
    *,
    svg: bool = False,
    processes: int = 1,
    executor=None,
) -> Path:
    """Write ``report.html``, the PNG figures (and SVG when ``svg``), ``results.json`` and
    ``timings.json`` into ``folder``; returns the page's path.

    ``design_text`` is the design file as read (embedded verbatim, with its assumed values
    listed); ``design_source`` says where it came from. The verdict comes first. ``timings``
    (stage -> seconds, e.g. from the CLI's progress display) go to ``timings.json`` with the
    design studies' own, never to ``results.json``. ``processes`` > 1 draws the figures in
    that many forked worker processes; an ``executor`` (e.g.
    :func:`flexshaft.parallel.pool.worker_pool`) draws them in its workers while the data files are
    written here.
    """
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    plan = plan_run_report(res, folder, design_text, design_source)
    if executor is not None:
        figures_done = start_figures(plan.jobs, folder, executor, svg=svg)
    else:

        def figures_done():
            return render_figures(plan.jobs, folder, svg=svg, processes=processes)

    (folder / "results.json").write_text(json.dumps(json_ready(plan.data), indent=2, allow_nan=False))
    studies_timings = getattr(res.design_studies, "timings", None) or {}
    (folder / "timings.json").write_text(
        json.dumps(
            {
                "note": "wall-clock seconds of this run; they vary from run to run (results.json does not)",
                "stages_s": {k: float(v) for k, v in (timings or {}).items()},
                "design_studies_s": {k: float(v) for k, v in studies_timings.items()},
            },
            indent=2,
        )
    )
    if res.design_studies is not None:
        from flexshaft.studies.chapter3 import save_study_data

        save_study_data(res.design_studies, folder / "studies")
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


def _rpm_or_none(speed):
    return None if speed is None or not np.isfinite(speed) else float(speed * _RPM)


def _stability_dict(res) -> dict | None:
    if res.stability is None:
        return None
    st = res.stability
    out = {
        "damping_model": st.damping_model,
        "onset_speed_rpm": _rpm_or_none(st.onset_speed),
        "analysed_to_rpm": float(st.speeds[-1] * _RPM),
        "unstable_mode_whirl": None if st.unstable_mode is None else str(st.whirl[-1, st.unstable_mode]),
        "thesis_shafts": {
            label: {m: _rpm_or_none(r.onset_speed) for m, r in models.items()}
            for label, models in res.shaft_comparison.items()
        },
    }
    if res.gain_map is not None:
        g = res.gain_map
        out["gain_map"] = {
            "kp_N_per_m": g.kp.tolist(),
            "kd_N_s_per_m": g.kd.tolist(),
            "onset_speed_rpm": [[_rpm_or_none(v) for v in row] for row in g.onset_speed],
            "min_damping_ratio_at_operating": g.margin_at_operating.tolist(),
        }
    return out


def _onset_text(speed, top):
    return f"stable to {top * _RPM:.0f}" if speed is None or not np.isfinite(speed) else f"{speed * _RPM:.0f}"


def _stability_section(res, figs: _Figures, op_rpm: float) -> Section:
    from flexshaft.plot.stability import log_decrement_figure, stability_map_figure

    st = res.stability
    top = st.speeds[-1]
    figures = []
    curves = {"this design (exact hysteretic loss)": st.log_decrements}
    onsets = {"this design (exact hysteretic loss)": _rpm_or_none(st.onset_speed)}
    texts = {"this design (exact hysteretic loss)": st.onset_description()}
    whirl = {"this design (exact hysteretic loss)": st.whirl}
    same_speeds = True
    for label, models in res.shaft_comparison.items():
        r = models["viscous"]
        same_speeds &= r.speeds.shape == st.speeds.shape and bool(np.allclose(r.speeds, st.speeds))
        name = f"{label} (viscous equivalent)"
        curves[name], onsets[name], texts[name], whirl[name] = (
            r.log_decrements,
            _rpm_or_none(r.onset_speed),
            r.onset_description(),
            r.whirl,
        )
    if not same_speeds:  # the comparison was run on other speeds: draw the design alone
        curves, onsets, texts, whirl = ({k: v[k] for k in list(v)[:1]} for v in (curves, onsets, texts, whirl))
    requirements = getattr(res.model.design, "requirements", None)
    required = requirements.required_log_decrement if requirements is not None else None
    figures.append(
        figs.add(
            "stability_log_decrement",
            "Log decrement of the tracked modes against speed, the onset of "
            "whirl instability marked ✕ (the thesis's three reference shafts "
            "with the viscous-equivalent internal damping, figures 4.2-4.4)",
            log_decrement_figure,
            st.speeds * _RPM,
            curves,
            onsets,
            op_rpm,
            onset_text={k: v for k, v in texts.items() if v},
            whirl=whirl,
            required=required,
        )
    )
    tables = []
    rows = [["this design", _onset_text(st.onset_speed, top), "—"]]
    rows += [
        [label, _onset_text(m["viscous"].onset_speed, top), _onset_text(m["hysteretic"].onset_speed, top)]
        for label, m in res.shaft_comparison.items()
    ]
    tables.append(
        Table("Onset speed of whirl instability [rpm]", ["shaft", "viscous equivalent", "exact hysteretic"], rows)
    )
    if res.gain_map is not None:
        g = res.gain_map
        onset = {f"K_p = {kp:.3g} N/m": g.onset_speed[i] * _RPM for i, kp in enumerate(g.kp)}
        figures.append(
            figs.add(
                "stability_map",
                "Onset speed against the actuator gains",
                stability_map_figure,
                g.kd,
                onset,
                op_rpm,
                g.max_speed * _RPM,
            )
        )
        tables.append(
            Table(
                "Smallest damping ratio at the operating speed",
                ["K_p [N/m]", *[f"K_d = {kd:g}" for kd in g.kd]],
                [[kp, *g.margin_at_operating[i]] for i, kp in enumerate(g.kp)],
            )
        )
    return Section(
        "Whirl stability",
        paragraphs=[
            "The composite's hysteretic loss acts in the rotating frame: as an equivalent viscous damping "
            "C_i = Im(K_shaft)/ω_ref it adds C_i and the circulatory stiffness Ω C_i S in the fixed frame "
            "(Zorzi & Nelson 1977), destabilising forward whirl above its natural frequency unless external "
            "damping (actuator K_d, boom structural damping) outweighs it. ω_ref is the first shaft natural "
            "frequency for the viscous model; the exact hysteretic model iterates each mode to its own "
            "relative whirl frequency |ω − Ω|."
        ],
        tables=tables,
        figures=figures,
    )


def _thermal_dict(res) -> dict | None:
    th = res.thermal
    if th is None:
        return None
    out = {"tailboom_c": {k: v.celsius for k, v in th.tailboom.items()}, "report_loss_model": th.loss_model}
    for lm, s in th.shaft.items():
        out[f"shaft_{lm}"] = {
            "peak_rise_K": s.peak_rise,
            "heat_W": float(s.sources.total.sum()),
            "air_c": kelvin_to_celsius(s.temperature.air_temperature),
        }
    sh = th.self_heating
    if sh is not None:
        out["self_heating"] = {"status": sh.status, "iterations": sh.iterations, "margin_K": sh.margin}
    return out


def _thermal_section(res, figs: _Figures) -> Section:
    from flexshaft.plot.thermal import shaft_temperature_figure, temperature_profiles_figure

    th = res.thermal
    env = th.environment
    shafts = th.shaft
    first = next(iter(shafts.values()))
    x = first.temperature.x
    xe = 0.5 * (x[:-1] + x[1:])
    rise = {f"{lm} loss model": s.temperature.temperature - s.temperature.air_temperature for lm, s in shafts.items()}
    heat = {f"{lm} loss model": s.sources.total / np.diff(x) for lm, s in shafts.items()}
    tables = []
    if th.tailboom:
        tables.append(
            Table(
                "Tailboom skin temperature (thesis: 44 °C hovering, 89 °C parked)",
                ["condition", "temperature [°C]", "h [W/m² K]", "correlation"],
                [[k, v.celsius, v.heat_transfer_coefficient, v.nusselt.method] for k, v in th.tailboom.items()],
            )
        )
    rows = [
        [
            lm,
            kelvin_to_celsius(s.temperature.air_temperature),
            s.temperature.heat_transfer_coefficient,
            float(s.sources.vibration.sum()),
            float(s.sources.static.sum()),
            s.peak_rise,
        ]
        for lm, s in shafts.items()
    ]
    tables.append(
        Table(
            "Shaft self-heating at the operating speed",
            ["loss model", "air [°C]", "h [W/m² K]", "vibration heat [W]", "static heat [W]", "peak rise [K]"],
            rows,
        )
    )
    paragraphs = [
        f"Ambient {kelvin_to_celsius(env.ambient_temperature):.1f} °C; the shaft's air and ends are at the boom's hover temperature. "
        "Heat is the hysteretic loss P = (ω/2)·Re(Xᴴ K'' X) of the imbalance response and of the static deflection "
        "seen by the rotating material. The thesis model cycles every response at Ω in the fixed frame; the "
        "rotating-frame model (used for the self-heating check) knows that synchronous forward whirl does not cycle "
        "the material, backward whirl is cycled at 2Ω and the static deflection at Ω."
    ]
    sh = th.self_heating
    if sh is not None:
        paragraphs.append(
            f"Self-heating with temperature-dependent matrix properties: {sh.status} after "
            f"{sh.iterations} iterations; margin to the allowable temperature {sh.margin:.1f} K."
        )
    figures = [
        figs.add(
            "shaft_temperature",
            "Shaft temperature rise and heat generation along the shaft",
            shaft_temperature_figure,
            x,
            rise,
            xe,
            heat,
        )
    ]
    prof = th.profiles
    if prof:
        figures.append(
            figs.add(
                "shaft_temperature_sweeps",
                f"Shaft temperature profiles against wall thickness and "
                f"convection ({th.loss_model} loss model; thesis figures "
                "3.18, 3.19)",
                temperature_profiles_figure,
                prof.x,
                prof.by_wall,
                prof.by_h,
            )
        )
    return Section("Thermal", paragraphs=paragraphs, tables=tables, figures=figures)


def _studies_json(res):
    if res.design_studies is None:
        return None
    from flexshaft.studies.chapter3 import headline

    return headline(res.design_studies)

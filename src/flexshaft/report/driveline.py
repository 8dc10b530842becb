"""Assemble the ``flexshaft run`` report from a :class:`flexshaft.studies.run.RunResults`.

Duck-typed on the results' plain attributes (arrays, dicts, small dataclasses); converts SI to
engineering units (rpm, Hz, mm) only here, at the edge.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from flexshaft.plot.driveline import (
    actuator_figure,
    campbell_figure,
    deflected_shape_figure,
    imbalance_response_figure,
    mode_shapes_figure,
    safety_factor_figure,
    save_figure,
)
from flexshaft.report.html import FigureRef, Section, Table, write_report

__all__ = ["results_json", "write_run_report"]

_RPM = 60 / (2 * np.pi)


def _bearing_dict(res) -> dict:
    """Static lateral and axial force and the imbalance force amplitude at the operating speed."""
    from flexshaft.analyses.response import bearing_forces, orbit_amplitude

    model = res.model
    loads = None
    if any(a.integrates for a in model.actuators):  # integral action: static force from equilibrium
        from flexshaft.assembly.loads import external_static_load, torque_load

        loads = external_static_load(model) + torque_load(model)
    static = bearing_forces(model, res.static_displacement, loads=loads)
    dynamic = bearing_forces(model, res.imbalance_at_speed, model.speed)
    out = {}
    for name, f in static.items():
        d = dynamic[name]
        out[name] = {
            "static_lateral_N": float(np.hypot(f[1].real, f[2].real)),
            "static_axial_N": float(abs(f[0].real)),
            "imbalance_lateral_amplitude_N": float(np.max(orbit_amplitude(d[1], d[2]))),
        }
    return out


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
    return _json_ready({
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
            "max_shaft_orbit_spin_up_m": float(res.shaft_peak.max()),
            "speed_of_max_rpm": float(res.speeds[np.argmax(res.shaft_peak)] * _RPM),
            "max_shaft_orbit_at_operating_m": float(res.shaft_peak[i_op]),
            "actuator_max_displacement_m": {k: float(v.max()) for k, v in res.actuator_displacement.items()},
            "actuator_max_force_N": {k: float(v.max()) for k, v in res.actuator_force.items()},
        },
        "static": {
            "boom_tip_v_m": float(qs[dm.boom(-1, "v")]) if dm.n_boom_nodes else None,
            "boom_tip_w_m": float(qs[dm.boom(-1, "w")]) if dm.n_boom_nodes else None,
            "max_shaft_deflection_m": float(np.max(np.hypot(dm.values(qs, "shaft", "v"), dm.values(qs, "shaft", "w")))),
        },
        "bearings": _bearing_dict(res),
        "strength_static": _strength_dict(res.strength_static),
        "strength_static_plus_imbalance": _strength_dict(res.strength_total),
        "buckling": res.buckling,
        "stability": _stability_dict(res),
        "thermal": _thermal_dict(res),
        "design_studies": studies,
        "notes": res.notes,
    })


def _json_ready(value):
    """Plain JSON data of ``results_json``: numpy scalars/arrays as Python, tuples as lists,
    NaN and infinities as None (strict JSON has neither)."""
    if isinstance(value, dict):
        return {str(k): _json_ready(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_json_ready(v) for v in value]
    if value is None or isinstance(value, (bool, str, int)):
        return value
    if isinstance(value, float):
        return value if np.isfinite(value) else None
    if hasattr(value, "tolist"):
        return _json_ready(value.tolist())
    return _json_ready(float(value))


def _modes_table(rows, caption) -> Table:
    return Table(caption, ["mode", "frequency [Hz]", "[rpm]", "damping ratio", "whirl", "component"],
                 [[r["mode"], r["frequency_Hz"], r["frequency_rpm"], r["damping_ratio"], r["whirl"], r["component"]] for r in rows])


def write_run_report(res, folder: str | Path, generated: str | None = None, design_text: str | None = None,
                     design_source: str = "design file", timings: dict | None = None) -> Path:
    """Write ``report.html``, the figures (PNG and SVG), ``results.json`` and ``timings.json``
    into ``folder``.

    ``design_text`` is the design file as read (embedded verbatim, with its assumed values
    listed); ``design_source`` says where it came from. The verdict comes first. ``timings``
    (stage -> seconds, e.g. from the CLI's progress display) go to ``timings.json`` with the
    design studies' own, never to ``results.json``.
    """
    from flexshaft.report.inputs import inputs_section, report_title
    from flexshaft.report.verdict import verdict_section

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    model = res.model
    dm = model.dofs
    design = model.design
    data = results_json(res)
    (folder / "results.json").write_text(json.dumps(data, indent=2, default=float))
    studies_timings = getattr(res.design_studies, "timings", None) or {}
    (folder / "timings.json").write_text(json.dumps({
        "note": "wall-clock seconds of this run; they vary from run to run (results.json does not)",
        "stages_s": {k: float(v) for k, v in (timings or {}).items()},
        "design_studies_s": {k: float(v) for k, v in studies_timings.items()},
    }, indent=2))
    op_rpm = model.speed * _RPM
    s = res.summary
    sections = []
    if res.verdict is not None:
        sections.append(verdict_section(res.verdict, op_rpm))
    if design_text is None:
        from flexshaft.design import baseline_design, baseline_text

        if design == baseline_design():
            design_text, design_source = baseline_text(), "embedded thesis baseline"
    sections.append(inputs_section(design, design_text, design_source))

    bearings = [[b.name, b.kind, b.x_shaft, b.x_boom if b.x_boom is not None else "ground", b.offset] for b in model.bearings]
    sections.append(Section(
        "Design summary",
        paragraphs=[f"{design.name}. Shaft {design.shaft.x_start:g}–{design.shaft.x_end:g} m, "
                    f"D_o = {design.shaft.outer_diameter * 1e3:.1f} mm, wall {design.shaft.wall_thickness * 1e3:.2f} mm, "
                    f"layup {design.shaft.layup or 'isotropic'}; {op_rpm:.0f} rpm, {model.power / 1e3:.0f} kW."],
        tables=[
            Table("Key numbers", ["quantity", "value"], [
                ["shaft mass [kg]", s["shaft_mass_kg"]],
                ["total mass (shaft, boom, end mass) [kg]", s["total_mass_kg"]],
                ["E* storage [GPa] / loss factor", f"{s['shaft_E_storage_Pa'] / 1e9:.3f} / {s['shaft_E_loss_factor']:.4f}"],
                ["G* storage [GPa] / loss factor", f"{s['shaft_G_storage_Pa'] / 1e9:.3f} / {s['shaft_G_loss_factor']:.4f}"],
                ["torque [N m]", s["torque_Nm"]],
                ["free DOFs", s["free_dofs"]],
            ]),
            Table("Bearings", ["name", "kind", "x shaft [m]", "x boom [m]", "offset h [m]"], bearings),
        ],
    ))

    camp = res.campbell
    crit = [c for c in camp.critical_speeds if c.speed <= model.speed * 1.25]
    p_camp = save_figure(campbell_figure(camp.speeds * _RPM, camp.frequencies, camp.whirl,
                                         [c.speed_rpm for c in crit], op_rpm), folder, "campbell")
    shapes = res.mode_shapes
    ns = np.arange(dm.n_shaft_nodes)
    shaft_shapes, boom_shapes = [], []
    for k in range(min(6, shapes.shapes.shape[1])):
        phi = shapes.shapes[:, k]
        label = f"mode {k + 1}, {shapes.frequencies[k]:.2f} Hz, {shapes.whirl[k]}, {shapes.component[k]}"
        shaft_shapes.append({"label": label, "v": phi[dm.shaft(ns, "v")], "w": phi[dm.shaft(ns, "w")]})
        if dm.n_boom_nodes:
            nb = np.arange(dm.n_boom_nodes)
            boom_shapes.append({"v": phi[dm.boom(nb, "v")], "w": phi[dm.boom(nb, "w")]})
    p_shapes = save_figure(mode_shapes_figure(dm.shaft_x, shaft_shapes, dm.boom_x if dm.n_boom_nodes else None,
                                              boom_shapes or None), folder, "mode_shapes")
    sections.append(Section(
        "Natural frequencies and Campbell diagram",
        paragraphs=["Damped eigenvalues of the linear model (gyroscopic terms, bearing damping and actuator K_d; "
                    "the hysteretic loss is treated in the stability analysis). Modes are tracked across speed by "
                    "the modal assurance criterion; whirl direction comes from the shaft orbits (forward: same "
                    "sense as the spin)."],
        tables=[_modes_table(res.modes_at_rest, "Natural frequencies at rest"),
                _modes_table(res.modes_at_speed, f"Natural frequencies at {op_rpm:.0f} rpm"),
                Table("Critical speeds (1× excitation) up to 125 % of the operating speed",
                      ["speed [rpm]", "tracked mode", "whirl"], [[c.speed_rpm, c.mode + 1, c.whirl] for c in crit])],
        figures=[FigureRef(p_camp["png"], "Campbell diagram"), FigureRef(p_shapes["png"], f"Mode shapes at {op_rpm:.0f} rpm")],
    ))

    rpm = res.speeds * _RPM
    amps = {"max over shaft": res.shaft_peak}
    amps.update({f"shaft at {a.name}": res.shaft_envelope[dm.node_at("shaft", a.link.x_shaft)] for a in model.actuators})
    p_imb = save_figure(imbalance_response_figure(rpm, amps, op_rpm, log_y=True), folder, "imbalance_response")
    figs = [FigureRef(p_imb["png"], "Synchronous imbalance response during spin-up (orbit major semi-axis)")]
    if model.actuators:
        p_act = save_figure(actuator_figure(rpm, res.actuator_displacement, res.actuator_force, operating_rpm=op_rpm), folder, "actuators")
        figs.append(FigureRef(p_act["png"], "Actuator relative displacement and force during spin-up"))
    imb = data["imbalance"]
    sections.append(Section(
        "Imbalance response over speed",
        paragraphs=[f"Rotating imbalance e_c m_s Ω² ({design.loads.imbalance_placement} placement), "
                    f"steady state at each speed from 2 % to 110 % of the operating speed. Peak shaft orbit "
                    f"{imb['max_shaft_orbit_spin_up_m'] * 1e3:.3f} mm at {imb['speed_of_max_rpm']:.0f} rpm; "
                    f"{imb['max_shaft_orbit_at_operating_m'] * 1e3:.4f} mm at the operating speed."],
        tables=[Table("Actuators (spin-up maxima)", ["actuator", "max relative displacement [mm]", "max force [N]"],
                      [[k, imb["actuator_max_displacement_m"][k] * 1e3, imb["actuator_max_force_N"][k]] for k in res.actuator_force])],
        figures=figs,
    ))

    qs = res.static_displacement
    p_def = save_figure(deflected_shape_figure(
        dm.shaft_x, dm.values(qs, "shaft", "v"), dm.values(qs, "shaft", "w"),
        dm.boom_x if dm.n_boom_nodes else None,
        dm.values(qs, "boom", "v") if dm.n_boom_nodes else None,
        dm.values(qs, "boom", "w") if dm.n_boom_nodes else None,
        [b.x_shaft for b in model.bearings]), folder, "static_deflection")
    st = data["static"]
    sections.append(Section(
        "Deflected shape under static loads",
        paragraphs=["External point and line loads, the manoeuvre load factor on every mass and the transmitted torque."
                    + (f" Boom tip: v = {st['boom_tip_v_m'] * 1e3:.2f} mm, w = {st['boom_tip_w_m'] * 1e3:.2f} mm." if st["boom_tip_v_m"] is not None else "")],
        figures=[FigureRef(p_def["png"], "Static deflection of shaft and tailboom")],
    ))

    if res.strength_total is not None:
        r = res.strength_total
        label = f"ply {r.ply + 1} ({r.ply_angle_deg:+.0f}°), φ = {r.phase_deg:.0f}°, {r.dominant_stress} dominates"
        p_sf = save_figure(safety_factor_figure(r.x_along, r.along_shaft, r.x, label), folder, "safety_factor")
        rows = []
        for name, rr in (("static", res.strength_static), ("static + imbalance", res.strength_total)):
            rows.append([name, rr.safety_factor, rr.x, rr.ply + 1, rr.ply_angle_deg, rr.phase_deg, rr.dominant_stress,
                         rr.stresses[0] / 1e6, rr.stresses[1] / 1e6, rr.stresses[2] / 1e6])
        b = res.buckling
        sections.append(Section(
            "Strength and torsional buckling",
            paragraphs=["Tsai-Wu safety factor of every ply at both ends of every shaft element, for the static response "
                        "superposed with the imbalance response at the operating speed over the phase φ ∈ [0, 2π) and "
                        "both signs of the bending strain.",
                        f"Torsional buckling ({b['theory']} shell, simply supported, both torque senses): "
                        f"T_cr = {b['critical_torque_positive_Nm']:.0f} N m (positive, n = {b['wave_number_positive']}), "
                        f"{b['critical_torque_negative_Nm']:.0f} N m (negative, n = {b['wave_number_negative']}); "
                        f"applied {b['torque_Nm']:.0f} N m; buckling safety factor {b['safety_factor']:.2f}. "
                        "The classical shell ignores transverse shear of the soft matrix and is unconservative for FMC walls."],
            tables=[Table("Critical ply", ["case", "R", "x [m]", "ply", "angle [°]", "φ [°]", "dominant",
                                           "σ1 [MPa]", "σ2 [MPa]", "τ12 [MPa]"], rows)],
            figures=[FigureRef(p_sf["png"], "Minimum Tsai-Wu safety factor along the shaft")],
        ))
    if res.thermal is not None:
        sections.append(_thermal_section(res, folder))
    if res.stability is not None:
        sections.append(_stability_section(res, folder, op_rpm))
    if res.design_studies is not None:
        from flexshaft.report.studies_section import design_studies_section
        from flexshaft.studies.chapter3 import save_study_data

        save_study_data(res.design_studies, folder / "studies")
        sections.append(design_studies_section(res.design_studies, folder))
    if res.notes:
        sections.append(Section("Notes", paragraphs=list(res.notes)))
    return write_report(folder, f"flexshaft report: {report_title(design)}", sections, design_name=design.name,
                        generated=generated)


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
            label: {m: _rpm_or_none(r.onset_speed) for m, r in models.items()} for label, models in res.shaft_comparison.items()
        },
    }
    if res.gain_map is not None:
        g = res.gain_map
        out["gain_map"] = {"kp_N_per_m": g.kp.tolist(), "kd_N_s_per_m": g.kd.tolist(),
                           "onset_speed_rpm": [[_rpm_or_none(v) for v in row] for row in g.onset_speed],
                           "min_damping_ratio_at_operating": g.margin_at_operating.tolist()}
    return out


def _onset_text(speed, top):
    return f"stable to {top * _RPM:.0f}" if speed is None or not np.isfinite(speed) else f"{speed * _RPM:.0f}"


def _stability_section(res, folder, op_rpm) -> Section:
    from flexshaft.plot.stability import real_parts_figure, stability_map_figure

    st = res.stability
    top = st.speeds[-1]
    figs = []
    curves = {"this design": st.real_parts}
    curves.update({label: models["viscous"].real_parts for label, models in res.shaft_comparison.items()})
    p = save_figure(real_parts_figure(st.speeds * _RPM, curves, op_rpm), folder, "stability_real_parts")
    figs.append(FigureRef(p["png"], "Real parts of the eigenvalues against speed (viscous-equivalent internal damping; "
                                    "thesis figures 4.2-4.4 for the three reference shafts)"))
    tables = []
    rows = [["this design", _onset_text(st.onset_speed, top), "—"]]
    rows += [[label, _onset_text(m["viscous"].onset_speed, top), _onset_text(m["hysteretic"].onset_speed, top)]
             for label, m in res.shaft_comparison.items()]
    tables.append(Table("Onset speed of whirl instability [rpm]", ["shaft", "viscous equivalent", "exact hysteretic"], rows))
    if res.gain_map is not None:
        g = res.gain_map
        onset = {f"K_p = {kp:.3g} N/m": g.onset_speed[i] * _RPM for i, kp in enumerate(g.kp)}
        p = save_figure(stability_map_figure(g.kd, onset, op_rpm, g.max_speed * _RPM), folder, "stability_map")
        figs.append(FigureRef(p["png"], "Onset speed against the actuator gains"))
        tables.append(Table("Smallest damping ratio at the operating speed", ["K_p [N/m]", *[f"K_d = {kd:g}" for kd in g.kd]],
                            [[kp, *g.margin_at_operating[i]] for i, kp in enumerate(g.kp)]))
    return Section(
        "Whirl stability",
        paragraphs=["The composite's hysteretic loss acts in the rotating frame: as an equivalent viscous damping "
                    "C_i = Im(K_shaft)/ω_ref it adds C_i and the circulatory stiffness Ω C_i S in the fixed frame "
                    "(Zorzi & Nelson 1977), destabilising forward whirl above its natural frequency unless external "
                    "damping (actuator K_d, boom structural damping) outweighs it. ω_ref is the first shaft natural "
                    "frequency for the viscous model; the exact hysteretic model iterates each mode to its own "
                    "relative whirl frequency |ω − Ω|."],
        tables=tables,
        figures=figs,
    )


def _thermal_dict(res) -> dict | None:
    th = res.thermal
    if th is None:
        return None
    out = {"tailboom_c": {k: v.celsius for k, v in th["tailboom"].items()}, "report_loss_model": th["loss_model"]}
    for lm, s in th["shaft"].items():
        out[f"shaft_{lm}"] = {"peak_rise_K": s.peak_rise, "heat_W": float(s.sources.total.sum()),
                              "air_c": s.temperature.air_temperature - 273.15}
    sh = th["self_heating"]
    if sh is not None:
        out["self_heating"] = {"status": sh.status, "iterations": sh.iterations, "margin_K": sh.margin}
    return out


def _thermal_section(res, folder) -> Section:
    from flexshaft.plot.thermal import shaft_temperature_figure, temperature_profiles_figure

    th = res.thermal
    env = th["environment"]
    shafts = th["shaft"]
    first = next(iter(shafts.values()))
    x = first.temperature.x
    xe = 0.5 * (x[:-1] + x[1:])
    rise = {f"{lm} loss model": s.temperature.temperature - s.temperature.air_temperature for lm, s in shafts.items()}
    heat = {f"{lm} loss model": s.sources.total / np.diff(x) for lm, s in shafts.items()}
    p = save_figure(shaft_temperature_figure(x, rise, xe, heat), folder, "shaft_temperature")
    tables = []
    if th["tailboom"]:
        tables.append(Table("Tailboom skin temperature (thesis: 44 °C hovering, 89 °C parked)",
                            ["condition", "temperature [°C]", "h [W/m² K]", "correlation"],
                            [[k, v.celsius, v.heat_transfer_coefficient, v.nusselt.method] for k, v in th["tailboom"].items()]))
    rows = [[lm, s.temperature.air_temperature - 273.15, s.temperature.heat_transfer_coefficient,
             float(s.sources.vibration.sum()), float(s.sources.static.sum()), s.peak_rise] for lm, s in shafts.items()]
    tables.append(Table("Shaft self-heating at the operating speed",
                        ["loss model", "air [°C]", "h [W/m² K]", "vibration heat [W]", "static heat [W]", "peak rise [K]"], rows))
    paragraphs = [
        f"Ambient {env.ambient_temperature - 273.15:.1f} °C; the shaft's air and ends are at the boom's hover temperature. "
        "Heat is the hysteretic loss P = (ω/2)·Re(Xᴴ K'' X) of the imbalance response and of the static deflection "
        "seen by the rotating material. The thesis model cycles every response at Ω in the fixed frame; the "
        "rotating-frame model (used for the self-heating check) knows that synchronous forward whirl does not cycle "
        "the material, backward whirl is cycled at 2Ω and the static deflection at Ω.",
    ]
    sh = th["self_heating"]
    if sh is not None:
        paragraphs.append(f"Self-heating with temperature-dependent matrix properties: {sh.status} after "
                          f"{sh.iterations} iterations; margin to the allowable temperature {sh.margin:.1f} K.")
    figures = [FigureRef(p["png"], "Shaft temperature rise and heat generation along the shaft")]
    prof = th.get("profiles")
    if prof:
        pp = save_figure(temperature_profiles_figure(prof["x"], prof["by_wall"], prof["by_h"]), folder, "shaft_temperature_sweeps")
        figures.append(FigureRef(pp["png"], f"Shaft temperature profiles against wall thickness and convection "
                                            f"({th['loss_model']} loss model; thesis figures 3.18, 3.19)"))
    return Section("Thermal", paragraphs=paragraphs, tables=tables, figures=figures)


def _studies_json(res):
    if res.design_studies is None:
        return None
    from flexshaft.studies.chapter3 import headline

    return headline(res.design_studies)

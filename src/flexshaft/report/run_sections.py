"""Sections of the ``flexshaft run`` report on the spin-up response, whirl stability and thermal
results of an :class:`~flexshaft.verdict.assess.Assessment` (with the thesis studies beside them).

Each returns a :class:`~flexshaft.report.html.Section` and adds its figures' jobs to a
:class:`Figures`; SI is converted to rpm, mm and °C here, through :mod:`flexshaft.units`.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft.analyses.loop_margins import ISO_14839_ZONE_LIMITS
from flexshaft.plot.driveline import actuator_figure, bode_figure, imbalance_response_figure, orbit_figure
from flexshaft.plot.loops import loop_sensitivity_figure
from flexshaft.plot.output import FigureJob
from flexshaft.plot.response import orbit_amplitude_mm
from flexshaft.plot.stability import log_decrement_figure, stability_map_figure
from flexshaft.plot.thermal import shaft_temperature_check_figure, shaft_temperature_figure, temperature_profiles_figure
from flexshaft.report.html import FigureRef, Section, Table
from flexshaft.report.results_json import rpm_or_none
from flexshaft.report.verdict import every_root_onset
from flexshaft.thesis.report_studies import ThesisStudies
from flexshaft.units import format_quantity, kelvin_to_celsius, m_to_mm, rad_s_to_rpm
from flexshaft.verdict.assess import Assessment, check_point
from flexshaft.verdict.gather import WHIRL_DAMPING_SHAFT_SHARE, actuator_limits, judged_whirl_modes
from flexshaft.verdict.text import limit_text, location_text

__all__ = ["Figures", "imbalance_section", "loops_section", "plot_result", "stability_section", "thermal_section"]


def plot_result(result, kind: str | None = None, **kwargs):
    """``result.plot(kind, **kwargs)``: a picklable figure function for :class:`FigureJob`."""
    return result.plot(kind, **kwargs)


class Figures:
    """Collects figure jobs and hands out their :class:`FigureRef`."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self.jobs: list[FigureJob] = []

    def add(self, stem: str, caption: str, function, *args, **kwargs) -> FigureRef:
        self.jobs.append(FigureJob(stem, function, args, kwargs))
        return FigureRef(self.folder / f"{stem}.png", caption)

    def result(self, stem: str, caption: str, result, kind: str | None = None, **kwargs) -> FigureRef:
        return self.add(stem, caption, plot_result, result, kind, **kwargs)


def _speed_range_rpm(evidence) -> tuple[float, float] | None:
    """The point's operating speed range [rpm] (None: one operating speed)."""
    found = evidence.operating_range
    return None if found is None else (rad_s_to_rpm(found[0]), rad_s_to_rpm(found[1]))


def imbalance_section(a: Assessment, figs: Figures, data: dict, op_rpm: float) -> Section:
    """The spin-up response: figures of the orbits, Bode plot, bearing orbits and actuators,
    tables of the actuator peaks and bearing loads."""
    model = a.model
    dm = model.dofs
    design = model.design
    spinup = a.spinup
    rpm = rad_s_to_rpm(spinup.speeds)
    limits = actuator_limits(model)
    act_gaps = [gap for act in model.actuators if (gap := limits[act.name].gap) is not None]
    amps = {"max over shaft": spinup.shaft_peak}
    amps.update(
        {f"shaft at {act.name}": spinup.envelope[dm.node_at("shaft", act.link.x_shaft)] for act in model.actuators}
    )
    figures = [
        figs.add(
            "imbalance_response",
            "Synchronous imbalance response during spin-up (orbit major semi-axis"
            + (f", at the governing point {a.governing_point})" if len(a.points) > 1 else ")"),
            imbalance_response_figure,
            rpm,
            amps,
            op_rpm,
            log_y=True,
            speed_range_rpm=_speed_range_rpm(a.evidence),
        )
    ]
    q = spinup.response
    if np.ndim(q) == 3 and q.shape[2] == rpm.size:
        i_op = int(np.argmin(np.abs(spinup.speeds - model.speed)))
        stations = {
            f"{act.name} (x = {act.link.x_shaft:.2f} m)": dm.node_at("shaft", act.link.x_shaft)
            for act in model.actuators
        }
        peak = int(np.argmax(spinup.envelope[:, i_op]))
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
                title="Imbalance response at the actuators (Bode)"
                if model.actuators
                else "Imbalance response at the largest orbit (Bode)",
            )
        )
    reactions = a.bearing_reactions
    if reactions:
        orbits = {f"{name} (x = {r.x_shaft:.2f} m)": r.orbit for name, r in reactions.items()}
        orbit_gaps = {f"{name} (x = {r.x_shaft:.2f} m)": r.gap for name, r in reactions.items() if r.gap is not None}
        figures.append(
            figs.add(
                "bearing_orbits",
                f"Shaft orbits relative to each bearing at {op_rpm:.0f} rpm"
                + (f" at the governing point {a.governing_point}" if len(a.points) > 1 else "")
                + " (worst load case), each about the shaft's static position in the bearing (dotted: the "
                "static offset); dashed: auxiliary-bearing gap, and the share of it static offset + orbit take "
                "at this speed (the actuator-excursion check adds the static offset to the spin-up's peak orbit: "
                "the actuator figure); viewed along +x, forward whirl clockwise",
                orbit_figure,
                orbits,
                orbit_gaps,
                centres={f"{name} (x = {r.x_shaft:.2f} m)": r.static_position for name, r in reactions.items()},
                title=f"Orbits at the bearings, {op_rpm:.0f} rpm",
            )
        )
    if model.actuators:
        # the point where the actuator excursion check governs (its spin-up and evidence)
        name = check_point(a, "actuator_orbit")
        point = a.point(name)
        spinup_shown = point.analyses.spinup
        evidence = {e.name: e for e in point.evidence.actuators}
        shown = f" ({name}, where the excursion check governs)" if len(a.points) > 1 else ""
        figures.append(
            figs.add(
                "actuators",
                f"Actuator excursion and force during spin-up{shown}: static + spin-up (solid; the spin-up "
                "part alone dotted) against each actuator's gap and force capacity (dashed), the peaks the "
                "actuator checks judge marked",
                actuator_figure,
                rad_s_to_rpm(spinup_shown.speeds),
                spinup_shown.actuator_displacement,
                spinup_shown.actuator_force,
                {n: lim.gap for n, lim in limits.items() if lim.gap is not None} or None,
                operating_rpm=op_rpm,
                speed_range_rpm=_speed_range_rpm(point.evidence),
                force_capacity={n: lim.force_capacity for n, lim in limits.items() if lim.force_capacity is not None}
                or None,
                static_offset={n: e.static_offset for n, e in evidence.items()},
                static_force={n: e.static_force for n, e in evidence.items()},
                checked={
                    n: (
                        rad_s_to_rpm(e.orbit_speed),
                        e.static_offset + e.peak_orbit,
                        rad_s_to_rpm(e.force_speed),
                        e.static_force + e.peak_force,
                    )
                    for n, e in evidence.items()
                },
            )
        )
    imb = data["imbalance"]
    # the spin-up above is the governing point's: the deflection check's own value beside it
    # when that check governs at another point
    verdict = _governing_sentence(a, "spinup_deflection")
    tables = [
        Table(
            "Actuators (spin-up maxima)",
            ["actuator", "max relative displacement [mm]", "max force [N]"],
            [
                [k, m_to_mm(imb["actuator_max_displacement_m"][k]), imb["actuator_max_force_N"][k]]
                for k in spinup.actuator_force
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
                    "static offset [mm]",
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
                        m_to_mm(r.static_offset),
                        orbit_amplitude_mm(*r.orbit),
                        None if r.gap is None else m_to_mm(r.gap),
                    ]
                    for n, r in reactions.items()
                ],
            )
        )
    return Section(
        "Imbalance response over speed",
        paragraphs=[
            f"Rotating imbalance e_c m Ω², m the whole rotating mass of ISO 21940-11 "
            f"({design.loads.imbalance_placement} placement), "
            f"steady state at each speed from 2 % to 130 % of the operating speed. Peak shaft orbit of "
            f"the spin-up to the operating speed {m_to_mm(imb['max_shaft_orbit_spin_up_m']):.3f} mm at "
            f"{imb['speed_of_max_rpm']:.0f} rpm (refined between the sampled speeds); "
            f"{m_to_mm(imb['max_shaft_orbit_at_operating_m']):.4f} mm at the operating speed; "
            f"largest over the whole scan {m_to_mm(imb['max_shaft_orbit_scan_m']):.3f} mm at "
            f"{imb['speed_of_max_scan_rpm']:.0f} rpm." + verdict
        ],
        tables=tables,
        figures=figures,
    )


def loops_section(a: Assessment, figs: Figures) -> Section | None:
    """The magnetic-bearing loops' robustness at the point where the sensitivity-peak check
    governs: each loop's margins (the numbers the three loop checks read) and its sensitivity
    function and open-loop phase, the requirements drawn. None without loops."""
    name = check_point(a, "loop_sensitivity")
    loops = a.point(name).analyses.bearing_loops
    if not loops:
        return None
    req = a.design.requirements
    at = f" at {name}, where the sensitivity-peak check governs" if len(a.points) > 1 else ""
    rows, curves, peaks, margins = [], {}, {}, {}
    for lp in loops:
        m = lp.margins
        label = f"{lp.actuator} ({lp.axis})"
        rows.append(
            [
                label,
                m.peak_sensitivity,
                m.zone,
                m.peak_frequency,
                m.gain_margin_upper_db,
                m.gain_margin_lower_db,
                m.phase_margin_deg,
                m.phase_margin_frequency,
            ]
        )
        curves[label] = (np.asarray(lp.frequencies, dtype=float), np.asarray(lp.sensitivity, dtype=complex))
        peaks[label] = (float(m.peak_frequency), float(m.peak_sensitivity))
        if m.phase_margin_frequency is not None and np.isfinite(m.phase_margin_deg):
            margins[label] = (float(m.phase_margin_frequency), float(m.phase_margin_deg))
    speed = rad_s_to_rpm(loops[0].speed)
    figure = figs.add(
        "loop_sensitivity",
        f"Sensitivity |S| and open-loop phase of each magnetic-bearing loop at {speed:.0f} rpm{at} (each axis "
        "with the other loops closed): the peaks and the smallest phase margins the verdict's loop checks read "
        "marked, the requirements dashed, ISO 14839-3's zones shaded",
        loop_sensitivity_figure,
        curves,
        peaks=peaks,
        phase_margins=margins,
        required_peak=req.max_sensitivity_peak,
        required_phase_margin_deg=req.min_phase_margin_deg,
        zone_limits=ISO_14839_ZONE_LIMITS,
    )
    return Section(
        "Magnetic-bearing loops",
        paragraphs=[
            f"Each control axis of each active bearing{at}, broken at its controller with the other loops closed "
            f"(ISO 14839-3): the sensitivity peak |S|max and its zone, the gain margins for a gain rise and a gain "
            f"fall, the smallest phase margin over the gain crossovers. Required: |S|max ≤ "
            f"{req.max_sensitivity_peak:g}, gain margin ≥ {req.min_gain_margin_db:g} dB, phase margin ≥ "
            f"{req.min_phase_margin_deg:g}°."
        ],
        tables=[
            Table(
                "Loop margins (inf: no crossover of that kind in the frequency range)",
                [
                    "loop",
                    "|S|max",
                    "zone",
                    "at [Hz]",
                    "gain margin, rise [dB]",
                    "gain margin, fall [dB]",
                    "phase margin [°]",
                    "at [Hz]",
                ],
                rows,
            )
        ],
        figures=[figure],
    )


def _judged_modes(a: Assessment) -> np.ndarray | None:
    """Which tracked modes of the whirl-stability curves the whirl-damping check judges: the
    lateral whirl modes with at least :data:`~flexshaft.verdict.gather.WHIRL_DAMPING_SHAFT_SHARE`
    of their kinetic energy in the shaft at the operating speed (the check's modes). Each tracked
    eigenvalue, interpolated to the operating speed, is matched to the nearest of the modes at
    that speed; one without a match within 2 % of |s| counts as judged (drawn as it is). None
    when the operating speed lies outside the curves' speeds."""
    st, m = a.stability, a.modes_at_speed
    speed = float(a.model.speed)
    speeds = np.asarray(st.speeds, dtype=float)
    if m is None or speeds.size < 2 or not speeds[0] <= speed <= speeds[-1]:
        return None
    s = np.array(
        [np.interp(speed, speeds, col.real) + 1j * np.interp(speed, speeds, col.imag) for col in st.eigenvalues.T]
    )
    modes = np.asarray(m.eigenvalues)
    whirl = judged_whirl_modes(m)  # the check's own selection
    judged = np.ones(s.size, dtype=bool)
    for k, root in enumerate(s):
        distance = np.abs(modes - root)
        j = int(np.argmin(distance))
        if distance[j] <= 0.02 * abs(root):
            judged[k] = bool(whirl[j])
    return judged


def _where_governs(a: Assessment, key: str, what: str) -> tuple[Any, str]:
    """The analyses of the point where check ``key`` governs (the assessment's own for a design
    of one point) and a caption clause naming the point (empty for one point): ``what`` is the
    check's name in the clause."""
    if len(a.points) <= 1:
        return a, ""
    name = check_point(a, key)
    return a.point(name).analyses, f" ({name}, where the {what} check governs)"


def _governing_sentence(a: Assessment, key: str) -> str:
    """' The <check> governs at <point>: <value> (required <limit>), <where>.' when check ``key``
    governs at another point than the governing one, whose analyses a section shows (empty for
    one point, the governing point, or without that check): the verdict's number beside it."""
    if len(a.points) <= 1:
        return ""
    try:
        c = a.verdict.check(key)
    except KeyError:
        return ""
    point = c.location.get("point", a.governing_point)  # check_point's rule, on the check in hand
    if point == a.governing_point or c.value is None:
        return ""
    where = location_text({k: v for k, v in c.location.items() if k != "point"})
    return (
        f" The {c.title} check governs at {point}: "
        f"{format_quantity(c.kind, c.value)} (required {limit_text(c)})" + (f", {where}" if where else "") + "."
    )


def _temperature_checked(a: Assessment) -> tuple[str, dict[str, Any]] | None:
    """Where the temperature check governs and what it reads there (the self-heating equilibrium,
    the value, the allowable, the material temperature: the figure's keywords); None: nothing."""
    name = check_point(a, "temperature")
    shown = a.point(name)
    th, evidence, conditions = shown.analyses.thermal, shown.evidence, shown.analyses.conditions
    if th is None or evidence.max_temperature is None:
        return None
    temperature = th.shaft_temperature
    return name, {
        "temperature": (temperature.x, temperature.temperature),
        "checked": evidence.max_temperature,
        "allowable": evidence.allowable_temperature,
        "material_temperature": None if conditions is None else conditions.material_temperature,
        "point": name if len(a.points) > 1 else "",
    }


def _onset_text(speed: float | None, top: float) -> str:
    if speed is None or not np.isfinite(speed):
        return f"stable to {rad_s_to_rpm(top):.0f}"
    return f"{rad_s_to_rpm(speed):.0f}"


def stability_section(a: Assessment, thesis: ThesisStudies | None, figs: Figures, op_rpm: float) -> Section:
    """Whirl stability: the design's log decrements beside the thesis's three shafts, the onset
    speeds and the onset over the actuator gains."""
    # the log decrements where the whirl-damping check governs, the onset and the every-root
    # check where the onset check does (the governing point's analyses when it is theirs)
    damped, damped_at = _where_governs(a, "whirl_damping", "whirl-damping")
    onset, onset_at = _where_governs(a, "whirl_onset", "whirl-onset")
    st = damped.stability
    comparison = thesis.shaft_comparison if thesis is not None else {}
    gain_map = thesis.gain_map if thesis is not None else None
    top = st.speeds[-1]
    figures = []
    curves = {"this design (exact hysteretic loss)": st.log_decrements}
    onsets = {"this design (exact hysteretic loss)": rpm_or_none(st.onset_speed)}
    texts = {"this design (exact hysteretic loss)": st.onset_description()}
    whirl = {"this design (exact hysteretic loss)": st.whirl}
    same_speeds = True
    for label, models in comparison.items():
        r = models["viscous"]
        same_speeds &= r.speeds.shape == st.speeds.shape and bool(np.allclose(r.speeds, st.speeds))
        name = f"{label} (viscous equivalent)"
        curves[name], onsets[name], texts[name], whirl[name] = (
            r.log_decrements,
            rpm_or_none(r.onset_speed),
            r.onset_description(),
            r.whirl,
        )
    if not same_speeds:  # the comparison was run on other speeds: draw the design alone
        for extra in list(curves)[1:]:  # the four dicts have the same keys, the design first
            del curves[extra], onsets[extra], texts[extra], whirl[extra]
    required = a.design.requirements.required_log_decrement
    judged = _judged_modes(damped)
    figures.append(
        figs.add(
            "stability_log_decrement",
            f"Log decrement of the tracked modes against speed{damped_at}, the onset of "
            "whirl instability marked ✕ (the thesis's three reference shafts "
            "with the viscous-equivalent internal damping, figures 4.2-4.4); grey: the design's modes the "
            "whirl log-decrement requirement does not judge (torsional, or less than "
            f"{WHIRL_DAMPING_SHAFT_SHARE:.0%} of their kinetic energy in the shaft at the operating speed)",
            log_decrement_figure,
            rad_s_to_rpm(st.speeds),
            curves,
            onsets,
            op_rpm,
            onset_text={k: v for k, v in texts.items() if v},
            whirl=whirl,
            required=required,
            judged=None if judged is None else {"this design (exact hysteretic loss)": judged},
        )
    )
    tables = []
    own = _onset_text(onset.stability.onset_speed, onset.stability.speeds[-1])
    own += every_root_onset(a.verdict, onset.stability.onset_speed)  # the verdict's lower one, if any
    rows = [["this design" + onset_at, *((own, "—") if onset.stability.damping_model == "viscous" else ("—", own))]]
    rows += [
        [label, _onset_text(m["viscous"].onset_speed, top), _onset_text(m["hysteretic"].onset_speed, top)]
        for label, m in comparison.items()
    ]
    tables.append(
        Table("Onset speed of whirl instability [rpm]", ["shaft", "viscous equivalent", "exact hysteretic"], rows)
    )
    roots = onset.roots
    tables.append(
        Table(
            f"Every root of the closed loop ({roots.coverage()}){onset_at}",
            ["speed [rpm]", "roots", "least damping ratio ζ", "unstable roots"],
            [
                [rad_s_to_rpm(v), int(n), float(z), int(u)]
                for v, n, z, u in zip(roots.speeds, roots.n_roots, roots.least_damping_ratio, roots.unstable_counts)
            ],
        )
    )
    if gain_map is not None:
        g = gain_map
        by_kp = {f"K_p = {kp:.3g} N/m": rad_s_to_rpm(g.onset_speed[i]) for i, kp in enumerate(g.kp)}
        active = [b for b in a.design.bearings if b.kind == "active"]
        gains = {(b.kp, b.kd or 0.0) for b in active if b.controller is None}
        design = None
        if len(gains) == 1 and len(active) == sum(b.controller is None for b in active):
            ((kp, kd),) = gains  # one pair of PD gains on every active bearing: the design's own point
            design = (kd, rpm_or_none(onset.stability.onset_speed), f"this design (K_p = {kp:.3g} N/m)")
        figures.append(
            figs.add(
                "stability_map",
                "Onset speed against the actuator gains; dashed: the onset the whirl-onset check requires; "
                f"star: the design's own gains and its onset{onset_at}",
                stability_map_figure,
                g.kd,
                by_kp,
                op_rpm,
                rad_s_to_rpm(g.max_speed),
                required_rpm=(1.0 + a.design.requirements.min_onset_margin) * op_rpm,
                design=design,
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


def thermal_section(a: Assessment, figs: Figures) -> Section:
    """Tailboom and shaft temperatures, the self-heating equilibrium and the thermal sweeps."""
    th = a.thermal
    assert th is not None  # the report adds this section only with a thermal result (report/driveline.py)
    # the thermal results are the governing point's (only it has the report's detail): the
    # temperature check's own value is named beside them when it governs elsewhere
    at = f" at {a.governing_point}" if len(a.points) > 1 else ""
    verdict = _governing_sentence(a, "temperature")
    env = th.environment
    shafts = th.shaft
    if not shafts:  # below the report's detail: the self-heating equilibrium alone
        sh = th.self_heating
        assert sh is not None  # no shaft profiles: the self-heating alone was computed (thermal_results)
        return Section(
            "Thermal",
            paragraphs=[
                f"Self-heating{at} with temperature-dependent matrix properties ({th.loss_model} loss model): "
                f"{sh.status} after {sh.iterations} iterations; peak {kelvin_to_celsius(sh.max_temperature):.1f} °C, "
                f"margin to the allowable temperature {sh.margin:.1f} K.{verdict} The report's resolution adds the "
                "tailboom, both loss models and the thermal-design sweeps."
            ],
        )
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
        f"Ambient {kelvin_to_celsius(env.ambient_temperature):.1f} °C; the shaft's air and ends are at the boom's "
        "hover temperature. "
        "Heat is the hysteretic loss P = (ω/2)·Re(Xᴴ K'' X) of the imbalance response and of the static deflection "
        "seen by the rotating material. The thesis model cycles every response at Ω in the fixed frame; the "
        "rotating-frame model (used for the self-heating check) knows that synchronous forward whirl does not cycle "
        "the material, backward whirl is cycled at 2Ω and the static deflection at Ω."
    ]
    sh = th.self_heating
    if sh is not None:
        paragraphs.append(
            f"Self-heating{at} with temperature-dependent matrix properties: {sh.status} after "
            f"{sh.iterations} iterations; margin to the allowable temperature {sh.margin:.1f} K.{verdict}"
        )
    # the temperature check's own reading on top, at the point where it governs
    checked = _temperature_checked(a)
    function: Callable[..., Any] = shaft_temperature_figure
    kwargs: dict[str, Any] = {}
    caption = f"Shaft temperature rise and heat generation along the shaft{at}"
    if checked is not None:
        where = f" at {checked[0]}, where the temperature check governs" if len(a.points) > 1 else ""
        function, kwargs = shaft_temperature_check_figure, checked[1]
        caption = (
            f"Shaft temperature{where}: the self-heating equilibrium along the shaft, the point's material temperature "
            f"and the value the check reads against the allowable (dashed); below, the rise above the air and the heat "
            f"generated under both loss models{at}"
        )
    figures = [figs.add("shaft_temperature", caption, function, x, rise, xe, heat, **kwargs)]
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

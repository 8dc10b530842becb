"""The ``flexshaft compare`` report: two drivelines side by side in one self-contained page.

Formats a :class:`flexshaft.comparison.Comparison`; converts SI to engineering units
(rpm, mm, °C, degrees, %) here. Writes ``report.html`` (:mod:`flexshaft.report.html`), the
figures (PNG and SVG, :mod:`flexshaft.plot.compare`), ``results.json`` (SI) and
``comparison.nc`` (the comparison's dataset).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from flexshaft.comparison import PART_KINDS, Comparison
from flexshaft.files import atomic_write_text
from flexshaft.plot.compare import (
    campbell_overlay_figure,
    mass_breakdown_figure,
    safety_factor_overlay_figure,
    spinup_overlay_figure,
    static_deflection_overlay_figure,
)
from flexshaft.plot.driveline import save_figure
from flexshaft.report.html import FigureRef, Section, Table, write_report
from flexshaft.report.results_json import json_ready
from flexshaft.report.verdict import location_text
from flexshaft.units import format_quantity, rad_s_to_rpm
from flexshaft.verdict.assess import check_point

__all__ = ["comparison_json", "format_metric", "write_compare_report"]

_STATUS = {"pass": "PASS", "fail": "FAIL", "not evaluated": "not evaluated"}


#: Display kind (:func:`flexshaft.units.format_quantity`) of a compared quantity's SI unit.
_KIND_OF_UNIT = {"rad/s": "speed", "m": "length", "K": "temperature", "rad": "angle"}


def format_metric(key: str, unit: str, value: float | None, lower_bound: bool = False) -> str:
    """A compared quantity in display units (rpm, mm, °C, degrees, %); ``lower_bound`` prefixes "> "."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "—"
    if lower_bound:
        return "> " + format_metric(key, unit, value)
    kind = "fraction" if key == "separation" else _KIND_OF_UNIT.get(unit)
    if kind is not None:
        return format_quantity(kind, value)
    if unit == "kg":
        return f"{value:.2f} kg"
    if key.startswith("count"):
        return f"{value:.0f}"
    return f"{value:.3g}"


def comparison_json(comparison: Comparison) -> dict:
    """Key numbers of both designs, JSON-ready (SI units)."""
    labels = comparison.labels
    out = {
        "designs": {
            label: {
                "name": run.model.design.name,
                "verdict": run.verdict.to_dict(),
                "mass_kg": dict(inv.mass),
                "parts": dict(inv.count),
                "total_mass_kg": inv.total_mass,
                "total_parts": inv.total_count,
                "mass_not_given": list(inv.mass_not_given),
                "critical_speeds": comparison.critical_speeds(d),
                "notes": list(run.notes),
            }
            for d, (label, run, inv) in enumerate(zip(labels, comparison.runs, comparison.inventories))
        },
        "metrics": [
            {
                "key": m.key,
                "title": m.title,
                "unit": m.unit,
                "values": {label: m.values[d] for d, label in enumerate(labels)},
                "lower_bounds": {label: m.lower_bounds[d] for d, label in enumerate(labels)},
                "notes": {label: m.notes[d] for d, label in enumerate(labels)},
            }
            for m in comparison.metrics()
        ],
    }
    return out


def _check_cells(check) -> list[str]:
    if check is None:
        return ["—", "—", "not listed"]
    bound = "> " if check.lower_bound else ""
    return [
        bound + format_quantity(check.kind, check.value),
        bound + format_quantity(check.kind, check.margin, margin=True),
        _STATUS[check.status],
    ]


def _verdict_section(comparison) -> Section:
    a, b = comparison.labels
    rows = []
    for key in comparison.check_keys:
        ca, cb = comparison.check(key, 0), comparison.check(key, 1)
        c = ca or cb
        limit = "—"
        if c.limit is not None:
            limit = ("≥ " if c.sense == "at least" else "≤ ") + format_quantity(c.kind, c.limit)
        if ca is not None and cb is not None and ca.limit is not None and cb.limit is not None and ca.limit != cb.limit:
            limit = f"{format_quantity(ca.kind, ca.limit)} / {format_quantity(cb.kind, cb.limit)}"
        where = " / ".join(
            location_text(x.location, compact=True)
            if x is not None and x.status != "not evaluated"
            else (x.note if x is not None else "—")
            for x in (ca, cb)
        )
        rows.append([c.title, limit, *_check_cells(ca), *_check_cells(cb), where])
    columns = [
        "requirement",
        "limit",
        f"{a} value",
        f"{a} margin",
        f"{a} status",
        f"{b} value",
        f"{b} margin",
        f"{b} status",
        f"where ({a} / {b})",
    ]
    lead = [f"{label}: {run.verdict.summary}." for label, run in zip(comparison.labels, comparison.runs)]
    lead.append(
        "Each design is checked against its own [requirements] (here the same limits); a requirement "
        "that does not apply to a driveline (ply strength of a metal shaft, actuators of a passive one, "
        "couplings of a one-piece shaft) is not evaluated or not listed and does not pass. The metal "
        "strength check is the smaller of the von Mises yield and modified-Goodman fatigue safety factors "
        "of the aluminium tubes (Shigley §7-4); the buckling check of a metal driveline is the isotropic "
        "shell's, per tube."
    )
    return Section(
        "Verdicts side by side",
        paragraphs=lead,
        tables=[Table("Every requirement of both verdicts (worst case of each)", columns, rows)],
    )


def _metrics_table(comparison, keys=None, caption="Key numbers") -> Table:
    a, b = comparison.labels
    rows = []
    for m in comparison.metrics():
        if keys is not None and m.key not in keys:
            continue
        rows.append(
            [
                m.title,
                *(format_metric(m.key, m.unit, m.values[d], m.lower_bounds[d]) for d in (0, 1)),
                m.notes[0],
                m.notes[1],
            ]
        )
    return Table(caption, ["quantity", a, b, f"note ({a})", f"note ({b})"], rows)


def _summary_section(comparison) -> Section:
    a, b = comparison.labels
    inv = comparison.inventories
    names = [f"{label}: {run.model.design.name}" for label, run in zip(comparison.labels, comparison.runs)]
    mass_text = (
        f"Driveline mass {inv[0].total_mass:.1f} kg ({a}) against {inv[1].total_mass:.1f} kg ({b}); "
        f"{inv[0].total_count} parts against {inv[1].total_count}. Without the actuators: "
        f"{inv[0].total_mass - inv[0].mass['actuators']:.1f} kg against "
        f"{inv[1].total_mass - inv[1].mass['actuators']:.1f} kg."
    )
    keys = (
        "mass_total",
        "count_total",
        "strength",
        "buckling",
        "critical_below",
        "critical_above",
        "separation",
        "whirl_onset",
        "log_decrement",
        "spinup_peak",
        "coupling_angle",
        "static_deflection",
        "shaft_temperature",
    )
    return Section(
        "Summary",
        paragraphs=[
            *names,
            mass_text,
            "Both drivelines carry the same tailboom, end mass, static loads, power, "
            "speed and imbalance eccentricity unless their design files say otherwise. "
            "Masses of couplings, bearings, dampers and actuators are the design "
            "files' installed-mass fields (assumed values in the embedded designs).",
        ],
        tables=[_metrics_table(comparison, keys, "Key numbers of both drivelines")],
    )


def _parts_section(comparison, folder: Path) -> Section:
    a, b = comparison.labels
    inv = comparison.inventories
    rows = [[kind, inv[0].count[kind], inv[0].mass[kind], inv[1].count[kind], inv[1].mass[kind]] for kind in PART_KINDS]
    rows.append(["total", inv[0].total_count, inv[0].total_mass, inv[1].total_count, inv[1].total_mass])
    fig = save_figure(
        mass_breakdown_figure({label: i.mass for label, i in zip(comparison.labels, inv)}), folder, "compare_mass"
    )
    notes = [
        f"{label}: {', '.join(i.mass_not_given)} without a mass (counted 0 kg)."
        for label, i in zip(comparison.labels, inv)
        if i.mass_not_given
    ]
    return Section(
        "Mass and part count",
        paragraphs=[
            "Segments are the separate shaft tubes (one more than the couplings); hangers and dampers are the contact "
            "bearings by their role; actuators the active magnetic bearings. Gearbox bearings that end the driveline "
            "are common to both and not counted.",
            *notes,
        ],
        tables=[Table("Parts by kind", ["kind", f"{a} count", f"{a} mass [kg]", f"{b} count", f"{b} mass [kg]"], rows)],
        figures=[FigureRef(fig["png"], "Driveline mass by part kind")],
    )


def _dynamics_section(comparison, folder: Path) -> Section:
    a, b = comparison.labels
    # each design's own operating speed (one line when they agree)
    op_rpm = {label: rad_s_to_rpm(run.model.speed) for label, run in zip(comparison.labels, comparison.runs)}
    curves = {
        label: (rad_s_to_rpm(run.campbell.speeds), run.campbell.frequencies, run.campbell.whirl)
        for label, run in zip(comparison.labels, comparison.runs)
    }
    campbell = save_figure(campbell_overlay_figure(curves, op_rpm), folder, "compare_campbell")
    # each design's own limit, as the verdict checks it (one line when they agree)
    limit = {
        label: run.model.design.requirements.max_spinup_deflection
        for label, run in zip(comparison.labels, comparison.runs)
    }
    spinup = save_figure(
        spinup_overlay_figure(
            {
                label: (rad_s_to_rpm(run.spinup.speeds), run.spinup.shaft_peak)
                for label, run in zip(comparison.labels, comparison.runs)
            },
            op_rpm,
            limit,
        ),
        folder,
        "compare_spinup",
    )
    rows = []
    for d, label in enumerate(comparison.labels):
        for c in comparison.critical_speeds(d):
            rows.append(
                [
                    label,
                    format_quantity("speed", c["speed"]),
                    c["mode"],
                    c["amplification_factor"],
                    format_quantity("fraction", c["margin"]),
                    format_quantity("fraction", c["required"]),
                    "PASS" if c["passed"] else "FAIL",
                    format_quantity("length", c["station"]),
                ]
            )
    keys = ("critical_below", "critical_above", "separation", "whirl_onset", "log_decrement", "spinup_peak")
    return Section(
        "Critical speeds, whirl and spin-up",
        paragraphs=[
            "Lateral critical speeds are the peaks of each design's unbalance response up to 130 % of the operating "
            "speed, with the API 684 amplification factor and separation margin; whirl onset from the linearised "
            "eigenvalues up to 150 % of the operating speed; the spin-up response is the steady imbalance response "
            "at each speed (the largest orbit over the shaft)."
        ],
        tables=[
            Table(
                "Lateral critical speeds and separation margins",
                ["design", "speed", "mode", "AF", "margin", "required", "status", "station"],
                rows,
            ),
            _metrics_table(comparison, keys, "Dynamics"),
        ],
        figures=[
            FigureRef(campbell["png"], f"Campbell diagrams of both drivelines ({a} blue, {b} orange)"),
            FigureRef(spinup["png"], "Spin-up: largest shaft orbit against speed"),
        ],
    )


def _strength_curve(run):
    """The strength safety factor along the shaft at the point where its check governs (the
    verdict's value: the tuned design's Tsai-Wu 1.68 at hot_day, not the governing cold_day's
    5.24, audit a1), the point named for a design of several."""
    key = "tsai_wu" if run.strength_total is not None else "metal_strength"
    name = check_point(run, key) if len(run.points) > 1 else ""
    shown = run.point(name).analyses if name else run  # one point: the assessment's own analyses
    if key == "tsai_wu":
        r = shown.strength_total
        x, sf = np.asarray(r.x_along, float).ravel(), np.asarray(r.along_shaft, float).ravel()
        criterion = "Tsai-Wu (plies)"
    else:
        metal = shown.metal_strength
        if metal is None or not metal.evaluated:
            return None
        x, sf = metal.along_shaft()
        criterion = "metal: min(yield, fatigue)"
    return x, sf, criterion + (f" at {name}" if name else "")


def _strength_section(comparison, folder: Path) -> Section:
    curves = {
        label: c for label, run in zip(comparison.labels, comparison.runs) if (c := _strength_curve(run)) is not None
    }
    figures, tables = [], []
    if curves:
        required = {
            label: run.model.design.requirements.min_safety_factor
            for label, run in zip(comparison.labels, comparison.runs)
            if label in curves
        }
        fig = save_figure(safety_factor_overlay_figure(curves, required), folder, "compare_safety_factor")
        figures.append(FigureRef(fig["png"], "Strength safety factor along the driveline"))
    for label, run in zip(comparison.labels, comparison.runs):
        metal = run.metal_strength
        if metal is None or not metal.evaluated:
            continue
        rows = []
        for segment in metal.segments:
            fatigue, yielding = metal.worst("fatigue", segment), metal.worst("yield", segment)
            buckling = next((b for b in metal.buckling if b.segment == segment), None)
            rows.append(
                [
                    segment,
                    fatigue["safety_factor"],
                    fatigue["station"],
                    fatigue["sigma_alternating"] / 1e6,
                    fatigue["sigma_mean"] / 1e6,
                    fatigue["tau_mean"] / 1e6,
                    yielding["safety_factor"],
                    None if buckling is None else buckling.safety_factor,
                ]
            )
        tables.append(
            Table(
                f"{label}: metal tubes, worst point of each",
                [
                    "segment",
                    "fatigue n_f",
                    "at x [m]",
                    "σ_a [MPa]",
                    "σ_m [MPa]",
                    "τ_m [MPa]",
                    "yield n_y",
                    "buckling T_cr/T",
                ],
                rows,
            )
        )
    return Section(
        "Strength along the driveline",
        paragraphs=[
            "Static loads (manoeuvre, tail-rotor thrust, torque) plus the imbalance response at the operating speed. "
            "Composite: the ply Tsai-Wu safety factor (thesis §2.6). Metal: the rotating tube sees the static bending "
            "as fully reversed stress, the forward whirl as a steady stress and the backward whirl at 2/rev; "
            "DE-Goodman fatigue (Shigley eq. 7-7) against the fatigue strength of the design file and first-cycle "
            "von Mises yield (eq. 7-16)."
        ],
        tables=tables,
        figures=figures,
    )


def _deflection_section(comparison, folder: Path) -> Section:
    shapes, joints = {}, {}
    for label, run in zip(comparison.labels, comparison.runs):
        dm = run.model.dofs
        q = np.real(run.static_displacement)
        shapes[label] = (dm.shaft_x, dm.values(q, "shaft", "v"), dm.values(q, "shaft", "w"))
        joints[label] = [c.x for c in run.model.couplings]
    fig = save_figure(static_deflection_overlay_figure(shapes, joints), folder, "compare_static_deflection")
    tables = []
    for label, run in zip(comparison.labels, comparison.runs):
        cm = run.coupling_misalignment
        if cm is None:
            continue
        rows = [
            [name, x, math.degrees(a), math.degrees(d), None if np.isnan(lim) else math.degrees(lim), m, f, t]
            for name, x, a, d, lim, m, f, t in zip(
                cm.names,
                cm.stations,
                cm.static_angle,
                cm.dynamic_angle,
                cm.allowable_angle,
                cm.static_moment,
                cm.axial_force,
                cm.torque,
            )
        ]
        tables.append(
            Table(
                f"{label}: coupling misalignment and loads",
                [
                    "coupling",
                    "x [m]",
                    "static angle [°]",
                    "whirl angle at Ω_op [°]",
                    "allowable [°]",
                    "moment k α [N m]",
                    "axial force [N]",
                    "torque [N m]",
                ],
                rows,
            )
        )
    return Section(
        "Static deflection and coupling misalignment",
        paragraphs=[
            "The shaft follows the tailboom under the static loads. A segmented driveline takes the boom's curvature "
            "as angles at its couplings (diamonds); a one-piece flexible shaft bends instead. The coupling moment "
            "k α is a rotating bending moment on the adjacent tubes, already in their strength check."
        ],
        tables=tables,
        figures=[FigureRef(fig["png"], "Static deflection of both shafts")],
    )


def _notes_section(comparison) -> Section:
    rows = [[label, note] for label, run in zip(comparison.labels, comparison.runs) for note in run.notes]
    return Section(
        "Notes",
        paragraphs=["What each run could not evaluate, and why."],
        tables=[Table("Run notes", ["design", "note"], rows)] if rows else [],
    )


def write_compare_report(comparison: Comparison, folder: str | Path, generated=None) -> Path:
    """Write ``report.html``, the figures, ``results.json`` and ``comparison.nc`` into ``folder``.

    Returns
    -------
    Path
        The written ``report.html``.
    """
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    atomic_write_text(
        folder / "results.json", json.dumps(json_ready(comparison_json(comparison)), indent=2, allow_nan=False)
    )
    comparison.save(folder / "comparison.nc")
    sections = [
        _summary_section(comparison),
        _verdict_section(comparison),
        _parts_section(comparison, folder),
        _dynamics_section(comparison, folder),
        _strength_section(comparison, folder),
        _deflection_section(comparison, folder),
        _notes_section(comparison),
    ]
    a, b = comparison.labels
    options = {"design_name": f"{a} vs {b}"}
    if generated is not None:
        options["generated"] = generated
    return write_report(folder, f"Driveline comparison: {a} vs {b}", sections, **options)

"""``results.json`` of ``flexshaft run``: the key numbers of an
:class:`~flexshaft.verdict.assess.Assessment` (and of the thesis studies beside it), JSON-ready.

Only formatting: SI to the units named in each key (rpm, °C through :mod:`flexshaft.units`);
every number comes from the assessment.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from flexshaft.analyses.summary import model_summary, modes_table
from flexshaft.thesis.design_studies import headline
from flexshaft.thesis.report_studies import ThesisStudies
from flexshaft.units import kelvin_to_celsius, rad_s_to_rpm
from flexshaft.verdict.assess import Assessment
from flexshaft.verdict.envelope import tightest_check

__all__ = ["json_ready", "results_json", "rpm_or_none"]


def _bearing_dict(a: Assessment) -> dict | None:
    """Static lateral and axial force, the static offset (shaft from the bearing's centre) and
    the imbalance force amplitude at the operating speed (from the assessment's bearing
    reactions)."""
    reactions = a.bearing_reactions
    if not reactions:
        return None
    return {
        name: {
            "static_lateral_N": r.static_lateral,
            "static_axial_N": r.static_axial,
            "static_offset_m": r.static_offset,
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


def results_json(a: Assessment, thesis: ThesisStudies | None = None) -> dict:
    """The key numbers of an assessment (and the thesis studies beside it), JSON-ready: SI units,
    each unit in its key (``_m``, ``_N``, ``_Pa``, ``_Hz``; speeds ``_rpm``, temperatures ``_c``
    [°C]), non-finite numbers as None.

    Nothing here depends on when or how fast the run went (no timestamp, no timings: those go
    to ``timings.json``), so two runs of one design give byte-identical ``results.json``.
    """
    model = a.model
    dm = model.dofs
    qs = a.static_displacement
    spinup = a.spinup
    summary = model_summary(model)
    i_op = int(np.argmin(np.abs(spinup.speeds - model.speed)))
    peaks = spinup.shaft_peak
    studies = None
    if thesis is not None and thesis.design_studies is not None:
        studies = {k: v for k, v in headline(thesis.design_studies).items() if k not in ("elapsed_s", "timings_s")}
    return json_ready(
        {
            "design": summary["name"],
            "verdict": a.verdict.to_dict(),
            "envelope": _envelope_dict(a),
            "summary": summary,
            "modes_at_rest": modes_table(a.modes_at_rest) if a.modes_at_rest is not None else [],
            "modes_at_operating_speed": modes_table(a.modes_at_speed),
            "critical_speeds": [
                {"speed_rpm": c.speed_rpm, "tracked_mode": c.mode + 1, "harmonic": c.harmonic, "whirl": c.whirl}
                for c in (a.campbell.critical_speeds if a.campbell is not None else ())
            ],
            "imbalance": {
                # the spin-up proper (to the operating speed, peaks refined): the verdict's finding here
                **_spinup_peak(a),
                "max_shaft_orbit_scan_m": float(peaks.max()),
                "speed_of_max_scan_rpm": float(rad_s_to_rpm(spinup.speeds[np.argmax(peaks)])),
                "max_shaft_orbit_at_operating_m": float(peaks[i_op]),
                "actuator_max_displacement_m": {k: float(v.max()) for k, v in spinup.actuator_displacement.items()},
                "actuator_max_force_N": {k: float(v.max()) for k, v in spinup.actuator_force.items()},
            },
            "static": {
                "boom_tip_v_m": float(qs[dm.boom(-1, "v")]) if dm.n_boom_nodes else None,
                "boom_tip_w_m": float(qs[dm.boom(-1, "w")]) if dm.n_boom_nodes else None,
                "max_shaft_deflection_m": float(
                    np.max(np.hypot(dm.values(qs, "shaft", "v"), dm.values(qs, "shaft", "w")))
                ),
            },
            "bearings": _bearing_dict(a),
            "strength_static": _strength_dict(a.strength_static),
            "strength_static_plus_imbalance": _strength_dict(a.strength_total),
            "buckling": a.buckling.to_dict() if a.buckling is not None else None,
            "stability": _stability_dict(a, thesis),
            "thermal": _thermal_dict(a),
            "design_studies": studies,
            "notes": [*a.notes, *(thesis.notes if thesis is not None else ())],
        }
    )


def _spinup_peak(a: Assessment) -> dict:
    """Peak shaft orbit of the spin-up to the operating speed and its speed, at the governing
    point whose analyses results.json holds: the verdict's ``spinup_deflection`` finding there
    (refined between the sampled speeds) when it was evaluated, else the largest sampled value
    up to the operating speed. With an envelope the check's own value is its worst point's,
    which may be another point (its findings name theirs; a single point's name none)."""
    check = next((c for c in a.verdict.checks if c.key == "spinup_deflection"), None)
    here = [
        f
        for f in (check.findings if check is not None else ())
        if f.value is not None
        and "speed" in f.location
        and f.location.get("point", a.governing_point) == a.governing_point
    ]
    if here:
        peak = max(here, key=lambda f: float(f.value))
        return {
            "max_shaft_orbit_spin_up_m": float(peak.value),
            "speed_of_max_rpm": rad_s_to_rpm(float(peak.location["speed"])),
        }
    spinup = a.spinup
    up = spinup.up_to(a.model.speed)
    up = up if up.size else np.arange(spinup.speeds.size)
    k = up[int(np.argmax(spinup.shaft_peak[up]))]
    return {
        "max_shaft_orbit_spin_up_m": float(spinup.shaft_peak[k]),
        "speed_of_max_rpm": float(rad_s_to_rpm(spinup.speeds[k])),
    }


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


def rpm_or_none(speed: float | None) -> float | None:
    """A speed [rad/s] in rpm; None when it is None or not finite."""
    return None if speed is None or not np.isfinite(speed) else float(rad_s_to_rpm(speed))


def _envelope_dict(a: Assessment) -> dict | None:
    """Each envelope point: its conditions, its own verdict (check by check: status, value,
    margin) and its tightest check; the governing point, whose analyses the rest of the file
    holds. None for a design judged at its own operating point (no ``[envelope]``)."""
    if a.design.envelope is None:
        return None
    points = []
    for p in a.points:
        operating, conditions = p.analyses.design.operating, p.analyses.conditions
        assert conditions is not None  # every envelope point is analysed at its conditions (verdict/assess.py)
        tightest = tightest_check(p.verdict)
        points.append(
            {
                "name": p.name,
                "ambient_temperature_c": conditions.ambient_temperature_c,
                "material_temperature_c": conditions.material_temperature_c,
                "speed_rpm": operating.rpm,
                "power_W": operating.power,
                "load_scale": conditions.point.load_scale,
                "passed": p.verdict.passed,
                "summary": p.verdict.summary,
                "tightest_check": None if tightest is None else tightest.key,
                "checks": {
                    c.key: {"status": c.status, "value": c.value, "limit": c.limit, "margin": c.margin}
                    for c in p.verdict.checks
                },
            }
        )
    return {"governing_point": a.governing_point, "points": points}


def _stability_dict(a: Assessment, thesis: ThesisStudies | None) -> dict:
    st = a.stability
    comparison = thesis.shaft_comparison if thesis is not None else {}
    out: dict[str, Any] = {
        "damping_model": st.damping_model,
        "onset_speed_rpm": rpm_or_none(st.onset_speed),
        "analysed_to_rpm": float(rad_s_to_rpm(st.speeds[-1])),
        "unstable_mode_whirl": st.onset_whirl,
        "thesis_shafts": {
            label: {m: rpm_or_none(r.onset_speed) for m, r in models.items()} for label, models in comparison.items()
        },
    }
    roots = a.roots
    out["every_root"] = {
        "method": roots.method,
        "speeds_rpm": rad_s_to_rpm(roots.speeds).tolist(),
        "least_damping_ratio": roots.least_damping_ratio.tolist(),
        "unstable_roots": roots.unstable_counts.tolist(),
        "basis_size": roots.basis_size,
        "estimated_relative_error": roots.error_estimate,
        "tolerance": roots.tolerance,
    }
    if thesis is not None and thesis.gain_map is not None:
        g = thesis.gain_map
        out["gain_map"] = {
            "kp_N_per_m": g.kp.tolist(),
            "kd_N_s_per_m": g.kd.tolist(),
            "onset_speed_rpm": [[rpm_or_none(v) for v in row] for row in g.onset_speed],
            "min_damping_ratio_at_operating": g.margin_at_operating.tolist(),
        }
    return out


def _thermal_dict(a: Assessment) -> dict | None:
    th = a.thermal
    if th is None:
        return None
    out: dict[str, Any] = {
        "tailboom_c": {k: v.celsius for k, v in th.tailboom.items()},
        "report_loss_model": th.loss_model,
    }
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

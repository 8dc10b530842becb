"""The design studies of thesis chapter 3 (docs/studies.md) on the sweep engine.

Each function builds a :class:`~flexshaft.sweep.Study` and runs it with
:func:`~flexshaft.sweep.run_sweep` (so ``run_dir``, ``jobs``, ``client`` and ``progress`` work
the same for all), returning an :class:`xarray.Dataset`. Output functions are module-level so
they run in worker processes and on Dask.

1. :func:`ply_angle_study`: safety factor vs α of (α/−α/−α/α), no imbalance (thesis: ±55°);
2. :func:`two_angle_study`: (α/−α/β/−β)s map (thesis: (55/−55/0/0)s);
3. :func:`wall_thickness_study`: safety factor with and without imbalance, first natural
   frequencies and the peak spin-up deflection vs wall thickness at fixed D_o;
4. :func:`proportional_gain_study`: safety factor and actuator displacement vs K_p;
5. :func:`buckling_study`: torsional buckling safety factor vs wall thickness;
6. :func:`spinup_gain_map`: the (K_p, K_d) spin-up map (fast path of
   :mod:`flexshaft.analyses.spinup`; the gains are vectorised, not swept point by point).
"""

from __future__ import annotations

import numpy as np

from flexshaft.sweep.run import run_sweep
from flexshaft.sweep.study import Output, Study, SweepError, Variable

__all__ = [
    "DOMINANT_STRESS_CODES",
    "buckling_study",
    "critical_ply_outputs",
    "one_angle_layup",
    "ply_angle_study",
    "proportional_gain_study",
    "spinup_gain_map",
    "strength_outputs",
    "two_angle_layup",
    "two_angle_study",
    "wall_thickness_study",
]


def _angle(a: float) -> str:
    return f"{float(a):g}"


def one_angle_layup(alpha: float) -> dict:
    """``(α/−α/−α/α)`` [deg] as a layup override."""
    a = _angle(alpha)
    return {"shaft.layup": f"({a}/-{a}/-{a}/{a})".replace("--", "")}


def two_angle_layup(angles) -> dict:
    """``(α/−α/β/−β)s`` [deg] from a pair (α, β)."""
    a, b = (_angle(x) for x in angles)
    return {"shaft.layup": f"({a}/-{a}/{b}/-{b})s".replace("--", "")}


def strength_outputs(point) -> dict:
    """Tsai-Wu safety factor, static (external loads + torque) and with the imbalance
    response at the operating speed (worst load case)."""
    from flexshaft.analyses import imbalance_response, static_response
    from flexshaft.analyses.shaft_strength import shaft_safety_factor
    from flexshaft.assembly.loads import external_static_load, imbalance_loads, torque_load

    model = point.model
    q_static = static_response(model, external_static_load(model) + torque_load(model))
    static = shaft_safety_factor(model, q_static).safety_factor
    if model.design.loads.eccentricity == 0.0 or model.speed == 0.0:  # no imbalance: the total is the static
        return {"safety_factor_static": static, "safety_factor": static}
    q_imb = imbalance_response(model, [model.speed], imbalance_loads(model))[:, :, 0]
    total = min(shaft_safety_factor(model, q_static, q_imb[:, c]).safety_factor for c in range(q_imb.shape[1]))
    return {"safety_factor_static": static, "safety_factor": total}


_STRENGTH = [
    Output("safety_factor_static", "1", "Tsai-Wu safety factor, static loads and torque"),
    Output("safety_factor", "1", "Tsai-Wu safety factor with the imbalance at the operating speed"),
]

#: Codes of the ``dominant_stress`` output (a float, so that it fits the results array).
DOMINANT_STRESS_CODES = {0: "sigma1", 1: "sigma2", 2: "tau12"}

_CRITICAL = [
    Output("sigma1", "Pa", "fibre-direction stress of the critical ply (thesis Table 3.3)"),
    Output("sigma2", "Pa", "transverse stress of the critical ply"),
    Output("tau12", "Pa", "in-plane shear stress of the critical ply"),
    Output("critical_ply_angle", "deg", "angle of the critical ply"),
    Output("critical_x", "m", "axial station of the critical point"),
    Output("dominant_stress", "1", "largest Tsai-Wu share: 0 sigma1, 1 sigma2, 2 tau12"),
]


def critical_ply_outputs(point) -> dict:
    """Static Tsai-Wu safety factor and the critical ply's stresses (thesis Table 3.3).

    The imbalance is not applied (study 1 runs with ``loads.eccentricity = 0``), so
    ``safety_factor`` equals ``safety_factor_static``.
    """
    from flexshaft.analyses import static_response
    from flexshaft.analyses.shaft_strength import shaft_safety_factor
    from flexshaft.assembly.loads import external_static_load, torque_load

    model = point.model
    r = shaft_safety_factor(model, static_response(model, external_static_load(model) + torque_load(model)))
    code = {v: k for k, v in DOMINANT_STRESS_CODES.items()}[str(r.dominant_stress)]
    return {
        "safety_factor_static": r.safety_factor,
        "safety_factor": r.safety_factor,
        "sigma1": r.stresses[0],
        "sigma2": r.stresses[1],
        "tau12": r.stresses[2],
        "critical_ply_angle": r.ply_angle_deg,
        "critical_x": r.x,
        "dominant_stress": float(code),
    }


def ply_angle_study(angles=np.arange(5.0, 90.0, 5.0), design=None, **run):
    """Safety factor vs the ply angle α of (α/−α/−α/α), no imbalance (thesis study 1), with
    the critical ply's σ1, σ2, τ12 (Table 3.3), its angle, station and dominant stress.

    The optimum on the assumed baseline is a narrow peak near 45° (docs/studies.md): use a
    step of 1° or finer there before concluding on it.
    """
    study = Study(
        "ply angle (a/-a/-a/a)",
        [Variable("alpha", angles, overrides=one_angle_layup, units="deg", long_name="ply angle")],
        _STRENGTH + _CRITICAL,
        critical_ply_outputs,
        base=design,
        fixed={"loads.eccentricity": 0.0},
    )
    return run_sweep(study, **run)


def two_angle_study(alphas=np.arange(0.0, 91.0, 15.0), betas=np.arange(0.0, 91.0, 15.0), design=None, **run):
    """Safety factor over (α/−α/β/−β)s, no imbalance (thesis study 2)."""
    study = Study(
        "two ply angles (a/-a/b/-b)s",
        [Variable("alpha", alphas, units="deg"), Variable("beta", betas, units="deg")],
        _STRENGTH,
        _two_angle_strength,
        base=design,
        fixed={"loads.eccentricity": 0.0},
    )
    return run_sweep(study, **run)


def _two_angle_strength(point) -> dict:
    from flexshaft.design import with_overrides
    from flexshaft.sweep.study import Point

    design = with_overrides(point.design, two_angle_layup((point.axes["alpha"], point.axes["beta"])))
    return strength_outputs(Point(point.index, point.values, point.axes, design))


def _wall_outputs(point) -> dict:
    """First frequency always; the spin-up peak when the design has actuators and the safety
    factors when the shaft is laminated (NaN otherwise, e.g. a plain isotropic shaft)."""
    from flexshaft.analyses import modes
    from flexshaft.analyses.spinup import clustered_receptance, spinup_curves, spinup_speeds

    nan = float("nan")
    out = {
        "spinup_peak_deflection": nan,
        "safety_factor_static": nan,
        "safety_factor": nan,
        "safety_factor_no_imbalance": nan,
    }
    model = point.model
    out["natural_frequency_1"] = float(modes(model, 0.0, 1).frequencies[0])
    if model.actuators:
        laws = [a.controller for a in model.actuators]
        # 100 even speeds and 17 more around each of the 3 largest peaks: within 0.5 % of the
        # true peak on the study's walls, where 200 even speeds fell up to 2.7 % short
        speeds = spinup_speeds(model, point.axes.get("n_speeds", 100))
        rec = clustered_receptance(model, laws, speeds, n_peaks=3, n_fine=17)
        out["spinup_peak_deflection"] = float(spinup_curves(rec, laws).shaft_peak.max())
    if model.shaft.laminate is not None:
        out.update(strength_outputs(point))
        # without imbalance the loads are the static ones: the same model, the static result
        out["safety_factor_no_imbalance"] = out["safety_factor_static"]
    return out


def wall_thickness_study(walls=np.linspace(0.0015, 0.006, 10), design=None, **run):
    """Safety factor with/without imbalance, first frequency and spin-up peak vs wall (study 3)."""
    study = Study(
        "wall thickness at fixed outer diameter",
        [Variable(path="shaft.wall_thickness", name="wall_thickness", values=walls, units="m")],
        _STRENGTH
        + [
            Output("safety_factor_no_imbalance", "1"),
            Output("natural_frequency_1", "Hz", "first natural frequency at rest"),
            Output("spinup_peak_deflection", "m", "peak shaft orbit during spin-up"),
        ],
        _wall_outputs,
        base=design,
    )
    return run_sweep(study, **run)


def _actuator_outputs(point) -> dict:
    from flexshaft.analyses import imbalance_response
    from flexshaft.analyses.response import actuator_response
    from flexshaft.assembly.loads import imbalance_loads

    model = point.model
    q = imbalance_response(model, [model.speed], imbalance_loads(model))
    worst_disp = 0.0
    for c in range(q.shape[1]):
        disp, _ = actuator_response(model, q[:, c], np.array([model.speed]))
        worst_disp = max(worst_disp, max(float(d[0]) for d in disp.values()))
    nan = float("nan")  # ply strength needs a laminated shaft (as in the wall study)
    strength = strength_outputs(point) if model.shaft.laminate is not None else {o.name: nan for o in _STRENGTH}
    return {**strength, "actuator_displacement": worst_disp}


def _both_actuators_kp(kp: float) -> dict:
    return {"bearings[1].kp": kp, "bearings[2].kp": kp}


def proportional_gain_study(kps=np.logspace(5, 8, 13), design=None, **run):
    """Safety factor and actuator displacement at the operating speed vs K_p (study 4).

    ``kps`` is applied to both active bearings of the baseline (design bearings 1 and 2).
    """
    study = Study(
        "proportional gain",
        [Variable("kp", kps, overrides=_both_actuators_kp, units="N/m")],
        _STRENGTH + [Output("actuator_displacement", "m", "relative orbit at the actuator, operating speed")],
        _actuator_outputs,
        base=design,
    )
    return run_sweep(study, **run)


def _buckling_outputs(point) -> dict:
    from flexshaft.analyses.shaft_buckling import shaft_buckling

    result = shaft_buckling(point.model, compare_classical=False)
    return {
        "critical_torque": float(min(result.result.torque_positive, result.result.torque_negative)),
        "buckling_safety_factor": result.safety_factor,
    }


def buckling_study(walls=np.linspace(0.0015, 0.006, 10), design=None, **run):
    """Torsional buckling safety factor vs wall thickness (study 5; shear-deformable shell).

    Raises
    ------
    SweepError
        When the design's shaft is not one laminated tube (the laminated-shell model's domain;
        a metal segment's buckling is part of the run's metal strength check).
    """
    from flexshaft.design import baseline_design

    base = design if design is not None else baseline_design()
    if base.segmented or base.materials[base.shaft.material].kind != "lamina":
        raise SweepError(
            f"study 'torsional buckling vs wall thickness': the shaft of {base.name!r} is not one "
            "laminated tube; the laminated-shell buckling model does not apply (a metal segment's "
            "buckling is checked by `flexshaft run`)"
        )
    study = Study(
        "torsional buckling vs wall thickness",
        [Variable(path="shaft.wall_thickness", name="wall_thickness", values=walls, units="m")],
        [Output("critical_torque", "N m", "smaller of the two senses"), Output("buckling_safety_factor", "1")],
        _buckling_outputs,
        base=design,
    )
    return run_sweep(study, **run)


def spinup_gain_map(kp=np.logspace(5, 8, 30), kd=None, design=None, n_speeds: int = 400):
    """The (K_p, K_d) spin-up map of a design as a Dataset (study 6), same law on every AMB."""
    from flexshaft.analyses.spinup import spinup_map, spinup_speeds
    from flexshaft.assembly import build_model
    from flexshaft.design import baseline_design

    model = build_model(design or baseline_design())
    kd = np.concatenate([[0.0], np.logspace(1, 4.5, 29)]) if kd is None else kd
    return spinup_map(model, kp, kd, spinup_speeds(model, n_speeds)).to_dataset()

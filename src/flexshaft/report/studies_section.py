"""The "design studies" section of the ``flexshaft run`` report (thesis chapter 3).

Draws the figures and tables of a :class:`flexshaft.thesis.design_studies.DesignStudies` (it only
consumes the studies' datasets and headline numbers).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from flexshaft.plot import studies as sf
from flexshaft.plot.output import FigureJob, render_figures
from flexshaft.report.html import FigureRef, Section, Table
from flexshaft.thesis.design_studies import TABLE_ANGLES, DesignStudies, nearest, two_angle_name
from flexshaft.thesis.ply_angle import DOMINANT_STRESS_CODES
from flexshaft.thesis.wall import quietest_spinup_wall
from flexshaft.units import rad_s_to_rpm

__all__ = ["design_studies_section", "studies_section_and_jobs"]

_STRESS_NAMES = {0: "σ1", 1: "σ2", 2: "τ12"}


def design_studies_section(results: DesignStudies, folder: str | Path, *, svg: bool = True, processes: int = 1):
    """The "Design studies" section of the ``flexshaft run`` report with its figures drawn and
    saved in ``folder`` (PNG, and SVG when ``svg``; names ``study_*``)."""

    section, jobs = studies_section_and_jobs(results, folder)
    render_figures(jobs, folder, svg=svg, processes=processes)
    return section


def studies_section_and_jobs(results: DesignStudies, folder: str | Path):
    """The "Design studies" section (figures referenced as ``folder/study_*.png``, tables of
    the headline numbers) and the :class:`~flexshaft.plot.output.FigureJob` that draw its
    figures (not drawn here)."""

    r = results
    folder = Path(folder)
    op_rpm = rad_s_to_rpm(r.operating_speed)
    figs, tables, jobs = [], [], []

    def add(call, stem, caption):
        function, args, kwargs = call
        jobs.append(FigureJob(stem, function, args, kwargs))
        figs.append(FigureRef(folder / f"{stem}.png", caption))

    def job(function, *args, **kwargs):
        return function, args, kwargs

    rows = []
    if r.optimal_angle is not None:
        at55 = float(nearest(r.ply_angle, "alpha", 55.0)["safety_factor"])
        rows.append(
            [
                "1. one ply angle (α/−α/−α/α), no imbalance",
                f"±{r.optimal_angle:g}° (R = {r.optimal_angle_safety_factor:.3g}; ±55°: R = {at55:.3g})",
                "±55°",
            ]
        )
    if r.best_two_angle is not None:
        rows.append(
            [
                "2. two ply angles (α/−α/β/−β)s, no imbalance",
                f"{two_angle_name(r.best_two_angle)} (R = {r.best_two_angle_safety_factor:.3g})",
                "(55/−55/0/0)s",
            ]
        )
    if r.best_wall is not None:
        rows.append(
            [
                "3. wall thickness (largest R with imbalance)",
                f"{r.best_wall * 1e3:g} mm (R = {r.best_wall_safety_factor:.3g})",
                "~3 mm",
            ]
        )
    quietest = quietest_spinup_wall(r.wall) if r.wall is not None else None
    if quietest is not None:
        rows.append(
            [
                "3. wall thickness (smallest spin-up peak under the design's gains)",
                f"{quietest[0] * 1e3:g} mm ({quietest[1] * 1e3:.3g} mm orbit)",
                "not studied (3 mm chosen)",
            ]
        )
    if (
        r.gains_after is not None
        and r.gains_before is not None
        and r.peak_before is not None
        and r.peak_after is not None
    ):
        rows.append(
            [
                "6. tuned gains: peak spin-up deflection",
                f"{r.peak_before * 1e3:.3g} mm at K_p = {r.gains_before[0]:.3g} N/m, "
                f"K_d = {r.gains_before[1]:.3g} N s/m → "
                f"{r.peak_after * 1e3:.3g} mm at K_p = {r.gains_after[0]:.3g} N/m, K_d = {r.gains_after[1]:.3g} N s/m",
                "38 mm → 4 mm",
            ]
        )
    tables.append(Table("Headline results beside the thesis's", ["study", "this design", "thesis"], rows))

    if r.ply_angle is not None:
        ds = r.ply_angle
        alpha = ds.alpha.values
        dom = [_code_name(c) for c in ds["dominant_stress"].values]
        add(
            job(sf.ply_angle_figure, alpha, ds["safety_factor"].values, dom),
            "study_ply_angle",
            "Safety factor vs ply orientation, one angle variable, no imbalance (thesis figure 3.2)",
        )
        wanted = sorted({*([] if r.optimal_angle is None else [r.optimal_angle]), *TABLE_ANGLES})
        trows = []
        for a in wanted:
            p = nearest(ds, "alpha", a)
            trows.append(
                [
                    float(p.alpha),
                    float(p["safety_factor"]),
                    float(p["critical_ply_angle"]),
                    float(p["critical_x"]),
                    float(p["sigma1"]) / 1e6,
                    float(p["sigma2"]) / 1e6,
                    float(p["tau12"]) / 1e6,
                    _STRESS_NAMES.get(int(p["dominant_stress"]), "?"),
                ]
            )
        tables.append(
            Table(
                "Most critical loading of the composite shaft (thesis Table 3.3), lamina axes",
                ["α [deg]", "R", "critical ply [deg]", "x [m]", "σ1 [MPa]", "σ2 [MPa]", "τ12 [MPa]", "dominant"],
                trows,
            )
        )
    if r.two_angle is not None:
        ds = r.two_angle
        add(
            job(
                sf.two_angle_figure, ds.alpha.values, ds.beta.values, ds["safety_factor"].values, best=r.best_two_angle
            ),
            "study_two_angle",
            "Safety factor of (α/−α/β/−β)s laminates, no imbalance (thesis figure 3.3)",
        )
    if r.wall is not None:
        ds = r.wall
        if np.isfinite(ds["safety_factor"].values).any():
            add(
                job(
                    sf.wall_thickness_figure,
                    ds.wall_thickness.values,
                    ds["safety_factor"].values,
                    ds["safety_factor_no_imbalance"].values,
                    ds["natural_frequency_1"].values,
                    ds["spinup_peak_deflection"].values,
                ),
                "study_wall",
                "Safety factor with and without imbalance, the shaft's first lateral natural frequency and the peak "
                "shaft orbit during spin-up (the design's gains, speeds clustered at the resonance "
                "peaks) vs wall thickness at fixed outer diameter (thesis figure 3.4, eq. 3.3)",
            )
    if r.forced_response is not None:
        ds = r.forced_response
        add(
            job(
                sf.forced_response_figure,
                rad_s_to_rpm(ds.speed.values),
                {f"wall {w * 1e3:g} mm": ds["shaft_peak"].values[k] for k, w in enumerate(ds.wall_thickness.values)},
                op_rpm,
            ),
            "study_forced_response",
            "Maximum shaft response to imbalance for two walls (thesis figure 3.5)",
        )
    if r.gain is not None:
        ds = r.gain
        add(
            job(
                sf.gain_figure,
                ds.kp.values,
                ds["safety_factor"].values,
                ds["actuator_displacement"].values,
                r.gains_before[0] if r.gains_before else None,
            ),
            "study_gain",
            "Safety factor and actuator displacement at the operating speed vs K_p (thesis figure 3.6)",
        )
    if r.buckling is not None:
        ds = r.buckling
        add(
            job(sf.buckling_figure, ds.wall_thickness.values, ds["buckling_safety_factor"].values),
            "study_buckling",
            "Torsional buckling safety factor vs wall thickness (thesis figure 3.10)",
        )
    if r.spinup_map is not None:
        ds = r.spinup_map
        other = {"design": r.gains_before}
        for var, scale, label, stem, caption in (
            (
                "shaft_peak",
                1e3,
                "max spin-up shaft orbit [mm]",
                "study_map_deflection",
                "Maximum spin-up shaft deflection vs control gains (thesis figure 3.12)",
            ),
            (
                "actuator_displacement_peak",
                1e3,
                "max actuator displacement [mm]",
                "study_map_actuator_displacement",
                "Maximum shaft displacement at the actuators vs control gains (thesis figure 3.15)",
            ),
            (
                "actuator_force_peak",
                1.0,
                "max actuator force [N]",
                "study_map_actuator_force",
                "Maximum actuator force vs control gains (thesis figure 3.16)",
            ),
        ):
            values = ds[var].values if ds[var].ndim == 2 else ds[var].values.max(axis=-1)
            add(
                job(
                    sf.gain_map_figure,
                    ds.kp.values,
                    ds.kd.values,
                    values,
                    label,
                    scale=scale,
                    best=r.gains_after,
                    other=other,
                    title=caption.split(" (")[0],
                ),
                stem,
                caption,
            )
    if r.surfaces is not None:
        ds = r.surfaces
        add(
            job(
                sf.response_surface_figure,
                ds.x.values,
                rad_s_to_rpm(ds.speed.values),
                {str(c): ds["shaft_orbit"].values[k] for k, c in enumerate(ds.case.values)},
            ),
            "study_response_surfaces",
            "Frequency-response surfaces during spin-up (thesis figures 3.13, 3.14)",
        )
    if r.tuned is not None:
        ds = r.tuned
        curves = {
            f"{c}: K_p = {float(ds.kp[k]):.3g} N/m, K_d = {float(ds.kd[k]):.3g} N s/m": ds["shaft_peak"].values[k]
            for k, c in enumerate(ds.case.values)
        }
        add(
            job(sf.tuned_gains_figure, rad_s_to_rpm(ds.speed.values), curves, op_rpm),
            "study_tuned_gains",
            "Spin-up response with the design gains and the tuned gains (thesis figure 3.17)",
        )
        trows = []
        for k, c in enumerate(ds.case.values):
            peak = r.peak_before if k == 0 else r.peak_after
            speed = r.peak_speed_before if k == 0 else r.peak_speed_after
            assert peak is not None and speed is not None  # set with the tuned curves (thesis.spinup_maps)
            trows.append(
                [
                    str(c),
                    float(ds.kp[k]),
                    float(ds.kd[k]),
                    peak * 1e3,
                    rad_s_to_rpm(speed),
                    float(ds["actuator_displacement"].values[k].max()) * 1e3,
                    float(ds["actuator_force"].values[k].max()),
                ]
            )
        tables.append(
            Table(
                "Spin-up with the design and the tuned gains (peaks refined on a fine speed grid)",
                [
                    "gains",
                    "K_p [N/m]",
                    "K_d [N s/m]",
                    "peak deflection [mm]",
                    "at [rpm]",
                    "max actuator displacement [mm]",
                    "max actuator force [N]",
                ],
                trows,
            )
        )
    if r.stability_map is not None:
        ds = r.stability_map
        add(
            job(
                sf.stability_margin_figure,
                ds.kp.values,
                ds.kd.values,
                ds["damping_ratio"].values,
                rad_s_to_rpm(ds["onset_speed"].values),
                r.gains_after,
            ),
            "study_stability_margin",
            "Smallest damping ratio at the operating speed over the actuator gains (whirl onset speed per cell)",
        )

    paragraphs = [
        f"Thesis chapter 3 studies at the {r.resolution!r} resolution ({r.elapsed:.1f} s). Studies 1 and 2 run without "
        "imbalance; study 3 with and without it; the spin-up studies use the synchronous imbalance response at every "
        "speed up to the operating speed with the same PD law on every active bearing. Peaks over speed are the "
        "largest values at the sampled speeds; the tuned-gain peaks are refined on a fine grid around the peak.",
        "One ply angle: on the assumed lamina (E_T = 0.10 GPa, G_LT = 0.035 GPa) a (±α) laminate with a free hoop "
        "has a matrix-dominated axial modulus E* (about 0.1 GPa for α ≥ 45°), so the shaft sags between its bearings "
        "under the 3.5 g manoeuvre load and the transverse ply stress σ2 against Y_t = 5.1 MPa governs. At exactly "
        "45° the fibre scissoring is pure ply shear (σ2 from bending vanishes), hence the sharp optimum there; the "
        "thesis's ±55° is not reproduced with these assumed properties and loads (docs/studies.md).",
    ]
    paragraphs += list(r.notes)
    return Section("Design studies (thesis chapter 3)", paragraphs=paragraphs, tables=tables, figures=figs), jobs


def _code_name(code) -> str:
    try:
        return DOMINANT_STRESS_CODES[int(code)]
    except (ValueError, KeyError):
        return "?"

"""Thermal study of a design: tailboom temperatures, shaft temperature, self-heating margin, and
the thesis's thermal-design sweeps (wall thickness, convection coefficient; figures 3.18, 3.19).

Every ``[thermal]`` field reaches the computation through
:func:`flexshaft.thermal.options.thermal_options`; the shaft's loss model is the design's
``[analysis] internal_damping`` unless a comparison overrides it.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from flexshaft.assembly.model import Model
from flexshaft.units import kelvin_to_celsius

__all__ = ["thermal_results", "thermal_summary", "temperature_profiles", "wall_thickness_sweep", "convection_sweep"]


def _options(design, convection: str | None = None):
    from flexshaft.thermal.options import thermal_options

    options = thermal_options(design.thermal)
    return options if convection is None else dataclasses.replace(options, shaft_convection=convection)


def wall_thickness_sweep(
    design, thicknesses, loss_model: str | None = None, options=None, air_temperature: float | None = None
) -> dict[str, np.ndarray]:
    """Shaft temperature against wall thickness at fixed D_o (thesis figure 3.18).

    Parameters
    ----------
    design : Design
        The design whose ``shaft.wall_thickness`` is varied.
    thicknesses : array_like
        Wall thicknesses [m].
    loss_model : {"thesis", "rotating"} or None
        None: the design's ``[analysis] internal_damping``.
    options : ThermalOptions, optional
        Default: the design's ``[thermal]`` table.
    air_temperature : float, optional
        Shaft air and end temperature [K]; default the design's boom hover temperature.

    Returns
    -------
    dict
        ``wall_thickness`` (n,) [m], ``peak_rise`` (n,) [K], ``heat`` (n,) total [W], ``x`` node
        stations [m] and ``rise`` (n, nodes) temperature above the air [K].
    """
    from flexshaft.assembly import build_model
    from flexshaft.design import with_overrides
    from flexshaft.thermal.analysis import shaft_air_temperature, shaft_thermal

    options = options or _options(design)
    loss_model = loss_model or design.analysis.internal_damping
    T_air = shaft_air_temperature(design.tailboom, options) if air_temperature is None else float(air_temperature)
    walls = np.atleast_1d(np.asarray(thicknesses, dtype=float))
    runs = [
        shaft_thermal(
            build_model(with_overrides(design, {"shaft.wall_thickness": float(t)})),
            options,
            loss_model,
            air_temperature=T_air,
        )
        for t in walls
    ]
    return {
        "wall_thickness": walls,
        "peak_rise": np.array([r.peak_rise for r in runs]),
        "heat": np.array([r.sources.total.sum() for r in runs]),
        "x": runs[0].temperature.x,
        "rise": np.array([r.temperature.temperature - r.temperature.air_temperature for r in runs]),
    }


def convection_sweep(
    model: Model, coefficients, loss_model: str | None = None, options=None, air_temperature: float | None = None
) -> dict[str, np.ndarray]:
    """Shaft temperature against the convection coefficient (thesis figure 3.19); the heat
    sources are computed once.

    Parameters
    ----------
    model : Model
        Assembled model of the design.
    coefficients : sequence of float or None
        h [W/(m^2 K)]; ``None`` entries use the rotating-cylinder correlation of the options.
    loss_model, options, air_temperature
        As in :func:`wall_thickness_sweep` (options default: the model's design's table).

    Returns
    -------
    dict
        ``heat_transfer_coefficient`` (n,) h used [W/(m^2 K)], ``from_correlation`` (n,) bool,
        ``peak_rise`` (n,) [K], ``x`` [m] and ``rise`` (n, nodes) [K].
    """
    from flexshaft.thermal.analysis import shaft_air_temperature, shaft_thermal
    from flexshaft.thermal.heat import heat_sources

    options = options or _options(model.design)
    T_air = shaft_air_temperature(model.design.tailboom, options) if air_temperature is None else float(air_temperature)
    sources = heat_sources(model, loss_model)
    runs = [
        shaft_thermal(
            model,
            options,
            air_temperature=T_air,
            sources=sources,
            heat_transfer_coefficient=None if h is None else float(h),
        )
        for h in coefficients
    ]
    return {
        "heat_transfer_coefficient": np.array([r.temperature.heat_transfer_coefficient for r in runs]),
        "from_correlation": np.array([h is None for h in coefficients]),
        "peak_rise": np.array([r.peak_rise for r in runs]),
        "x": runs[0].temperature.x,
        "rise": np.array([r.temperature.temperature - r.temperature.air_temperature for r in runs]),
    }


def temperature_profiles(
    design,
    model: Model,
    walls=(0.0015, 0.003, 0.005),
    coefficients=(5.0, 20.0, None),
    loss_model: str | None = None,
    options=None,
) -> dict:
    """Shaft temperature rise along x for several wall thicknesses [m] at fixed D_o and several
    convection coefficients [W/(m² K)] (``None``: the rotating-cylinder correlation), thesis
    figures 3.18 and 3.19. Returns ``{"x": ..., "by_wall": {label: rise}, "by_h": {label: rise}}``."""
    from flexshaft.thermal.analysis import shaft_air_temperature

    options = options or _options(design)
    air = shaft_air_temperature(design.tailboom, options)
    by_wall = wall_thickness_sweep(design, walls, loss_model, options, air)
    by_h = convection_sweep(model, coefficients, loss_model, options, air)
    h_labels = [
        f"h = {h:.0f} W/m²K" + (" (correlation)" if corr else "")
        for h, corr in zip(by_h["heat_transfer_coefficient"], by_h["from_correlation"])
    ]
    return {
        "x": model.dofs.shaft_x,
        "by_wall": {f"wall {t * 1e3:.1f} mm": rise for t, rise in zip(by_wall["wall_thickness"], by_wall["rise"])},
        "by_h": dict(zip(h_labels, by_h["rise"])),
    }


def thermal_results(
    design, model: Model, loss_model: str | None = None, convection: str | None = None, self_heat: bool = False
) -> dict:
    """Thermal results of a design.

    Parameters
    ----------
    design : Design
        Its ``[thermal]`` table gives every option; its ``[analysis] internal_damping`` the loss
        model.
    model : Model
        The design's assembled model.
    loss_model : {"thesis", "rotating"} or None
        Override of the design's loss model (for a comparison).
    convection : {"becker", "kendoush"} or None
        Override of ``[thermal] shaft_convection``.
    self_heat : bool
        Iterate the temperature-dependent matrix properties to the self-heating equilibrium.

    Returns
    -------
    dict
        ``options``, ``environment``, ``loss_model`` (the one used), ``tailboom``
        ({"hover", "parked"}: BoomTemperature, empty without a tailboom), ``shaft`` (both loss
        models, for comparison), ``self_heating`` (SelfHeating or None), ``profiles``;
        and for a verdict: ``max_shaft_temperature`` [K] and ``max_shaft_temperature_c`` [°C]
        (the self-heating equilibrium's peak when computed, else the peak with reference-
        temperature properties, ``max_shaft_temperature_source`` says which),
        ``allowable_temperature`` [K], ``allowable_temperature_c`` [°C] and
        ``temperature_margin`` = allowable − max [K].
    """
    from flexshaft.thermal.analysis import shaft_thermal
    from flexshaft.thermal.selfheating import self_heating
    from flexshaft.thermal.tailboom import boom_equivalent_diameter, tailboom_temperatures

    options = _options(design, convection)
    loss_model = loss_model or design.analysis.internal_damping
    out: dict = {"options": options, "environment": options.environment, "loss_model": loss_model}
    has_boom = design.tailboom is not None
    out["profiles"] = temperature_profiles(design, model, loss_model=loss_model, options=options) if has_boom else None
    out["tailboom"] = (
        tailboom_temperatures(boom_equivalent_diameter(design.tailboom), options.environment, options.boom_convection)
        if has_boom
        else {}
    )
    out["shaft"] = {lm: shaft_thermal(model, options, lm) for lm in ("thesis", "rotating")}
    sh = self_heating(model, options, loss_model) if self_heat else None
    out["self_heating"] = sh
    peak = sh.max_temperature if sh is not None else out["shaft"][loss_model].max_temperature
    allowable = options.allowable_temperature
    out.update(
        max_shaft_temperature=peak,
        max_shaft_temperature_c=kelvin_to_celsius(peak),
        max_shaft_temperature_source="self_heating" if sh is not None else "reference_properties",
        allowable_temperature=allowable,
        allowable_temperature_c=kelvin_to_celsius(allowable),
        temperature_margin=allowable - peak,
    )
    return out


def thermal_summary(
    design,
    model: Model,
    loss_model: str | None = None,
    convection: str | None = None,
    self_heat: bool = False,
    sweeps: bool = False,
) -> dict:
    """JSON-ready thermal numbers (°C, K, W); ``sweeps`` adds the peak rise against wall
    thickness and convection coefficient (thesis figures 3.18, 3.19)."""
    r = thermal_results(design, model, loss_model, convection, self_heat)
    out = {}
    if sweeps:
        prof = r["profiles"] or temperature_profiles(design, model, loss_model=r["loss_model"], options=r["options"])
        out["peak_rise_K_by_wall"] = {k: float(v.max()) for k, v in prof["by_wall"].items()}
        out["peak_rise_K_by_convection"] = {k: float(v.max()) for k, v in prof["by_h"].items()}
    if r["tailboom"]:
        out["tailboom_c"] = {k: round(v.celsius, 2) for k, v in r["tailboom"].items()}
        out["tailboom_flags"] = {k: v.nusselt.note for k, v in r["tailboom"].items() if not v.nusselt.in_range}
    for lm, s in r["shaft"].items():
        t = s.temperature
        out[f"shaft_{lm}_loss_model"] = {
            "air_c": round(kelvin_to_celsius(t.air_temperature), 2),
            "h_W_m2K": round(t.heat_transfer_coefficient, 2),
            "heat_vibration_W": float(s.sources.vibration.sum()),
            "heat_static_W": float(s.sources.static.sum()),
            "peak_rise_K": float(s.peak_rise),
            "peak_x_m": float(t.x[int(np.argmax(t.temperature))]),
        }
    out["loss_model"] = r["loss_model"]
    out["max_shaft_temperature_c"] = round(r["max_shaft_temperature_c"], 4)
    out["max_shaft_temperature_K"] = round(r["max_shaft_temperature"], 4)
    out["max_shaft_temperature_source"] = r["max_shaft_temperature_source"]
    out["allowable_temperature_c"] = round(r["allowable_temperature_c"], 4)
    out["temperature_margin_K"] = round(r["temperature_margin"], 4)
    sh = r["self_heating"]
    if sh is not None:
        out["self_heating"] = {"status": sh.status, "iterations": sh.iterations, "margin_K": round(sh.margin, 3)}
    return out

"""Thermal study of a design: tailboom temperatures, shaft temperature, self-heating margin."""

from __future__ import annotations

import numpy as np

from flexshaft.assembly.model import Model

__all__ = ["thermal_summary", "thermal_results", "temperature_profiles"]


def thermal_results(design, model: Model, loss_model: str | None = None, convection: str | None = None,
                    self_heat: bool = False) -> dict:
    """Raw thermal results: boom temperatures, both shaft loss models, optional self-heating."""
    from flexshaft.thermal import shaft_thermal, tailboom_temperatures
    from flexshaft.thermal.selfheating import self_heating

    th = design.thermal
    env = th.environment()
    loss_model = loss_model or th.loss_model
    convection = convection or th.shaft_convection
    out = {"environment": env, "loss_model": loss_model}
    out["profiles"] = temperature_profiles(design, model, loss_model=loss_model) if design.tailboom is not None else None
    out["tailboom"] = tailboom_temperatures(design, env) if design.tailboom is not None else {}
    out["shaft"] = {lm: shaft_thermal(model, env, lm, convection=convection) for lm in ("thesis", "rotating")}
    out["self_heating"] = self_heating(model, env, loss_model, convection=convection) if self_heat else None
    return out


def temperature_profiles(design, model: Model, walls=(0.0015, 0.003, 0.005), coefficients=(5.0, 20.0, None),
                         loss_model: str | None = None) -> dict:
    """Shaft temperature rise along x for several wall thicknesses [m] at fixed D_o and several
    convection coefficients [W/(m² K)] (``None``: the rotating-cylinder correlation), thesis
    figures 3.18 and 3.19. Returns ``{"x": ..., "by_wall": {label: rise}, "by_h": {label: rise}}``."""
    from flexshaft.assembly import build_model
    from flexshaft.design import with_overrides
    from flexshaft.thermal import shaft_thermal
    from flexshaft.thermal.analysis import shaft_air_temperature
    from flexshaft.thermal.heat import heat_sources

    env = design.thermal.environment()
    loss_model = loss_model or design.thermal.loss_model
    air = shaft_air_temperature(design, env)
    out = {"by_wall": {}, "by_h": {}, "x": model.dofs.shaft_x}
    for t in walls:
        r = shaft_thermal(build_model(with_overrides(design, {"shaft.wall_thickness": float(t)})), env, loss_model,
                          air_temperature=air)
        out["by_wall"][f"wall {t * 1e3:.1f} mm"] = r.temperature.temperature - r.temperature.air_temperature
    sources = heat_sources(model, loss_model)
    for h in coefficients:
        r = shaft_thermal(model, env, loss_model, air_temperature=air, sources=sources,
                          heat_transfer_coefficient=None if h is None else float(h))
        label = f"h = {r.temperature.heat_transfer_coefficient:.0f} W/m²K" + (" (correlation)" if h is None else "")
        out["by_h"][label] = r.temperature.temperature - r.temperature.air_temperature
    return out


def thermal_summary(design, model: Model, loss_model: str | None = None, convection: str | None = None,
                    self_heat: bool = False, sweeps: bool = False) -> dict:
    """JSON-ready thermal numbers (°C, K, W); ``sweeps`` adds the peak rise against wall
    thickness and convection coefficient (thesis figures 3.18, 3.19)."""
    r = thermal_results(design, model, loss_model, convection, self_heat)
    out = {}
    if sweeps:
        prof = temperature_profiles(design, model, loss_model=loss_model)
        out["peak_rise_K_by_wall"] = {k: float(v.max()) for k, v in prof["by_wall"].items()}
        out["peak_rise_K_by_convection"] = {k: float(v.max()) for k, v in prof["by_h"].items()}
    if r["tailboom"]:
        out["tailboom_c"] = {k: round(v.celsius, 2) for k, v in r["tailboom"].items()}
        out["tailboom_flags"] = {k: v.nusselt.note for k, v in r["tailboom"].items() if not v.nusselt.in_range}
    for lm, s in r["shaft"].items():
        t = s.temperature
        out[f"shaft_{lm}_loss_model"] = {
            "air_c": round(t.air_temperature - 273.15, 2),
            "h_W_m2K": round(t.heat_transfer_coefficient, 2),
            "heat_vibration_W": float(s.sources.vibration.sum()),
            "heat_static_W": float(s.sources.static.sum()),
            "peak_rise_K": float(s.peak_rise),
            "peak_x_m": float(t.x[int(np.argmax(t.temperature))]),
        }
    out["report_loss_model"] = r["loss_model"]
    sh = r["self_heating"]
    if sh is not None:
        out["self_heating"] = {"status": sh.status, "iterations": sh.iterations, "margin_K": round(sh.margin, 3)}
    return out

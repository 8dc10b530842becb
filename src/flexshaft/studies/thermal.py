"""Thermal study of a design: tailboom temperatures, shaft temperature, self-heating margin."""

from __future__ import annotations

import numpy as np

from flexshaft.assembly.model import Model

__all__ = ["thermal_summary", "thermal_results"]


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
    out["tailboom"] = tailboom_temperatures(design, env) if design.tailboom is not None else {}
    out["shaft"] = {lm: shaft_thermal(model, env, lm, convection=convection) for lm in ("thesis", "rotating")}
    out["self_heating"] = self_heating(model, env, loss_model, convection=convection) if self_heat else None
    return out


def thermal_summary(design, model: Model, loss_model: str | None = None, convection: str | None = None,
                    self_heat: bool = False) -> dict:
    """JSON-ready thermal numbers (°C, K, W)."""
    r = thermal_results(design, model, loss_model, convection, self_heat)
    out = {}
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

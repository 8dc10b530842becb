"""Thermal study of a design: tailboom temperatures, shaft temperature, self-heating margin, and
the thesis's thermal-design sweeps (wall thickness, convection coefficient; figures 3.18, 3.19).

Every ``[thermal]`` field reaches the computation through
:func:`flexshaft.thermal.options.thermal_options`; the shaft's loss model is the design's
``[analysis] internal_damping`` unless a comparison overrides it. :func:`thermal_results`
returns a :class:`ThermalResults`.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from flexshaft.assembly import build_model
from flexshaft.assembly.model import Model
from flexshaft.design import with_overrides
from flexshaft.thermal.analysis import ShaftThermal, shaft_air_temperature, shaft_thermal
from flexshaft.thermal.correlations import RotatingMethod
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.heat import LossModel, heat_sources
from flexshaft.thermal.options import ThermalOptions, thermal_options
from flexshaft.thermal.selfheating import SelfHeating, self_heating
from flexshaft.thermal.shaft import ShaftTemperature
from flexshaft.thermal.tailboom import BoomTemperature, boom_equivalent_diameter, tailboom_temperatures
from flexshaft.units import kelvin_to_celsius, m_to_mm

__all__ = [
    "TemperatureProfiles",
    "ThermalResults",
    "convection_sweep",
    "temperature_profiles",
    "thermal_results",
    "thermal_summary",
    "wall_thickness_sweep",
]


def _options(design, convection: RotatingMethod | None = None) -> ThermalOptions:
    options = thermal_options(design.thermal)
    return options if convection is None else dataclasses.replace(options, shaft_convection=convection)


@dataclass(frozen=True)
class TemperatureProfiles:
    """Shaft temperature rise along x [K] for several wall thicknesses and convection
    coefficients (thesis figures 3.18, 3.19): ``x`` node stations [m], ``by_wall`` and ``by_h``
    label -> rise (nodes,)."""

    x: np.ndarray
    by_wall: Mapping[str, np.ndarray]
    by_h: Mapping[str, np.ndarray]


@dataclass(frozen=True)
class ThermalResults:
    """Thermal results of a design (:func:`thermal_results`), SI units.

    Attributes
    ----------
    options : ThermalOptions
        The design's ``[thermal]`` table (and the convection override) as used.
    loss_model : {"thesis", "rotating"}
        The shaft's loss model used for the verdict's numbers.
    tailboom : mapping of str to BoomTemperature
        ``"hover"`` and ``"parked"`` skin temperatures; empty without a tailboom, or when only
        the self-heating was asked for.
    shaft : mapping of str to ShaftThermal
        The shaft temperature with reference-temperature properties under both loss models (for
        comparison); empty when only the self-heating was asked for.
    self_heating : SelfHeating or None
        The self-heating equilibrium with temperature-dependent matrix properties (None: not
        computed).
    profiles : TemperatureProfiles or None
        The thermal-design sweeps (None without a tailboom or when not asked for).
    """

    options: ThermalOptions
    loss_model: LossModel
    tailboom: Mapping[str, BoomTemperature]
    shaft: Mapping[str, ShaftThermal]
    self_heating: SelfHeating | None
    profiles: TemperatureProfiles | None

    @property
    def environment(self) -> ThermalEnvironment:
        return self.options.environment

    @property
    def shaft_temperature(self) -> ShaftTemperature:
        """The shaft temperature the verdict reads: the self-heating equilibrium's when computed,
        else the one with reference-temperature properties under :attr:`loss_model`."""
        if self.self_heating is not None:
            return self.self_heating.thermal.temperature
        return self.shaft[self.loss_model].temperature

    @property
    def max_shaft_temperature(self) -> float:
        """Peak shaft temperature [K] (see :attr:`shaft_temperature`)."""
        if self.self_heating is not None:
            return self.self_heating.max_temperature
        return self.shaft[self.loss_model].max_temperature

    @property
    def max_shaft_temperature_c(self) -> float:
        """[°C]."""
        return kelvin_to_celsius(self.max_shaft_temperature)

    @property
    def max_shaft_temperature_source(self) -> str:
        """``"self_heating"`` or ``"reference_properties"``."""
        return "self_heating" if self.self_heating is not None else "reference_properties"

    @property
    def allowable_temperature(self) -> float:
        """Matrix allowable temperature [K]."""
        return self.options.allowable_temperature

    @property
    def allowable_temperature_c(self) -> float:
        """[°C]."""
        return kelvin_to_celsius(self.allowable_temperature)

    @property
    def temperature_margin(self) -> float:
        """Allowable − peak shaft temperature [K]."""
        return self.allowable_temperature - self.max_shaft_temperature


def wall_thickness_sweep(
    design, thicknesses, loss_model: LossModel | None = None, options=None, air_temperature: float | None = None
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
    model: Model, coefficients, loss_model: LossModel | None = None, options=None, air_temperature: float | None = None
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
    loss_model: LossModel | None = None,
    options=None,
) -> TemperatureProfiles:
    """Shaft temperature rise along x for several wall thicknesses [m] at fixed D_o and several
    convection coefficients [W/(m² K)] (``None``: the rotating-cylinder correlation), thesis
    figures 3.18 and 3.19."""
    options = options or _options(design)
    air = shaft_air_temperature(design.tailboom, options)
    by_wall = wall_thickness_sweep(design, walls, loss_model, options, air)
    by_h = convection_sweep(model, coefficients, loss_model, options, air)
    h_labels = [
        f"h = {h:.0f} W/m²K" + (" (correlation)" if corr else "")
        for h, corr in zip(by_h["heat_transfer_coefficient"], by_h["from_correlation"])
    ]
    return TemperatureProfiles(
        by_h["x"],  # the thermal model's stations (a segmented shaft's differ from the mesh's shaft_x)
        {f"wall {m_to_mm(t):.1f} mm": rise for t, rise in zip(by_wall["wall_thickness"], by_wall["rise"])},
        dict(zip(h_labels, by_h["rise"])),
    )


def thermal_results(
    design,
    model: Model,
    loss_model: LossModel | None = None,
    convection: RotatingMethod | None = None,
    self_heat: bool = False,
    detail: bool = True,
) -> ThermalResults:
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
    detail : bool
        Also the tailboom temperatures, the shaft under both loss models and the thermal-design
        sweeps; False (with ``self_heat``): the self-heating equilibrium alone, what the
        verdict's temperature check reads.
    """
    if not (detail or self_heat):
        raise ValueError("thermal_results: detail=False computes the self-heating alone; it needs self_heat=True")
    options = _options(design, convection)
    loss_model = loss_model or design.analysis.internal_damping
    has_boom = detail and design.tailboom is not None
    profiles = temperature_profiles(design, model, loss_model=loss_model, options=options) if has_boom else None
    tailboom = (
        tailboom_temperatures(boom_equivalent_diameter(design.tailboom), options.environment, options.boom_convection)
        if has_boom
        else {}
    )
    shaft = {lm: shaft_thermal(model, options, lm) for lm in ("thesis", "rotating")} if detail else {}
    sh = self_heating(model, options, loss_model) if self_heat else None
    return ThermalResults(options, loss_model, tailboom, shaft, sh, profiles)


def thermal_summary(
    design,
    model: Model,
    loss_model: LossModel | None = None,
    convection: RotatingMethod | None = None,
    self_heat: bool = False,
    sweeps: bool = False,
) -> dict:
    """JSON-ready thermal numbers (°C, K, W); ``sweeps`` adds the peak rise against wall
    thickness and convection coefficient (thesis figures 3.18, 3.19)."""
    r = thermal_results(design, model, loss_model, convection, self_heat)
    out: dict[str, Any] = {}
    if sweeps:
        prof = r.profiles or temperature_profiles(design, model, loss_model=r.loss_model, options=r.options)
        out["peak_rise_K_by_wall"] = {k: float(v.max()) for k, v in prof.by_wall.items()}
        out["peak_rise_K_by_convection"] = {k: float(v.max()) for k, v in prof.by_h.items()}
    if r.tailboom:
        out["tailboom_c"] = {k: round(v.celsius, 2) for k, v in r.tailboom.items()}
        out["tailboom_flags"] = {k: v.nusselt.note for k, v in r.tailboom.items() if not v.nusselt.in_range}
    for lm, s in r.shaft.items():
        t = s.temperature
        out[f"shaft_{lm}_loss_model"] = {
            "air_c": round(kelvin_to_celsius(t.air_temperature), 2),
            "h_W_m2K": round(t.heat_transfer_coefficient, 2),
            "heat_vibration_W": float(s.sources.vibration.sum()),
            "heat_static_W": float(s.sources.static.sum()),
            "peak_rise_K": float(s.peak_rise),
            "peak_x_m": float(t.x[int(np.argmax(t.temperature))]),
        }
    out["loss_model"] = r.loss_model
    out["max_shaft_temperature_c"] = round(r.max_shaft_temperature_c, 4)
    out["max_shaft_temperature_K"] = round(r.max_shaft_temperature, 4)
    out["max_shaft_temperature_source"] = r.max_shaft_temperature_source
    out["allowable_temperature_c"] = round(r.allowable_temperature_c, 4)
    out["temperature_margin_K"] = round(r.temperature_margin, 4)
    sh = r.self_heating
    if sh is not None:
        out["self_heating"] = {"status": sh.status, "iterations": sh.iterations, "margin_K": round(sh.margin, 3)}
    return out

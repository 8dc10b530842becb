"""Self-heating equilibrium: temperature-dependent FMC properties iterated to a fixed point.

The matrix properties follow the options' :class:`~flexshaft.thermal.matrix.MatrixTemperatureLaw`
(E_T, G_LT soften and their loss factors grow with temperature; fibre properties fixed), or the
temperature table of each element's own lamina when it has one (the table wins,
:func:`~flexshaft.thermal.matrix.matrix_law_for`): a segment of another lamina than the
``[shaft]``'s follows its own table, or the law without the ``[shaft]`` lamina's table.

Fixed point, per element: each element e carries its own temperature T_e (mean of its nodes),
hence its own lamina, laminate E*_e, G*_e and element stiffness. The model variant is the
original global K with the uniform shaft elements replaced by the per-element ones
(:func:`model_with_shaft_moduli`). Then response (imbalance at Ω + static) → heat per element
→ finite-difference temperature → new T_e, until max |ΔT| < tol (Picard iteration; it converges
when the loop gain d(heat)/dT × thermal resistance < 1, which is exactly when a stable
equilibrium exists). **Thermal runaway**: an iterate exceeds the law's allowable temperature,
i.e. there is no fixed point below it (the iteration increases monotonically when heat grows
with temperature, so it cannot jump over a lower fixed point).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.guards import RefusedInputError
from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import scatter
from flexshaft.laminate import Laminate, equivalent_moduli
from flexshaft.thermal.analysis import ShaftThermal, shaft_air_temperature, shaft_thermal
from flexshaft.thermal.heat import (
    LossModel,
    element_segments,
    element_tubes,
    heat_sources,
    resolve_loss_model,
    shaft_response_amplitudes,
    shaft_stiffness_matrices,
)
from flexshaft.thermal.matrix import MatrixTemperatureLaw, matrix_law_for
from flexshaft.thermal.options import ThermalOptions, options_of
from flexshaft.units import kelvin_to_celsius

__all__ = [
    "MatrixTemperatureLaw",
    "FixedPoint",
    "fixed_point",
    "model_with_shaft_moduli",
    "SelfHeating",
    "self_heating",
    "runaway_onset",
]


@dataclass(frozen=True)
class FixedPoint:
    """Outcome of a fixed-point iteration on temperatures.

    ``status`` is "converged", "runaway" (an iterate exceeded the allowable temperature) or
    "not_converged" (max_iter reached below it). ``history`` holds max T of each iterate [K].
    """

    temperature: np.ndarray
    status: str
    iterations: int
    history: np.ndarray

    @property
    def converged(self) -> bool:
        return self.status == "converged"


def fixed_point(
    update: Callable[[np.ndarray], np.ndarray], initial, allowable: float, tol: float = 1e-4, max_iter: int = 100
) -> FixedPoint:
    """Picard iteration ``T ← update(T)`` with runaway detection.

    Parameters
    ----------
    update : callable
        Maps temperatures [K] to new temperatures [K] (same shape).
    initial : array_like
        Starting temperatures [K].
    allowable : float
        Runaway when any iterate exceeds it [K].
    tol : float
        Converged when max |ΔT| < tol [K].
    """
    T = np.asarray(initial, dtype=float).copy()
    history = []
    for k in range(1, max_iter + 1):
        new = np.asarray(update(T), dtype=float)
        history.append(float(new.max()))
        if not np.all(np.isfinite(new)) or new.max() > allowable:
            return FixedPoint(new, "runaway", k, np.array(history))
        done = np.max(np.abs(new - T)) < tol
        T = new
        if done:
            return FixedPoint(T, "converged", k, np.array(history))
    return FixedPoint(T, "not_converged", max_iter, np.array(history))


def model_with_shaft_moduli(model: Model, youngs_moduli, shear_moduli) -> Model:
    """A copy of ``model`` whose shaft elements carry per-element complex moduli (nel,) [Pa].

    The global K loses the uniform shaft elements and gains the per-element ones; mass,
    gyroscopic matrix, bearings and loads are unchanged (density does not vary).
    """
    sdofs = model.dofs.element_dofs("shaft")
    n = model.dofs.size
    old = scatter(shaft_stiffness_matrices(model), sdofs, n)
    Ke = shaft_stiffness_matrices(model, youngs_moduli, shear_moduli)
    new = scatter(Ke, sdofs, n)
    K = (model.K - old.real + new.real).tocsr()  # the model's K is the real storage stiffness
    return dataclasses.replace(model, K=K, shaft_loss_stiffness=scatter(Ke.imag, sdofs, n))


def _element_laws(model: Model, law: MatrixTemperatureLaw) -> tuple[list[MatrixTemperatureLaw], list[str | None]]:
    """The matrix law of every shaft element and the name of its lamina (None without a design):
    ``law`` (the ``[shaft]`` lamina's, its table attached) for an element of the ``[shaft]``'s
    material; for a segment of another lamina, ``law`` with that lamina's own table, or without
    any table (:func:`~flexshaft.thermal.heat.element_segments`)."""
    nel = len(model.dofs.shaft_element_x)
    design = model.design
    if design is None or not model.segments:
        return [law] * nel, [None] * nel
    others = dataclasses.replace(law, table=None)
    laws = {design.shaft.material: law}
    names = [model.segments[k].material for k in element_segments(model)]
    for name in names:
        if name not in laws:
            laws[name] = matrix_law_for(design.materials[name], others)
    return [laws[name] for name in names], names


def _element_moduli(model: Model, law: MatrixTemperatureLaw, temperatures: np.ndarray):
    """Complex moduli (nel,) of each element's tube at its temperature: a laminated tube's from
    its law's lamina (:func:`_element_laws`), an isotropic tube's (a metal segment) unchanged."""
    tubes = element_tubes(model)
    if all(t.laminate is None for t in tubes):
        raise RefusedInputError("self-heating needs a laminated (FMC) shaft; the model's shaft is isotropic")
    laws, names = _element_laws(model, law)
    E = np.array([t.youngs_modulus for t in tubes], dtype=complex)
    G = np.array([t.shear_modulus for t in tubes], dtype=complex)
    rounded = np.round(np.asarray(temperatures, dtype=float), 6)
    cache: dict = {}
    for e, tube in enumerate(tubes):
        lam = tube.laminate
        if lam is None:
            continue
        key = (id(tube), id(laws[e]), rounded[e])  # laminae of equal values share a tube, not a law
        if key not in cache:
            try:
                cache[key] = equivalent_moduli(
                    Laminate(lam.angles, lam.thicknesses, laws[e].lamina(lam.lamina, rounded[e]))
                )
            except ValueError as error:  # the law took the matrix beyond a valid ply
                if laws[e].table is not None:
                    raise RefusedInputError(
                        f"the temperature table of lamina {names[e]!r} gives no valid ply at {rounded[e]:.6g} K: "
                        f"{error}; its [materials.{names[e]}.temperature_table] sets it"
                    ) from None
                raise RefusedInputError(
                    f"the matrix temperature law gives no valid ply at {rounded[e]:.6g} K (reference "
                    f"{law.reference_temperature:.6g} K, θ_E {law.modulus_decay:g} K: E_T scaled by "
                    f"{np.exp(-(rounded[e] - law.reference_temperature) / law.modulus_decay):.3g}): {error}; "
                    "[thermal] matrix_reference_temperature_c and matrix_modulus_decay set it"
                ) from None
        E[e], G[e] = cache[key]
    return E, G


@dataclass(frozen=True)
class SelfHeating:
    """Self-heating equilibrium (or runaway) of the shaft.

    Attributes
    ----------
    status : str
        "converged", "runaway" or "not_converged".
    element_temperature : ndarray
        Last iterate of the element temperatures [K].
    thermal : ShaftThermal
        Heat sources and temperature of the last iterate.
    iterations : int
        Picard iterations done.
    allowable_temperature : float
        The matrix allowable temperature [K] the runaway check used.
    history : ndarray
        Maximum temperature of each iterate [K].
    """

    status: str
    element_temperature: np.ndarray
    thermal: ShaftThermal
    iterations: int
    allowable_temperature: float
    history: np.ndarray

    @property
    def max_temperature(self) -> float:
        """Peak shaft temperature of the last iterate [K]."""
        return self.thermal.max_temperature

    @property
    def max_temperature_c(self) -> float:
        """Peak shaft temperature of the last iterate [°C]."""
        return kelvin_to_celsius(self.max_temperature)

    @property
    def margin(self) -> float:
        """Allowable temperature − peak temperature [K] (negative at runaway)."""
        return self.allowable_temperature - self.max_temperature


def self_heating(
    model: Model,
    options: ThermalOptions | None = None,
    loss_model: LossModel | None = None,
    *,
    imbalance_scale: float = 1.0,
    static_scale: float = 1.0,
    air_temperature: float | None = None,
    tol: float = 1e-3,
    max_iter: int = 60,
    **thermal_kwargs,
) -> SelfHeating:
    """Iterate response → heat → temperature → lamina properties per element to a fixed point.

    Parameters
    ----------
    model : Model
        Assembled model with a laminated shaft.
    options : ThermalOptions
        Environment, correlations, ply conductivities and the matrix temperature law with its
        allowable temperature (default: the model's design's ``[thermal]`` table,
        :func:`~flexshaft.thermal.options.options_of`, as ``flexshaft run`` solves it). The temperature table of each
        element's own lamina, when it has one, replaces the law's exponentials.
    loss_model : {"thesis", "rotating"} or None
        None: the design's ``[analysis] internal_damping``.
    imbalance_scale, static_scale : float
        Multipliers of the imbalance and static loads [-] (to find where runaway starts).
    air_temperature : float, optional
        T_∞ and end temperature [K]; default the boom's hover temperature.
    tol : float
        Converged when max |ΔT| < tol [K].
    max_iter : int
        Iteration limit.
    **thermal_kwargs
        Passed to :func:`~flexshaft.thermal.analysis.shaft_thermal`.
    """
    options = options or options_of(model)
    shaft_material = None if model.design is None else model.design.shaft_material
    law = matrix_law_for(shaft_material, options.matrix_law)
    loss_model = resolve_loss_model(model, loss_model)
    tailboom = None if model.design is None else model.design.tailboom
    T_air = shaft_air_temperature(tailboom, options) if air_temperature is None else float(air_temperature)
    nel = len(model.dofs.shaft_element_nodes)
    last: dict[str, ShaftThermal] = {}

    def update(T_el: np.ndarray) -> np.ndarray:
        E, G = _element_moduli(model, law, T_el)
        variant = model_with_shaft_moduli(model, E, G)
        q_imb, q_st = shaft_response_amplitudes(variant, imbalance_scale, static_scale)
        src = heat_sources(
            variant, loss_model, q_imb, q_st, loss_stiffness=shaft_stiffness_matrices(variant, E, G).imag
        )
        res = shaft_thermal(variant, options, loss_model, air_temperature=T_air, sources=src, **thermal_kwargs)
        last["thermal"] = res
        return res.temperature.element_temperature

    fp = fixed_point(update, np.full(nel, T_air), law.allowable_temperature, tol, max_iter)
    return SelfHeating(fp.status, fp.temperature, last["thermal"], fp.iterations, law.allowable_temperature, fp.history)


def runaway_onset(
    model: Model,
    scales,
    options: ThermalOptions | None = None,
    loss_model: LossModel | None = None,
    refine: int = 0,
    **kwargs,
) -> tuple[float | None, list[SelfHeating]]:
    """First load multiple (imbalance and static loads scaled together, increasing ``scales``)
    at which the self-heating has no fixed point below the allowable temperature; ``refine``
    bisection steps then narrow it between the last stable and the first runaway scale.

    Returns ``(scale or None, results)``.
    """

    def run(s: float) -> SelfHeating:
        return self_heating(model, options, loss_model, imbalance_scale=float(s), static_scale=float(s), **kwargs)

    results, lo = [], None
    for s in scales:
        r = run(s)
        results.append(r)
        if r.status == "runaway":
            hi = float(s)
            if lo is not None:
                for _ in range(refine):
                    mid = 0.5 * (lo + hi)
                    rm = run(mid)
                    results.append(rm)
                    lo, hi = (lo, mid) if rm.status == "runaway" else (mid, hi)
            return hi, results
        lo = float(s)
    return None, results

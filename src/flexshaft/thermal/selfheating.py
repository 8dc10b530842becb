"""Self-heating equilibrium: temperature-dependent FMC properties iterated to a fixed point.

The polyurethane matrix softens and gets lossier as it warms; the fibre properties (E_L, η_L)
do not change. :class:`MatrixTemperatureLaw` is a documented, assumed shift law (no data in the
thesis)::

    E_T(T)  = E_T(T_ref)  · exp(−(T − T_ref)/θ_E),     G_LT likewise,
    η_T(T)  = min(η_T(T_ref)  · exp(+(T − T_ref)/θ_η), η_max),   η_LT likewise,

with T_ref = 20 °C (the 10 Hz lamina data), θ_E = 40 K (the rubbery-plateau modulus of a
90A urethane roughly halves every 28 K as the hard segments soften), θ_η = 60 K and an
allowable temperature of 100 °C (hard-segment softening; the thesis's "critical temperature of
the matrix"). Replace it with measured master curves when available.

Fixed point, per element: each element e carries its own temperature T_e (mean of its nodes),
hence its own lamina, laminate E*_e, G*_e and element stiffness. The model variant is the
original global K with the uniform shaft elements replaced by the per-element ones
(:func:`model_with_shaft_moduli`). Then response (imbalance at Ω + static) → heat per element
→ finite-difference temperature → new T_e, until max |ΔT| < tol (Picard iteration; it converges
when the loop gain d(heat)/dT × thermal resistance < 1, which is exactly when a stable
equilibrium exists). **Thermal runaway**: an iterate exceeds the allowable temperature, i.e.
there is no fixed point below it (the iteration increases monotonically when heat grows with
temperature, so it cannot jump over a lower fixed point).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Callable

import numpy as np

from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import scatter
from flexshaft.laminate import Lamina, Laminate, equivalent_moduli
from flexshaft.thermal.analysis import ShaftThermal, shaft_air_temperature, shaft_thermal
from flexshaft.thermal.environment import ZERO_CELSIUS, ThermalEnvironment
from flexshaft.thermal.heat import LossModel, heat_sources, shaft_response_amplitudes, shaft_stiffness_matrices

__all__ = ["MatrixTemperatureLaw", "FixedPoint", "fixed_point", "model_with_shaft_moduli",
           "SelfHeating", "self_heating", "runaway_onset"]


@dataclass(frozen=True)
class MatrixTemperatureLaw:
    """Temperature dependence of the matrix-dominated lamina properties (assumed; see module).

    Parameters
    ----------
    reference_temperature : float
        Temperature of the lamina data [K].
    modulus_decay : float
        θ_E [K]: E_T and G_LT scale by exp(−ΔT/θ_E).
    loss_growth : float
        θ_η [K]: η_T and η_LT scale by exp(+ΔT/θ_η), capped at ``max_loss_factor``.
    max_loss_factor : float
        Cap on the matrix loss factors [-].
    allowable_temperature : float
        Matrix critical temperature [K]; no fixed point below it = thermal runaway.
    """

    reference_temperature: float = 20.0 + ZERO_CELSIUS
    modulus_decay: float = 40.0
    loss_growth: float = 60.0
    max_loss_factor: float = 1.0
    allowable_temperature: float = 100.0 + ZERO_CELSIUS

    def lamina(self, lamina: Lamina, temperature: float) -> Lamina:
        """The lamina at ``temperature`` [K] from its reference-temperature complex moduli."""
        dT = float(temperature) - self.reference_temperature
        soft = np.exp(-dT / self.modulus_decay)
        lossy = np.exp(dT / self.loss_growth)

        def matrix(E: complex) -> complex:
            eta = min(E.imag / E.real * lossy, self.max_loss_factor)
            return E.real * soft * (1 + 1j * eta)

        return Lamina(complex(lamina.E_L), matrix(complex(lamina.E_T)), matrix(complex(lamina.G_LT)),
                      lamina.nu_LT, lamina.density)


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


def fixed_point(update: Callable[[np.ndarray], np.ndarray], initial, allowable: float,
                tol: float = 1e-4, max_iter: int = 100) -> FixedPoint:
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


def _element_moduli(model: Model, law: MatrixTemperatureLaw, temperatures: np.ndarray):
    lam = model.shaft.laminate
    if lam is None:
        raise ValueError("self-heating needs a laminated (FMC) shaft; the model's shaft is isotropic")
    rounded = np.round(temperatures, 6)
    uniq, inverse = np.unique(rounded, return_inverse=True)
    E, G = np.empty(uniq.size, complex), np.empty(uniq.size, complex)
    for k, T in enumerate(uniq):
        E[k], G[k] = equivalent_moduli(Laminate(lam.angles, lam.thicknesses, law.lamina(lam.lamina, T)))
    return E[inverse.ravel()], G[inverse.ravel()]


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
    margin : float
        Allowable temperature − peak temperature [K] (negative at runaway).
    """

    status: str
    element_temperature: np.ndarray
    thermal: ShaftThermal
    iterations: int
    margin: float
    history: np.ndarray


def self_heating(
    model: Model, env: ThermalEnvironment | None = None, loss_model: LossModel = "thesis",
    law: MatrixTemperatureLaw | None = None, *, imbalance_scale: float = 1.0, static_scale: float = 1.0,
    air_temperature: float | None = None, tol: float = 1e-3, max_iter: int = 60, **thermal_kwargs,
) -> SelfHeating:
    """Iterate response → heat → temperature → lamina properties per element to a fixed point.

    ``imbalance_scale``/``static_scale`` multiply the imbalance and static loads (to find the
    load where runaway starts); other keywords go to :func:`shaft_thermal`.
    """
    law = law or MatrixTemperatureLaw()
    T_air = shaft_air_temperature(model.design, env) if air_temperature is None else float(air_temperature)
    nel = model.dofs.n_shaft_nodes - 1
    last: dict[str, ShaftThermal] = {}

    def update(T_el: np.ndarray) -> np.ndarray:
        E, G = _element_moduli(model, law, T_el)
        variant = model_with_shaft_moduli(model, E, G)
        q_imb, q_st = shaft_response_amplitudes(variant, imbalance_scale, static_scale)
        src = heat_sources(variant, loss_model, q_imb, q_st, loss_stiffness=shaft_stiffness_matrices(variant, E, G).imag)
        res = shaft_thermal(variant, env, loss_model, air_temperature=T_air, sources=src, **thermal_kwargs)
        last["thermal"] = res
        return res.temperature.element_temperature

    fp = fixed_point(update, np.full(nel, T_air), law.allowable_temperature, tol, max_iter)
    peak = float(last["thermal"].temperature.temperature.max())
    return SelfHeating(fp.status, fp.temperature, last["thermal"], fp.iterations,
                       law.allowable_temperature - peak, fp.history)


def runaway_onset(model: Model, scales, env: ThermalEnvironment | None = None, loss_model: LossModel = "thesis",
                  law: MatrixTemperatureLaw | None = None, refine: int = 0, **kwargs) -> tuple[float | None, list[SelfHeating]]:
    """First load multiple (imbalance and static loads scaled together, increasing ``scales``)
    at which the self-heating has no fixed point below the allowable temperature; ``refine``
    bisection steps then narrow it between the last stable and the first runaway scale.

    Returns ``(scale or None, results)``.
    """
    run = lambda s: self_heating(model, env, loss_model, law, imbalance_scale=float(s), static_scale=float(s), **kwargs)
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

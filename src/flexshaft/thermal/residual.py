r"""Thermal residual stress of a laminate whose matrix stiffens as it cools: the incremental integral.

A cured laminate is stress-free at T_sf (``stress_free_temperature_c``). Cooled to T, its plies
would shrink by different amounts (α_L ≈ 0 along the fibres, α_T ≈ 1e-4 1/K across them) and,
bonded, load each other. With moduli that do not depend on temperature the residual ply stress
is linear in the temperature change, ``σ = σ₁(Q) (T − T_sf)`` with σ₁ the stress per kelvin of
the free laminate (:func:`flexshaft.laminate.thermal_ply_stresses`).

A urethane matrix's transverse and shear moduli grow by large factors as it cools (the
lamina's temperature table or the ``[thermal]`` law: ×33 from 100 °C to −40 °C with
θ_E = 40 K). Taking the final, cold moduli for the whole cool-down, ``σ₁(Q(T)) (T − T_sf)``,
supposes that a strain imposed while the matrix was soft is carried at the stiffness it has
later. For a polymer in its transition region that is not what happens: the modulus rises
on cooling because relaxation slows (time-temperature superposition), which does not raise the
stress already carried; each increment of the thermal mismatch is carried at the stiffness of
the moment. Summed over the cool-down (the elastic limit of linear thermo-viscoelasticity
without relaxation; relaxation during and after the cool-down lowers the stress further)::

    σ(T) = ∫_{T_sf}^{T} σ₁(Q(T')) dT'                                                      (1)

where σ₁(Q(T')) is the stress increment per kelvin of the free laminate with the plies'
moduli at T'. It is exact for moduli that do not vary (then (1) is the linear result), and an
upper bound of the viscoelastic residual stress when they do. The secant form overestimates it:
for E_T ∝ exp(−(T − T_ref)/θ) cooled by ΔT, the ratio of the two is
θ (e^{ΔT/θ} − 1)/(ΔT e^{ΔT/θ}), 0.28 from 100 °C to −40 °C with θ = 40 K.

Quadrature: composite Gauss-Legendre, four points on each sub-interval of at most
:data:`MAX_STEP` kelvin, the sub-intervals also breaking at the rows of a temperature table
(where the piecewise-exponential interpolation has a kink): the law's integrand is smooth and
the 4-point rule on 10 K steps integrates an exponential of scale θ = 40 K to ~1e-11.

Beyond the table's ends the properties are held at the end row's values (a table is never
extrapolated): a cool-down starting above the table's top uses its top row there.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from flexshaft.laminate import Laminate, thermal_ply_stresses
from flexshaft.thermal.matrix import MatrixTemperatureLaw

__all__ = ["MAX_STEP", "residual_ply_stresses", "secant_ply_stresses"]

#: Longest sub-interval of the quadrature of eq. (1) [K].
MAX_STEP = 10.0
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(4)


def _laminate_at(laminate: Laminate, law: MatrixTemperatureLaw, temperature: float) -> Laminate:
    """``laminate`` with its lamina at ``temperature`` [K] (held at the table's ends)."""
    if law.table is not None:
        temperature = min(max(temperature, law.table.temperatures[0]), law.table.temperatures[-1])
    return dataclasses.replace(laminate, lamina=law.lamina(laminate.lamina, temperature))


def _breaks(law: MatrixTemperatureLaw, start: float, end: float) -> np.ndarray:
    """Sub-interval ends from ``start`` to ``end`` [K]: the table's rows between them, then each
    piece cut into equal steps of at most :data:`MAX_STEP`."""
    low, high = min(start, end), max(start, end)
    rows = [] if law.table is None else [t for t in law.table.temperatures if low < t < high]
    knots = np.array(sorted({low, high, *rows}))
    pieces = [np.linspace(a, b, max(1, int(np.ceil((b - a) / MAX_STEP))) + 1) for a, b in zip(knots[:-1], knots[1:])]
    out = np.unique(np.concatenate(pieces)) if pieces else np.array([low, high])
    return out if start <= end else out[::-1]


def residual_ply_stresses(
    laminate: Laminate, law: MatrixTemperatureLaw, stress_free_temperature: float, temperature: float
) -> np.ndarray:
    """Residual ply stresses (n_plies, 3) [Pa] at ``temperature`` by the incremental integral (1).

    Parameters
    ----------
    laminate : Laminate
        The laminate with its lamina at the law's reference temperature (the model's).
    law : MatrixTemperatureLaw
        How its moduli vary with temperature (:func:`flexshaft.thermal.options.matrix_law_from`,
        with the lamina's table when it has one).
    stress_free_temperature : float
        T_sf [K].
    temperature : float
        T [K].

    Returns
    -------
    ndarray, shape (n_plies, 3)
        (σ1, σ2, τ12) [Pa] of each ply in its material axes.
    """
    for name, value in (("stress_free_temperature", stress_free_temperature), ("temperature", temperature)):
        if not (np.isfinite(value) and value > 0):
            raise ValueError(f"{name} must be a positive absolute temperature [K] (got {value!r})")
    total = np.zeros((laminate.angles.size, 3))
    knots = _breaks(law, float(stress_free_temperature), float(temperature))
    for a, b in zip(knots[:-1], knots[1:]):
        half, middle = 0.5 * (b - a), 0.5 * (a + b)
        for x, w in zip(_NODES, _WEIGHTS):
            total += thermal_ply_stresses(_laminate_at(laminate, law, middle + half * x), w * half)
    return total


def secant_ply_stresses(
    laminate: Laminate, law: MatrixTemperatureLaw, stress_free_temperature: float, temperature: float
) -> np.ndarray:
    """The secant form σ₁(Q(T)) (T − T_sf) (n_plies, 3) [Pa]: the moduli at ``temperature`` for
    the whole cool-down (module docstring; what the strength check without this module does)."""
    return thermal_ply_stresses(
        _laminate_at(laminate, law, float(temperature)), float(temperature) - float(stress_free_temperature)
    )

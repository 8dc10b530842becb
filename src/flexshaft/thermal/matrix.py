"""Temperature dependence of the matrix-dominated lamina properties (assumed law).

The polyurethane matrix softens and gets lossier as it warms; the fibre properties (E_L, η_L)
do not change. :class:`MatrixTemperatureLaw` is a documented, assumed shift law (no data in the
thesis)::

    E_T(T)  = E_T(T_ref)  · exp(−(T − T_ref)/θ_E),     G_LT likewise,
    η_T(T)  = min(η_T(T_ref)  · exp(+(T − T_ref)/θ_η), η_max),   η_LT likewise,

with T_ref = 20 °C (the 10 Hz lamina data), θ_E = 40 K (the rubbery-plateau modulus of a
90A urethane roughly halves every 28 K as the hard segments soften), θ_η = 60 K and an
allowable temperature of 100 °C (hard-segment softening; the thesis's "critical temperature of
the matrix"). Replace it with measured master curves when available.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flexshaft.laminate import Lamina
from flexshaft.units import celsius_to_kelvin

__all__ = ["MatrixTemperatureLaw"]


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

    reference_temperature: float = celsius_to_kelvin(20.0)
    modulus_decay: float = 40.0
    loss_growth: float = 60.0
    max_loss_factor: float = 1.0
    allowable_temperature: float = celsius_to_kelvin(100.0)

    def __post_init__(self) -> None:
        for name in (
            "reference_temperature",
            "modulus_decay",
            "loss_growth",
            "max_loss_factor",
            "allowable_temperature",
        ):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"MatrixTemperatureLaw.{name} must be finite and > 0, got {value!r}")

    def lamina(self, lamina: Lamina, temperature: float) -> Lamina:
        """The lamina at ``temperature`` [K] from its reference-temperature complex moduli."""
        dT = float(temperature) - self.reference_temperature
        soft = np.exp(-dT / self.modulus_decay)
        lossy = np.exp(dT / self.loss_growth)

        def matrix(E: complex) -> complex:
            eta = min(E.imag / E.real * lossy, self.max_loss_factor)
            return E.real * soft * (1 + 1j * eta)

        return Lamina(
            complex(lamina.E_L), matrix(complex(lamina.E_T)), matrix(complex(lamina.G_LT)), lamina.nu_LT, lamina.density
        )

"""Temperature dependence of the lamina: a table over temperature, or the assumed law.

The polyurethane matrix softens and gets lossier as it warms; the fibre properties (E_L, η_L)
do not change unless a table says so. There is one way to get a lamina at a temperature,
:meth:`MatrixTemperatureLaw.properties` (its wrappers :meth:`MatrixTemperatureLaw.lamina` for
the analyses' complex-modulus lamina and :meth:`MatrixTemperatureLaw.material` for the
design file's lamina), with two sources:

* a :class:`LaminaTable` (the design file's ``[materials.<name>.temperature_table]``): storage
  moduli and loss factors at listed temperatures. Between rows each property is interpolated
  linearly in temperature on its logarithm,

      ln p(T) = ln p_i + (T − T_i)/(T_(i+1) − T_i) · (ln p_(i+1) − ln p_i),

  i.e. piecewise exponential: the form of the law below (which the table then reproduces
  exactly) and of dynamic-mechanical data read on a log scale, positive by construction.
  Outside the table nothing is extrapolated: a temperature beyond its ends is refused with the
  temperature and the range (an Arrhenius or WLF shift carried past the measured range, across
  a glass transition, would be a guess presented as data). The lamina's own values stay its
  values at the reference temperature, and the table gives the variation from there:
  p(T) = p_ref · p_table(T)/p_table(T_ref) (= p_table(T) when the table's reference row repeats
  the lamina's values; a loss factor is capped at ``max_loss_factor`` like the law's).
* without a table, the documented, assumed shift law (no data in the thesis)::

      E_T(T)  = E_T(T_ref)  · exp(−(T − T_ref)/θ_E),     G_LT likewise,
      η_T(T)  = min(η_T(T_ref)  · exp(+(T − T_ref)/θ_η), η_max),   η_LT likewise,

  with T_ref = 20 °C (the 10 Hz lamina data), θ_E = 40 K (the rubbery-plateau modulus of a
  90A urethane roughly halves every 28 K as the hard segments soften), θ_η = 60 K and an
  allowable temperature of 100 °C (hard-segment softening; the thesis's "critical temperature
  of the matrix").

The table of a design's shaft lamina takes precedence (:func:`matrix_law_for`); the law's
allowable temperature applies to both.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from flexshaft.design.materials import Lamina as LaminaMaterial
from flexshaft.design.temperature_table import TABLE_COLUMNS, TemperatureTable
from flexshaft.laminate import Lamina
from flexshaft.units import celsius_to_kelvin, kelvin_to_celsius

__all__ = ["PROPERTY_NAMES", "LaminaTable", "MatrixTemperatureLaw", "matrix_law_for"]

#: The temperature-dependent properties of a lamina: storage moduli [Pa] and loss factors [-],
#: named as the design file's lamina keys.
PROPERTY_NAMES = TABLE_COLUMNS


@dataclass(frozen=True)
class LaminaTable:
    """Lamina properties at listed temperatures (SI), interpolated on their logarithms.

    Parameters
    ----------
    temperatures : tuple of float
        Strictly increasing temperatures [K], at least two.
    columns : tuple of (str, tuple of float)
        (property name, values) pairs, one value per temperature, every value > 0; names from
        :data:`PROPERTY_NAMES` (storage moduli [Pa], loss factors [-]).
    """

    temperatures: tuple[float, ...]
    columns: tuple[tuple[str, tuple[float, ...]], ...]

    def __post_init__(self) -> None:
        T = np.asarray(self.temperatures, dtype=float)
        if T.ndim != 1 or T.size < 2 or not np.all(np.isfinite(T)) or not np.all(np.diff(T) > 0.0) or T[0] <= 0.0:
            raise ValueError(
                f"LaminaTable.temperatures must be at least two strictly increasing absolute temperatures [K], "
                f"got {self.temperatures!r}"
            )
        for name, values in self.columns:
            if name not in PROPERTY_NAMES:
                raise ValueError(f"LaminaTable column {name!r} is not one of {PROPERTY_NAMES}")
            v = np.asarray(values, dtype=float)
            if v.shape != T.shape or not np.all(np.isfinite(v)) or not np.all(v > 0.0):
                raise ValueError(
                    f"LaminaTable column {name} must hold {T.size} finite values > 0 (one per temperature), "
                    f"got {values!r}"
                )

    @classmethod
    def from_schema(cls, table: TemperatureTable) -> LaminaTable:
        """The table of a design file (°C → K)."""
        return cls(
            tuple(celsius_to_kelvin(t) for t in table.temperature_c),
            tuple((name, tuple(float(v) for v in values)) for name, values in table.columns().items()),
        )

    @property
    def range_c(self) -> tuple[float, float]:
        """(lowest, highest) temperature of the table [°C]."""
        return kelvin_to_celsius(self.temperatures[0]), kelvin_to_celsius(self.temperatures[-1])

    def at(self, temperature: float) -> dict[str, float]:
        """Every column at ``temperature`` [K]: exact at a row, log-linear between rows.

        Raises
        ------
        ValueError
            When ``temperature`` lies outside the table (no extrapolation).
        """
        T = float(temperature)
        low, high = self.temperatures[0], self.temperatures[-1]
        if not low <= T <= high:
            lo_c, hi_c = self.range_c
            raise ValueError(
                f"temperature {kelvin_to_celsius(T):.6g} °C is outside the lamina's temperature_table "
                f"[{lo_c:.6g}, {hi_c:.6g}] °C; the table is not extrapolated: extend it"
            )
        index = int(np.searchsorted(self.temperatures, T, side="right")) - 1
        if self.temperatures[index] == T:
            return {name: values[index] for name, values in self.columns}
        t0, t1 = self.temperatures[index], self.temperatures[index + 1]
        w = (T - t0) / (t1 - t0)
        return {name: values[index] * (values[index + 1] / values[index]) ** w for name, values in self.columns}


@dataclass(frozen=True)
class MatrixTemperatureLaw:
    """Temperature dependence of the lamina properties: a table, or the assumed law (module).

    Parameters
    ----------
    reference_temperature : float
        Temperature of the lamina data [K]: the lamina's own values apply there.
    modulus_decay : float
        θ_E [K]: E_T and G_LT scale by exp(−ΔT/θ_E) (law only).
    loss_growth : float
        θ_η [K]: η_T and η_LT scale by exp(+ΔT/θ_η), capped at ``max_loss_factor`` (law only).
    max_loss_factor : float
        Cap on the matrix loss factors [-] (law only).
    allowable_temperature : float
        Matrix critical temperature [K]; no fixed point below it = thermal runaway.
    table : LaminaTable or None
        Properties at listed temperatures, spanning the reference temperature; when given it
        replaces the law (each property follows the table's ratio to its reference value).
    """

    reference_temperature: float = celsius_to_kelvin(20.0)
    modulus_decay: float = 40.0
    loss_growth: float = 60.0
    max_loss_factor: float = 1.0
    allowable_temperature: float = celsius_to_kelvin(100.0)
    table: LaminaTable | None = None

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

    def properties(self, reference: Mapping[str, float], temperature: float) -> dict[str, float]:
        """The lamina's storage moduli [Pa] and loss factors [-] at ``temperature`` [K].

        ``reference`` holds the values of :data:`PROPERTY_NAMES` at the reference temperature.
        With a table, each of its columns scales its value by p_table(T)/p_table(T_ref) (the
        others are kept); otherwise the law scales E_T, G_LT and their loss factors (E_L and
        loss_E_L are kept). Loss factors are capped at ``max_loss_factor``. At the reference
        temperature the reference values come back unchanged (exactly).
        """
        values = {name: float(reference[name]) for name in PROPERTY_NAMES}
        T = float(temperature)
        if not math.isfinite(T) or T <= 0.0:
            raise ValueError(f"temperature must be a positive absolute temperature [K], got {temperature!r}")
        if T == self.reference_temperature:
            return values
        if self.table is not None:
            at_T, at_ref = self.table.at(T), self.table.at(self.reference_temperature)
            for name in at_T:
                if values[name] == at_ref[name]:  # the table's own value, exactly at its rows
                    values[name] = at_T[name]
                else:
                    values[name] *= at_T[name] / at_ref[name]
                if name.startswith("loss_"):
                    values[name] = min(values[name], self.max_loss_factor)
            return values
        dT = T - self.reference_temperature
        soft = math.exp(-dT / self.modulus_decay)
        lossy = math.exp(dT / self.loss_growth)
        for modulus in ("E_T", "G_LT"):
            values[modulus] *= soft
            values["loss_" + modulus] = min(values["loss_" + modulus] * lossy, self.max_loss_factor)
        return values

    def lamina(self, lamina: Lamina, temperature: float) -> Lamina:
        """The analyses' complex-modulus lamina at ``temperature`` [K] from its reference values.

        G_13 and G_23 follow G_LT and E_T in proportion (their defaults G_LT and E_T/3 stay
        so); the other fields are kept.
        """
        reference = {}
        for name in ("E_L", "E_T", "G_LT"):
            modulus = complex(getattr(lamina, name))
            reference[name], reference["loss_" + name] = modulus.real, modulus.imag / modulus.real
        new = self.properties(reference, temperature)

        def complex_modulus(name: str) -> complex:
            unchanged = new[name] == reference[name] and new["loss_" + name] == reference["loss_" + name]
            return complex(getattr(lamina, name)) if unchanged else new[name] * (1 + 1j * new["loss_" + name])

        E_L, E_T, G_LT = complex_modulus("E_L"), complex_modulus("E_T"), complex_modulus("G_LT")
        G_13, G_23 = lamina.transverse_shear_moduli
        return dataclasses.replace(
            lamina,
            E_L=E_L,
            E_T=E_T,
            G_LT=G_LT,
            G_13=G_13 * (G_LT / complex(lamina.G_LT)),
            G_23=G_23 * (E_T / complex(lamina.E_T)),
        )

    def material(self, material: LaminaMaterial, temperature: float) -> LaminaMaterial:
        """The design file's lamina at ``temperature`` [K]: its moduli and loss factors replaced.

        Explicit ``G_13`` and ``G_23`` scale with G_LT and E_T; strengths, expansion and the
        table itself are kept (the caller moves the reference temperature to ``temperature``,
        see :func:`flexshaft.thermal.envelope.design_at_point`).
        """
        reference = {name: getattr(material, name) for name in PROPERTY_NAMES}
        new = self.properties(reference, temperature)
        if new == reference:
            return material
        update = dict(new)
        if material.G_13 is not None:
            update["G_13"] = material.G_13 * new["G_LT"] / reference["G_LT"]
        if material.G_23 is not None:
            update["G_23"] = material.G_23 * new["E_T"] / reference["E_T"]
        return LaminaMaterial.model_validate({**material.model_dump(), **update})


def matrix_law_for(material, law: MatrixTemperatureLaw) -> MatrixTemperatureLaw:
    """``law`` with the temperature table of ``material`` when it has one (the table wins).

    ``material`` is a design-file material (or None); an isotropic material or a lamina
    without a table leaves the law as it is.
    """
    table = getattr(material, "temperature_table", None)
    if table is None:
        return law
    return dataclasses.replace(law, table=LaminaTable.from_schema(table))

"""Materials of the design file: ``[materials.<name>]`` tables, an orthotropic ply or an isotropic metal.

Moduli are storage values [Pa], loss factors are dimensionless, densities [kg/m³]. The ``kind``
key selects the model (``"lamina"`` or ``"isotropic"``).
"""

from __future__ import annotations

import math
from typing import Annotated, Literal, Union

from pydantic import Field, model_validator

from flexshaft.design.fields import (
    Finite,
    FrozenModel,
    LossFactor,
    NonNegative,
    Positive,
    Problems,
    format_number,
    format_value,
)

__all__ = ["Isotropic", "Lamina", "Material"]


class Lamina(FrozenModel):
    """Orthotropic unidirectional ply with hysteretic (complex) moduli.

    Moduli are storage values [Pa]; ``loss_*`` are loss factors η, so the complex modulus is
    E' (1 + iη). Strengths are positive magnitudes [Pa]. ``F12`` is the Tsai-Wu interaction
    coefficient [1/Pa²]; when omitted the analysis uses −½·sqrt(F11·F22).
    """

    kind: Literal["lamina"]
    density: Positive
    E_L: Positive
    E_T: Positive
    G_LT: Positive
    nu_LT: NonNegative
    loss_E_L: LossFactor = 0.0
    loss_E_T: LossFactor = 0.0
    loss_G_LT: LossFactor = 0.0
    X_t: Positive
    X_c: Positive
    Y_t: Positive
    Y_c: Positive
    S: Positive
    F12: Finite | None = None

    @model_validator(mode="after")
    def _check(self) -> Lamina:
        problems = Problems()
        limit = math.sqrt(self.E_L / self.E_T)
        if not self.nu_LT < limit:
            problems.add(
                ("nu_LT",),
                f"must be less than sqrt(E_L/E_T) = {format_number(limit)} for a positive-definite ply "
                f"stiffness (got {format_value(self.nu_LT)})",
            )
        if self.F12 is not None:
            bound = math.sqrt(1.0 / (self.X_t * self.X_c * self.Y_t * self.Y_c))
            if not abs(self.F12) < bound:
                problems.add(
                    ("F12",),
                    f"|F12| must be less than sqrt(F11*F22) = {format_number(bound)} 1/Pa^2 for a closed "
                    f"Tsai-Wu envelope (got {format_value(self.F12)})",
                )
        problems.raise_if_any()
        return self

    @property
    def nu_TL(self) -> float:
        """Minor Poisson ratio ν_TL = ν_LT E_T / E_L [-]."""
        return self.nu_LT * self.E_T / self.E_L


class Isotropic(FrozenModel):
    """Isotropic material: moduli [Pa], density [kg/m³], structural loss factor [-]."""

    kind: Literal["isotropic"]
    E: Positive
    G: Positive
    density: Positive
    loss_factor: LossFactor = 0.0

    @model_validator(mode="after")
    def _check(self) -> Isotropic:
        problems = Problems()
        if not self.poisson_ratio <= 0.5:
            problems.add(
                ("G",),
                f"gives Poisson ratio E/(2G) - 1 = {format_number(self.poisson_ratio)}, outside (-1, 0.5] "
                f"(got {format_value(self.G)}; allowed: G >= E/3 = {format_number(self.E / 3.0)} Pa)",
            )
        problems.raise_if_any()
        return self

    @property
    def poisson_ratio(self) -> float:
        """ν = E/(2G) − 1 [-]."""
        return self.E / (2.0 * self.G) - 1.0


Material = Annotated[Union[Lamina, Isotropic], Field(discriminator="kind")]

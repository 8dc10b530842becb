"""The ``[requirements]`` table of the design file: the limits a design's results must meet.

Every field has a default that a user overrides; the defaults and their sources are stated in
``docs/requirements.md``. Quantities are SI: ``min_onset_margin`` is a fraction of the operating
speed (0.15 = 15 % above it), ``max_spinup_deflection`` a length [m]. The limits that belong to
a component live with it: the auxiliary-bearing gap and the force capacity on each active
bearing (``gap`` [m], ``force_capacity`` [N]) and the matrix allowable temperature in
``[thermal] allowable_temperature_c``.

The whirl damping requirement is a minimum logarithmic decrement δ of every mode at the
operating speed, or equivalently a minimum damping ratio ζ (δ = 2πζ/√(1 − ζ²)); give at most
one of the two. With neither, δ ≥ 0.1 applies (API 617's acceptance level).
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import Field, model_validator

from flexshaft.design.fields import FrozenModel, Problems, format_value
from flexshaft.design.quantities import Deflection, SafetyFactor

__all__ = [
    "DEFAULT_MAX_SENSITIVITY_PEAK",
    "DEFAULT_MIN_GAIN_MARGIN_DB",
    "DEFAULT_MIN_LOG_DECREMENT",
    "DEFAULT_MIN_PHASE_MARGIN_DEG",
    "DEFAULT_MIN_TORSIONAL_SEPARATION",
    "Requirements",
    "log_decrement_from_damping_ratio",
]

#: API 617 acceptance level of the logarithmic decrement, used when neither whirl damping
#: requirement is given.
DEFAULT_MIN_LOG_DECREMENT = 0.1
#: Separation of every torsional natural frequency from every excitation frequency over the
#: operating speed range (API's 10 %, docs/requirements.md).
DEFAULT_MIN_TORSIONAL_SEPARATION = 0.10
#: Largest sensitivity peak |S|max of a magnetic-bearing loop: the upper limit of ISO 14839-3's
#: zone B (docs/requirements.md).
DEFAULT_MAX_SENSITIVITY_PEAK = 4.0
#: Smallest gain margin of a magnetic-bearing loop, either way [dB] (assumed, docs/requirements.md).
DEFAULT_MIN_GAIN_MARGIN_DB = 6.0
#: Smallest phase margin of a magnetic-bearing loop [deg] (assumed, docs/requirements.md).
DEFAULT_MIN_PHASE_MARGIN_DEG = 30.0

Margin = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        ge=0.0,
        le=10.0,
        description=("margin as a fraction of the operating speed, 0 to 10"),
        json_schema_extra={"unit": "-"},
    ),
]
LogDecrement = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        ge=0.0,
        le=100.0,
        description=("logarithmic decrement, 0 to 100"),
        json_schema_extra={"unit": "-"},
    ),
]
DampingRatio = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        ge=0.0,
        lt=1.0,
        description=("damping ratio in [0, 1)"),
        json_schema_extra={"unit": "-"},
    ),
]


Fraction = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        ge=0.0,
        le=1.0,
        description=("fraction from 0 to 1"),
        json_schema_extra={"unit": "-"},
    ),
]
SensitivityPeak = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        gt=1.0,
        le=100.0,
        description=("sensitivity-function peak |S|max, above 1 (every loop reaches 1) and at most 100"),
        json_schema_extra={"unit": "-"},
    ),
]
GainMarginDb = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        ge=0.0,
        le=60.0,
        description=("gain margin in dB, 0 to 60"),
        json_schema_extra={"unit": "dB"},
    ),
]
PhaseMarginDeg = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        ge=0.0,
        le=90.0,
        description=("phase margin in degrees, 0 to 90"),
        json_schema_extra={"unit": "deg"},
    ),
]


def log_decrement_from_damping_ratio(damping_ratio: float) -> float:
    """δ = 2πζ/√(1 − ζ²) of a damping ratio ζ in [0, 1)."""
    return 2.0 * math.pi * damping_ratio / math.sqrt(1.0 - damping_ratio * damping_ratio)


class Requirements(FrozenModel):
    """Limits the results of a design must meet (``[requirements]``; see docs/requirements.md).

    Attributes
    ----------
    min_safety_factor : float
        Minimum ply Tsai-Wu safety factor under the static loads plus the imbalance response
        at the operating speed [-].
    min_buckling_safety_factor : float
        Minimum torsional-buckling safety factor T_cr/T [-].
    min_onset_margin : float
        Whirl instability must not start below (1 + margin) × the operating speed [-].
    min_log_decrement : float or None
        Minimum log decrement δ [-] of every whirl mode at the operating speed; give at most
        one of this and ``min_damping_ratio``; neither means δ ≥ 0.1.
    min_damping_ratio : float or None
        Minimum damping ratio ζ [-], checked as δ = 2πζ/√(1 − ζ²); instead of
        ``min_log_decrement``.
    separation : {"api684", "off"}
        Separation margin of the lateral critical speeds from the operating speed by the
        amplification-factor rule of API 684 / API 617, or no separation requirement.
    max_spinup_deflection : float or None
        Largest allowed shaft orbit amplitude during spin-up to the operating speed [m]; None:
        no limit (the check is reported as not evaluated).
    min_torsional_separation : float
        Smallest separation of every torsional natural frequency from every excitation
        frequency over the operating speed range, a fraction of the excitation frequency [-].
    max_sensitivity_peak : float
        Largest sensitivity-function peak |S|max of every magnetic-bearing loop [-] (4: the
        upper limit of ISO 14839-3's zone B; 3 for zone A).
    min_gain_margin_db : float
        Smallest gain margin of every magnetic-bearing loop, for a gain rise and a gain fall [dB].
    min_phase_margin_deg : float
        Smallest phase margin of every magnetic-bearing loop [deg].
    """

    min_safety_factor: SafetyFactor = 1.5
    min_buckling_safety_factor: SafetyFactor = 2.0
    min_onset_margin: Margin = 0.15
    min_log_decrement: LogDecrement | None = None
    min_damping_ratio: DampingRatio | None = None
    separation: Literal["api684", "off"] = "api684"
    max_spinup_deflection: Deflection | None = None
    min_torsional_separation: Fraction = DEFAULT_MIN_TORSIONAL_SEPARATION
    max_sensitivity_peak: SensitivityPeak = DEFAULT_MAX_SENSITIVITY_PEAK
    min_gain_margin_db: GainMarginDb = DEFAULT_MIN_GAIN_MARGIN_DB
    min_phase_margin_deg: PhaseMarginDeg = DEFAULT_MIN_PHASE_MARGIN_DEG

    @model_validator(mode="after")
    def _check(self) -> Requirements:
        problems = Problems()
        if self.min_log_decrement is not None and self.min_damping_ratio is not None:
            problems.add(
                ("min_damping_ratio",),
                "give at most one of min_log_decrement and min_damping_ratio "
                f"(got min_log_decrement = {format_value(self.min_log_decrement)}, "
                f"min_damping_ratio = {format_value(self.min_damping_ratio)})",
            )
        problems.raise_if_any()
        return self

    @property
    def required_log_decrement(self) -> float:
        """The whirl damping requirement as a log decrement δ [-]."""
        if self.min_log_decrement is not None:
            return self.min_log_decrement
        if self.min_damping_ratio is not None:
            return log_decrement_from_damping_ratio(self.min_damping_ratio)
        return DEFAULT_MIN_LOG_DECREMENT

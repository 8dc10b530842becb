"""The evidence a requirements verdict judges: the few numbers each requirement needs, in SI,
with where they occur.

:func:`flexshaft.verdict.gather.gather_evidence` builds an :class:`Evidence` from the analyses of
an operating point; :func:`flexshaft.verdict.checks.evaluate` checks it against the design's
requirements. Tests fill it directly.

Locations are small mappings with SI values (``station`` [m], ``speed`` [rad/s], ``frequency``
[rad/s]) and labels (``actuator``, ``mode``, ``ply``, ``case``, ``detail``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from flexshaft.analyses.criticals import LateralCritical

__all__ = [
    "ActuatorEvidence",
    "CouplingEvidence",
    "Evidence",
    "LateralCritical",
    "Location",
    "LoopEvidence",
    "MetalEvidence",
    "ModeDamping",
    "TorsionalEvidence",
]

#: Where a value occurs: SI values and labels.
Location = Mapping[str, Any]


@dataclass(frozen=True)
class ModeDamping:
    """One mode at the operating speed: damped natural frequency [rad/s], log decrement [-]."""

    label: str
    frequency: float
    log_decrement: float


@dataclass(frozen=True)
class ActuatorEvidence:
    """Peaks of one active bearing and its limits.

    Attributes
    ----------
    name : str
    peak_orbit : float
        Largest relative orbit amplitude (shaft − attachment) during spin-up [m].
    orbit_speed : float
        Speed of that peak [rad/s].
    peak_force : float
        Largest force amplitude during spin-up [N].
    force_speed : float
        Speed of that peak [rad/s].
    static_offset, static_force : float
        Static relative displacement [m] and force [N] under the static loads; the checks add
        them to the peaks (the orbit is centred on the static position).
    gap, force_capacity : float or None
        Auxiliary-bearing radial clearance [m] and actuator force capacity [N]; None: not given.
    """

    name: str
    peak_orbit: float
    orbit_speed: float
    peak_force: float
    force_speed: float
    static_offset: float = 0.0
    static_force: float = 0.0
    gap: float | None = None
    force_capacity: float | None = None


@dataclass(frozen=True)
class MetalEvidence:
    """The smallest safety factor [-] of one criterion in one metal segment, and its station [m].

    ``criterion`` names it, e.g. "fatigue (modified Goodman)" or "yield (von Mises)".
    """

    segment: str
    criterion: str
    safety_factor: float
    station: float


@dataclass(frozen=True)
class CouplingEvidence:
    """Misalignment of one coupling: static and whirling angle [rad], allowable [rad] or None."""

    name: str
    station: float
    static_angle: float
    dynamic_angle: float
    allowable_angle: float | None = None


@dataclass(frozen=True)
class TorsionalEvidence:
    """One torsional mode against its nearest excitation over the operating speed range.

    ``frequency`` is its natural frequency [rad/s], ``margin`` the separation
    min |f_n − f_e|/f_e over the excitation's band [-] (0 inside it), ``excitation`` its name
    (e.g. "tail rotor 4/rev") and ``band`` the excitation's frequencies [rad/s] at the lowest
    and highest operating speeds.
    """

    label: str
    frequency: float
    margin: float
    excitation: str
    band: tuple[float, float]


@dataclass(frozen=True)
class LoopEvidence:
    """Robustness of one control axis of one magnetic bearing.

    ``peak_sensitivity`` max |S(iω)| [-] at ``peak_frequency`` [rad/s];
    ``gain_margin_upper`` / ``gain_margin_lower`` [dB]: the smallest gain rise (> 0) and the
    gain fall nearest 0 dB (< 0) that put the loop on −1 (None: no phase crossover of that
    kind in the frequency range); ``phase_margin`` [rad] the smallest over the gain crossovers
    (None: none); ``speed`` [rad/s] the spin speed of the loop.
    """

    actuator: str
    axis: str
    speed: float
    peak_sensitivity: float
    peak_frequency: float
    gain_margin_upper: float | None = None
    gain_margin_lower: float | None = None
    phase_margin: float | None = None
    phase_margin_frequency: float | None = None


@dataclass(frozen=True)
class Evidence:
    """The results a verdict needs, SI units; None where the result does not exist.

    Attributes
    ----------
    operating_speed : float
        Ω_op [rad/s].
    operating_range : (float, float) or None
        The lowest and highest operating speeds [rad/s] (``[operating] speed_range``; None:
        Ω_op alone): the separation margins are measured from them, the spin-up peaks taken
        up to the highest.
    safety_factor, safety_factor_location
        Minimum Tsai-Wu safety factor [-] and where it occurs.
    buckling_safety_factor, buckling_location
        Torsional-buckling safety factor [-] and the governing torque sense.
    stability_max_speed : float or None
        Highest speed of the stability analysis [rad/s]; None: no stability analysis.
    onset_speed, onset_location
        Lowest whirl-instability onset speed [rad/s] (None: stable up to ``stability_max_speed``)
        and the unstable mode or root: of the tracked modes, or the lowest speed of the
        every-root check (:mod:`flexshaft.analyses.root_stability`) with an unstable root (the
        onset is then at or below it).
    modes_at_operating : tuple of ModeDamping or None
        The lateral whirl modes at the operating speed (shaft share at least 10 %).
    whirl_modes_top : float or None
        Frequency of the highest lateral whirl mode computed at the operating speed [rad/s]
        (whatever its shaft share): the whirl-damping check holds no mode above it.
    whirl_scope : float or None
        Damped frequency [rad/s] below which every lateral mode at the operating speed is held
        (:func:`~flexshaft.verdict.point_tasks.required_onset_speed`).
    critical_speeds : tuple of LateralCritical or None
        Lateral critical speeds (peaks of the unbalance response) with their AF.
    critical_search_max_speed : float or None
        Highest speed searched for critical speeds [rad/s].
    actuators : tuple of ActuatorEvidence
    max_temperature, temperature_location, thermal_runaway
        Maximum shaft temperature [K], where, and whether the self-heating ran away.
    self_heating_status : str or None
        The self-heating iteration's status ("converged", "runaway", "not_converged"); None
        without self-heating (constant properties).
    allowable_temperature : float or None
        Matrix allowable temperature [K].
    spinup_peak, spinup_location
        Largest shaft orbit amplitude during spin-up [m] and where (station, speed).
    metal_strength : tuple of MetalEvidence or None
        Safety factors of the isotropic segments; None: the shaft has none (no check).
    coupling_angles : tuple of CouplingEvidence or None
        Misalignment of every coupling; None: the design has no couplings (no check).
    strength_note : str
        How the ply check took its compressive strength and torque (kink band or X_c, the
        torque factor), shown with the ``tsai_wu`` check.
    torque_factor : float
        Peak over steady torque of the torsional forced response [-] (1 without one).
    torsional_modes : tuple of TorsionalEvidence or None
        Every torsional mode checked for separation; None: not evaluated (see ``notes``).
    loops : tuple of LoopEvidence or None
        Every control axis of the magnetic bearings; None: no active bearings.
    notes : mapping
        Check key -> why its evidence is missing (shown as "not evaluated: <note>").
    """

    operating_speed: float
    operating_range: tuple[float, float] | None = None
    safety_factor: float | None = None
    safety_factor_location: Location = field(default_factory=dict)
    buckling_safety_factor: float | None = None
    buckling_location: Location = field(default_factory=dict)
    stability_max_speed: float | None = None
    onset_speed: float | None = None
    onset_location: Location = field(default_factory=dict)
    modes_at_operating: tuple[ModeDamping, ...] | None = None
    whirl_modes_top: float | None = None
    whirl_scope: float | None = None
    critical_speeds: tuple[LateralCritical, ...] | None = None
    critical_search_max_speed: float | None = None
    actuators: tuple[ActuatorEvidence, ...] = ()
    max_temperature: float | None = None
    temperature_location: Location = field(default_factory=dict)
    thermal_runaway: bool = False
    self_heating_status: str | None = None
    allowable_temperature: float | None = None
    spinup_peak: float | None = None
    spinup_location: Location = field(default_factory=dict)
    metal_strength: tuple[MetalEvidence, ...] | None = None
    coupling_angles: tuple[CouplingEvidence, ...] | None = None
    strength_note: str = ""
    torque_factor: float = 1.0
    torsional_modes: tuple[TorsionalEvidence, ...] | None = None
    loops: tuple[LoopEvidence, ...] | None = None
    notes: Mapping[str, str] = field(default_factory=dict)

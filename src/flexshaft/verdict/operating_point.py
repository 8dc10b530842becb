"""Every analysis of a design at one operating point: the recipe the verdict judges.

:func:`analyse_point` builds the design's model and runs, at the grids of a
:class:`~flexshaft.resolution.Resolution`, the analyses the requirements read:

* modes at the operating speed (the lateral whirl modes: as many more modes as it takes to hold
  ``resolution.modes`` lateral ones), the spin-up imbalance response and the lateral critical
  speeds on it, static loads and bearing reactions;
* the torsional modes, their separation from the excitations over the operating speed range,
  and the forced response to the tail rotor's torque oscillation
  (:mod:`flexshaft.analyses.torsional`), whose torque factor multiplies the steady torque of
  the strength and buckling checks;
* ply strength with the effective compressive strength min(X_c, kink band)
  (:func:`flexshaft.strength.compressive_strength`) and the thermal residual stress integrated
  over the cool-down (:mod:`flexshaft.thermal.residual`), metal strength, coupling
  misalignment, torsional buckling, the shaft's self-heating;
* whirl stability of the tracked modes (:mod:`flexshaft.analyses.stability`) and of every root
  of the closed loop at rest, at the operating speed and at the speed the onset requirement
  must reach (:mod:`flexshaft.analyses.root_stability`);
* the robustness of every magnetic-bearing loop at the operating speed
  (:mod:`flexshaft.analyses.bearing_loops`);

and, with ``detail`` (the report's), what only the report shows (modes at rest, the Campbell
diagram up to the highest excitation the checks use, the strength's load shares, the
classical-shell buckling, the thermal sweeps): :func:`add_report_detail` adds them to a point
computed without. It returns them as a frozen :class:`PointAnalyses`.

One operating point is a design as it stands: the design's own, or an envelope point's design
(:func:`flexshaft.design.points.design_at_point`) with the point's
:class:`~flexshaft.thermal.envelope.PointConditions` (its material temperature sets the
thermal residual stress). :mod:`flexshaft.verdict.assess` calls it once per point.

Parallel: the analyses that do not need each other are tasks (:mod:`flexshaft.verdict.point_tasks`);
with an ``executor`` they run in its workers, each rebuilding the model from the design, while
this process computes the rest. The results do not depend on where they were computed
(tests/test_tasks.py).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping
from concurrent.futures import Executor
from dataclasses import dataclass
from typing import Any

import numpy as np

from flexshaft.analyses.bearing_loops import BearingLoop
from flexshaft.analyses.campbell import Campbell
from flexshaft.analyses.criticals import CriticalSpeeds
from flexshaft.analyses.dense_spectrum import WHOLE_DENSE_BASIS_UP_TO
from flexshaft.analyses.loop_grid import natural_frequencies
from flexshaft.analyses.metal_strength import MetalStrength, metal_strength
from flexshaft.analyses.misalignment import CouplingMisalignment, coupling_misalignment
from flexshaft.analyses.modal import Modes, modes
from flexshaft.analyses.reactions import BearingReaction, bearing_reactions
from flexshaft.analyses.response import imbalance_response
from flexshaft.analyses.root_stability import RootStability
from flexshaft.analyses.shaft_buckling import ShaftBuckling
from flexshaft.analyses.shaft_strength import StrengthResult, shaft_safety_factor, static_load_parts
from flexshaft.analyses.spinup_response import SpinupResponse
from flexshaft.analyses.stability import StabilityResult
from flexshaft.analyses.torsional import (
    TorsionalForcedResponse,
    TorsionalModes,
    TorsionalSeparation,
    torsional_forced_response,
    torsional_modes,
    torsional_separation,
)
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.assembly.model import Model
from flexshaft.design import Design
from flexshaft.resolution import Resolution
from flexshaft.strength import CompressiveStrength, compressive_strength
from flexshaft.thermal.envelope import PointConditions
from flexshaft.thermal.options import matrix_law_from
from flexshaft.thermal.residual import residual_ply_stresses
from flexshaft.thermal.study import ThermalResults
from flexshaft.units import celsius_to_kelvin
from flexshaft.verdict.point_tasks import (
    campbell_task,
    independent_tasks,
    report_buckling,
    report_thermal,
    required_onset_speed,
)

__all__ = [
    "OVERDAMPED_RATIO",
    "PointAnalyses",
    "add_campbell",
    "add_report_detail",
    "analyse_point",
    "lateral_modes",
    "whirl_modes",
]


@dataclass(frozen=True, kw_only=True)
class PointAnalyses:
    """The analyses of a design at one operating point, SI units.

    Attributes
    ----------
    design : Design
        The design analysed (an envelope point's design at that point).
    resolution : Resolution
        The grids they were computed at.
    model : Model
        The assembled model.
    modes_at_rest : Modes or None
        Damped modes at rest (None below the report's detail).
    modes_at_speed : Modes
        Damped modes at the operating speed: at least ``resolution.modes`` lateral ones.
    campbell : Campbell or None
        Campbell diagram (None without Campbell speeds).
    spinup : SpinupResponse
        Imbalance response over the spin-up scan (worst case at each speed).
    criticals : CriticalSpeeds
        Lateral critical speeds on the spin-up scan, labelled with the Campbell modes.
    static_displacement : ndarray
        Static response to the external loads and the steady torque (ndof,) [m, rad].
    imbalance_at_speed : ndarray
        Imbalance response at the operating speed (ndof, n_cases) [m, rad].
    bearing_reactions : mapping of str to BearingReaction
        Static and imbalance loads of every bearing.
    strength_static, strength_total : StrengthResult or None
        Tsai-Wu of the laminated shaft under the static loads (the torque times the torsional
        torque factor), and with the imbalance at the operating speed (worst load case), with
        the effective compressive strength and the incremental thermal residual stress; None
        without a one-piece laminated shaft.
    compressive_strength : CompressiveStrength or None
        The shaft lamina's X_c against its kink-band strength at the point (None without one).
    residual_temperature : float or None
        Temperature of the thermal residual stress [K] (None without a laminated shaft).
    buckling : ShaftBuckling or None
        Torsional buckling of the laminated shaft under the steady torque (None without one).
    metal_strength : MetalStrength or None
        Fatigue, yield and buckling of the isotropic segments (None without one).
    coupling_misalignment : CouplingMisalignment or None
        Static and whirling angle of every coupling (None without couplings).
    thermal : ThermalResults or None
        Shaft temperature and self-heating (None without a laminated shaft).
    stability : StabilityResult
        Whirl stability of the tracked modes from rest over the resolution's whirl speeds.
    roots : RootStability
        Every root of the closed loop at rest, the operating speed and the required onset speed.
    torsional_modes : TorsionalModes or None
        Modes of the twist subsystem (None when the model has no free twist).
    torsional_separation : tuple of TorsionalSeparation or None
        Each torsional mode against its nearest excitation over the operating speed range
        (None at rest or without torsional modes).
    torsional_response : TorsionalForcedResponse or None
        Dynamic torque of the tail rotor's torque oscillation (None without a ``[tail_rotor]``
        or at rest).
    bearing_loops : tuple of BearingLoop or None
        Sensitivity peak and margins of every control axis at the operating speed (None
        without active bearings).
    conditions : PointConditions or None
        The envelope point's conditions (None: the design's own operating point).
    notes : tuple of str
        Analyses skipped and why.
    """

    design: Design
    resolution: Resolution
    model: Model
    modes_at_rest: Modes | None
    modes_at_speed: Modes
    campbell: Campbell | None
    spinup: SpinupResponse
    criticals: CriticalSpeeds
    static_displacement: np.ndarray
    imbalance_at_speed: np.ndarray
    bearing_reactions: Mapping[str, BearingReaction]
    strength_static: StrengthResult | None
    strength_total: StrengthResult | None
    compressive_strength: CompressiveStrength | None
    residual_temperature: float | None
    buckling: ShaftBuckling | None
    metal_strength: MetalStrength | None
    coupling_misalignment: CouplingMisalignment | None
    thermal: ThermalResults | None
    stability: StabilityResult
    roots: RootStability
    torsional_modes: TorsionalModes | None
    torsional_separation: tuple[TorsionalSeparation, ...] | None
    torsional_response: TorsionalForcedResponse | None
    bearing_loops: tuple[BearingLoop, ...] | None
    conditions: PointConditions | None = None
    notes: tuple[str, ...] = ()

    @property
    def operating_speed(self) -> float:
        """Ω_op [rad/s]."""
        return float(self.model.speed)

    @property
    def point_name(self) -> str:
        """The envelope point's name, or ``"operating point"`` for the design's own."""
        return self.conditions.name if self.conditions is not None else "operating point"

    @property
    def torque_factor(self) -> float:
        """Peak over steady shaft torque of the torsional forced response [-] (1 without one)."""
        return 1.0 if self.torsional_response is None else float(self.torsional_response.torque_factor)


def analyse_point(
    design: Design,
    resolution: Resolution,
    *,
    conditions: PointConditions | None = None,
    detail: bool | None = None,
    executor: Executor | None = None,
    progress: Callable[[str], None] | None = None,
) -> PointAnalyses:
    """Every analysis of ``design`` at its operating point (see the module docstring).

    Parameters
    ----------
    design : Design
        A validated design (an envelope point's design at that point).
    resolution : Resolution
        Grid sizes and ranges.
    conditions : PointConditions, optional
        The envelope point's conditions (its material temperature is the thermal residual's).
    detail : bool, optional
        Also compute what only the report shows; default ``resolution.report_detail``.
    executor : concurrent.futures.Executor, optional
        A pool (e.g. :func:`flexshaft.parallel.pool.worker_pool`) for the independent analyses.
    progress : callable, optional
        Called with a short label before each step.
    """
    step = progress or _quiet
    detail = resolution.report_detail if detail is None else bool(detail)
    step("assembling the model")
    model = build_model(design)
    speed = model.speed
    own = independent_tasks(design, model, resolution, executor, detail=detail)
    step("natural frequencies")
    at_rest = modes(model, 0.0, resolution.modes) if detail else None
    at_speed = lateral_modes(model, speed, resolution.modes, up_to=required_onset_speed(model))
    notes: list[str] = []
    step("torsional dynamics")
    torsion, separation, response = _torsional(model, notes)
    step("static loads and strength")
    parts = static_load_parts(model)
    factor = 1.0 if response is None else float(response.torque_factor)
    q_static = parts["external"] + parts["torque"]
    q_peak = parts["external"] + factor * parts["torque"]  # the steady torque times the torque factor
    q_at_speed = (
        imbalance_response(model, [speed], imbalance_loads(model))[:, :, 0]
        if speed > 0
        else np.zeros((model.dofs.size, 1), complex)
    )
    reactions = bearing_reactions(model, q_static, q_at_speed)
    strength = _strength(
        design,
        model,
        {"external": parts["external"], "torque": factor * parts["torque"]},
        q_at_speed,
        conditions,
        detail,
        notes,
    )
    metal = misalignment = None
    if any(design.materials[seg.material].kind == "isotropic" for seg in model.segments):
        step("metal strength")
        metal = metal_strength(model, q_peak, q_at_speed)
    if model.couplings:
        misalignment = coupling_misalignment(model, q_static, q_at_speed)
    if model.shaft.laminate is None:
        notes.append("shaft thermal model needs a laminated shaft (lamina conductivities); skipped")
    done = {key: outcome.value for key, outcome in own.results(step).items()}
    spinup, criticals = done["spinup"]
    roots, loops = done["roots"]
    camp = done.get("campbell")
    return PointAnalyses(
        design=design,
        resolution=resolution,
        model=model,
        modes_at_rest=at_rest,
        modes_at_speed=at_speed,
        campbell=camp,
        spinup=spinup,
        criticals=criticals.labelled(camp),
        static_displacement=q_static,
        imbalance_at_speed=q_at_speed,
        bearing_reactions=reactions,
        strength_static=strength[0],
        strength_total=strength[1],
        compressive_strength=strength[2],
        residual_temperature=strength[3],
        buckling=done.get("buckling"),
        metal_strength=metal,
        coupling_misalignment=misalignment,
        thermal=done.get("thermal"),
        stability=done["stability"],
        roots=roots,
        torsional_modes=torsion,
        torsional_separation=separation,
        torsional_response=response,
        bearing_loops=loops,
        conditions=conditions,
        notes=tuple(notes),
    )


def add_report_detail(p: PointAnalyses, resolution: Resolution | None = None) -> PointAnalyses:
    """``p`` with what only the report shows (modes at rest, the Campbell diagram with the
    critical speeds labelled by it, the strength's load shares, the classical-shell buckling,
    the thermal sweeps), computed at ``resolution`` (default ``p.resolution``); the verdict's
    numbers do not change."""
    resolution = resolution or p.resolution
    model = p.model
    camp = campbell_task(model, resolution) if resolution.campbell_speeds else None
    notes: list[str] = []
    strength = p.strength_static, p.strength_total
    if model.shaft.laminate is not None:
        parts = static_load_parts(model)
        parts = {"external": parts["external"], "torque": p.torque_factor * parts["torque"]}
        strength = _strength(p.design, model, parts, p.imbalance_at_speed, p.conditions, True, notes)[:2]
    return dataclasses.replace(
        p,
        resolution=resolution,
        modes_at_rest=modes(model, 0.0, resolution.modes),
        campbell=camp,
        criticals=p.criticals.labelled(camp),
        strength_static=strength[0],
        strength_total=strength[1],
        buckling=report_buckling(model) if p.buckling is not None else None,
        thermal=report_thermal(model) if p.thermal is not None else None,
    )


def add_campbell(p: PointAnalyses) -> PointAnalyses:
    """``p`` with its Campbell diagram at ``p.resolution`` and the critical speeds labelled by
    it; nothing else (the verdict's numbers do not change)."""
    camp = campbell_task(p.model, p.resolution)
    return dataclasses.replace(p, campbell=camp, criticals=p.criticals.labelled(camp))


#: Roots with at least this damping ratio are no whirl modes: overdamped or real roots (the
#: controllers' integrator, derivative-filter and amplifier states, a divergence), which come
#: first in frequency order; ζ = 0.99 is a log decrement of 44.
OVERDAMPED_RATIO = 0.99


def whirl_modes(found: Modes) -> np.ndarray:
    """Mask of the lateral vibration modes of ``found``: lateral, with a damping ratio below
    :data:`OVERDAMPED_RATIO` (not a real or overdamped root)."""
    s = np.asarray(found.eigenvalues)
    zeta = -s.real / np.where(np.abs(s) > 0, np.abs(s), 1.0)
    return (np.asarray(found.kind) == "lateral") & (zeta < OVERDAMPED_RATIO)


#: Modes asked for beyond the lateral ones at the first try of :func:`lateral_modes`: the first
#: torsional mode of a driveline with a free twist lies among its lowest ten (the tuned and
#: current designs); one solve of n + 1 modes then costs less than one of n and another of n + 1.
_FIRST_EXTRA = 1


def lateral_modes(model: Model, speed: float, n_lateral: int, up_to: float = 0.0) -> Modes:
    """Damped modes at ``speed`` [rad/s], the lowest ones, until ``n_lateral`` of them are
    lateral vibration modes (:func:`whirl_modes`) and every mode with a damped frequency below
    ``up_to`` [rad/s] is among them: the torsional and axial modes and the real roots of the
    controllers' states among them do not take the whirl modes' places.

    The shortest prefix (in the modes' order: by damped frequency) that holds ``n_lateral``
    whirl modes and every mode below ``up_to``, from one solve of :data:`_FIRST_EXTRA` more
    modes than that when it holds them (larger ones otherwise, half as many more each time
    until a mode at or above ``up_to`` is solved); each eigenvalue is within its error estimate
    (``error_estimate``, below the modal analyses' tolerance) of the full model's, whatever the
    number of modes solved."""
    n_free = model.dofs.free.size
    n = min(max(int(n_lateral) + _FIRST_EXTRA, _modes_below(model, up_to)), n_free)
    found = modes(model, speed, n)
    for _ in range(6):
        missing = n_lateral - int(np.sum(whirl_modes(found)))
        if missing <= 0 or found.eigenvalues.size >= n_free:
            break
        n = min(n + missing, n_free)
        found = modes(model, speed, n)
    while found.eigenvalues.size and found.eigenvalues[-1].imag < up_to and n < n_free:
        n = min(n + max(4, n // 2), n_free)  # the scope reaches past the modes solved
        found = modes(model, speed, n)
    count = np.cumsum(whirl_modes(found))
    if count.size == 0 or count[-1] < n_lateral:
        return found
    below = int(np.sum(found.eigenvalues.imag < up_to))  # a prefix: the modes are in that order
    return _first_modes(found, max(int(np.searchsorted(count, n_lateral)) + 1, below))


def _modes_below(model: Model, up_to: float) -> int:
    """How many modes one solve takes to reach ``up_to`` [rad/s]: the undamped natural frequencies
    at rest (of K + K_a, M: read off the model's whole spectrum, which its modal bases compute
    anyway, :func:`~flexshaft.analyses.loop_grid.natural_frequencies`) below 1.1 × it, plus two
    (the damping and the spin move them; :func:`lateral_modes` solves again if they fall short).
    Above :data:`~flexshaft.analyses.dense_spectrum.WHOLE_DENSE_BASIS_UP_TO` free DOFs, where no
    whole spectrum is computed, 0: the solves extend until they reach it."""
    if not up_to > 0 or model.dofs.free.size > WHOLE_DENSE_BASIS_UP_TO:
        return 0
    return int(natural_frequencies(model, 0.0, 1.1 * up_to).size) + 2


def _first_modes(found: Modes, k: int) -> Modes:
    """The first ``k`` modes of ``found``."""
    if k >= found.eigenvalues.size:
        return found
    shares = found.shares
    return dataclasses.replace(
        found,
        eigenvalues=found.eigenvalues[:k],
        shapes=found.shapes[:, :k],
        kind=found.kind[:k],
        whirl=found.whirl[:k],
        whirl_ratios=found.whirl_ratios[:k],
        component=found.component[:k],
        shares=dataclasses.replace(shares, **{f.name: getattr(shares, f.name)[:k] for f in dataclasses.fields(shares)}),
        error_estimate=None if found.error_estimate is None else found.error_estimate[:k],
    )


def _quiet(label: str) -> None:
    """No progress display."""


def _torsional(model: Model, notes: list[str]):
    """Torsional modes, their separation over the operating speed range and the tail rotor's
    forced response (None where the model has no free twist or the point is at rest)."""
    try:
        torsion = torsional_modes(model)
    except ValueError as exc:  # every twist held: no torsional subsystem
        notes.append(f"torsional analysis skipped: {exc}")
        return None, None, None
    if model.speed <= 0 or model.design is None:
        notes.append("torsional separation and forced response need a shaft speed: the point is at rest")
        return torsion, None, None
    separation = torsional_separation(model, torsion)
    response = torsional_forced_response(model) if model.drive.has_rotor else None
    return torsion, separation, response


def _strength(design: Design, model: Model, parts, q_at_speed, conditions, detail: bool, notes: list[str]):
    """(static, static + imbalance, compressive strength, residual temperature) of a one-piece
    laminated shaft with the effective X_c and the incremental thermal residual stress."""
    if model.shaft.laminate is None:
        if design.segmented:
            notes.append("ply strength and laminated-shell buckling assume one laminated tube; the shaft is segmented")
        else:
            notes.append("ply strength and laminated-shell buckling need a lamina shaft material; skipped")
        return None, None, None, None
    material = design.materials[design.shaft.material]
    assert material.kind == "lamina"  # the model's shaft has a laminate only for a lamina material
    temperature = (
        conditions.material_temperature
        if conditions is not None
        else celsius_to_kelvin(design.thermal.ambient_temperature_c)
    )
    residual = residual_ply_stresses(
        model.shaft.laminate, matrix_law_from(design.thermal, material), material.stress_free_temperature, temperature
    )
    options: dict[str, Any] = {"kinking": True, "temperature": temperature, "residual_stress": residual}
    static = shaft_safety_factor(model, parts, **options)
    # the leave-one-out load shares are the report's; the minimum is the same without them
    totals = [
        shaft_safety_factor(model, parts, q_at_speed[:, c], leave_one_out=detail, **options)
        for c in range(q_at_speed.shape[1])
    ]
    return static, min(totals, key=lambda r: r.safety_factor), compressive_strength(material), temperature

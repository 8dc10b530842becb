"""Rotor unbalance by ISO 21940-11: the one definition of the run, the spin-up map and Monte-Carlo.

ISO 21940-11:2016 (§5.3) grades the permissible residual unbalance of a rigid rotor by the
product of the permissible specific unbalance (mass eccentricity) and the maximum service
speed, ``e_per Ω = G``, G [mm/s] the balance grade (G 6.3, G 2.5, ...). The permissible
residual unbalance is that eccentricity times the mass m of the rotor being balanced::

    e_per = G/Ω,        U_per = e_per · m                                        [m], [kg m]

m is the whole rotating assembly balanced as one: here the shaft tubes, the disks
(``[[disks]]``) and the coupling hubs (``[[couplings]]`` ``mass``). Not counted: the rotors of
the magnetic bearings (the design's bearing ``mass`` is the installed part, stator and housing
included, for the mass breakdown only) and the tail rotor and gearboxes (balanced as parts of
their own).

The design's imbalance (``[loads]``): an explicit ``eccentricity`` e_c [m] is this e_per; a
``balance_grade`` G gives e_c = G/Ω_max with Ω_max the highest operating speed
(``[operating] speed_range``). The rotating force of the run is ``e_c m Ω²``
(:func:`flexshaft.assembly.loads.imbalance_loads`, shared equally among the bays); the
Monte-Carlo draws one eccentricity per bay and weighs it with the bay's own rotating mass
(:func:`bay_rotating_masses`: ``U_b = e_b m_b``, Σ m_b = m).

Until this module the force used the tube mass alone (``e_c m_s Ω²``): a driveline with disks
or coupling hubs carried too little imbalance (the segmented ``current`` driveline: 4.0 kg of
coupling hubs on 11.26 kg of tubes, 26 % low); a plain tube's force is unchanged.
"""

from __future__ import annotations

import numpy as np

from flexshaft.assembly.mesh import merge_tolerance
from flexshaft.assembly.size import bearing_bays

__all__ = [
    "RotatingPart",
    "bay_rotating_masses",
    "design_eccentricity",
    "imbalance_bays",
    "permissible_eccentricity",
    "permissible_unbalance",
    "rotating_mass",
    "rotating_parts",
]


def permissible_eccentricity(grade_mm_s: float, speed: float) -> float:
    """e_per = G/Ω [m] of balance grade G [mm/s] at the maximum service speed Ω [rad/s]
    (ISO 21940-11 §5.3).

    Raises
    ------
    ValueError
        When G or Ω is not a finite number > 0.
    """
    for name, value, unit in (("grade_mm_s", grade_mm_s, "mm/s (e.g. 6.3)"), ("speed", speed, "rad/s")):
        if isinstance(value, bool) or not (np.isfinite(value) and value > 0):
            raise ValueError(f"{name} must be a finite number > 0 {unit} (got {value!r})")
    return float(grade_mm_s) * 1e-3 / float(speed)


def permissible_unbalance(grade_mm_s: float, speed: float, mass: float) -> float:
    """U_per = e_per · m [kg m] of a rotor of mass m [kg] balanced to grade G [mm/s] at its
    maximum service speed Ω [rad/s]."""
    if isinstance(mass, bool) or not (np.isfinite(mass) and mass >= 0):
        raise ValueError(f"mass must be a finite number >= 0 kg (got {mass!r})")
    return permissible_eccentricity(grade_mm_s, speed) * float(mass)


def design_eccentricity(design) -> float:
    """The design's mass eccentricity e_c [m]: ``[loads] eccentricity``, or the permissible
    eccentricity of its ``balance_grade`` at the highest operating speed (0 when neither)."""
    loads = design.loads
    if loads.balance_grade is None:
        return float(loads.eccentricity)
    return permissible_eccentricity(loads.balance_grade, design.operating.speed_limits[1])


class RotatingPart:
    """One lumped rotating part: ``name``, station ``x`` [m] and ``mass`` [kg]."""

    __slots__ = ("name", "x", "mass")

    def __init__(self, name: str, x: float, mass: float):
        self.name, self.x, self.mass = name, float(x), float(mass)

    def __repr__(self) -> str:
        return f"RotatingPart({self.name!r}, x={self.x:g} m, mass={self.mass:g} kg)"


def rotating_parts(model) -> list[RotatingPart]:
    """The lumped rotating parts of the balanced assembly: every disk and coupling hub, in
    order of station (the tubes are :attr:`~flexshaft.assembly.model.Model.shaft_mass`)."""
    parts = [RotatingPart(c.name, c.x, c.mass) for c in model.couplings]
    if model.design is not None:
        parts += [RotatingPart(d.name, d.x, d.mass) for d in model.design.disks]
    return sorted(parts, key=lambda p: p.x)


def rotating_mass(model) -> float:
    """m of ISO 21940-11: tubes plus disks plus coupling hubs [kg]."""
    return float(model.shaft_mass + sum(p.mass for p in rotating_parts(model)))


def imbalance_bays(model) -> list[tuple[float, float]]:
    """Shaft bays: the spans between consecutive bearing stations (overhangs excluded).

    Stations closer than the mesh's merge tolerance (:func:`~flexshaft.assembly.mesh.merge_tolerance`)
    are one station, as they are one node: a bearing 1e-9 m beside another adds no bay.
    """
    shaft_x = model.dofs.shaft_x
    elements = model.design.mesh.shaft_elements if model.design is not None else max(shaft_x.size - 1, 1)
    tolerance = merge_tolerance(float(shaft_x[-1] - shaft_x[0]), elements)
    return bearing_bays([b.x_shaft for b in model.bearings], tolerance)


def _tube_mass_between(model, a: float, b: float) -> float:
    """Mass of the tubes between stations a < b [m] (ρ A per zone of the shaft)."""
    if not model.segments:  # a hand-built model: the [shaft] tube over its whole length
        x0, x1 = float(model.dofs.shaft_x[0]), float(model.dofs.shaft_x[-1])
        return float(model.shaft_mass * (min(b, x1) - max(a, x0)) / (x1 - x0))
    total = 0.0
    for seg in model.segments:
        lo, hi = max(a, seg.x_start), min(b, seg.x_end)
        if hi > lo:
            p = seg.properties
            total += p.density * np.pi * (p.outer_diameter**2 - p.inner_diameter**2) / 4.0 * (hi - lo)
    return float(total)


def bay_rotating_masses(model) -> np.ndarray:
    """Rotating mass of each bay (:func:`imbalance_bays`) [kg]: the tubes between its bearings
    and the disks and coupling hubs on it; an overhang (ahead of the first bearing, behind the
    last) joins its end bay, so that the bays' masses sum to :func:`rotating_mass` (a part at
    exactly an inner bearing's x is counted once, in the bay ending there: a tie-break, not a
    physical rule, as the bay's unbalance acts at its middle). One bay (the
    whole shaft) when the shaft has fewer than two bearing stations.

    The Monte-Carlo unbalance of bay b is ``U_b = e_b m_b`` with this m_b.
    """
    x0, x1 = float(model.dofs.shaft_x[0]), float(model.dofs.shaft_x[-1])
    bays = imbalance_bays(model) or [(x0, x1)]
    edges = [x0] + [b for _, b in bays[:-1]] + [x1]  # each bay widened over its overhang
    tubes = np.array([_tube_mass_between(model, a, b) for a, b in zip(edges[:-1], edges[1:])])
    ends = np.array([b for _, b in bays[:-1]])
    for part in rotating_parts(model):
        tubes[int(np.searchsorted(ends, part.x, side="left"))] += part.mass
    return tubes

"""The driveline's total mass, the optimizer's default mass objective: tubes, couplings,
hangers, dampers and actuators.

The tubes' mass comes from their geometry and density (``Model.shaft_mass``); every other part's
from its ``mass`` field in the design file (the installed mass: bearing, housing and bracket;
for an actuator the magnet, coils, rotor sleeve, housing and sensors), as in the mass breakdown
of ``flexshaft compare`` (:func:`flexshaft.comparison.driveline_inventory`). A gearbox's bearing
(``role = "gearbox"``) ends the driveline and is not counted.

An **active bearing without a mass** (``mass`` omitted, 0) is estimated from its force capacity
at :data:`ACTUATOR_KG_PER_N`, the embedded designs' own assumption: 7.0 kg for a 1500 N radial
magnetic bearing (about 4.5 kg of laminated stator, 1 kg of coils, 0.5 kg of rotor sleeve and
1 kg of housing and sensors; no electronics; ``flexshaft baseline``). This is an assumed
proportion (force ∝ pole area at a given flux density, and the stator's mass with it), not a
published sizing law; give each actuator's ``mass`` for a real design. A contact bearing or a
coupling without a mass counts 0 kg and is listed by :func:`driveline_mass_parts`.
"""

from __future__ import annotations

from flexshaft.assembly.model import Model
from flexshaft.verdict.gather import actuator_limits

__all__ = ["ACTUATOR_KG_PER_N", "actuator_mass_estimate", "driveline_mass", "driveline_mass_parts"]

#: Installed mass per newton of force capacity of an active magnetic bearing [kg/N] (assumed,
#: module docstring): the embedded designs' 7.0 kg for 1500 N.
ACTUATOR_KG_PER_N = 7.0 / 1500.0


def actuator_mass_estimate(force_capacity: float | None) -> float:
    """Estimated installed mass [kg] of an active bearing of ``force_capacity`` [N]
    (:data:`ACTUATOR_KG_PER_N`); 0 when no capacity is known."""
    if force_capacity is None or not force_capacity > 0:
        return 0.0
    return float(force_capacity) * ACTUATOR_KG_PER_N


def driveline_mass_parts(model: Model) -> dict[str, tuple[float, str]]:
    """Mass [kg] of every driveline part by name, with where it comes from: ``"geometry"``
    (the tubes, one entry ``"shaft"``), ``"design"`` (its ``mass`` field), ``"estimate"``
    (an actuator without a mass, from its force capacity) or ``"not given"`` (0 kg)."""
    design = model.design
    parts = {"shaft": (float(model.shaft_mass), "geometry")}
    if design is None:
        return parts
    limits = actuator_limits(model)
    for coupling in design.couplings:
        parts[coupling.name] = (float(coupling.mass), "design" if coupling.mass > 0 else "not given")
    for bearing in design.bearings:
        if bearing.kind != "active" and bearing.role == "gearbox":
            continue
        if bearing.mass > 0:
            parts[bearing.name] = (float(bearing.mass), "design")
        elif bearing.kind == "active":
            limit = limits.get(bearing.name)
            estimate = actuator_mass_estimate(None if limit is None else limit.force_capacity)
            parts[bearing.name] = (estimate, "estimate" if estimate > 0 else "not given")
        else:
            parts[bearing.name] = (0.0, "not given")
    return parts


def driveline_mass(model: Model) -> float:
    """Total driveline mass [kg]: the tubes, and every coupling, hanger, damper and actuator
    (:func:`driveline_mass_parts`). Without estimated actuators it equals the total of
    ``flexshaft compare``'s mass breakdown (:func:`~flexshaft.comparison.driveline_inventory`)."""
    return float(sum(mass for mass, _ in driveline_mass_parts(model).values()))

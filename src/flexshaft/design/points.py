"""The design at an operating point of its envelope: a data operation on a validated design.

:func:`design_at_point` applies to a design one ``[[envelope.points]]`` entry and the conditions
the thermal models found there (:func:`flexshaft.thermal.envelope.point_conditions`: the changed
``[thermal]`` keys and the laminae at the material temperature), and returns the validated design
at the point. What it changes:

* ``[thermal]``: the keys of ``conditions.thermal`` (ambient, sky, solar transmission and the
  matrix reference temperature, which moves to the material temperature with the laminae);
* ``[materials]``: the laminae of ``conditions.materials``;
* ``[operating]``: the point's ``speed_rpm`` (the main-rotor speed scales with it: the two are
  geared; at rest it is dropped) and ``power`` when given;
* ``[loads]``: ``load_scale`` multiplies the manoeuvre load factor and every point load (force
  and moment) and line load; the imbalance is not scaled.

The design is rebuilt from its dump and validated again; with no change it equals the input.
"""

from __future__ import annotations

from typing import Any

from flexshaft.design.envelope import EnvelopePoint, envelope_point
from flexshaft.design.io import design_from_dict
from flexshaft.design.schema import Design
from flexshaft.units import rad_s_to_rpm

__all__ = ["design_at_point"]


def design_at_point(design: Design, point: EnvelopePoint | str, conditions: Any) -> Design:
    """The design at one operating point (module docstring).

    Parameters
    ----------
    design : Design
        The design (left unchanged).
    point : EnvelopePoint or str
        A point, or the name of one of ``design.envelope.points`` (of the default points
        without an ``[envelope]``; :func:`~flexshaft.design.envelope.envelope_point`).
    conditions : PointConditions
        What the thermal models found at the point
        (:func:`flexshaft.thermal.envelope.point_conditions`); any object with ``thermal``
        (dict of ``[thermal]`` keys to values) and ``materials`` (dict of material names to
        laminae).

    Raises
    ------
    DesignError
        When the design at the point breaks the schema (e.g. a speed or a load scaled out of
        its range), with the field path.
    """
    if isinstance(point, str):
        point = envelope_point(design, point)
    data = design.model_dump()
    data["thermal"].update(conditions.thermal)
    for name, material in conditions.materials.items():
        data["materials"][name] = material.model_dump()
    operating = data["operating"]
    if point.speed_rpm is not None:
        base_rpm = operating["speed_rpm"]
        if base_rpm is None:
            base_rpm = rad_s_to_rpm(operating["speed"])
        if operating["main_rotor_speed_rpm"] is not None and base_rpm > 0.0:
            if point.speed_rpm > 0.0:
                operating["main_rotor_speed_rpm"] *= point.speed_rpm / base_rpm
            else:  # at rest: no main-rotor excitation lines
                operating["main_rotor_speed_rpm"] = None
        operating["speed_rpm"], operating["speed"] = point.speed_rpm, None
    if point.power is not None:
        operating["power"] = point.power
    if point.load_scale != 1.0:
        scale = point.load_scale
        loads = data["loads"]
        loads["load_factor"] = tuple(scale * g for g in loads["load_factor"])
        for load in loads["point"]:
            load["force"] = tuple(scale * f for f in load["force"])
            load["moment"] = tuple(scale * m for m in load["moment"])
        for load in loads["line"]:
            load["force_per_length"] = tuple(scale * f for f in load["force_per_length"])
    return design_from_dict(data, f"<envelope point {point.name}>")

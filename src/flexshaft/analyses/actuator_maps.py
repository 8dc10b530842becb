"""The run-up's outputs at the active bearings: maps of the reduced model's state envelope to each
bearing's relative displacement and to the force it carries (:func:`actuator_outputs`), used by
:func:`flexshaft.analyses.transient.transient_response`.

The force is the bearing's whole law ``G(s) d_s − k_s d_a`` (``G = k_i A(s) C(s)``), the force
:meth:`flexshaft.assembly.model.Actuator.carried_force` gives on the full model, here summed over
the reduced model's channels of the bearing (:func:`flexshaft.analyses.eigen.reduce`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.eigen import ReducedModel
from flexshaft.assembly.model import Model

__all__ = ["ActuatorOutput", "actuator_outputs", "law_damping", "law_stiffness"]


@dataclass(frozen=True)
class ActuatorOutput:
    """Maps of the state envelope to one active bearing's outputs (see :func:`actuator_outputs`)."""

    displacement: np.ndarray  # (2, n): relative displacement at the magnet
    force: np.ndarray  # (2, n): carried force G d_s − k_s d_a
    rows: np.ndarray  # (2, n_free): the magnet's rows B_a (the residual's displacement)
    sensing: np.ndarray  # (2, n_free): the sensor's rows B_s (= B_a when collocated)
    static_terms: tuple[tuple[float, float, np.ndarray], ...]  # per channel (D, E, measured rows)
    has_states: bool  # a channel's law has states (then the residual force is quasi-static)


def actuator_outputs(model: Model, red: ReducedModel) -> list[ActuatorOutput]:
    """Per actuator: the maps of the state envelope to its relative displacement and to the
    force it carries, with what the residual (static correction) needs.

    The force is the bearing's whole law, ``G(s) d_s − k_s d_a`` with ``G = k_i A(s) C(s)``,
    summed over the reduced model's channels of that bearing (each ``E s + D + C (sI − A)⁻¹ B``
    on what it measures): one channel ``G − k_s`` on the magnet when the sensor is collocated,
    else ``−k_s`` on the magnet and ``G`` on the sensor
    (:func:`flexshaft.analyses.eigen.reduce`). Its feedthrough D acts on the displacement, its
    ideal-derivative part E on the velocity, its states through C. (It used to be the
    controller C(s) alone for a PD law: the current demand, without k_i, k_s and the amplifier
    lag; without E for a law with states; and the sensor's channel was never counted, or
    taken for the next bearing's.)"""
    nb, n = red.size, red.n_states
    free = model.dofs.free
    channels = iter(red.actuators)
    out = []
    start = 2 * nb
    for act in model.actuators:
        D = np.zeros((2, n))
        F = np.zeros((2, n))
        rows = act.lateral_rows.tocsr()[:, free].toarray()
        sensing = rows if act.collocated else act.sensing_rows.tocsr()[:, free].toarray()
        terms = []
        has_states = False
        for measured in (rows,) if act.collocated else (rows, sensing):  # reduce()'s channel order
            states = next(channels)
            if measured is rows:
                D[:, :nb] = states.rows
            stiffness, damping = law_stiffness(states), law_damping(states)
            F[:, :nb] += stiffness * states.sensing
            F[:, nb : 2 * nb] += damping * states.sensing
            m = states.A.shape[0]
            F[:, start : start + m] = states.C
            start += m
            has_states = has_states or m > 0
            terms.append((stiffness, damping, measured))
        out.append(ActuatorOutput(D, F, rows, sensing, tuple(terms), has_states))
    return out


def law_stiffness(states) -> float:
    """Feedthrough D of an actuator channel's law [N/m] (the part in the basis included)."""
    return states.stiffness + states.basis_stiffness


def law_damping(states) -> float:
    """Ideal-derivative part E of an actuator channel's law [N s/m] (the part in the
    projected damping included)."""
    return states.damping + states.damping_in_basis

"""Plain-data summaries of a model for the CLI, JSON output and the report."""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.modal import Modes, modes
from flexshaft.assembly.model import Model
from flexshaft.units import rad_s_to_rpm

__all__ = ["model_summary", "modes_table"]


def model_summary(model: Model) -> dict:
    """Key numbers of the assembled model (SI units, JSON-ready)."""
    design = model.design
    dm = model.dofs
    sh = model.shaft
    out = {
        "name": design.name if design is not None else "",
        "dofs": int(dm.size),
        "free_dofs": int(dm.free.size),
        "shaft_nodes": int(dm.n_shaft_nodes),
        "boom_nodes": int(dm.n_boom_nodes),
        "shaft_mass_kg": model.shaft_mass,
        "total_mass_kg": None,
        "shaft_E_storage_Pa": sh.youngs_modulus.real,
        "shaft_E_loss_factor": sh.youngs_modulus.imag / sh.youngs_modulus.real,
        "shaft_G_storage_Pa": sh.shear_modulus.real,
        "shaft_G_loss_factor": sh.shear_modulus.imag / sh.shear_modulus.real,
        "operating_speed_rpm": rad_s_to_rpm(model.speed),
        "torque_Nm": model.power / model.speed if model.speed > 0 else 0.0,
    }
    # total mass from a rigid vertical translation of every node
    rigid = np.zeros(dm.size)
    rigid[dm.shaft(np.arange(dm.n_shaft_nodes), "v")] = 1.0
    if dm.n_boom_nodes:
        rigid[dm.boom(np.arange(dm.n_boom_nodes), "v")] = 1.0
    out["total_mass_kg"] = float(rigid @ (model.M @ rigid))
    return out


def modes_table(m: Modes) -> list[dict]:
    """One row per mode: frequency [Hz], damping ratio, log decrement, kind, whirl, component
    (:meth:`Modes.table`)."""
    return m.table()


def modes_at(model: Model, speed: float, n_modes: int = 10) -> list[dict]:
    """:func:`modes_table` of the damped modes at ``speed`` [rad/s]."""
    return modes_table(modes(model, speed=speed, n_modes=n_modes))

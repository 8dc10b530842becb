"""The structure's receptance at its magnetic bearings, once per speed, for the spin-up studies.

:func:`actuator_receptance` solves the driveline **without** its actuators, ``Z₀(Ω) q = Ω² Q₁``
and ``Z₀(Ω) W = B_aᵀ``, at every speed (banded LU,
:class:`~flexshaft.analyses.banded.BandedHarmonicSolver`); :mod:`flexshaft.analyses.spinup`
then couples any feedback law to it exactly (its module docstring gives the equations).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from flexshaft.analyses.banded import solver_for
from flexshaft.analyses.guards import check_finite_array, check_model, check_spin_speeds
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.assembly.model import Model
from flexshaft.parallel.threads import single_blas_thread

__all__ = ["ActuatorReceptance", "actuator_receptance"]


@dataclass(frozen=True)
class ActuatorReceptance:
    """Gain-independent responses of the structure with the actuators removed.

    Rows ``shaft_rows`` are the shaft ``v`` DOFs of every node followed by the ``w`` DOFs.

    Attributes
    ----------
    speeds : ndarray
        Ω [rad/s], (n_speeds,).
    shaft_free : ndarray
        Imbalance response of the shaft rows without actuators, (n_speeds, 2 n_nodes, n_cases) [m].
    shaft_per_force : ndarray
        Shaft rows per unit actuator force, (n_speeds, 2 n_nodes, 2 n_act) [m/N].
    actuator_free : ndarray
        Actuator relative displacement without actuators ``g``, (n_speeds, 2 n_act, n_cases) [m].
    receptance : ndarray
        Actuator receptance ``S = B_a Z₀⁻¹ B_aᵀ``, (n_speeds, 2 n_act, 2 n_act) [m/N].
    actuator_names : tuple of str
    shaft_x : ndarray
        Shaft node stations [m].
    plant : ndarray
        ``k_i A(iΩ)`` of each actuator, (n_speeds, n_act) [N/A] (1 for the thesis's bearing).
    negative_stiffness : ndarray
        k_s of each actuator, (n_act,) [N/m].
    sensor_free, sensor_receptance : ndarray or None
        ``g_s = B_s q₀`` (n_speeds, 2 n_act, n_cases) [m] and ``S_s = B_s Z₀⁻¹ B_aᵀ``
        (n_speeds, 2 n_act, 2 n_act) [m/N]; None when every sensor is collocated.
    """

    speeds: np.ndarray
    shaft_free: np.ndarray
    shaft_per_force: np.ndarray
    actuator_free: np.ndarray
    receptance: np.ndarray
    actuator_names: tuple[str, ...]
    shaft_x: np.ndarray
    plant: np.ndarray | None = None
    negative_stiffness: np.ndarray | None = None
    sensor_free: np.ndarray | None = None
    sensor_receptance: np.ndarray | None = None

    @property
    def n_actuators(self) -> int:
        return len(self.actuator_names)

    def merged(self, other: ActuatorReceptance) -> ActuatorReceptance:
        """This receptance and ``other`` (the same model at other speeds) on the union of
        their speeds, in increasing order; a speed in both is taken from ``self``."""
        if other.actuator_names != self.actuator_names or not np.array_equal(other.shaft_x, self.shaft_x):
            raise ValueError("merged: the receptances belong to different models")
        extra = ~np.isin(other.speeds, self.speeds)
        order = np.argsort(np.concatenate([self.speeds, other.speeds[extra]]), kind="stable")

        def join(name):
            mine, theirs = getattr(self, name), getattr(other, name)
            if mine is None or theirs is None:
                if (mine is None) != (theirs is None):
                    raise ValueError(f"merged: {name} is given for one receptance only")
                return None
            return np.concatenate([mine, theirs[extra]])[order]

        per_speed = (
            "speeds",
            "shaft_free",
            "shaft_per_force",
            "actuator_free",
            "receptance",
            "plant",
            "sensor_free",
            "sensor_receptance",
        )
        return replace(self, **{name: join(name) for name in per_speed})

    @property
    def collocated(self) -> bool:
        """True when every actuator senses at its magnet (the original fast path)."""
        return self.sensor_receptance is None

    def feedback(self, laws: np.ndarray) -> np.ndarray:
        """``G = k_i A(iΩ) C(iΩ)`` from controller values ``laws`` (..., n_speeds, n_act)."""
        if self.plant is None or np.all(self.plant == 1.0):
            return laws
        return laws * self.plant


@single_blas_thread
def actuator_receptance(model: Model, speeds, loads_per_speed_squared=None) -> ActuatorReceptance:
    """Solve the structure without its actuators once per speed (banded LU).

    Parameters
    ----------
    model : Model
        The driveline; its actuators' controllers are ignored here (their magnets' k_s, k_i,
        amplifier lag and sensor positions are kept for the coupling).
    speeds : array_like
        Spin speeds Ω [rad/s]; the excitation is synchronous (ω = Ω).
    loads_per_speed_squared : ndarray, optional
        Q₁ (ndof,) or (ndof, n_cases) [N s²]; default
        :func:`flexshaft.assembly.loads.imbalance_loads`.

    Raises
    ------
    SingularSystemError
        When the structure without actuators is singular at a speed (no damping there).
    """

    check_model(model)
    if not model.actuators:
        raise ValueError("the model has no active bearings: nothing to tune")
    speeds = check_spin_speeds(speeds)
    if loads_per_speed_squared is not None:
        check_finite_array("loads_per_speed_squared", loads_per_speed_squared, "N s^2")
    Q1 = imbalance_loads(model) if loads_per_speed_squared is None else np.asarray(loads_per_speed_squared)
    Q1 = Q1.reshape(Q1.shape[0], -1)
    n_cases = Q1.shape[1]
    solver = solver_for(model, passive=True)  # kept with the model: one set-up for all its speed grids
    free = solver.free
    B = np.vstack([a.lateral_rows.toarray() for a in model.actuators])  # (2 n_act, ndof)
    collocated = all(a.collocated for a in model.actuators)
    Bs = None if collocated else np.vstack([a.sensing_rows.toarray() for a in model.actuators])[:, free]
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    rows = np.concatenate([dm.shaft(nodes, "v"), dm.shaft(nodes, "w")])
    rhs = np.hstack([Q1[free].astype(complex), B[:, free].T.astype(complex)])  # (n_free, n_cases + 2 n_act)
    n_out = rows.size
    n_b = B.shape[0]
    shaft_free = np.empty((speeds.size, n_out, n_cases), complex)
    shaft_per_force = np.empty((speeds.size, n_out, n_b), complex)
    actuator_free = np.empty((speeds.size, n_b, n_cases), complex)
    receptance = np.empty((speeds.size, n_b, n_b), complex)
    sensor_free = None if collocated else np.empty((speeds.size, n_b, n_cases), complex)
    sensor_receptance = None if collocated else np.empty((speeds.size, n_b, n_b), complex)
    full = np.zeros((dm.size, rhs.shape[1]), complex)
    Bf = B[:, free]
    for k, (speed, x) in enumerate(zip(speeds, solver.sweep([(s, s) for s in speeds], rhs))):
        x[:, :n_cases] *= speed * speed
        full[free] = x
        shaft_free[k] = full[rows, :n_cases]
        shaft_per_force[k] = full[rows, n_cases:]
        actuator_free[k] = Bf @ x[:, :n_cases]
        receptance[k] = Bf @ x[:, n_cases:]
        if Bs is not None and sensor_free is not None and sensor_receptance is not None:  # not collocated
            sensor_free[k] = Bs @ x[:, :n_cases]
            sensor_receptance[k] = Bs @ x[:, n_cases:]
    s = 1j * speeds
    return ActuatorReceptance(
        speeds=speeds,
        shaft_free=shaft_free,
        shaft_per_force=shaft_per_force,
        actuator_free=actuator_free,
        receptance=receptance,
        actuator_names=tuple(a.name for a in model.actuators),
        shaft_x=np.asarray(dm.shaft_x, dtype=float),
        plant=np.stack([np.broadcast_to(a.plant(s), s.shape) for a in model.actuators], axis=-1),
        negative_stiffness=np.array([a.negative_stiffness for a in model.actuators], dtype=float),
        sensor_free=sensor_free,
        sensor_receptance=sensor_receptance,
    )

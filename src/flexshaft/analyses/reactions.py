"""What the bearings carry: their forces for a displacement, the actuators' response over
speed and the worst-case orbits, and the bearing reactions of the static + imbalance load case
(thesis §2.3–2.5; split from :mod:`flexshaft.analyses.response`, whose responses they read)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.guards import check_finite_array, check_model, check_speed, check_spin_speed, require_finite
from flexshaft.analyses.response import orbit_amplitude, static_actuator_forces
from flexshaft.assembly.loads import external_static_load, torque_load
from flexshaft.assembly.model import Model

__all__ = ["BearingReaction", "actuator_response", "bearing_forces", "bearing_reactions", "worst_case_orbits"]


def bearing_forces(
    model: Model, q: np.ndarray, omega: float = 0.0, loads=None, speed: float | None = None
) -> dict[str, np.ndarray]:
    """Forces carried by each bearing [N, N m] over (u, v, w, β, γ) for displacement ``q``.

    Contact bearings: ``(k + iωc) · rel``; active bearings: ``G(iω) d_s − k_s d_a`` on v and w
    (:meth:`~flexshaft.assembly.model.Actuator.carried_force`; ``C(iω) · rel`` for the thesis's
    PD bearing). ``q`` may carry trailing axes (cases); complex amplitudes give complex forces.

    A bearing with integral action holds ``d_s = 0`` statically with a force that is not a
    function of ``q``: at ``omega = 0`` pass the static ``loads`` (and ``speed``) that produced
    ``q``, and its force is the constraint force of :func:`static_actuator_forces`.

    Raises
    ------
    ValueError
        For an integrating actuator at ``omega = 0`` without ``loads``.
    """
    check_model(model)
    omega = check_speed(omega, "omega")
    check_finite_array("q", q, "m, rad")
    out = {}
    actuators = {a.name: a for a in model.actuators}
    static = {}
    if omega == 0.0 and any(a.integrates for a in model.actuators):
        if loads is None:
            names = ", ".join(a.name for a in model.actuators if a.integrates)
            raise ValueError(
                f"actuator(s) {names} integrate (C(0) infinite): their static force is not a function "
                "of the displacement; pass the static loads (bearing_forces(model, q, loads=Q))"
            )
        static = static_actuator_forces(model, loads, speed)
    for link in model.bearings:
        rel = link.rows @ q
        if link.name in actuators:
            force = np.zeros(rel.shape, dtype=complex)
            if link.name in static and actuators[link.name].integrates:
                force[1:3] = static[link.name]
            else:
                force[1:3] = actuators[link.name].carried_force(q, 1j * omega)
            out[link.name] = force
        else:
            gain = link.stiffness + 1j * omega * link.damping
            out[link.name] = gain.reshape((5,) + (1,) * (np.ndim(rel) - 1)) * rel
    for name, force in out.items():
        require_finite(f"force of bearing {name!r}", force)
    return out


def actuator_response(model: Model, q: np.ndarray, omegas: np.ndarray):
    """Relative orbit amplitude [m] and force amplitude [N] at each actuator.

    ``q`` is (ndof, n) complex at frequencies ``omegas`` [rad/s]; the force is the carried
    force ``G(iω) d_s − k_s d_a`` of the magnetic bearing (``C(iω) d`` for the thesis's PD
    bearing).
    """
    check_model(model)
    q = check_finite_array("q", q, "m, rad")
    omegas = check_finite_array("omegas", omegas, "rad/s")
    if np.any(np.asarray(omegas) < 0):
        raise ValueError("omegas must be >= 0 rad/s")
    disp, force = {}, {}
    for a in model.actuators:
        d = a.lateral_rows @ q  # (2, n)
        s = 1j * np.asarray(omegas)
        disp[a.name] = orbit_amplitude(d[0], d[1])
        if a.collocated:
            force[a.name] = np.abs(a.law(s)) * disp[a.name]
        else:
            f = a.carried_force(q, s)
            force[a.name] = orbit_amplitude(f[0], f[1])
        require_finite(f"force of actuator {a.name!r}", force[a.name])
    return disp, force


def worst_case_orbits(model: Model, q: np.ndarray):
    """Shaft orbit amplitudes (nodes, cases, speeds) [m] of responses ``q`` (ndof, cases,
    speeds) and the worst load case at each speed (the largest orbit over the nodes)."""
    check_model(model)
    q = check_finite_array("q", q, "m, rad")
    if q.ndim != 3 or q.shape[0] != model.dofs.size:
        raise ValueError(f"q must have shape ({model.dofs.size}, cases, speeds) (got {q.shape})")
    dm = model.dofs
    n = np.arange(dm.n_shaft_nodes)
    amp = orbit_amplitude(q[dm.shaft(n, "v")], q[dm.shaft(n, "w")])  # (nodes, cases, speeds)
    case = np.argmax(amp.max(axis=0), axis=0)  # worst case per speed
    return amp, case


@dataclass(frozen=True)
class BearingReaction:
    """Loads and relative motion of one bearing: static, and imbalance at one speed.

    Attributes
    ----------
    name, kind : str
        The bearing's name and kind ("contact" or "active").
    x_shaft : float
        Shaft station [m].
    static_force : ndarray, shape (5,)
        Force carried under the static loads over (u, v, w, β, γ) [N, N m].
    imbalance_force : ndarray, shape (5, ncases)
        Complex force amplitude carried at the imbalance speed, per load case [N, N m].
    imbalance_motion : ndarray, shape (5, ncases)
        Complex relative displacement (shaft minus support) at the imbalance speed [m, rad].
    speed : float
        The imbalance speed Ω [rad/s].
    gap : float or None
        Radial clearance of the auxiliary (backup) bearing from the design [m].
    static_motion : ndarray, shape (5,), or None
        Relative displacement (shaft minus support) under the static loads [m, rad]: where the
        imbalance orbit is centred (a magnetic bearing without integral action sags by its
        share of the weight over its stiffness).
    """

    name: str
    kind: str
    x_shaft: float
    static_force: np.ndarray
    imbalance_force: np.ndarray
    imbalance_motion: np.ndarray
    speed: float
    gap: float | None = None
    static_motion: np.ndarray | None = None

    @property
    def static_lateral(self) -> float:
        """|(F_v, F_w)| of the static force [N]."""
        return float(np.hypot(self.static_force[1].real, self.static_force[2].real))

    @property
    def static_axial(self) -> float:
        """|F_u| of the static force [N]."""
        return float(abs(self.static_force[0].real))

    @property
    def imbalance_lateral_amplitude(self) -> float:
        """Largest lateral force over the cycle and the load cases [N]."""
        return float(np.max(orbit_amplitude(self.imbalance_force[1], self.imbalance_force[2])))

    @property
    def static_position(self) -> tuple[float, float]:
        """Relative (v, w) static displacement [m], the centre of the orbit ((0, 0) when not
        given)."""
        if self.static_motion is None:
            return 0.0, 0.0
        return float(self.static_motion[1]), float(self.static_motion[2])

    @property
    def static_offset(self) -> float:
        """Distance of the static position from the bearing's centre [m]."""
        return float(np.hypot(*self.static_position))

    @property
    def worst_case(self) -> int:
        """Load case of the largest relative orbit."""
        return int(np.argmax(orbit_amplitude(self.imbalance_motion[1], self.imbalance_motion[2])))

    @property
    def orbit(self) -> tuple[complex, complex]:
        """Relative (v, w) amplitude of the worst load case [m]."""
        k = self.worst_case
        return complex(self.imbalance_motion[1, k]), complex(self.imbalance_motion[2, k])


def bearing_reactions(
    model: Model, q_static: np.ndarray, q_at_speed: np.ndarray, speed: float | None = None, loads=None
) -> dict[str, BearingReaction]:
    """Static and imbalance loads and relative motion of every bearing.

    Parameters
    ----------
    q_static : ndarray, shape (ndof,)
        Static displacement under ``loads`` at the model's operating speed [m, rad].
    q_at_speed : ndarray, shape (ndof,) or (ndof, ncases)
        Complex imbalance response at ``speed`` [m, rad].
    speed : float or None
        Its spin speed Ω [rad/s] (the model's operating speed when None).
    loads : ndarray or None
        The static load vector [N, N m] that produced ``q_static``; needed only by actuators
        with integral action (their static force is the constraint force of the equilibrium,
        not a function of q); default the design's external loads plus the torque.

    Returns
    -------
    dict of str to BearingReaction
        In the model's bearing order.
    """
    speed = check_spin_speed(model.speed if speed is None else speed)
    q_static = np.asarray(q_static)
    q_dyn = np.asarray(q_at_speed)
    q_dyn = q_dyn[:, None] if q_dyn.ndim == 1 else q_dyn
    if q_static.shape != (model.dofs.size,) or q_dyn.ndim != 2 or q_dyn.shape[0] != model.dofs.size:
        raise ValueError(
            f"q_static must have shape ({model.dofs.size},) and q_at_speed ({model.dofs.size}[, ncases]); "
            f"got {q_static.shape} and {np.shape(q_at_speed)}"
        )
    if loads is None and any(a.integrates for a in model.actuators):
        loads = external_static_load(model) + torque_load(model)
    static = bearing_forces(model, q_static, loads=loads)  # the static response is at the operating speed
    if speed == 0.0 and any(a.integrates for a in model.actuators):
        # at rest an integrating actuator's force is not a function of q (C(0) is infinite); no
        # synchronous load acts there, so the response at speed is zero and so are its forces
        if np.any(q_dyn != 0):
            raise ValueError("at rest (speed 0) with an integrating actuator q_at_speed must be zero")
        dynamic = {link.name: np.zeros((link.rows.shape[0], q_dyn.shape[1]), complex) for link in model.bearings}
    else:
        dynamic = bearing_forces(model, q_dyn, speed)
    gaps = {b.name: getattr(b, "gap", None) for b in model.design.bearings} if model.design is not None else {}
    return {
        link.name: BearingReaction(
            link.name,
            link.kind,
            float(link.x_shaft),
            np.real(static[link.name]),
            dynamic[link.name],
            link.rows @ q_dyn,
            speed,
            gaps.get(link.name),
            np.real(link.rows @ q_static),
        )
        for link in model.bearings
    }

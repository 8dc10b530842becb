"""Load vectors on the global DOF vector (thesis §2.4).

* point and line loads on the shaft or boom: consistent nodal loads ``∫ Nᵀ f``;
* point loads on the end mass: ``Bᵀ F`` through the end-mass kinematics (eq. 2.37);
* a load factor ``n`` [g] on every mass: ``M · (n g)`` applied to the rigid translation field;
* the torque ``T = P/Ω`` at the tail rotor (the shaft's aft end; forward end held in twist or
  tied to its gearbox);
* the rotating imbalance ``F = e_c m Ω²`` (ISO 21940-11: m the whole balanced rotor's mass,
  :mod:`flexshaft.assembly.balance`) shared among the shaft bays between bearings,
  as complex amplitudes of a forward-rotating load: ``Q_v = F``, ``Q_w = −iF`` (the force turns
  from +y towards +z with the spin); :func:`per_bay_imbalance_loads` takes each bay's own
  unbalance, angle and position.
"""

from __future__ import annotations

from typing import Literal

import numpy as np

from flexshaft.assembly.balance import design_eccentricity, imbalance_bays, rotating_mass
from flexshaft.assembly.dofs import BOOM_FIELDS, SHAFT_FIELDS, Component
from flexshaft.assembly.model import Model
from flexshaft.assembly.size import MAX_WORST_BAYS
from flexshaft.design import DesignError, Problem
from flexshaft.elements.boom import BOOM_COLUMNS
from flexshaft.elements.inertia import end_mass_kinematics
from flexshaft.elements.shape import beam_shape, gauss_points

__all__ = [
    "STANDARD_GRAVITY",
    "point_load",
    "line_load",
    "inertial_load",
    "torque_load",
    "external_static_load",
    "imbalance_bays",
    "imbalance_loads",
    "per_bay_imbalance_loads",
    "IMBALANCE_PLACEMENTS",
    "MAX_WORST_BAYS",
]

STANDARD_GRAVITY = 9.80665  # m/s^2
_AXES = {"x": 0, "y": 1, "z": 2}
#: Imbalance placements :func:`imbalance_loads` knows.
IMBALANCE_PLACEMENTS = ("mid_bay", "distributed", "worst")
_MEMBERS = ("shaft", "boom", "end_mass")


def _vector3(name: str, value, unit: str) -> np.ndarray:
    """A finite (x, y, z) vector, or a ValueError naming it."""
    try:
        out = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be three finite numbers (x, y, z) [{unit}] (got {value!r})") from None
    if out.shape != (3,) or not np.all(np.isfinite(out)):
        raise ValueError(f"{name} must be three finite numbers (x, y, z) [{unit}] (got {value!r})")
    return out


def _member(model: Model, on: str, allowed=_MEMBERS) -> None:
    if on not in allowed:
        raise ValueError(f"on must be one of {', '.join(map(repr, allowed))} (got {on!r})")
    if on != "shaft" and (
        model.design is None
        or model.design.tailboom is None
        or (on == "end_mass" and model.design.tailboom.end_mass is None)
    ):
        raise ValueError(f"the model has no {'tailboom end mass' if on == 'end_mass' else 'tailboom'} (on = {on!r})")


def _rows(model: Model, on: Component, x):
    """Element DOFs and shape rows (fields × element DOFs) at stations ``x`` on a member."""
    dm = model.dofs
    located = [dm.locate(on, float(xx)) for xx in np.atleast_1d(x)]
    e = np.array([l[0] for l in located])
    xi = np.array([l[1] for l in located])
    L = np.array([l[2] for l in located])
    s = beam_shape(xi[:, None], L)  # (n, 1, 12)
    fields = SHAFT_FIELDS if on == "shaft" else BOOM_FIELDS
    N = np.stack([s.N[f][:, 0] for f in fields], axis=1)  # (n, nf, 12)
    if on == "boom":
        N = N[..., BOOM_COLUMNS]
    return dm.element_dofs(on)[e], N, fields


def _scatter_vector(size: int, dofs: np.ndarray, values: np.ndarray, dtype=float) -> np.ndarray:
    Q = np.zeros(size, dtype=dtype)
    np.add.at(Q, dofs.ravel(), values.ravel())
    return Q


def _generalised(fields, force, moment) -> np.ndarray:
    """Force (x, y, z) and moment (x, y, z) as values on a member's fields."""
    comp = {"u": force[0], "v": force[1], "w": force[2], "theta": moment[0], "beta": moment[1], "gamma": moment[2]}
    return np.array([comp[f] for f in fields])


def point_load(
    model: Model, on: Literal["shaft", "boom", "end_mass"], force, moment=(0.0, 0.0, 0.0), x: float | None = None
) -> np.ndarray:
    """Load vector of a point force [N] and moment [N m] (x, y, z components).

    Parameters
    ----------
    on : {"shaft", "boom", "end_mass"}
        Where it acts; ``x`` [m] is required on the shaft or boom.
    """
    _member(model, on)
    force = _vector3("force", force, "N")
    moment = _vector3("moment", moment, "N m")
    dm = model.dofs
    if on == "end_mass":
        em = model.design.tailboom.end_mass
        tip = np.array([dm.boom(-1, f) for f in BOOM_FIELDS])
        gen = end_mass_kinematics(em.offset).T @ force
        gen[2:] += moment  # a couple on the rigid mass acts on the tip rotations
        return _scatter_vector(dm.size, tip, gen)
    if x is None or isinstance(x, bool) or not np.isfinite(x):
        raise ValueError(f"x must be a finite station [m] on the {on} (got {x!r})")
    dofs, N, fields = _rows(model, on, x)
    g = _generalised(fields, force, moment)
    return _scatter_vector(dm.size, dofs, np.einsum("nfd,f->nd", N, g))


def line_load(model: Model, on: Component, x_start: float, x_end: float, force_per_length) -> np.ndarray:
    """Consistent load vector of a uniform line load [N/m] between two stations [m]."""
    _member(model, on, ("shaft", "boom"))
    if not (np.isfinite(x_start) and np.isfinite(x_end) and x_start < x_end):
        raise ValueError(f"x_start < x_end must be finite stations [m] (got x_start = {x_start!r}, x_end = {x_end!r})")
    dm = model.dofs
    xs = dm.shaft_x if on == "shaft" else dm.boom_x
    q = _vector3("force_per_length", force_per_length, "N/m")
    xi, w = gauss_points(4)
    Q = np.zeros(dm.size)
    for a, b in zip(xs[:-1], xs[1:]):
        lo, hi = max(a, x_start), min(b, x_end)
        if hi <= lo:
            continue
        pts = lo + (hi - lo) * xi
        dofs, N, fields = _rows(model, on, pts)
        g = _generalised(fields, q, np.zeros(3))
        Q += _scatter_vector(dm.size, dofs, np.einsum("nfd,f,n->nd", N, g, w * (hi - lo)))
    return Q


def rigid_translation(model: Model, direction) -> np.ndarray:
    """Global vector of a unit rigid translation along ``direction`` (x, y, z)."""
    dm = model.dofs
    d = np.asarray(direction, dtype=float)
    r = np.zeros(dm.size)
    ns = np.arange(dm.n_shaft_nodes)
    for f, c in zip(("u", "v", "w"), d):
        r[dm.shaft(ns, f)] = c
    if dm.n_boom_nodes:
        nb = np.arange(dm.n_boom_nodes)
        r[dm.boom(nb, "v")] = d[1]
        r[dm.boom(nb, "w")] = d[2]
    return r


def inertial_load(model: Model, load_factor) -> np.ndarray:
    """Load factor [g] (x, y, z) on every mass: ``Q = M · (n g r)`` with r the rigid translation.

    The boom has no axial DOF, so an x load factor acts on the shaft only.
    """
    n = _vector3("load_factor", load_factor, "g")
    return model.M @ rigid_translation(model, n * STANDARD_GRAVITY)


def torque_load(model: Model, torque: float | None = None) -> np.ndarray:
    """Transmitted torque at the tail rotor [N m], default ``P/Ω``.

    The forward end is held in twist (the drive) or tied to its gearbox; the tail rotor resists
    the spin, so it carries ``−T`` about +x: on its own twist DOF behind an elastic drive
    (:attr:`~flexshaft.assembly.drive.DriveTrain.rotor_dof`, the same torque in the shaft),
    else on the shaft's aft node.
    """
    if torque is None:
        torque = model.power / model.speed if model.speed > 0 else 0.0
    if not np.isfinite(torque):
        raise ValueError(f"torque must be a finite number [N m] (got {torque!r})")
    Q = np.zeros(model.dofs.size)
    dof = model.drive.rotor_dof
    Q[model.dofs.shaft(-1, "theta") if dof is None else dof] = -torque
    return Q


def external_static_load(model: Model) -> np.ndarray:
    """Sum of the design's point loads, line loads and load factor (not the torque)."""
    loads = model.design.loads
    Q = inertial_load(model, loads.load_factor)
    for p in loads.point:
        Q += point_load(model, p.on, p.force, p.moment, p.x)
    for ln in loads.line:
        Q += line_load(model, ln.on, ln.x_start, ln.x_end, ln.force_per_length)
    return Q


def imbalance_loads(model: Model, placement: str | None = None, eccentricity: float | None = None) -> np.ndarray:
    """Rotating imbalance load vectors per unit Ω² [N s²], columns = load cases.

    The force ``e_c m Ω²`` (m the rotating mass of ISO 21940-11,
    :func:`~flexshaft.assembly.balance.rotating_mass`: tubes, disks and coupling hubs) is
    shared equally among the bays. ``placement``:

    * ``"mid_bay"``: a point force at each bay's midpoint, all in phase (one case);
    * ``"distributed"``: uniform over each bay (one case);
    * ``"worst"``: every combination of in-phase/anti-phase mid-bay forces (2^(nbays−1)
      cases, at most :data:`MAX_WORST_BAYS` bays); the response is taken as the worst case.

    Multiply by Ω² for the amplitude at speed Ω. Complex: ``Q_v = F``, ``Q_w = −iF``.

    Parameters
    ----------
    placement : {"mid_bay", "distributed", "worst"} or None
        Default: the design's ``loads.imbalance_placement``.
    eccentricity : float or None
        Mass eccentricity e_c [m], finite and >= 0; default: the design's
        (:func:`~flexshaft.assembly.balance.design_eccentricity`: its ``eccentricity`` or
        ``balance_grade``).

    Raises
    ------
    ValueError
        For an unknown placement, a non-finite or negative eccentricity, or ``"worst"`` with
        more than :data:`MAX_WORST_BAYS` bays (2^(bays−1) load cases): a
        :class:`~flexshaft.design.DesignError` naming ``loads.imbalance_placement`` when the
        placement is the design's (a user error every command reports as such).
    """
    loads = model.design.loads if model.design is not None else None
    designed = placement is None and loads is not None
    placement = placement or (loads.imbalance_placement if loads else "mid_bay")
    if placement not in IMBALANCE_PLACEMENTS:
        raise ValueError(f"placement must be one of {', '.join(map(repr, IMBALANCE_PLACEMENTS))} (got {placement!r})")
    ecc = eccentricity if eccentricity is not None else (design_eccentricity(model.design) if loads else 0.0)
    if isinstance(ecc, bool) or not (
        isinstance(ecc, (int, float, np.floating, np.integer)) and np.isfinite(ecc) and ecc >= 0
    ):
        raise ValueError(f"eccentricity must be a finite number >= 0 [m] (got {ecc!r})")
    bays = imbalance_bays(model)
    if not bays:
        bays = [(model.dofs.shaft_x[0], model.dofs.shaft_x[-1])]
    if placement == "worst" and len(bays) > MAX_WORST_BAYS:
        message = (
            f'placement "worst" enumerates 2^(bays-1) load cases: {len(bays)} bays give '
            f"2^{len(bays) - 1} (allowed: at most {MAX_WORST_BAYS} bays, or placement "
            '"mid_bay" / "distributed")'
        )
        if designed:
            raise DesignError([Problem("loads.imbalance_placement", message)])
        raise ValueError(message)
    share = ecc * rotating_mass(model) / len(bays)
    rotating = np.array([0.0, 1.0, -1j])  # (x, y, z) complex direction
    if placement == "distributed":
        columns = []
        for a, b in bays:
            re = line_load(model, "shaft", a, b, rotating.real * share / (b - a))
            im = line_load(model, "shaft", a, b, rotating.imag * share / (b - a))
            columns.append(re + 1j * im)
        per_bay = np.array(columns).T  # (ndof, nbays)
    else:  # the point loads of every bay midpoint from one evaluation of the shape functions
        dofs, N, fields = _rows(model, "shaft", [0.5 * (a + b) for a, b in bays])
        g = _generalised(fields, rotating * share, np.zeros(3))
        per_bay = np.zeros((model.dofs.size, len(bays)), dtype=complex)
        for k, values in enumerate(np.einsum("nfd,f->nd", N, g)):
            np.add.at(per_bay[:, k], dofs[k], values)
    if placement != "worst":
        return per_bay.sum(axis=1, keepdims=True)
    nb = per_bay.shape[1]
    signs = [
        np.array([1.0] + [1.0 if (k >> j) & 1 == 0 else -1.0 for j in range(nb - 1)]) for k in range(2 ** (nb - 1))
    ]
    return np.stack([per_bay @ s for s in signs], axis=1)


def per_bay_imbalance_loads(model: Model, unbalance, angle=0.0, position=0.5) -> np.ndarray:
    """One rotating load vector per unit Ω² [N s²] (ndof,) from each bay's own unbalance.

    Bay b (:func:`imbalance_bays`, or the whole shaft when there are none) carries a point
    unbalance ``U_b = e_b m_b`` [kg m] at angle ``ψ_b`` [rad] ahead of the reference mark, at
    ``x = a_b + position_b (b_b − a_b)``: ``Q_v = U_b e^{iψ_b}``, ``Q_w = −i U_b e^{iψ_b}``, so
    the force at phase φ is ``U_b Ω² (cos(φ + ψ_b), sin(φ + ψ_b))`` in (y, z).

    Parameters
    ----------
    unbalance : array_like
        U_b per bay [kg m] (a scalar is used for every bay); >= 0.
    angle : array_like
        ψ_b per bay [rad].
    position : array_like
        Fraction of each bay's length in [0, 1] (0.5: mid-bay).
    """
    bays = imbalance_bays(model) or [(model.dofs.shaft_x[0], model.dofs.shaft_x[-1])]
    n = len(bays)
    values = {}
    for name, value in (("unbalance", unbalance), ("angle", angle), ("position", position)):
        v = (
            np.broadcast_to(np.asarray(value, dtype=float), (n,))
            if np.ndim(value) == 0
            else np.asarray(value, dtype=float)
        )
        if v.shape != (n,):
            raise ValueError(f"{name}: expected one value per bay ({n} bays), got shape {np.shape(value)}")
        if not np.all(np.isfinite(v)):
            raise ValueError(f"{name}: values must be finite, got {v.tolist()}")
        values[name] = v
    if np.any(values["unbalance"] < 0):
        raise ValueError(f"unbalance: values must be >= 0 kg m, got {values['unbalance'].tolist()}")
    if np.any((values["position"] < 0) | (values["position"] > 1)):
        raise ValueError(f"position: fractions of the bay must lie in [0, 1], got {values['position'].tolist()}")
    Q = np.zeros(model.dofs.size, dtype=complex)
    for (a, b), U, psi, frac in zip(bays, values["unbalance"], values["angle"], values["position"]):
        amplitude = U * np.exp(1j * psi)
        rotating = amplitude * np.array([0.0, 1.0, -1j])
        x = a + frac * (b - a)
        Q += point_load(model, "shaft", rotating.real, x=x) + 1j * point_load(model, "shaft", rotating.imag, x=x)
    return Q

"""The assembled driveline model: global matrices, DOF map, bearings and actuators.

Equation of motion in the frequency domain (thesis eqs. 2.38-2.40)::

    [−ω² M + iω (Ω G + C) + K + L(ω, Ω) + Σ_a B_aᵀ C_a(iω) B_a] q = Q

``K`` is the real storage stiffness (members and contact-bearing springs), ``C`` viscous
damping (bearing dampers), ``C_a(s)`` each actuator's law (``K_p + s K_d`` for the PD law or
any proper transfer function). ``L(ω, Ω)`` is the hysteretic loss, built from three real loss
matrices by :mod:`flexshaft.analyses.loss` according to :attr:`Model.internal_damping`:

* ``loss_fixed``: loss that acts in the fixed frame at the excitation frequency: the tailboom
  and the shaft's axial and torsional strains (rotation does not cycle them differently);
* ``loss_lateral``: the shaft's bending (and shear) loss K''_lat;
* ``loss_circulatory``: ``K''_lat S``, S the −90° rotation of each shaft node's lateral pairs
  (:func:`rotation_generator`), the circulatory form the rotating-frame loss takes in the fixed
  frame.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
import scipy.sparse as sp

from flexshaft.assembly.controller import Controller
from flexshaft.assembly.dofs import DofMap
from flexshaft.assembly.drive import DriveTrain
from flexshaft.units import rad_s_to_rpm

__all__ = [
    "Controller",
    "Actuator",
    "BearingLink",
    "CouplingLink",
    "SegmentProperties",
    "ShaftProperties",
    "Model",
    "rotation_generator",
]


def rotation_generator(dofs: DofMap) -> sp.csr_matrix:
    """S: per shaft node (v, w) → (w, −v) and (β, γ) → (γ, −β); zero on u, θ and the boom.

    ``S`` rotates each node's lateral translation by −90° about x (the pair (γ, −β) =
    ∂(v, w)/∂x rotates with it). A forward circular whirl (W = −iV) satisfies S q = −i q, a
    backward one S q = +i q.
    """
    n = np.arange(dofs.n_shaft_nodes)
    v, w, b, g = (dofs.shaft(n, f) for f in ("v", "w", "beta", "gamma"))
    rows = np.concatenate([v, w, b, g])
    cols = np.concatenate([w, v, g, b])
    vals = np.concatenate([np.ones_like(v), -np.ones_like(v), np.ones_like(v), -np.ones_like(v)]).astype(float)
    if len(dofs.tied):  # a node tied to its neighbour at a rigid coupling lists the same pair twice
        rows, first = np.unique(rows, return_index=True)
        cols, vals = cols[first], vals[first]
    return sp.csr_matrix((vals, (rows, cols)), shape=(dofs.size, dofs.size))


@dataclass(frozen=True)
class BearingLink:
    """A bearing's kinematics: rows giving the relative displacement (u, v, w, β, γ).

    ``rows`` is a sparse (5, ndof) matrix; ``rows @ q`` is shaft minus attachment point.
    """

    name: str
    kind: str
    x_shaft: float
    x_boom: float | None
    offset: float
    rows: sp.csr_matrix
    stiffness: np.ndarray = field(default_factory=lambda: np.zeros(5))  # per (u, v, w, β, γ), contact
    damping: np.ndarray = field(default_factory=lambda: np.zeros(5))


@dataclass(frozen=True)
class Actuator:
    """An active magnetic bearing: magnet at ``link``, displacement sensor at ``sensor``.

    Force on the shaft (lateral, each of v and w)::

        f = k_s d_a + k_i i,    i = −A(s) C(s) d_s,    A(s) = 1/(1 + s/ω_a)

    ``d_a = B_a q`` is the relative displacement at the magnet (:attr:`lateral_rows`, the
    actuation rows), ``d_s = B_s q`` at the sensor (:attr:`sensing_rows`; ``B_s = B_a`` when
    collocated). In the dynamic stiffness the bearing adds ``B_aᵀ G(s) B_s − k_s B_aᵀ B_a``
    with the feedback law ``G(s) = k_i A(s) C(s)`` [N/m]. The thesis's ideal PD bearing is
    ``k_s = 0``, ``k_i = 1``, no lag, collocated: then ``G = C`` is the force law [N/m].

    Attributes
    ----------
    link : BearingLink
        Magnet (actuation) point.
    controller : Controller
        C(s) from the measured displacement to the current command [A/m] (to the force [N/m]
        when ``current_gain = 1``).
    current_gain : float
        k_i [N/A].
    negative_stiffness : float
        k_s [N/m] (>= 0: the magnet's open-loop negative stiffness).
    amplifier_bandwidth : float or None
        ω_a [rad/s] of the first-order amplifier lag (None: ideal amplifier).
    sensor : BearingLink or None
        Sensing point (None: collocated with the magnet).
    air_gap, bias_current : float or None
        Nominal magnetic gap g_0 [m] and bias current i_0 [A] (information).
    saturation_force : float or None
        Largest force of one control axis [N] from the saturation flux density
        (:func:`flexshaft.elements.magnetic.saturation_force`), None when not given.
    """

    link: BearingLink
    controller: Controller
    current_gain: float = 1.0
    negative_stiffness: float = 0.0
    amplifier_bandwidth: float | None = None
    sensor: BearingLink | None = None
    air_gap: float | None = None
    bias_current: float | None = None
    saturation_force: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.controller, Controller):  # e.g. a python-control TransferFunction
            object.__setattr__(self, "controller", Controller.from_transfer_function(self.controller))
        for field_name, value, allowed in (
            ("current_gain", self.current_gain, "a finite number > 0 N/A"),
            ("negative_stiffness", self.negative_stiffness, "a finite number >= 0 N/m"),
        ):
            ok = np.isfinite(value) and (value > 0 if field_name == "current_gain" else value >= 0)
            if not ok:
                raise ValueError(f"actuator {self.link.name!r}: {field_name} must be {allowed} (got {value!r})")
        bandwidth = self.amplifier_bandwidth
        if bandwidth is not None and not (np.isfinite(bandwidth) and bandwidth > 0):
            raise ValueError(
                f"actuator {self.link.name!r}: amplifier_bandwidth must be None or a finite number > 0 rad/s "
                f"(got {bandwidth!r})"
            )
        if self.controller.relative_degree < -1:
            raise ValueError(
                f"actuator {self.link.name!r}: C(s) is improper by more than one degree "
                "(at most an ideal derivative is allowed)"
            )

    @property
    def name(self) -> str:
        return self.link.name

    @cached_property
    def lateral_rows(self) -> sp.csr_matrix:
        """(2, ndof) actuation rows B_a: the lateral relative displacement (v, w) at the magnet."""
        return self.link.rows[1:3]

    @cached_property
    def sensing_rows(self) -> sp.csr_matrix:
        """(2, ndof) sensing rows B_s: the lateral relative displacement at the sensor."""
        return self.lateral_rows if self.sensor is None else self.sensor.rows[1:3]

    @cached_property
    def lateral_gram(self) -> sp.csr_matrix:
        """``B_aᵀ B_a`` (ndof, ndof): the actuation rows' stiffness pattern for a unit gain."""
        return (self.lateral_rows.T @ self.lateral_rows).tocsr()

    @property
    def collocated(self) -> bool:
        """True when the sensor measures at the magnet (B_s = B_a)."""
        return self.sensor is None

    def plant(self, s):
        """``k_i A(s)`` [N/A]: current command to force at Laplace variable(s) ``s``."""
        value = (
            np.ones_like(np.asarray(s, dtype=complex))
            if self.amplifier_bandwidth is None
            else 1.0 / (1.0 + np.asarray(s) / self.amplifier_bandwidth)
        )
        return value if self.current_gain == 1.0 else self.current_gain * value

    def feedback_gain(self, s, controller: Controller | None = None):
        """``G(s) = k_i A(s) C(s)`` [N/m] at ``s``; ``controller`` replaces C(s) when given."""
        value = (controller or self.controller)(s)
        if self.amplifier_bandwidth is not None:
            value = value / (1.0 + s / self.amplifier_bandwidth)
        return value if self.current_gain == 1.0 else self.current_gain * value

    def law(self, s):
        """Collocated-equivalent force law ``G(s) − k_s`` [N/m] at ``s`` (the whole law of a
        collocated bearing: carried force = law · d_a)."""
        value = self.feedback_gain(s)
        return value - self.negative_stiffness if self.negative_stiffness else value

    @cached_property
    def feedback(self) -> Controller:
        """G(s) = k_i A(s) C(s) as one transfer function."""
        law = self.controller
        if self.amplifier_bandwidth is not None:
            law = law.series(Controller.lag(self.amplifier_bandwidth))
        return law if self.current_gain == 1.0 else law.scaled(self.current_gain)

    @cached_property
    def collocated_law(self) -> Controller:
        """The law on ``B_aᵀ · B_a``: ``G − k_s`` when collocated, else ``−k_s``."""
        if self.collocated:
            return self.feedback.shifted(-self.negative_stiffness) if self.negative_stiffness else self.feedback
        return Controller.constant(-self.negative_stiffness)

    @property
    def sensed_law(self) -> Controller | None:
        """The law on ``B_aᵀ · B_s`` of a non-collocated bearing (G), None when collocated."""
        return None if self.collocated else self.feedback

    @cached_property
    def basis_stiffness(self) -> float:
        """Stiffness [N/m] on ``B_aᵀB_a`` in the modal basis: the positive part of the
        proportional gain of ``G − k_s`` (see :attr:`Controller.basis_stiffness`)."""
        law = self.collocated_law if self.collocated else self.feedback.shifted(-self.negative_stiffness)
        return law.basis_stiffness

    @property
    def integrates(self) -> bool:
        """True when C(s) has integral action: statically the bearing holds d_s = 0."""
        return self.feedback.integrates

    def carried_force(self, q: np.ndarray, s) -> np.ndarray:
        """Force carried by the bearing ``G(s) d_s − k_s d_a`` (v, w) for displacement ``q``
        (the shaft receives its negative); q may have trailing axes."""
        d_a = self.lateral_rows @ q
        if self.collocated:
            return np.asarray(self.law(s)) * d_a
        out = np.asarray(self.feedback_gain(s)) * (self.sensing_rows @ q)
        return out - self.negative_stiffness * d_a if self.negative_stiffness else out


@dataclass(frozen=True)
class ShaftProperties:
    """Equivalent properties of the shaft, needed by strength and thermal analyses."""

    outer_diameter: float
    inner_diameter: float
    youngs_modulus: complex
    shear_modulus: complex
    density: float
    laminate: Any = None  # flexshaft.laminate.Laminate for a composite shaft, else None


@dataclass(frozen=True)
class SegmentProperties:
    """One zone of the shaft, ``[x_start, x_end]`` [m], and its tube (a segmented shaft has several)."""

    name: str
    x_start: float
    x_end: float
    material: str  # name in the design's [materials]
    properties: ShaftProperties

    @property
    def length(self) -> float:
        """[m]."""
        return self.x_end - self.x_start

    @property
    def mass(self) -> float:
        """Tube mass ρ A L [kg]."""
        p = self.properties
        return float(p.density * np.pi * (p.outer_diameter**2 - p.inner_diameter**2) / 4 * self.length)


@dataclass(frozen=True)
class CouplingLink:
    """A coupling element between shaft nodes ``node_a`` (forward side) and ``node_b`` (aft side).

    ``stiffness`` per (u, v, w, θ, β, γ) [N/m, N m/rad]; a rigid direction (``rigid``) is an
    exact constraint (:attr:`~flexshaft.assembly.dofs.DofMap.tied`) and shows ``inf``.
    ``allowable_angle`` [rad] or None.
    """

    name: str
    x: float
    node_a: int
    node_b: int
    stiffness: np.ndarray
    rigid: np.ndarray
    mass: float = 0.0
    allowable_angle: float | None = None

    @property
    def angular_stiffness(self) -> float:
        """Bending stiffness about each axis [N m/rad] (inf when rigid)."""
        return float(self.stiffness[4])


@dataclass(frozen=True, eq=False)
class Model:
    """Assembled global matrices (full size; restrict to ``dofs.free`` to solve).

    Equality is identity (``eq=False``: the sparse matrices have no ``==`` that answers one
    truth value), so a model can key the caches of the analyses computed from it
    (``functools.lru_cache``, e.g. :func:`flexshaft.analyses.banded.solver_for`).

    Attributes
    ----------
    M : csr_matrix
        Mass [kg, kg m^2].
    K : csr_matrix
        Real storage stiffness incl. contact bearings [N/m, N m/rad].
    C : csr_matrix
        Viscous damping (bearing dampers) [N s/m].
    G : csr_matrix
        Gyroscopic matrix per unit spin speed (skew-symmetric) [kg m^2].
    speed : float
        Operating speed Ω [rad/s].
    shaft_loss_stiffness, boom_loss_stiffness : csr_matrix
        Loss stiffness K'' = Im(K*) of the shaft and tailboom elements [N/m, N m/rad].
    internal_damping : {"rotating", "thesis"}
        How the shaft's loss acts (see :mod:`flexshaft.analyses.loss`).
    shaft : ShaftProperties
        The ``[shaft]`` tube. For a segmented shaft (several zones or any coupling) it is the
        nominal tube without its laminate: the analyses that assume one laminated tube
        (ply strength, laminated-shell buckling, shaft thermal) are then not evaluated.
    segments : tuple of SegmentProperties
        Every zone of the shaft with its tube (one for a one-piece shaft).
    couplings : tuple of CouplingLink
        Coupling elements, in order of station.
    drive : DriveTrain
        The tail rotor and gearbox on the shaft's end twists, reflected to the shaft
        (:mod:`flexshaft.assembly.drive`); empty without ``[tail_rotor]``/``[main_gearbox]``.
    """

    dofs: DofMap
    M: sp.csr_matrix
    K: sp.csr_matrix
    C: sp.csr_matrix
    G: sp.csr_matrix
    bearings: tuple[BearingLink, ...]
    actuators: tuple[Actuator, ...]
    shaft: ShaftProperties
    speed: float
    power: float
    design: Any = None
    shaft_loss_stiffness: sp.csr_matrix | None = None  # Im(K*) of the shaft elements (rotating material)
    boom_loss_stiffness: sp.csr_matrix | None = None  # Im(K*) of the boom elements (fixed frame)
    internal_damping: str = "rotating"
    segments: tuple[SegmentProperties, ...] = ()
    couplings: tuple[CouplingLink, ...] = ()
    drive: DriveTrain = DriveTrain()

    def __repr__(self) -> str:
        """One line: the design, the mesh, the DOFs, the bearings and the operating speed (the
        matrices are in the attributes)."""
        name = getattr(self.design, "name", None)
        rpm = rad_s_to_rpm(self.speed)
        return (
            f"Model({name!r}, {self.dofs.n_shaft_nodes} shaft nodes, {self.dofs.n_boom_nodes} boom nodes, "
            f"{self.dofs.size} DOFs ({self.dofs.free.size} free), {len(self.bearings)} bearings "
            f"({len(self.actuators)} active), {rpm:.0f} rpm, internal damping {self.internal_damping!r})"
        )

    @cached_property
    def _loss_split(self) -> tuple[sp.csr_matrix, sp.csr_matrix, sp.csr_matrix]:
        n = self.dofs.size
        shaft = self.shaft_loss_stiffness if self.shaft_loss_stiffness is not None else sp.csr_matrix((n, n))
        boom = self.boom_loss_stiffness if self.boom_loss_stiffness is not None else sp.csr_matrix((n, n))
        nodes = np.arange(self.dofs.n_shaft_nodes)
        lateral = np.zeros(n, dtype=bool)
        for f in ("v", "w", "beta", "gamma"):
            lateral[self.dofs.shaft(nodes, f)] = True
        entries = shaft.tocoo()
        keep = lateral[entries.row] & lateral[entries.col]  # P K P with P the lateral 0/1 diagonal
        K_lat = sp.csr_matrix((entries.data[keep], (entries.row[keep], entries.col[keep])), shape=(n, n))
        K_fix = (boom + shaft - K_lat).tocsr()
        K_circ = (K_lat @ rotation_generator(self.dofs)).tocsr()
        for A in (K_lat, K_fix, K_circ):
            A.eliminate_zeros()
        return K_fix, K_lat, K_circ

    @property
    def loss_fixed(self) -> sp.csr_matrix:
        """Loss stiffness acting in the fixed frame: tailboom + shaft axial and torsion [N/m]."""
        return self._loss_split[0]

    @property
    def loss_lateral(self) -> sp.csr_matrix:
        """The shaft's lateral (bending, shear) loss stiffness K''_lat [N/m, N m/rad]."""
        return self._loss_split[1]

    @property
    def loss_circulatory(self) -> sp.csr_matrix:
        """``K''_lat S`` [N/m]: the rotating-frame loss seen from the fixed frame."""
        return self._loss_split[2]

    @property
    def has_loss(self) -> bool:
        """True when some member carries hysteretic loss."""
        return bool(self.loss_fixed.nnz or self.loss_lateral.nnz)

    @property
    def all_pd(self) -> bool:
        """True when every actuator is collocated with a PD force law ``G − k_s`` (its gains then
        describe it completely: :attr:`Kp` and :attr:`Kd` when the stiffness is not negative)."""
        return all(a.collocated and a.collocated_law.is_pd for a in self.actuators)

    def actuator_matrix(self, gains) -> sp.csr_matrix:
        """``Σ Bᵀ g_a B`` over actuators for per-actuator scalar gains ``g_a`` (actuation rows)."""
        out = sp.csr_matrix(
            (self.dofs.size, self.dofs.size), dtype=np.result_type(*gains, float) if len(gains) else float
        )
        for act, g in zip(self.actuators, gains):
            out = out + g * act.lateral_gram
        return out.tocsr()

    @property
    def Kp(self) -> sp.csr_matrix:
        """Actuator stiffness of the modal basis Σ B_aᵀ k_a B_a [N/m], ``k_a`` =
        :attr:`Actuator.basis_stiffness` (K_p of a PD law; never negative, so that the basis
        problem stays positive semi-definite; the rest enters the state matrix)."""
        return self.actuator_matrix([a.basis_stiffness for a in self.actuators])

    @property
    def Kd(self) -> sp.csr_matrix:
        """Ideal-derivative (damping) part of the collocated laws Σ B_aᵀ E_a B_a [N s/m]
        (K_d of a PD law; 0 for proper transfer functions)."""
        return self.actuator_matrix([a.collocated_law.realization()[4] for a in self.actuators])

    def controller_matrix(self, s) -> sp.csr_matrix:
        """Actuator dynamic stiffness ``Σ B_aᵀ (G_a(s) B_s − k_s B_a)`` at one complex ``s``."""
        out = self.actuator_matrix(
            [complex(a.law(s)) if a.collocated else -a.negative_stiffness for a in self.actuators]
        )
        for a in self.actuators:
            if not a.collocated:
                out = out + complex(a.feedback_gain(s)) * (a.lateral_rows.T @ a.sensing_rows)
        return out.tocsr()

    def passive(self) -> Model:
        """The same model with every actuator switched off (zero law, no magnet stiffness)."""
        import dataclasses

        off = Controller.pd(0.0, 0.0)
        return dataclasses.replace(
            self,
            actuators=tuple(
                dataclasses.replace(
                    a, controller=off, current_gain=1.0, negative_stiffness=0.0, amplifier_bandwidth=None
                )
                for a in self.actuators
            ),
        )

    @property
    def shaft_mass(self) -> float:
        """Mass of the shaft tubes [kg] (disks and coupling hubs excluded)."""
        if len(self.segments) > 1:
            return float(sum(seg.mass for seg in self.segments))
        sh = self.shaft
        area = np.pi * (sh.outer_diameter**2 - sh.inner_diameter**2) / 4
        return float(sh.density * area * (self.dofs.shaft_x[-1] - self.dofs.shaft_x[0]))

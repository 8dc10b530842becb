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

from flexshaft.assembly.dofs import DofMap

__all__ = ["Controller", "Actuator", "BearingLink", "ShaftProperties", "Model", "rotation_generator"]


@dataclass(frozen=True)
class Controller:
    """Actuator law ``f = −C(s) d`` on the lateral relative displacement d.

    ``numerator``/``denominator`` are polynomial coefficients in s, highest power first;
    the PD law is ``numerator = (kd, kp)``, ``denominator = (1,)``.
    """

    numerator: tuple[float, ...]
    denominator: tuple[float, ...] = (1.0,)

    @classmethod
    def pd(cls, kp: float, kd: float) -> "Controller":
        """Proportional-derivative law ``C(s) = kp + kd s`` [N/m, N s/m]."""
        return cls(numerator=(float(kd), float(kp)), denominator=(1.0,))

    @property
    def is_pd(self) -> bool:
        return len(self.denominator) == 1 and len(self.numerator) <= 2

    @property
    def kp(self) -> float:
        """Static stiffness C(0) [N/m]."""
        return float(np.polyval(self.numerator, 0.0) / np.polyval(self.denominator, 0.0))

    @property
    def kd(self) -> float:
        """Derivative gain of a PD law [N s/m] (0 for a pure proportional law)."""
        if not self.is_pd:
            raise ValueError("kd is defined for a PD controller only")
        return float(self.numerator[0] / self.denominator[0]) if len(self.numerator) == 2 else 0.0

    def __call__(self, s):
        """C(s) for complex Laplace variable(s) ``s``."""
        return np.polyval(self.numerator, s) / np.polyval(self.denominator, s)

    @property
    def basis_stiffness(self) -> float:
        """Stiffness [N/m] this law contributes to the modal basis and static solutions: K_p of a
        PD law; for a transfer function its static gain C(0) when finite and positive, else 0
        (its dynamics then enter through the controller states)."""
        if self.is_pd:
            return self.kp
        den0 = float(np.polyval(self.denominator, 0.0))
        if den0 == 0.0:
            return 0.0
        k0 = float(np.polyval(self.numerator, 0.0)) / den0
        return k0 if np.isfinite(k0) and k0 > 0 else 0.0

    def derivative(self, s):
        """dC/ds at ``s`` (for Newton-type eigenvalue refinement)."""
        num, den = np.poly1d(self.numerator), np.poly1d(self.denominator)
        return (num.deriv()(s) * den(s) - num(s) * den.deriv()(s)) / den(s) ** 2

    def state_space(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
        """Minimal realization ``(A, B, C, D)`` of a proper C(s): ẋ = A x + B d, C(s)d = C x + D d.

        Controllable canonical form of the transfer function with leading zeros dropped and
        common roots of numerator and denominator cancelled (so the realization is minimal).
        A PD law is improper and has no realization: use :attr:`kp` and :attr:`kd`.
        """
        num = np.trim_zeros(np.asarray(self.numerator, dtype=float), "f")
        den = np.trim_zeros(np.asarray(self.denominator, dtype=float), "f")
        if num.size == 0:
            return np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)), 0.0
        num, den = _cancel_common_roots(num, den)
        if num.size > den.size:
            raise ValueError("C(s) is improper (numerator degree above the denominator's): no state-space form")
        num, den = num / den[0], den / den[0]
        n = den.size - 1
        num = np.concatenate([np.zeros(den.size - num.size), num])
        D = float(num[0])
        if n == 0:
            return np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)), D
        A = np.zeros((n, n))
        A[:-1, 1:] = np.eye(n - 1)
        A[-1, :] = -den[1:][::-1]
        B = np.zeros((n, 1))
        B[-1, 0] = 1.0
        C = (num[1:] - D * den[1:])[::-1][None, :]
        return A, B, C, D


def _cancel_common_roots(num: np.ndarray, den: np.ndarray, tol: float = 1e-9) -> tuple[np.ndarray, np.ndarray]:
    """Remove roots shared by numerator and denominator (pole-zero cancellation)."""
    zeros, poles = list(np.roots(num)), list(np.roots(den))
    kept_poles = []
    for p in poles:
        match = [k for k, z in enumerate(zeros) if abs(z - p) <= tol * max(1.0, abs(p))]
        if match:
            zeros.pop(match[0])
        else:
            kept_poles.append(p)
    if len(kept_poles) == len(poles):
        return num, den
    new_num = num[0] * np.real_if_close(np.poly(zeros)) if zeros else np.array([num[0]])
    new_den = den[0] * np.real_if_close(np.poly(kept_poles)) if kept_poles else np.array([den[0]])
    return np.real(new_num), np.real(new_den)


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
    """An active bearing: its link and controller. Acts on rows v and w of the link."""

    link: BearingLink
    controller: Controller

    @property
    def name(self) -> str:
        return self.link.name

    @property
    def lateral_rows(self) -> sp.csr_matrix:
        """(2, ndof) rows of the lateral relative displacement (v, w)."""
        return self.link.rows[1:3]


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
class Model:
    """Assembled global matrices (full size; restrict to ``dofs.free`` to solve).

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

    @cached_property
    def _loss_split(self) -> tuple[sp.csr_matrix, sp.csr_matrix, sp.csr_matrix]:
        n = self.dofs.size
        shaft = self.shaft_loss_stiffness if self.shaft_loss_stiffness is not None else sp.csr_matrix((n, n))
        boom = self.boom_loss_stiffness if self.boom_loss_stiffness is not None else sp.csr_matrix((n, n))
        nodes = np.arange(self.dofs.n_shaft_nodes)
        lateral = np.zeros(n)
        for f in ("v", "w", "beta", "gamma"):
            lateral[self.dofs.shaft(nodes, f)] = 1.0
        P = sp.diags(lateral)
        K_lat = (P @ shaft @ P).tocsr()
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
        """True when every actuator is a PD law (then K_p, K_d matrices describe them)."""
        return all(a.controller.is_pd for a in self.actuators)

    def actuator_matrix(self, gains) -> sp.csr_matrix:
        """``Σ Bᵀ g_a B`` over actuators for per-actuator scalar gains ``g_a``."""
        out = sp.csr_matrix((self.dofs.size, self.dofs.size), dtype=np.result_type(*gains, float) if len(gains) else float)
        for act, g in zip(self.actuators, gains):
            B = act.lateral_rows
            out = out + g * (B.T @ B)
        return out.tocsr()

    @property
    def Kp(self) -> sp.csr_matrix:
        """Actuator stiffness matrix Σ Bᵀ k_a B [N/m], ``k_a`` = :attr:`Controller.basis_stiffness`
        (K_p of a PD law; the finite static gain C(0) of a transfer function, else 0)."""
        return self.actuator_matrix([a.controller.basis_stiffness for a in self.actuators])

    @property
    def Kd(self) -> sp.csr_matrix:
        """Actuator derivative (damping) matrix of the PD laws [N s/m] (transfer functions: 0)."""
        return self.actuator_matrix([a.controller.kd if a.controller.is_pd else 0.0 for a in self.actuators])

    def controller_matrix(self, s) -> sp.csr_matrix:
        """Actuator dynamic stiffness ``Σ Bᵀ C_a(s) B`` at one complex ``s``."""
        return self.actuator_matrix([complex(a.controller(s)) for a in self.actuators])

    @property
    def shaft_mass(self) -> float:
        """Mass of the shaft tube [kg] (disks excluded)."""
        sh = self.shaft
        area = np.pi * (sh.outer_diameter**2 - sh.inner_diameter**2) / 4
        return float(sh.density * area * (self.dofs.shaft_x[-1] - self.dofs.shaft_x[0]))

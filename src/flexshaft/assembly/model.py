"""The assembled driveline model: global matrices, DOF map, bearings and actuators.

Equation of motion in the frequency domain (thesis eqs. 2.38-2.40)::

    [−ω² M + iω (Ω G + C + K_d) + K + K_p] q = Q

``K`` is complex (composite and boom hysteretic loss) and includes the contact-bearing
springs; ``C`` is viscous damping (bearing dampers); actuators add ``Bᵀ C(iω) B`` where
``C(s) = K_p + s K_d`` for the PD law or any transfer function.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import scipy.sparse as sp

from flexshaft.assembly.dofs import DofMap

__all__ = ["Controller", "Actuator", "BearingLink", "ShaftProperties", "Model"]


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
        Complex stiffness incl. contact bearings [N/m, N m/rad].
    C : csr_matrix
        Viscous damping (bearing dampers) [N s/m].
    G : csr_matrix
        Gyroscopic matrix per unit spin speed (skew-symmetric) [kg m^2].
    speed : float
        Operating speed Ω [rad/s].
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
    shaft_loss_stiffness: sp.csr_matrix | None = None  # Im(K) of the shaft elements (rotating material)
    boom_loss_stiffness: sp.csr_matrix | None = None  # Im(K) of the boom elements (fixed frame)

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
        """Actuator proportional stiffness matrix, Σ Bᵀ C(0) B [N/m]."""
        return self.actuator_matrix([a.controller.kp for a in self.actuators])

    @property
    def Kd(self) -> sp.csr_matrix:
        """Actuator derivative (damping) matrix of PD laws [N s/m]."""
        return self.actuator_matrix([a.controller.kd for a in self.actuators])

    def controller_matrix(self, s) -> sp.csr_matrix:
        """Actuator dynamic stiffness ``Σ Bᵀ C_a(s) B`` at one complex ``s``."""
        return self.actuator_matrix([complex(a.controller(s)) for a in self.actuators])

    @property
    def shaft_mass(self) -> float:
        """Mass of the shaft tube [kg] (disks excluded)."""
        sh = self.shaft
        area = np.pi * (sh.outer_diameter**2 - sh.inner_diameter**2) / 4
        return float(sh.density * area * (self.dofs.shaft_x[-1] - self.dofs.shaft_x[0]))

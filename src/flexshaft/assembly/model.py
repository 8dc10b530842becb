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
    """A linear law ``y = C(s) u`` given as a ratio of polynomials in s.

    ``numerator``/``denominator`` are polynomial coefficients in s, highest power first; the
    PD law is ``numerator = (kd, kp)``, ``denominator = (1,)``. As an actuator's controller it
    maps the measured displacement to the force (thesis: [N/m]) or, for a magnetic bearing,
    to the current command [A/m] (see :class:`Actuator`). The numerator may exceed the
    denominator's degree by one (an ideal derivative: PD, unfiltered PID); see
    :meth:`realization`.
    """

    numerator: tuple[float, ...]
    denominator: tuple[float, ...] = (1.0,)

    @classmethod
    def pd(cls, kp: float, kd: float) -> "Controller":
        """Proportional-derivative law ``C(s) = kp + kd s`` [N/m, N s/m]."""
        return cls(numerator=(float(kd), float(kp)), denominator=(1.0,))

    @classmethod
    def constant(cls, gain: float) -> "Controller":
        """The static law ``C(s) = gain``."""
        return cls(numerator=(float(gain),), denominator=(1.0,))

    @classmethod
    def pid(cls, kp: float, ki: float = 0.0, kd: float = 0.0, derivative_cutoff: float | None = None) -> "Controller":
        """``C(s) = kp + ki/s + kd s/(1 + s/ω_d)`` with the derivative-filter corner ω_d [rad/s].

        ``derivative_cutoff=None`` is the ideal derivative ``kd s``. Without integral action
        (``ki = 0``) there is no pole at the origin.
        """
        kp, ki, kd = float(kp), float(ki), float(kd)
        if derivative_cutoff is None:
            return cls.pd(kp, kd) if ki == 0.0 else cls((kd, kp, ki), (1.0, 0.0))
        wd = float(derivative_cutoff)
        if not (np.isfinite(wd) and wd > 0):
            raise ValueError(f"derivative_cutoff must be a finite number > 0 rad/s (got {derivative_cutoff!r})")
        if ki == 0.0:
            return cls((kd + kp / wd, kp), (1.0 / wd, 1.0))
        return cls((kd + kp / wd, kp + ki / wd, ki), (1.0 / wd, 1.0, 0.0))

    @classmethod
    def lag(cls, bandwidth: float) -> "Controller":
        """First-order low-pass ``1/(1 + s/ω_a)`` of bandwidth ω_a [rad/s] (an amplifier)."""
        w = float(bandwidth)
        if not (np.isfinite(w) and w > 0):
            raise ValueError(f"bandwidth must be a finite number > 0 rad/s (got {bandwidth!r})")
        return cls((1.0,), (1.0 / w, 1.0))

    @classmethod
    def from_transfer_function(cls, tf: Any) -> "Controller":
        """A Controller from any SISO transfer-function object with ``num`` and ``den``.

        Duck-typed: a ``control.TransferFunction`` of python-control (``num``/``den`` as
        nested lists ``[[array]]``), a ``scipy.signal.TransferFunction``/``lti`` or any object
        whose ``num`` and ``den`` are coefficient sequences (highest power first). A
        :class:`Controller` is returned unchanged. python-control is not needed to use this.
        """
        if isinstance(tf, Controller):
            return tf
        if not (hasattr(tf, "num") and hasattr(tf, "den")):
            raise TypeError(f"expected a transfer function with num and den, got {type(tf).__name__}")
        if getattr(tf, "dt", None) not in (None, 0):
            raise ValueError(f"a continuous-time transfer function is needed (got dt = {tf.dt!r})")

        def coefficients(value, name):
            while isinstance(value, (list, tuple)) and len(value) == 1 and np.ndim(value[0]) >= 1:
                value = value[0]  # python-control's SISO num/den: [[array]]
            try:
                out = np.asarray(value, dtype=float)
            except (TypeError, ValueError):
                raise ValueError(f"transfer function {name} must be one coefficient sequence (a SISO system)") from None
            if out.ndim > 1 and all(n == 1 for n in out.shape[:-1]):
                out = out.reshape(-1)
            out = np.atleast_1d(out)
            if out.ndim != 1 or out.size == 0 or not np.all(np.isfinite(out)):
                raise ValueError(f"transfer function {name} must be one finite coefficient sequence of a SISO "
                                 f"system (got shape {out.shape})")
            return tuple(float(v) for v in out)

        num, den = coefficients(tf.num, "numerator"), coefficients(tf.den, "denominator")
        law = cls(num, den)
        if not np.any(np.asarray(den)):
            raise ValueError("transfer function denominator is zero")
        if law.relative_degree < -1:
            raise ValueError("C(s) is improper by more than one degree (at most an ideal derivative is allowed)")
        return law

    def series(self, other: "Controller") -> "Controller":
        """The product ``C(s) · other(s)`` (two blocks in series)."""
        return Controller(tuple(np.polymul(self.numerator, other.numerator)), tuple(np.polymul(self.denominator, other.denominator)))

    def scaled(self, gain: float) -> "Controller":
        """``gain · C(s)``."""
        return Controller(tuple(float(gain) * np.asarray(self.numerator, dtype=float)), self.denominator)

    def shifted(self, constant: float) -> "Controller":
        """``C(s) + constant``."""
        return Controller(tuple(np.polyadd(self.numerator, float(constant) * np.asarray(self.denominator, dtype=float))),
                          self.denominator)

    @property
    def is_pd(self) -> bool:
        return len(self.denominator) == 1 and len(self.numerator) <= 2

    @property
    def relative_degree(self) -> int:
        """Degree of the denominator minus the numerator's (after leading zeros; −1: ideal derivative)."""
        num = np.trim_zeros(np.asarray(self.numerator, dtype=float), "f")
        den = np.trim_zeros(np.asarray(self.denominator, dtype=float), "f")
        return (den.size - 1) - (num.size - 1) if num.size else den.size

    @property
    def integrates(self) -> bool:
        """True when C(s) has a pole at s = 0 (after cancellation): integral action, C(0) infinite."""
        num = np.trim_zeros(np.asarray(self.numerator, dtype=float), "f")
        den = np.trim_zeros(np.asarray(self.denominator, dtype=float), "f")
        if num.size == 0:
            return False
        num, den = _cancel_common_roots(num, den)
        return float(den[-1]) == 0.0

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
    def static_gain(self) -> float:
        """C(0); ``inf`` for integral action, −inf/inf by the sign of the integral gain."""
        if self.integrates:
            num = np.trim_zeros(np.asarray(self.numerator, dtype=float), "f")
            den = np.trim_zeros(np.asarray(self.denominator, dtype=float), "f")
            num, den = _cancel_common_roots(num, den)
            den_nz = np.trim_zeros(den, "b")
            return float(np.sign(num[-1] / den_nz[-1])) * np.inf if num[-1] != 0 else np.inf
        return self.kp

    @property
    def proportional_gain(self) -> float:
        """The constant term of C(s) at s = 0: C(0) when finite, else the s⁰ coefficient of the
        Laurent series about s = 0 (``kp`` of a PID, whatever its integral gain)."""
        num = np.trim_zeros(np.asarray(self.numerator, dtype=float), "f")
        den = np.trim_zeros(np.asarray(self.denominator, dtype=float), "f")
        if num.size == 0:
            return 0.0
        num, den = _cancel_common_roots(num, den)
        order = 0
        while den.size > 1 and den[-1] == 0.0:
            den, order = den[:-1], order + 1
        # Taylor coefficients of num/den about 0, ascending, up to the power `order`
        a, b = num[::-1], den[::-1]
        series = []
        for k in range(order + 1):
            value = (a[k] if k < a.size else 0.0) - sum(series[j] * (b[k - j] if k - j < b.size else 0.0) for j in range(k))
            series.append(value / b[0])
        return float(series[order])

    @property
    def basis_stiffness(self) -> float:
        """Stiffness [N/m] this law contributes to the modal basis: its
        :attr:`proportional_gain` (K_p of a PD or PID law, C(0) of a finite-gain transfer
        function) when positive, else 0, so that the basis stiffness K + Σ k_a BᵀB stays
        positive semi-definite (its dynamics enter through the state matrix)."""
        if self.is_pd:
            kp = self.kp
            return kp if kp > 0 else 0.0
        k0 = self.proportional_gain
        return k0 if np.isfinite(k0) and k0 > 0 else 0.0

    def derivative(self, s):
        """dC/ds at ``s`` (for Newton-type eigenvalue refinement)."""
        num, den = np.poly1d(self.numerator), np.poly1d(self.denominator)
        return (num.deriv()(s) * den(s) - num(s) * den.deriv()(s)) / den(s) ** 2

    def realization(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, float]:
        """``(A, B, C, D, E)`` with ``C(s) = E s + D + C (sI − A)⁻¹ B``, minimal.

        ``E`` is the ideal-derivative part (non-zero only when the numerator exceeds the
        denominator's degree by one: PD, unfiltered PID), ``(A, B, C, D)`` the controllable
        canonical realization of the proper remainder after cancelling common roots. A PD law
        gives no states, ``D = kp``, ``E = kd``.
        """
        num = np.trim_zeros(np.asarray(self.numerator, dtype=float), "f")
        den = np.trim_zeros(np.asarray(self.denominator, dtype=float), "f")
        if num.size == 0:
            return np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)), 0.0, 0.0
        num, den = _cancel_common_roots(num, den)
        E = 0.0
        if num.size == den.size + 1:
            E = float(num[0] / den[0])
            num = num[1:] - E * np.concatenate([den[1:], [0.0]])  # num − E s den, degree ≤ den's
        elif num.size > den.size:
            raise ValueError("C(s) is improper by more than one degree: no state-space form")
        A, B, C, D = _controllable_form(num, den)
        return A, B, C, D, E

    def state_space(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
        """Minimal realization ``(A, B, C, D)`` of a proper C(s): ẋ = A x + B d, C(s)d = C x + D d.

        Controllable canonical form of the transfer function with leading zeros dropped and
        common roots of numerator and denominator cancelled (so the realization is minimal).
        An improper law (PD) has no such realization: use :meth:`realization`.
        """
        num = np.trim_zeros(np.asarray(self.numerator, dtype=float), "f")
        den = np.trim_zeros(np.asarray(self.denominator, dtype=float), "f")
        if num.size == 0:
            return np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)), 0.0
        num, den = _cancel_common_roots(num, den)
        if num.size > den.size:
            raise ValueError("C(s) is improper (numerator degree above the denominator's): no state-space form")
        return _controllable_form(num, den)


def _controllable_form(num: np.ndarray, den: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """Controllable canonical (A, B, C, D) of a proper num/den (numerator degree ≤ denominator's)."""
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
        for field_name, value, allowed in (("current_gain", self.current_gain, "a finite number > 0 N/A"),
                                           ("negative_stiffness", self.negative_stiffness, "a finite number >= 0 N/m")):
            ok = np.isfinite(value) and (value > 0 if field_name == "current_gain" else value >= 0)
            if not ok:
                raise ValueError(f"actuator {self.link.name!r}: {field_name} must be {allowed} (got {value!r})")
        bandwidth = self.amplifier_bandwidth
        if bandwidth is not None and not (np.isfinite(bandwidth) and bandwidth > 0):
            raise ValueError(f"actuator {self.link.name!r}: amplifier_bandwidth must be None or a finite number > 0 rad/s "
                             f"(got {bandwidth!r})")
        if self.controller.relative_degree < -1:
            raise ValueError(f"actuator {self.link.name!r}: C(s) is improper by more than one degree "
                             "(at most an ideal derivative is allowed)")

    @property
    def name(self) -> str:
        return self.link.name

    @property
    def lateral_rows(self) -> sp.csr_matrix:
        """(2, ndof) actuation rows B_a: the lateral relative displacement (v, w) at the magnet."""
        return self.link.rows[1:3]

    @property
    def sensing_rows(self) -> sp.csr_matrix:
        """(2, ndof) sensing rows B_s: the lateral relative displacement at the sensor."""
        return self.lateral_rows if self.sensor is None else self.sensor.rows[1:3]

    @property
    def collocated(self) -> bool:
        """True when the sensor measures at the magnet (B_s = B_a)."""
        return self.sensor is None

    def plant(self, s):
        """``k_i A(s)`` [N/A]: current command to force at Laplace variable(s) ``s``."""
        value = np.ones_like(np.asarray(s, dtype=complex)) if self.amplifier_bandwidth is None \
            else 1.0 / (1.0 + np.asarray(s) / self.amplifier_bandwidth)
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
        """True when every actuator is collocated with a PD force law ``G − k_s`` (its gains then
        describe it completely: :attr:`Kp` and :attr:`Kd` when the stiffness is not negative)."""
        return all(a.collocated and a.collocated_law.is_pd for a in self.actuators)

    def actuator_matrix(self, gains) -> sp.csr_matrix:
        """``Σ Bᵀ g_a B`` over actuators for per-actuator scalar gains ``g_a`` (actuation rows)."""
        out = sp.csr_matrix((self.dofs.size, self.dofs.size), dtype=np.result_type(*gains, float) if len(gains) else float)
        for act, g in zip(self.actuators, gains):
            B = act.lateral_rows
            out = out + g * (B.T @ B)
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
        out = self.actuator_matrix([complex(a.law(s)) if a.collocated else -a.negative_stiffness for a in self.actuators])
        for a in self.actuators:
            if not a.collocated:
                out = out + complex(a.feedback_gain(s)) * (a.lateral_rows.T @ a.sensing_rows)
        return out.tocsr()

    def passive(self) -> "Model":
        """The same model with every actuator switched off (zero law, no magnet stiffness)."""
        import dataclasses

        off = Controller.pd(0.0, 0.0)
        return dataclasses.replace(self, actuators=tuple(
            dataclasses.replace(a, controller=off, current_gain=1.0, negative_stiffness=0.0, amplifier_bandwidth=None)
            for a in self.actuators))

    @property
    def shaft_mass(self) -> float:
        """Mass of the shaft tube [kg] (disks excluded)."""
        sh = self.shaft
        area = np.pi * (sh.outer_diameter**2 - sh.inner_diameter**2) / 4
        return float(sh.density * area * (self.dofs.shaft_x[-1] - self.dofs.shaft_x[0]))

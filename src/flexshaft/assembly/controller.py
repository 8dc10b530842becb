"""Linear controller laws C(s) as ratios of polynomials: PD, PID, lags, any transfer function.

A :class:`Controller` is what an active bearing's feedback is made of
(:class:`~flexshaft.assembly.model.Actuator`): it is evaluated at s = iω in the frequency
domain and realised as controller states (:meth:`Controller.realization`) in the
eigen-analyses. python-control's ``TransferFunction`` (or any object with SISO ``num`` and
``den``) converts with :meth:`Controller.from_transfer_function`; python-control itself is not
needed.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["Controller"]


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
    def pd(cls, kp: float, kd: float) -> Controller:
        """Proportional-derivative law ``C(s) = kp + kd s`` [N/m, N s/m]."""
        return cls(numerator=(float(kd), float(kp)), denominator=(1.0,))

    @classmethod
    def constant(cls, gain: float) -> Controller:
        """The static law ``C(s) = gain``."""
        return cls(numerator=(float(gain),), denominator=(1.0,))

    @classmethod
    def pid(cls, kp: float, ki: float = 0.0, kd: float = 0.0, derivative_cutoff: float | None = None) -> Controller:
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
    def lag(cls, bandwidth: float) -> Controller:
        """First-order low-pass ``1/(1 + s/ω_a)`` of bandwidth ω_a [rad/s] (an amplifier)."""
        w = float(bandwidth)
        if not (np.isfinite(w) and w > 0):
            raise ValueError(f"bandwidth must be a finite number > 0 rad/s (got {bandwidth!r})")
        return cls((1.0,), (1.0 / w, 1.0))

    @classmethod
    def from_transfer_function(cls, tf: Any) -> Controller:
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
                raise ValueError(
                    f"transfer function {name} must be one finite coefficient sequence of a SISO "
                    f"system (got shape {out.shape})"
                )
            return tuple(float(v) for v in out)

        num, den = coefficients(tf.num, "numerator"), coefficients(tf.den, "denominator")
        law = cls(num, den)
        if not np.any(np.asarray(den)):
            raise ValueError("transfer function denominator is zero")
        if law.relative_degree < -1:
            raise ValueError("C(s) is improper by more than one degree (at most an ideal derivative is allowed)")
        return law

    def series(self, other: Controller) -> Controller:
        """The product ``C(s) · other(s)`` (two blocks in series)."""
        return Controller(
            tuple(np.polymul(self.numerator, other.numerator)), tuple(np.polymul(self.denominator, other.denominator))
        )

    def scaled(self, gain: float) -> Controller:
        """``gain · C(s)``."""
        return Controller(tuple(float(gain) * np.asarray(self.numerator, dtype=float)), self.denominator)

    def shifted(self, constant: float) -> Controller:
        """``C(s) + constant``."""
        return Controller(
            tuple(np.polyadd(self.numerator, float(constant) * np.asarray(self.denominator, dtype=float))),
            self.denominator,
        )

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
        series: list[float] = []
        for k in range(order + 1):
            value = (a[k] if k < a.size else 0.0) - sum(
                series[j] * (b[k - j] if k - j < b.size else 0.0) for j in range(k)
            )
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
        num, den = np.asarray(self.numerator, dtype=float), np.asarray(self.denominator, dtype=float)
        d = np.polyval(den, s)
        return (np.polyval(np.polyder(num), s) * d - np.polyval(num, s) * np.polyval(np.polyder(den), s)) / d**2

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

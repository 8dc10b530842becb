r"""The complex-envelope system of a run-up and its exponential integrator.

Used by :mod:`flexshaft.analyses.transient` (which states the physics). The envelope state
``Z`` (modal displacements, modal velocities, controller states) obeys

    Ż = J(Ω) Z + b (Ω² − iΩ̇),   J(Ω) = J₀ + Ω J₁ − R(Ω),

with J₀ the speed-independent first-order matrix (stiffness, viscous damping, PD gains,
controller states, fixed-frame loss as per-mode viscous damping), J₁ the gyroscopic part and
the frame rotation −i, and R(Ω) the rotating-frame loss with its speed-dependent reference
frequencies ω_j + Ω.

Integrator: exponential time differencing (ETDRK4, Cox & Matthews 2002) in the eigenbasis of
``J(Ω_ref)`` at a reference speed. Writing ``Ẑ = S Z`` (S scales the modal displacements by
ω_j and balances the controller states, so the basis is well conditioned) and ``Ẑ = V w``
with ``S J(Ω_ref) S⁻¹ = V Λ V⁻¹``,

    ẇ = Λ w + N(w, t),   N = V⁻¹ S [(J(Ω) − J(Ω_ref)) Z + b (Ω² − iΩ̇)],

the stiff and oscillatory part Λ is integrated exactly (every free vibration keeps its
frequency and decay whatever the step), and ETDRK4 integrates the slow remainder: the
forcing, the drift of the gyroscopic and loss terms and the frame rotation −i(Ω − Ω_ref) since
the reference. The reference is refreshed (one dense eigen-decomposition) when the speed has
moved by :data:`REFRESH_SPEED_FRACTION` of the largest speed. The step is controlled by step
doubling (one step h against two of h/2; the difference over 2⁴ − 1 estimates the local error
in the energy norm ‖Ẑ‖, held below ``rtol`` times the largest state so far; an error of
exactly zero, a zero load, doubles the step). Outputs between steps come from the exact
exponential of Λ plus a second-order interpolation of N.

Refusals, so that a run ends with a result or a message and never runs on for hours or returns
an absurd number: more than :data:`MAX_STEPS` steps; a free whirl that grows more than
:data:`MAX_GROWTH`-fold over the run (``∫ max(0, max Re λ(Ω_ref)) dt``, the system unstable
at the run's speeds: the envelope would show the instability, not the imbalance response).

References
----------
Cox, S. M., Matthews, P. C. (2002). Exponential time differencing for stiff systems.
J. Comput. Phys. 176, 430-455.
Hochbruck, M., Ostermann, A. (2010). Exponential integrators. Acta Numerica 19, 209-286.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass
from math import factorial

import numpy as np
import scipy.linalg as la

from flexshaft.analyses.eigen import DIVERGENCE_TOLERANCE, ReducedModel
from flexshaft.analyses.guards import RefusedInputError, UnstableResponseError
from flexshaft.analyses.stability import STABILITY_TOLERANCE
from flexshaft.assembly.model import Model

__all__ = [
    "ETD_STABLE_STEP",
    "MAX_GROWTH",
    "MAX_STEPS",
    "REFRESH_SPEED_FRACTION",
    "EnvelopeRun",
    "EnvelopeSystem",
    "growing_whirl",
    "integrate_envelope",
    "phi_functions",
]

#: The eigenbasis is refreshed when Ω has moved by this fraction of the largest speed.
REFRESH_SPEED_FRACTION = 0.02
#: Most integration steps (accepted and rejected) of one run: about 2 ms each on the embedded
#: drivelines (35-70 envelope states), so a run is refused rather than computed for minutes.
MAX_STEPS = 100_000
#: h·|rate| up to which ETDRK4 integrates an oscillatory remainder stably (its stability region
#: reaches about 2.8 along the imaginary axis, Cox & Matthews 2002, fig. 1).
ETD_STABLE_STEP = 2.8
#: Largest growth of a free whirl over a run, exp(∫ max(0, growth rate) dt): beyond it the
#: envelope shows the instability, not the imbalance response, and the run is refused
#: (a short run-up of a controller with K_i = 1e15 returned 4e97 m).
MAX_GROWTH = 1e3
_SERIES_BELOW = 0.25  # |z| below which φ_k use their Taylor series (12 terms: 0.25¹²/12! ≈ 1e-16)
_SERIES_TERMS = 12
_INVERSE_FACTORIALS = np.array([1.0 / factorial(m) for m in range(_SERIES_TERMS + 4)])
_SERIES_COEFFICIENTS = np.array([[_INVERSE_FACTORIALS[m + k] for k in (1, 2, 3)] for m in range(_SERIES_TERMS)])


def phi_functions(z: np.ndarray, order: int = 3) -> tuple[np.ndarray, ...]:
    """``(e^z, φ₁, …, φ_order)`` elementwise, ``φ_k(z) = Σ_m z^m/(m+k)!`` (Taylor series for
    |z| < 0.25, where the closed forms ``φ_{k+1} = (φ_k − 1/k!)/z`` cancel)."""
    z = np.asarray(z, dtype=complex)
    e = np.exp(z)
    small = np.abs(z) < _SERIES_BELOW
    zs = np.where(small, 1.0, z)
    phis = [(e - 1.0) / zs]
    for k in range(1, order):
        phis.append((phis[-1] - _INVERSE_FACTORIALS[k]) / zs)
    if small.any():
        powers = z[small][:, None] ** np.arange(_SERIES_TERMS)  # (n_small, terms)
        series = powers @ _SERIES_COEFFICIENTS[:, :order]
        for k in range(order):
            phis[k][small] = series[:, k]
    return (e, *phis)


class EnvelopeSystem:
    """``Ż = J(Ω) Z + b (Ω² − iΩ̇)`` of a reduced model (see the module docstring).

    Parameters
    ----------
    model : Model
        The driveline (its internal-damping model chooses the loss form).
    red : ReducedModel
        Its modal reduction.
    loads_per_speed_squared : ndarray
        One rotating load vector Q₁ [N s²] on the full DOF vector.
    max_speed : float
        Largest speed of the run [rad/s] (to check that the state matrix is affine in Ω).
    """

    def __init__(self, model: Model, red: ReducedModel, loads_per_speed_squared: np.ndarray, max_speed: float):
        nb = red.size
        self.nb, self.n = nb, red.n_states
        A0 = red.state_matrix(0.0)
        top = max(max_speed, 1.0)
        A1 = (red.state_matrix(top) - A0) / top
        if not np.allclose(red.state_matrix(0.5 * top), A0 + 0.5 * top * A1, rtol=1e-10, atol=1e-10 * np.abs(A0).max()):
            raise NotImplementedError("the reduced model's state matrix is not affine in the speed")
        omega = np.sqrt(np.clip(red.w2, 0.0, None))
        self.omega = np.maximum(omega, max(1e-6 * omega.max(), 1e-3))
        self.frequency = float(self.omega.max())  # the largest basis frequency [rad/s]
        d0 = 1.0 / np.sqrt(self.omega)
        rotating = model.internal_damping != "thesis"
        fixed = red.F if rotating else red.F + red.L
        self.J0 = A0.astype(complex)
        self.J0[nb : 2 * nb, nb : 2 * nb] -= d0[:, None] * fixed * d0[None, :]
        self.gyroscopic = A1[nb : 2 * nb, nb : 2 * nb].copy()
        if np.abs(A1).sum() > np.abs(self.gyroscopic).sum() * (1 + 1e-12) + 1e-300:
            raise NotImplementedError("the speed enters the state matrix outside the gyroscopic block")
        # the rotating-frame loss blocks L, S of the reduced model; None with the thesis model or no loss
        self.lateral: np.ndarray | None
        self.circulatory: np.ndarray | None
        self.lateral, self.circulatory = (red.L, red.S) if rotating and np.any(red.L) else (None, None)
        Q = np.asarray(loads_per_speed_squared)
        if Q.ndim != 1 or Q.size != model.dofs.size:
            raise ValueError(
                f"loads_per_speed_squared must be one load vector of {model.dofs.size} values, got shape {Q.shape}"
            )
        if not np.all(np.isfinite(Q)):
            raise ValueError("loads_per_speed_squared contains NaN or inf")
        self.b = np.zeros(self.n, complex)
        self.b[nb : 2 * nb] = red.Phi.T @ Q[model.dofs.free]
        self.scale = np.concatenate([self.omega, np.ones(self.n - nb)])
        if self.n > 2 * nb:  # controller states: scale by balancing (their gains span ~1e11)
            Jhat = self.matrix(top) * self.scale[:, None] / self.scale[None, :]
            _, (T, _) = la.matrix_balance(Jhat, permute=False, separate=True)
            self.scale[2 * nb :] = np.exp(np.mean(np.log(T[: 2 * nb]))) / T[2 * nb :]

    def _rotating(self, speed: float) -> tuple[np.ndarray, np.ndarray] | None:
        """Blocks of R(Ω): damping on ẏ and circulatory stiffness on y, (nb, nb) each."""
        if self.lateral is None:
            return None
        d = 1.0 / np.sqrt(self.omega + speed)
        dd = d[:, None] * d[None, :]
        return dd * self.lateral, speed * dd * self.circulatory

    def matrix(self, speed: float) -> np.ndarray:
        """J(Ω) (n, n) complex."""
        nb = self.nb
        J = self.J0.copy()
        J[nb : 2 * nb, nb : 2 * nb] += speed * self.gyroscopic
        J.flat[:: self.n + 1] -= 1j * speed
        blocks = self._rotating(speed)
        if blocks is not None:
            J[nb : 2 * nb, nb : 2 * nb] -= blocks[0]
            J[nb : 2 * nb, :nb] -= blocks[1]
        return J

    def drift(self, speeds, reference: float, Z: np.ndarray) -> np.ndarray:
        """``(J(Ω_k) − J(Ω_ref) + i(Ω_k − Ω_ref)) Z_k``: the drift of the gyroscopic and
        rotating-loss terms since the reference (the frame rotation left out), for state
        columns Z (n, k) at speeds Ω_k (k,)."""
        nb = self.nb
        speeds = np.asarray(speeds, dtype=float)
        y, v = Z[:nb], Z[nb : 2 * nb]
        acc = (speeds - reference) * (self.gyroscopic @ v)
        if self.lateral is not None:
            k = Z.shape[1]
            d = 1.0 / np.sqrt(self.omega[:, None] + np.concatenate([speeds, np.full(k, reference)]))
            both = np.concatenate([v, v], axis=1)
            damping = d * (self.lateral @ (d * both))
            stiffness = d * (self.circulatory @ (d * np.concatenate([y, y], axis=1)))
            acc -= damping[:, :k] - damping[:, k:] + speeds * stiffness[:, :k] - reference * stiffness[:, k:]
        out = np.zeros_like(Z)
        out[nb : 2 * nb] = acc
        return out

    def steady_state(self, speed: float) -> np.ndarray:
        """Envelope of the steady synchronous response at constant Ω (n,)."""
        return la.solve(self.matrix(speed), -self.b * speed * speed)

    def drift_rate(self, max_speed: float) -> float:
        """Largest rate [1/s] of the speed-dependent remainder the integrator treats explicitly:
        the gyroscopic drift ``(Ω − Ω_ref) G̃`` between two refreshes of the eigenbasis, with
        |Ω − Ω_ref| up to :data:`REFRESH_SPEED_FRACTION` × the largest speed. A step must keep
        ``h × rate`` below :data:`ETD_STABLE_STEP`."""
        gyroscopic = float(np.linalg.norm(self.gyroscopic, 2)) if self.gyroscopic.size else 0.0
        return REFRESH_SPEED_FRACTION * max(max_speed, 1.0) * gyroscopic

    def norm(self, Z: np.ndarray) -> float:
        """Energy-like norm ``‖S Z‖ = √(Σ ω_j²|Y_j|² + |V_j|² + Σ s_x²|x|²)`` (s_x: the
        controller states' balancing scale)."""
        W = self.scale * Z
        return float(np.sqrt(np.sum(W.real**2 + W.imag**2)))


class _Basis:
    """The eigenbasis of ``S J(Ω_ref) S⁻¹``."""

    def __init__(self, system: EnvelopeSystem, speed: float):
        S = system.scale
        Jhat = system.matrix(speed) * S[:, None] / S[None, :]
        lam, V = la.eig(Jhat, check_finite=False)
        self.speed, self.lam, self.V = speed, lam, V
        self.Vinv = la.inv(V, check_finite=False)
        self.condition = float(np.linalg.norm(V, 1) * np.linalg.norm(self.Vinv, 1))

    def to_modal(self, Zhat: np.ndarray) -> np.ndarray:
        return self.Vinv @ Zhat


def growing_whirl(lam: np.ndarray, speed: float, scale: float) -> bool:
    """Whether the envelope eigenvalues λ at the reference speed Ω hold a free whirl that grows.

    An envelope eigenvalue is λ = s − iΩ (the frame rotation, :meth:`EnvelopeSystem.matrix`), so
    the mode's s = λ + iΩ. It grows when ζ = −Re s/|s| is below
    −:data:`~flexshaft.analyses.stability.STABILITY_TOLERANCE`, the rule of the whirl-stability
    analysis: an undamped mode's real part is round-off (±1e-9 1/s on a conservative tube),
    not an instability. A root near s = 0 (|s| at most
    :data:`~flexshaft.analyses.eigen.DIVERGENCE_TOLERANCE` × ``scale``, the largest basis
    frequency [rad/s], at least 1: a rigid-body mode's round-off) does not count, as the eigen
    analyses count a divergence. The scale is the structure's, not the spectrum's: a fast
    controller pole (an amplifier's 1 MHz) must not raise the bound over a real divergence.
    """
    s = np.asarray(lam) + 1j * speed
    size = np.abs(s)
    floor = DIVERGENCE_TOLERANCE * max(scale, 1.0)
    return bool(np.any((s.real > STABILITY_TOLERANCE * size) & (size > floor)))


def _quantise(h: float) -> float:
    """Round a step down to the grid 2^(k/8) s, so that the ETD coefficients are reused."""
    return float(2.0 ** (np.floor(8 * np.log2(h)) / 8))


@dataclass
class EnvelopeRun:
    """Envelope states at the output times and integration statistics."""

    times: np.ndarray
    states: np.ndarray  # (n, n_t) complex
    steps: int
    rejected: int
    refreshes: int
    max_condition: float
    max_growth_rate: float
    growing: bool  # a reference basis held a growing free whirl (:func:`growing_whirl`)


def integrate_envelope(
    system: EnvelopeSystem,
    speeds_at: Callable[[np.ndarray], np.ndarray],
    accelerations_at: Callable[[np.ndarray], np.ndarray],
    breakpoints: np.ndarray,
    initial: np.ndarray,
    output_times: np.ndarray,
    *,
    rtol: float = 1e-6,
    max_step: float | None = None,
    max_speed: float | None = None,
) -> EnvelopeRun:
    """Integrate the envelope system from t = 0 to ``breakpoints[-1]`` [s].

    Parameters
    ----------
    speeds_at, accelerations_at : callable
        Ω(t) [rad/s] and dΩ/dt [rad/s²] at an array of times, elementwise (e.g.
        :meth:`~flexshaft.analyses.speed_profile.SpeedProfile.speeds_at` and
        :meth:`~flexshaft.analyses.speed_profile.SpeedProfile.accelerations_at`): the steps
        evaluate Ω at many times at once.
    breakpoints : ndarray
        Increasing times [s] from 0 that the steps land on (Ω̇ may jump there).
    initial : ndarray
        Z(0) (n,) complex.
    output_times : ndarray
        Increasing times [s] within [0, breakpoints[-1]] at which Z is returned.
    rtol : float
        Local error per step relative to the largest ‖Z‖ so far.
    max_step : float, optional
        Largest step [s].
    max_speed : float, optional
        Largest speed of the run [rad/s] (sets the refresh interval).

    Raises
    ------
    RefusedInputError
        When the run needs more than :data:`MAX_STEPS` steps.
    UnstableResponseError
        When a free whirl grows by more than :data:`MAX_GROWTH` over the run (the system is
        unstable at its speeds), or the response overflows.
    """
    duration = float(breakpoints[-1])

    def speed(t: float) -> float:
        return float(speeds_at(np.array([t]))[0])

    top = max(max_speed if max_speed is not None else float(np.max(speeds_at(np.linspace(0, duration, 257)))), 1.0)
    refresh_every = REFRESH_SPEED_FRACTION * top
    max_step = duration / 50 if max_step is None else float(max_step)
    S = system.scale
    z = np.asarray(initial, dtype=complex)
    outputs = np.asarray(output_times, dtype=float)
    states = np.zeros((system.n, outputs.size), complex)
    k_out = 0
    while k_out < outputs.size and outputs[k_out] <= 0.0:
        states[:, k_out] = z
        k_out += 1

    def drift_and_load(basis: _Basis, W: np.ndarray, times: np.ndarray, until: float) -> np.ndarray:
        """N without the frame rotation, V⁻¹ S [drift Z + load], for columns W (n, k) at times (k,)
        of a step that ends at or before ``until``, just below the next breakpoint: Ω̇ there is
        its own segment's (the profile's Ω̇ is right-continuous, the next segment's at the
        breakpoint itself)."""
        s = speeds_at(times)
        Z = (basis.V @ W) / S[:, None]
        load = system.b[:, None] * (s * s - 1j * accelerations_at(np.minimum(times, until)))
        return basis.Vinv @ (S[:, None] * (system.drift(s, basis.speed, Z) + load))

    def rotation(t0: float, mid: np.ndarray, tau: np.ndarray) -> np.ndarray:
        """θ = ∫ (Ω − Ω_mid) from t0 to t0 + τ (Simpson; exact for linear Ω), elementwise."""
        f = [speeds_at(t0 + c * tau) - mid for c in (0.0, 0.5, 1.0)]
        return tau / 6.0 * (f[0] + 4.0 * f[1] + f[2])

    def etd(basis: _Basis, w: np.ndarray, t: float, h: np.ndarray, N0: np.ndarray, until: float) -> np.ndarray:
        """ETDRK4 from (t, w) over each step length h_k (k,) at once, (n, k): on u = w e^{iθ}
        with L = Λ − i(Ω(t + h/2) − Ω_ref) and the rotation θ since t exact; N0 = N(w, t)."""
        h = np.asarray(h, dtype=float)
        mid = speeds_at(t + 0.5 * h)
        lam = basis.lam[:, None] - 1j * (mid - basis.speed)
        r_half = np.exp(1j * rotation(t, mid, 0.5 * h))
        r_end = np.exp(1j * rotation(t, mid, h))
        e, p1, p2, p3 = phi_functions(lam * h)
        e2, q1 = phi_functions(lam * (0.5 * h), order=1)
        half = 0.5 * h * q1
        w, N0 = w[:, None], N0[:, None]
        a = e2 * w + half * N0
        Na = r_half * drift_and_load(basis, a / r_half, t + 0.5 * h, until)
        b = e2 * w + half * Na
        Nb = r_half * drift_and_load(basis, b / r_half, t + 0.5 * h, until)
        c = e2 * a + half * (2 * Nb - N0)
        Nc = r_end * drift_and_load(basis, c / r_end, t + h, until)
        u = e * w + h * ((p1 - 3 * p2 + 4 * p3) * N0 + 2 * (p2 - 2 * p3) * (Na + Nb) + (4 * p3 - p2) * Nc)
        return u / r_end

    basis = _Basis(system, speed(0.0))
    refreshes, max_condition, growth = 1, basis.condition, float(basis.lam.real.max())
    growing = growing_whirl(basis.lam, basis.speed, system.frequency)
    exponent, growth_limit = 0.0, float(np.log(MAX_GROWTH))  # ∫ max(0, growth rate) dt so far
    w = basis.to_modal(S * z)
    with warnings.catch_warnings():  # a scale for the error only: an ill-conditioned solve is good enough
        warnings.simplefilter("ignore", la.LinAlgWarning)
        steady = system.steady_state(top)
    scale = max(system.norm(z), 1e-3 * system.norm(steady) if np.all(np.isfinite(steady)) else 0.0, 1e-300)
    h = _quantise(min(max_step, 0.25 / top))
    t, steps, rejected = 0.0, 0, 0
    for stop in breakpoints[1:]:
        until = float(np.nextafter(stop, -np.inf))  # the steps' segment ends here (Ω̇ may jump at stop)
        while t < stop - 1e-12 * duration:
            if abs(speed(t) - basis.speed) > refresh_every:
                new = _Basis(system, speed(t))
                w = new.to_modal(basis.V @ w)
                basis = new
                refreshes += 1
                max_condition = max(max_condition, basis.condition)
                growth = max(growth, float(basis.lam.real.max()))
                growing = growing or growing_whirl(basis.lam, basis.speed, system.frequency)
            h = min(h, stop - t)
            N_start = drift_and_load(basis, w[:, None], np.array([t]), until)[:, 0]
            big, half = etd(basis, w, t, np.array([h, 0.5 * h]), N_start, until).T
            N_half = drift_and_load(basis, half[:, None], np.array([t + 0.5 * h]), until)[:, 0]
            small = etd(basis, half, t + 0.5 * h, np.array([0.5 * h]), N_half, until)[:, 0]
            error = np.linalg.norm(basis.V @ (small - big)) / 15.0
            size = float(np.linalg.norm(basis.V @ small))
            if not (np.isfinite(error) and np.isfinite(size)):
                raise UnstableResponseError(
                    f"the response overflowed at t = {t:.6g} s, Ω = {speed(t):.6g} rad/s: the system is unstable "
                    f"there (largest growth rate {max(growth, float(basis.lam.real.max())):.3g} 1/s); its "
                    "stability analysis shows which mode and which bearing or controller gains make it so"
                )
            tolerance = rtol * max(scale, size)
            if error > tolerance and h <= 1e-9 * duration:
                raise RuntimeError(f"step size underflow at t = {t:.6g} s (h = {h:.3g} s) for rtol = {rtol:g}")
            if steps + rejected >= MAX_STEPS:
                raise RefusedInputError(
                    f"the run needs more than {MAX_STEPS:,} integration steps (at t = {t:.4g} s of {duration:.4g} s "
                    f"the step is {h:.3g} s): the speed-dependent terms change faster than the integrator "
                    "follows; shorten the run or see flexshaft.analyses.envelope"
                )
            if error <= tolerance:
                exponent += max(float(basis.lam.real.max()), 0.0) * h
                if exponent > growth_limit:
                    raise UnstableResponseError(
                        f"the system is unstable there: at Ω = {speed(t):.6g} rad/s the growth rate is "
                        f"{float(basis.lam.real.max()):.3g} 1/s, and by t = {t + h:.4g} s a free whirl has grown "
                        f"e^{exponent:.3g} = {np.exp(exponent):.3g}-fold (more than {MAX_GROWTH:g}), so the "
                        "response shows the instability, not the imbalance; the stability analysis (flexshaft "
                        "stability) shows which mode and which bearing or controller gains make it so; a run "
                        "that ends below the onset speed, or a shorter one, stays within it"
                    )
                for t0, w0, N0 in ((t, w, N_start), (t + 0.5 * h, half, N_half)):
                    k_end = int(np.searchsorted(outputs, t0 + 0.5 * h, side="right"))
                    if k_end > k_out:  # outputs inside this half step: ETDRK4 from its start
                        dense = etd(basis, w0, t0, outputs[k_out:k_end] - t0, N0, until)
                        states[:, k_out:k_end] = (basis.V @ dense) / S[:, None]
                        k_out = k_end
                t, w = t + h, small
                scale = max(scale, size)
                steps += 1
            else:
                rejected += 1
            # an error of exactly 0 (a zero load: the state stays 0) doubles the step; it used to
            # divide by 1e-300 and shrink the step to nothing, so the run never ended
            grow = 2.0 if error == 0.0 else min(2.0, max(0.25, 0.9 * (tolerance / error) ** 0.2))
            h = _quantise(min(h * grow, max_step))
    while k_out < outputs.size:  # round-off at the very end
        states[:, k_out] = (basis.V @ w) / S
        k_out += 1
    return EnvelopeRun(outputs, states, steps, rejected, refreshes, max_condition, growth, growing)

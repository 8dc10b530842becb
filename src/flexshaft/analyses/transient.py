r"""Run-up and run-down through the criticals: the imbalance response in the time domain.

Equations (docs/model.md, thesis eqs. 2.38-2.40 with a time-varying speed). The shaft spins at
Ω(t) ≥ 0 with phase φ(t) = ∫₀ᵗ Ω dτ. An unbalance U = e·m [kg m] at angle ψ on the shaft sits at
``e (cos(φ+ψ), sin(φ+ψ))`` in the (y, z) plane; the force it puts on the shaft is minus its
mass times its acceleration, in complex form (r = v + i w)

    F_v + i F_w = U (Ω² − i Ω̇) e^{i(φ+ψ)},

the centrifugal term U Ω² plus the tangential term U Ω̇ that lags it by 90° (it resists the
angular acceleration). With the rotating load vector ``Q₁`` of
:mod:`flexshaft.assembly.loads` (``Q_v = U e^{iψ}``, ``Q_w = −i U e^{iψ}`` per unit Ω²) the load
is ``Q(t) = Re[Q₁ (Ω² − iΩ̇) e^{iφ}]``. The equation of motion is

    M q̈ + (Ω(t) G + C) q̇ + K q + (loss) + (actuators) = Q(t),

on the modal basis of :func:`flexshaft.analyses.eigen.reduce` (``q = Φ y``, the lowest
undamped non-spinning modes with the actuators' basis stiffness; transfer-function actuators
carry their controller states, :meth:`ReducedModel.state_matrix`). The term Ω̇ K_st of the
gyroscopic moment (Lalanne & Ferraris) is left out: it is of order I_p Ω̇ / (EI/ℓ) ≈ 1e-5 for
the baseline tube even at 500 rad/s².

Loss (the causal equivalent). The hysteretic loss ``i K'' sgn ω`` has no exact causal time
form. Each loss matrix becomes an equivalent viscous damping with a reference frequency per
mode, scaled symmetrically in modal coordinates, ``D = W^{-1/2} K̃'' W^{-1/2}``:

* fixed-frame loss (tailboom; shaft axial and torsion; with ``internal_damping = "thesis"``
  also the shaft's bending): ``W = diag(ω_j)``, the basis frequencies. Each mode meets its own
  loss ``i K̃''_jj`` at resonance, where the loss matters;
* ``internal_damping = "rotating"``: the shaft's bending loss acts on the velocity relative to
  the spin, ``D (ẏ + Ω S̃' y)`` (Zorzi & Nelson 1977; S the −90° rotation of the lateral pairs),
  with ``W = diag(ω_j + Ω)``: the frequency at which the spinning material is cycled by the
  backward whirl of mode j. The forward synchronous response meets no loss in either model;
  the backward synchronous part meets exactly ``i K̃''`` at each resonance Ω = ω_j; free
  forward whirl meets ``(ω_j − Ω)/(ω_j + Ω)`` of the hysteretic loss, never more (a reference
  of ω_j alone would overstate the supercritical circulatory force up to several-fold and miss
  the backward synchronous response by up to 2x).

Away from resonance the steady state differs from the hysteretic frequency response by the
mismatch of the damping where stiffness dominates; measured on the baseline over 150 speeds
of the spin-up it is below 0.52 % (shaft) and 0.95 % (actuators), 0.2 % at the 55-Hz peak
(``tests/test_transient.py``). The rotating model's whirl onset moves from 3319 rpm
(hysteretic eigen-analysis) to 3673 rpm: the causal loss grows from zero below the spin line
instead of switching on at full strength. The quasi-static response of the modes left out
of the basis (:func:`residual_flexibility`) is added to every output.

Integration. The response is carried as a complex envelope Z: with ``z = Z e^{iφ}`` the
complex solution of ``ż = A(Ω) z + b (Ω² − iΩ̇) e^{iφ}`` (A real, so Re z is the physical
state), Z obeys

    Ż = (A(Ω) − iΩ) Z + b (Ω² − iΩ̇),

which has no fast forcing: the forced response is slow in Z and a free vibration of mode j
turns at ω_j − Ω. :mod:`flexshaft.analyses.envelope` integrates it by exponential time
differencing in the eigenbasis of the system at a reference speed (every free vibration
exact, whatever the step; ETDRK4 for the slow rest; step doubling for the error). The
envelope ``orbit_amplitude(Z_v, Z_w)`` at a station is the largest deflection over the angular
position of the imbalance at that instant; for an axisymmetric rotor it is the instantaneous
whirl radius |r(t)| exactly, and in steady state it is the major semi-axis of the orbit of the
frequency response, so run-up and spin-up curves compare directly.

References
----------
Zorzi, E. S., Nelson, H. D. (1977). Finite element simulation of rotor-bearing systems with
internal damping. J. Eng. Power 99, 71-76.
Lalanne, M., Ferraris, G. (1998). *Rotordynamics Prediction in Engineering*, 2nd ed., Wiley.
Lewis, F. M. (1932). Vibration during acceleration through a critical speed. Trans. ASME 54.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from flexshaft.analyses.actuator_maps import actuator_outputs
from flexshaft.analyses.eigen import ReducedModel, reduce
from flexshaft.analyses.envelope import ETD_STABLE_STEP, MAX_GROWTH, MAX_STEPS, EnvelopeSystem, integrate_envelope
from flexshaft.analyses.guards import (
    RefusedInputError,
    UnstableResponseError,
    check_count,
    check_model,
    check_spin_speed,
)
from flexshaft.analyses.reduced_basis import modal_basis
from flexshaft.analyses.response import imbalance_response, orbit_amplitude
from flexshaft.analyses.speed_profile import SpeedProfile
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import restrict
from flexshaft.plot.transient import runup_envelope_figure

__all__ = [
    "SpeedProfile",  # the run's speed law (flexshaft.analyses.speed_profile), part of this module's API
    "SteadyEnvelope",
    "TransientResult",
    "default_basis_size",
    "default_output_step",
    "residual_flexibility",
    "run_up",
    "steady_state_envelope",
    "transient_response",
]

#: Basis modes up to this multiple of the largest speed (at least :data:`MIN_BASIS` modes).
BASIS_FREQUENCY_RATIO = 4.0
MIN_BASIS = 12
#: Largest number of output samples of one run.
MAX_OUTPUTS = 200_000
#: Output samples per radian of the fastest envelope content (|ω_j − Ω| ≤ Ω_max): 8 per period.
OUTPUT_SAMPLES_PER_RADIAN = 8 / (2 * np.pi)
_SQ3 = np.sqrt(3.0)


def default_basis_size(model: Model, max_speed: float) -> int:
    """Basis modes: every undamped mode below :data:`BASIS_FREQUENCY_RATIO` × the largest
    speed, at least :data:`MIN_BASIS` (see the convergence study in ``benchmarks/runup.py``)."""

    n_free = model.dofs.free.size
    guess = min(n_free, 60)
    while True:
        w2, _ = modal_basis(model, guess)
        below = int(np.sum(w2 < (BASIS_FREQUENCY_RATIO * max(max_speed, 1.0)) ** 2))
        if below < guess or guess >= n_free:
            return int(min(max(below, MIN_BASIS), n_free))
        guess = min(2 * guess, n_free)


# ---------------------------------------------------------------------------------------------
# Results


@dataclass(frozen=True)
class TransientResult:
    """A run-up or run-down: envelopes over time (see the module docstring).

    Attributes
    ----------
    time, speed, acceleration, phase : ndarray
        t [s], Ω [rad/s], dΩ/dt [rad/s²], φ = ∫Ω dt [rad] at the output instants (n_t,).
    shaft_x : ndarray
        Shaft node stations [m].
    shaft_orbit : ndarray
        Envelope (largest deflection over the imbalance's angular position) at every shaft
        node, (n_nodes, n_t) [m].
    actuator_displacement, actuator_force : ndarray
        Envelope of the lateral relative displacement [m] and of the force [N] at each active
        bearing, (n_act, n_t).
    modal_displacement, modal_velocity : ndarray
        Complex envelopes Y, V of the modal coordinates (nb, n_t): ``q = Re(Φ Y e^{iφ})``.
    shaft_envelope : ndarray
        Complex envelopes of the shaft's v and w at every node, static correction included,
        (2, n_nodes, n_t) [m]: ``v(t) = Re(shaft_envelope[0] e^{iφ})``. Linear in the load,
        so responses to several loads superpose.
    actuator_envelope, actuator_force_envelope : ndarray
        Complex envelopes of each active bearing's lateral relative displacement [m] and
        force [N], (n_act, 2, n_t).
    basis_size : int
    steps, rejected, refreshes : int
        Accepted and rejected steps, eigenbasis refreshes of the integration.
    max_growth_rate : float
        Largest real part of the system's eigenvalues at the reference speeds of the run
        [1/s]: the fastest growth of an unstable run, the slowest decay of a stable one;
        round-off (about ±1e-9 1/s) when a mode is undamped.
    unstable : bool
        A free whirl grows inside the run's speed range (the response there grows whatever
        the imbalance): a mode's damping ratio below −STABILITY_TOLERANCE, the rule of
        :func:`flexshaft.analyses.stability`, a real root only above DIVERGENCE_TOLERANCE × the
        largest basis frequency (:func:`flexshaft.analyses.envelope.growing_whirl`).
    """

    time: np.ndarray
    speed: np.ndarray
    acceleration: np.ndarray
    phase: np.ndarray
    shaft_x: np.ndarray
    shaft_orbit: np.ndarray
    actuator_displacement: np.ndarray
    actuator_force: np.ndarray
    actuator_names: tuple[str, ...]
    modal_displacement: np.ndarray
    modal_velocity: np.ndarray
    basis_size: int
    internal_damping: str
    steps: int
    rejected: int
    refreshes: int
    max_growth_rate: float
    unstable: bool
    basis: np.ndarray = field(repr=False)
    residual: np.ndarray | None = field(repr=False)
    force_scale: np.ndarray = field(repr=False)
    shaft_envelope: np.ndarray = field(repr=False)
    actuator_envelope: np.ndarray = field(repr=False)
    actuator_force_envelope: np.ndarray = field(repr=False)

    @property
    def shaft_peak(self) -> np.ndarray:
        """Largest envelope over the shaft nodes at each instant (n_t,) [m]."""
        return self.shaft_orbit.max(axis=0)

    def peak(self, values: np.ndarray | None = None) -> tuple[float, float, float]:
        """(largest value, time [s], speed [rad/s]) of ``values`` (default :attr:`shaft_peak`),
        refined by a parabola through the largest sample and its neighbours."""
        v = self.shaft_peak if values is None else np.asarray(values)
        k = int(np.argmax(v))
        if 0 < k < v.size - 1:
            t3, v3 = self.time[k - 1 : k + 2], v[k - 1 : k + 2]
            a, b, c = np.polyfit(t3 - t3[1], v3, 2)
            if a < 0:
                dt = float(np.clip(-b / (2 * a), t3[0] - t3[1], t3[2] - t3[1]))
                t = t3[1] + dt
                return float(c + b * dt + a * dt * dt), float(t), float(np.interp(t, self.time, self.speed))
        return float(v[k]), float(self.time[k]), float(self.speed[k])

    def displacement(self, rows: np.ndarray) -> np.ndarray:
        """Physical time signal ``Re((Φ_rows Y + r_rows f) e^{iφ})`` [m, rad] of free-DOF
        ``rows`` at the output instants (r the residual flexibility, f = Ω² − iΩ̇)."""
        q = self.basis[rows] @ self.modal_displacement
        if self.residual is not None:
            q = q + self.residual[rows][:, None] * self.force_scale
        return np.real(q * np.exp(1j * self.phase))

    def to_dataset(self):
        """The result as an :class:`xarray.Dataset` with units in attrs."""
        import xarray as xr

        return xr.Dataset(
            {
                "speed": ("time", self.speed, {"units": "rad/s"}),
                "acceleration": ("time", self.acceleration, {"units": "rad/s^2"}),
                "shaft_orbit": (("x", "time"), self.shaft_orbit, {"units": "m", "long_name": "deflection envelope"}),
                "shaft_peak": (
                    "time",
                    self.shaft_peak,
                    {"units": "m", "long_name": "largest deflection over the shaft"},
                ),
                "actuator_displacement": (("actuator", "time"), self.actuator_displacement, {"units": "m"}),
                "actuator_force": (("actuator", "time"), self.actuator_force, {"units": "N"}),
            },
            coords={
                "time": ("time", self.time, {"units": "s"}),
                "x": ("x", self.shaft_x, {"units": "m"}),
                "actuator": ("actuator", list(self.actuator_names)),
            },
            attrs={"basis_size": self.basis_size, "internal_damping": self.internal_damping, "steps": self.steps},
        )

    def plot(self, ax=None, steady: SteadyEnvelope | None = None):
        """Shaft envelope against speed, with the steady-state spin-up curve when given
        (:func:`flexshaft.plot.transient.runup_envelope_figure`)."""

        return runup_envelope_figure({"transient": self}, steady=steady, ax=ax)


@dataclass(frozen=True)
class SteadyEnvelope:
    """Steady-state (frequency-domain, hysteretic) spin-up envelopes at constant speeds.

    ``shaft_orbit`` (n_nodes, n_speeds) [m]; ``actuator_displacement`` and ``actuator_force``
    (n_act, n_speeds) [m], [N].
    """

    speeds: np.ndarray
    shaft_orbit: np.ndarray
    actuator_displacement: np.ndarray
    actuator_force: np.ndarray

    @property
    def shaft_peak(self) -> np.ndarray:
        return self.shaft_orbit.max(axis=0)


def steady_state_envelope(model: Model, speeds, loads_per_speed_squared=None) -> SteadyEnvelope:
    """The steady synchronous response at each speed [rad/s] (banded direct solve, exact
    hysteretic loss), as the envelopes :class:`TransientResult` reports."""

    speeds = np.atleast_1d(np.asarray(speeds, dtype=float))
    Q1 = imbalance_loads(model)[:, 0] if loads_per_speed_squared is None else np.asarray(loads_per_speed_squared)
    q = imbalance_response(model, speeds, Q1)  # (ndof, n_speeds)
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    shaft = orbit_amplitude(q[dm.shaft(nodes, "v")], q[dm.shaft(nodes, "w")])
    disp, force = [], []
    for a in model.actuators:
        d = a.lateral_rows @ q
        disp.append(orbit_amplitude(d[0], d[1]))
        f = a.carried_force(q, 1j * speeds)  # G(iΩ) d_s − k_s d_a
        force.append(orbit_amplitude(f[0], f[1]))
    empty = np.zeros((0, speeds.size))
    return SteadyEnvelope(speeds, shaft, np.array(disp) if disp else empty, np.array(force) if force else empty)


# ---------------------------------------------------------------------------------------------


def residual_flexibility(model: Model, red: ReducedModel, loads_per_speed_squared: np.ndarray) -> np.ndarray | None:
    """Static response of the modes left out of the basis to Q₁ [m/(rad/s)²] on the free DOFs:
    ``(K + K_a)⁻¹ Q₁ − Φ Λ⁻¹ Φᵀ Q₁`` (None when the basis stiffness is singular)."""
    import scipy.sparse.linalg as spla

    free = model.dofs.free
    if np.any(red.w2 <= 1e-9 * red.w2.max()):
        return None
    Q = np.asarray(loads_per_speed_squared)[free]
    try:
        lu = spla.splu(restrict((model.K + model.Kp).tocsr(), free).tocsc())
    except RuntimeError:
        return None
    static = lu.solve(np.ascontiguousarray(Q.real)) + 1j * lu.solve(np.ascontiguousarray(Q.imag))
    return static - red.Phi @ ((red.Phi.T @ Q) / red.w2)


def transient_response(
    model: Model,
    profile: SpeedProfile,
    *,
    loads_per_speed_squared=None,
    basis_size: int | None = None,
    reduced: ReducedModel | None = None,
    rtol: float = 1e-5,
    max_step: float | None = None,
    output_step: float | None = None,
    initial: str | np.ndarray = "steady",
    static_correction: bool = True,
) -> TransientResult:
    """Time response to the rotating imbalance while the speed follows ``profile``.

    Parameters
    ----------
    model : Model
        The driveline.
    profile : SpeedProfile
        Ω(t) [rad/s].
    loads_per_speed_squared : ndarray, optional
        One rotating load vector Q₁ [N s²] (ndof,), e.g. from
        :func:`flexshaft.assembly.loads.imbalance_loads` (default: its first case) or
        :func:`flexshaft.assembly.loads.per_bay_imbalance_loads`.
    basis_size : int, optional
        Modal basis size (default :func:`default_basis_size`); ignored with ``reduced``.
    reduced : ReducedModel, optional
        A precomputed :func:`~flexshaft.analyses.eigen.reduce` of ``model``.
    rtol : float
        Local error per step relative to the largest state so far (energy norm).
    max_step : float, optional
        Largest integration step [s] (default: duration/50).
    output_step : float, optional
        Spacing of the output samples [s] (default: 8 samples per period of the fastest
        envelope content, π/(4 Ω_max)).
    initial : {"steady", "rest"} or ndarray
        Start from the steady response at Ω(0) (rest when Ω(0) = 0), from rest, or from a
        given envelope state (n_states,) (with ``Z = z`` at t = 0 since φ(0) = 0).
    static_correction : bool
        Add the quasi-static response of the modes left out of the basis
        (:func:`residual_flexibility` times ``Ω² − iΩ̇``) to every output: the modal
        truncation error of the bearing relative displacements drops from ~10 % to ~0.1 % at
        16-32 modes on the baseline. The actuators see it through their law ``G(iΩ) − k_s`` (quasi-static).
    """

    check_model(model)
    if not isinstance(profile, SpeedProfile):
        raise TypeError("profile must be a SpeedProfile (SpeedProfile.constant_acceleration, .table or .from_callable)")
    if not (0 < rtol < 1e-2):
        raise RefusedInputError(f"rtol must be in (0, 0.01), got {rtol!r}")
    for name, value in (("max_step", max_step), ("output_step", output_step)):
        if value is not None and not (
            isinstance(value, (int, float, np.floating)) and np.isfinite(value) and value > 0
        ):
            raise RefusedInputError(f"{name} must be a finite time > 0 s or None, got {value!r}")
    top = profile.max_speed
    n_free = model.dofs.free.size
    if reduced is None:
        if basis_size is None:
            nb = default_basis_size(model, top)
        else:
            nb = check_count(basis_size, "basis_size")
            if nb > n_free:  # reduce() of more modes than DOFs used to run until memory ran out
                raise RefusedInputError(f"basis_size must be at most the model's {n_free} free DOFs (got {nb})")
        reduced = reduce(model, nb)
    red = reduced
    Q1 = imbalance_loads(model)[:, 0] if loads_per_speed_squared is None else loads_per_speed_squared
    system = EnvelopeSystem(model, red, Q1, top)
    n, nb = system.n, system.nb

    if isinstance(initial, str):
        if initial not in ("steady", "rest"):
            raise ValueError(f"initial must be 'steady', 'rest' or a state vector, got {initial!r}")
        start = profile.speed(0.0)
        z = system.steady_state(start) if initial == "steady" and start > 0 else np.zeros(n, complex)
    else:
        z = np.asarray(initial, dtype=complex).copy()
        if z.shape != (n,):
            raise ValueError(f"initial state must have {n} values, got shape {z.shape}")
    duration = profile.duration
    if output_step is None:
        output_step = default_output_step(top)
    count = int(np.ceil(duration / output_step)) + 1
    if count > MAX_OUTPUTS:
        raise RefusedInputError(
            f"{count} output samples (duration {duration:g} s / output_step {output_step:g} s) exceed "
            f"{MAX_OUTPUTS}; give a larger output_step or a shorter run"
        )
    _refuse_growth_at_constant_speed(system, profile)
    needed = duration * system.drift_rate(top) / ETD_STABLE_STEP
    if needed > MAX_STEPS:
        raise RefusedInputError(
            f"the run would need about {needed:.3g} integration steps (at most {MAX_STEPS:,}): the gyroscopic "
            f"coupling changes with the speed at a rate of {system.drift_rate(top):.3g} 1/s"
            + _gyroscopic_culprit(model)
        )
    T = np.linspace(0.0, duration, count)
    run = integrate_envelope(
        system,
        profile.speeds_at,
        profile.accelerations_at,
        profile.breakpoints,
        z,
        T,
        rtol=rtol,
        max_step=max_step,
        max_speed=top,
    )
    Z = run.states
    speed = profile.speeds_at(T)
    accel = np.array([profile.acceleration(x) for x in T])
    # φ by the two-point Gauss rule on each interval (exact for piecewise-linear Ω)
    centre, half = 0.5 * (T[:-1] + T[1:]), 0.5 * np.diff(T) / _SQ3
    w = (profile.speeds_at(centre - half) + profile.speeds_at(centre + half)) * 0.5 * np.diff(T)
    phase = np.concatenate([[0.0], np.cumsum(w)])

    force_scale = speed**2 - 1j * accel  # f(t): the load is Re(Q₁ f e^{iφ})
    force_rate = 1j * speed * force_scale + 2 * speed * accel  # envelope of d/dt (f e^{iφ})
    residual = residual_flexibility(model, red, Q1) if static_correction else None
    dm = model.dofs
    pos = np.full(dm.size, -1)
    pos[dm.free] = np.arange(dm.free.size)
    nodes = np.arange(dm.n_shaft_nodes)
    Y = Z[:nb]
    shaft_rows = [_rows(red.Phi, pos[dm.shaft(nodes, f)]) @ Y for f in ("v", "w")]
    if residual is not None:
        res = np.concatenate([residual, [0.0]])  # index −1: a constrained DOF
        shaft_rows = [r + res[pos[dm.shaft(nodes, f)]][:, None] * force_scale for r, f in zip(shaft_rows, ("v", "w"))]
    shaft = orbit_amplitude(*shaft_rows)
    act_disp: list[np.ndarray] = []
    act_force: list[np.ndarray] = []
    for maps, act in zip(actuator_outputs(model, red), model.actuators):
        d, f = maps.displacement @ Z, maps.force @ Z
        if residual is not None:
            d_res = (maps.rows @ residual)[:, None]
            d = d + d_res * force_scale
            if not maps.has_states:  # laws without states (PD): D d + E ḋ of the quasi-static part
                for stiffness, damping, measured in maps.static_terms:
                    f = f + (measured @ residual)[:, None] * (stiffness * force_scale + damping * force_rate)
            else:  # G(iΩ) d_s − k_s d_a of the quasi-static part
                sensed = (maps.sensing @ residual)[:, None]
                gain = np.asarray(act.feedback_gain(1j * speed))
                f = f + (gain * sensed - act.negative_stiffness * d_res) * force_scale
        act_disp.append(d)
        act_force.append(f)
    n_act = len(act_disp)
    disp_envelope = np.array(act_disp).reshape(n_act, 2, T.size)
    force_envelope = np.array(act_force).reshape(n_act, 2, T.size)
    return TransientResult(
        time=T,
        speed=speed,
        acceleration=accel,
        phase=phase,
        shaft_x=np.asarray(dm.shaft_x, dtype=float),
        shaft_orbit=shaft,
        actuator_displacement=orbit_amplitude(disp_envelope[:, 0], disp_envelope[:, 1]),
        actuator_force=orbit_amplitude(force_envelope[:, 0], force_envelope[:, 1]),
        actuator_names=tuple(a.name for a in model.actuators),
        modal_displacement=Y,
        modal_velocity=Z[nb : 2 * nb],
        basis_size=nb,
        internal_damping=model.internal_damping,
        steps=run.steps,
        rejected=run.rejected,
        refreshes=run.refreshes,
        max_growth_rate=run.max_growth_rate,
        unstable=run.growing,
        basis=red.Phi,
        residual=residual,
        force_scale=force_scale,
        shaft_envelope=np.stack(shaft_rows),
        actuator_envelope=disp_envelope,
        actuator_force_envelope=force_envelope,
    )


def default_output_step(max_speed: float) -> float:
    """Output spacing [s] of a run up to ``max_speed`` [rad/s]:
    :data:`OUTPUT_SAMPLES_PER_RADIAN` samples per radian of the fastest envelope content."""
    return 1.0 / (OUTPUT_SAMPLES_PER_RADIAN * max(max_speed, 1e-3))


def _refuse_growth_at_constant_speed(system: EnvelopeSystem, profile: SpeedProfile) -> None:
    """Refuse before integrating a run that holds an unstable speed long enough for a free whirl
    to grow more than :data:`~flexshaft.analyses.envelope.MAX_GROWTH`-fold (the integration
    would find it only at that time: a 900 s dwell of the baseline at 4800 rpm, growth rate
    0.0098 1/s, took 30 s to refuse)."""
    times = profile.breakpoints
    speeds = profile.speeds_at(times)
    exponent = 0.0
    for (t0, t1), (s0, s1) in zip(zip(times[:-1], times[1:]), zip(speeds[:-1], speeds[1:])):
        if s0 == s1 and t1 > t0:
            rate = float(np.linalg.eigvals(system.matrix(float(s0))).real.max())
            exponent += max(rate, 0.0) * (t1 - t0)
            if exponent > np.log(MAX_GROWTH):
                raise UnstableResponseError(
                    f"the system is unstable at Ω = {s0:.6g} rad/s (growth rate {rate:.3g} 1/s): held there "
                    f"for {t1 - t0:.4g} s a free whirl grows e^{exponent:.3g}-fold (more than {MAX_GROWTH:g}), so "
                    "the response would show the instability, not the imbalance; a shorter dwell, or a speed "
                    "below the whirl onset (flexshaft stability), stays within it"
                )


def _gyroscopic_culprit(model: Model) -> str:
    """Which inertia makes the gyroscopic coupling that fast: a disk or coupling whose polar
    inertia exceeds twice its diametral one, which no rigid body has (I_p ≤ I_1 + I_2 = 2 I_d)."""
    worst, text = 2.0, ""
    design = model.design
    for table, items in (("disks", design.disks), ("couplings", design.couplings)):
        for k, item in enumerate(items):
            ratio = item.polar_inertia / max(item.diametral_inertia, 1e-300)
            if item.polar_inertia > 0 and ratio > worst:
                worst = ratio
                text = (
                    f"; {table}[{k}].polar_inertia = {item.polar_inertia:g} kg m² is {ratio:.3g} × its "
                    f"diametral_inertia = {item.diametral_inertia:g} kg m², which no rigid body has "
                    "(I_p ≤ 2 I_d): check the two inertias"
                )
    return text or "; a shorter run, or fewer modes (basis_size), needs fewer steps"


def _rows(Phi: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """Basis rows of free DOFs; a constrained DOF (−1) gives a zero row."""
    out = np.zeros((rows.size, Phi.shape[1]))
    ok = rows >= 0
    out[ok] = Phi[rows[ok]]
    return out


def run_up(
    model: Model, duration: float, *, start: float = 0.0, stop: float | None = None, dwell: float = 0.0, **options
) -> TransientResult:
    """Constant-acceleration run-up from ``start`` to ``stop`` (default the operating speed)
    [rad/s] in ``duration`` [s], then ``dwell`` [s] at ``stop``; a run-down when stop < start.
    ``options`` go to :func:`transient_response`."""
    check_model(model)
    start = check_spin_speed(start, "start")
    stop = model.speed if stop is None else check_spin_speed(stop, "stop")
    if not (isinstance(duration, (int, float, np.floating)) and np.isfinite(duration) and duration > 0):
        raise RefusedInputError(f"duration must be a finite time > 0 s, got {duration!r}")
    if not (isinstance(dwell, (int, float, np.floating)) and np.isfinite(dwell) and dwell >= 0):
        raise RefusedInputError(f"dwell must be a finite time >= 0 s, got {dwell!r}")
    if stop == start:
        raise RefusedInputError(
            f"start and stop are both {start:g} rad/s: a run-up needs two different speeds"
            + (" (the design's operating speed is 0: give stop)" if stop == 0.0 else "")
        )
    profile = SpeedProfile.constant_acceleration(start, stop, (stop - start) / duration, dwell)
    return transient_response(model, profile, **options)

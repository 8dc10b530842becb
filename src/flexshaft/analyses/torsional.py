r"""Torsional dynamics of the driveline: natural frequencies, separation margins, forced response.

The twist θ of the shaft nodes and the drive train's own twist DOF (the tail rotor behind its
drive spring, :mod:`flexshaft.assembly.drive`) form a subsystem nothing else couples to: the
bearings act on u, v, w, β, γ, and the gyroscopic terms of disks and coupling hubs on β, γ.
Restricted to the free twist DOFs, the model's matrices give its torsional modes exactly
(:func:`torsional_system`, which checks the decoupling); the full model's modes classified
``"torsional"`` are the same (tests/test_torsional.py).

Modes. The undamped natural frequencies solve ``K φ = ω² M φ``; the damped ones the quadratic
eigenproblem ``[s² M + s C + K + i K''] φ = 0`` of the positive-frequency branch (the shaft's
torsional loss K'' is hysteretic and acts in the fixed frame, C holds the tail rotor's
aerodynamic damping), which is what :func:`flexshaft.analyses.modal.modes` solves for them.

Excitations (:func:`torsional_excitations`), each a fixed multiple of the shaft speed Ω:

* the shaft's 1/rev;
* the tail rotor's 1/rev and N/rev (blade passage) at Ω/n (``[tail_rotor]``);
* the main rotor's harmonics k/rev, k = 1 … N_mr, at Ω_mr (``[operating] main_rotor_speed_rpm``,
  geared to the shaft, so Ω_mr/Ω is constant; 1/rev only without ``main_rotor_blades``).

Gear-mesh frequencies are not included (the design has no tooth counts).

Separation (the rule used). Every torsional natural frequency f_n stays at least the design's
``[requirements] min_torsional_separation`` (:data:`TORSIONAL_SEPARATION` = 10 % by default) away
from every excitation frequency in the operating speed range [Ω_lo, Ω_hi]
(``[operating] speed_range``). An excitation of ratio r sweeps the band
[f_lo, f_hi] = r [Ω_lo, Ω_hi]/2π, and the margin ``min |f_n − f_e|/f_e`` over the band is

.. math:: m = 1 - f_n/f_{lo} \;(f_n < f_{lo}),\qquad m = f_n/f_{hi} - 1 \;(f_n > f_{hi}),\qquad m = 0 \text{ inside.}

This is the 10 % separation margin API recommends for torsional natural frequencies (API 617's
torsional analysis; Wang, Feese & Pettinato 2012, who note that the amplification factor is not
part of it). The clause text of API 684 itself was not available to check.

Forced response (:func:`torsional_forced_response`). The tail rotor's torque oscillates at 1/rev
and N/rev with amplitudes a₁, a_N (fractions of its mean torque; ``[tail_rotor]``
``torque_oscillation_1p``/``_np``). Reflected to the shaft, the harmonic k is a torque
a_k T on the rotor's twist DOF (T = P/Ω the shaft's mean torque), solved as
``[K + i K'' + i ω C − ω² M] θ = Q`` at ω = k Ω/n. The dynamic torque of each shaft element is
``G* J (θ_b − θ_a)/L``, its wall shear stress ``|T| r_o/J`` (outer surface of the tube). The
harmonics add in the worst phase: the peak torque is ``T + Σ_k |T_k|`` and the factor on the
steady torque ``1 + Σ_k |T_k|/T`` (largest over the elements and over the speed range).

References
----------
Wang, Q., Feese, T. D., Pettinato, B. C. (2012). Torsional natural frequencies: measurement vs.
prediction. Proc. 41st Turbomachinery Symposium, Texas A&M, Houston.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as la

from flexshaft.analyses.guards import check_count, check_model, require_finite
from flexshaft.assembly.model import Model
from flexshaft.design.requirements import DEFAULT_MIN_TORSIONAL_SEPARATION

__all__ = [
    "TORSIONAL_SEPARATION",
    "TorqueHarmonic",
    "TorsionalExcitation",
    "TorsionalForcedResponse",
    "TorsionalModes",
    "TorsionalSeparation",
    "TorsionalSystem",
    "separation_margin",
    "torsional_excitations",
    "torsional_forced_response",
    "torsional_modes",
    "torsional_separation",
    "torsional_system",
]

#: Required separation of a torsional natural frequency from every excitation frequency in the
#: operating range, a fraction of the excitation frequency, when the design does not set one: the
#: requirement's default (API's 10 %, see the module docstring).
TORSIONAL_SEPARATION = DEFAULT_MIN_TORSIONAL_SEPARATION
#: An eigenvalue ω² below this fraction of the largest is a rigid-body twist (0 Hz): zero to the
#: accuracy of the generalized eigen-solver (a few hundred ε times the largest eigenvalue when a
#: near-massless node makes the mass matrix ill-conditioned).
_RIGID = 1e3 * np.finfo(float).eps


# ------------------------------------------------------------------------------------------------
# The torsional subsystem and its modes


@dataclass(frozen=True)
class TorsionalSystem:
    """The model restricted to its free twist DOFs (dense): mass [kg m²], stiffness and loss
    stiffness [N m/rad], damping [N m s/rad]; ``dofs`` their global indices."""

    dofs: np.ndarray
    M: np.ndarray
    K: np.ndarray
    K_loss: np.ndarray
    C: np.ndarray


def torsional_system(model: Model) -> TorsionalSystem:
    """The free twist DOFs of the shaft and the drive train and the model's matrices on them.

    Raises
    ------
    ValueError
        When some matrix couples the twist to another DOF (the subsystem would not be exact),
        or the model has no free twist DOF.
    """
    check_model(model)
    dm = model.dofs
    twist = dm.unique(np.concatenate([dm.shaft(np.arange(dm.n_shaft_nodes), "theta"), dm.extra_dofs]))
    dofs = np.intersect1d(twist, dm.free)
    if dofs.size == 0:
        raise ValueError("the model has no free twist DOF (every shaft node is held in twist)")
    others = np.setdiff1d(dm.free, dofs)
    loss = model.shaft_loss_stiffness
    for name, A in (("M", model.M), ("K", model.K), ("C", model.C), ("G", model.G), ("K''", loss)):
        if A is not None and others.size and abs(A[dofs][:, others]).sum() > 0.0:
            raise ValueError(f"the model's {name} couples the twist to other DOFs: no torsional subsystem")
    dense = {name: A[dofs][:, dofs].toarray() for name, A in (("M", model.M), ("K", model.K), ("C", model.C))}
    K_loss = np.zeros_like(dense["K"]) if loss is None else loss[dofs][:, dofs].toarray()
    return TorsionalSystem(dofs, dense["M"], dense["K"], K_loss, dense["C"])


@dataclass(frozen=True)
class TorsionalModes:
    """Torsional modes, sorted by undamped natural frequency.

    Attributes
    ----------
    natural_frequencies : ndarray
        Undamped natural frequencies [Hz] (0 for a free rigid-body twist).
    eigenvalues : ndarray
        Damped eigenvalues s = −ζω_n + iω_d [rad/s] (hysteretic loss and viscous damping): each
        undamped mode's nearest root not taken by a lower mode. An overdamped mode has a real
        root (without loss the one nearest iω_n of those left; with loss its fast root, the
        one with Im s > 0); a rigid-body twist has 0.
    shapes : ndarray
        Undamped mode shapes on the full DOF vector (ndof, n_modes) [rad], mass-normalised.
    """

    natural_frequencies: np.ndarray
    eigenvalues: np.ndarray
    shapes: np.ndarray

    @property
    def frequencies(self) -> np.ndarray:
        """Damped natural frequencies Im(s)/2π [Hz]."""
        return self.eigenvalues.imag / (2.0 * np.pi)

    @property
    def damping_ratios(self) -> np.ndarray:
        """ζ = −Re(s)/|s| [-] (0 for a rigid-body twist; 1 for an overdamped mode, whose
        eigenvalue is a real root)."""
        magnitude = np.abs(self.eigenvalues)
        return np.where(magnitude > 0, -self.eigenvalues.real / np.where(magnitude > 0, magnitude, 1.0), 0.0)


def torsional_modes(model: Model, n_modes: int | None = None) -> TorsionalModes:
    """The lowest ``n_modes`` (default: all) torsional modes of the model (module docstring)."""
    system = torsional_system(model)
    n = system.dofs.size if n_modes is None else min(check_count(n_modes, "n_modes"), system.dofs.size)
    w2, phi = la.eigh(system.K, system.M)
    omega = np.sqrt(np.where(w2 <= _RIGID * w2.max(), 0.0, w2))
    s = _damped_roots(system)
    matched = np.empty(n, dtype=complex)
    free = np.ones(s.size, dtype=bool)
    origin = np.sqrt(_RIGID * w2.max())  # a rigid twist's root: 0 to round-off
    for k in range(n):  # each undamped mode takes the nearest damped root not yet taken
        if omega[k] == 0.0:  # a rigid-body twist takes the root at the origin, if one is left
            near = np.flatnonzero(free & (np.abs(s) <= origin))
            if near.size:
                free[near[np.argmin(np.abs(s[near]))]] = False
            matched[k] = 0.0
            continue
        distance = np.where(free, np.abs(s - 1j * omega[k]), np.inf)
        j = int(np.argmin(distance))
        assert np.isfinite(distance[j]), "fewer damped roots than modes"  # n roots at least (_damped_roots)
        matched[k], free[j] = s[j], False
    shapes = np.zeros((model.dofs.size, n))
    shapes[system.dofs] = phi[:, :n]
    require_finite("torsional eigenvalues", matched)
    return TorsionalModes(omega[:n] / (2.0 * np.pi), matched, shapes)


def _damped_roots(system: TorsionalSystem) -> np.ndarray:
    """Roots of ``det(s² M + s C + K + i K'') = 0`` with Im s > 0 (first-order companion form),
    and without loss (a real system) also the real roots: an overdamped mode has two, and a real
    eigen-solution gives them with Im s = 0 exactly, where a complex one scatters them by
    round-off to either side of the axis."""
    n = system.dofs.size
    Minv = la.inv(system.M)
    lossy = bool(np.any(system.K_loss))
    K = system.K + 1j * system.K_loss if lossy else system.K
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ system.C]])
    s = np.asarray(la.eigvals(A), dtype=complex)
    return s[s.imag > 0] if lossy else s[s.imag >= 0]


# ------------------------------------------------------------------------------------------------
# Excitations and separation margins


@dataclass(frozen=True)
class TorsionalExcitation:
    """A torsional excitation at ``ratio`` × the shaft speed: ω_e = ratio · Ω.

    ``source`` is ``"shaft"``, ``"tail_rotor"`` or ``"main_rotor"``, ``order`` its harmonic of
    that source's speed (N for the tail rotor's blade passage), ``name`` e.g. ``"tail rotor 4/rev"``.
    """

    name: str
    source: str
    order: int
    ratio: float

    def band(self, low_speed: float, high_speed: float) -> tuple[float, float]:
        """Its frequencies [Hz] at the lowest and highest shaft speeds [rad/s]."""
        return self.ratio * low_speed / (2.0 * np.pi), self.ratio * high_speed / (2.0 * np.pi)


def torsional_excitations(design) -> tuple[TorsionalExcitation, ...]:
    """The shaft's 1/rev, the tail rotor's 1/rev and N/rev, the main rotor's 1 … N/rev."""
    out = [TorsionalExcitation("shaft 1/rev", "shaft", 1, 1.0)]
    rotor = design.tail_rotor
    if rotor is not None:
        out.append(TorsionalExcitation("tail rotor 1/rev", "tail_rotor", 1, 1.0 / rotor.gearbox_ratio))
        if rotor.blades > 1:
            name = f"tail rotor {rotor.blades}/rev"
            out.append(TorsionalExcitation(name, "tail_rotor", rotor.blades, rotor.blades / rotor.gearbox_ratio))
    operating = design.operating
    if operating.main_rotor_speed_rpm is not None and operating.speed_rad_s > 0:
        once = operating.main_rotor_speed_rpm * 2.0 * np.pi / 60.0 / operating.speed_rad_s
        for k in range(1, (operating.main_rotor_blades or 1) + 1):
            out.append(TorsionalExcitation(f"main rotor {k}/rev", "main_rotor", k, k * once))
    return tuple(out)


def separation_margin(natural_frequency: float, low: float, high: float) -> float:
    """Smallest |f_n − f_e|/f_e over the excitation band [low, high] [Hz] (module docstring):
    ``1 − f_n/low`` below it, ``f_n/high − 1`` above it, 0 inside."""
    values = (natural_frequency, low, high)
    if not all(np.isfinite(v) for v in values) or natural_frequency < 0 or not 0 < low <= high:
        raise ValueError(
            f"need a natural frequency >= 0 and an excitation band 0 < low <= high [Hz] "
            f"(got f_n = {natural_frequency!r}, band [{low!r}, {high!r}])"
        )
    if natural_frequency < low:
        return 1.0 - natural_frequency / low
    if natural_frequency > high:
        return natural_frequency / high - 1.0
    return 0.0


@dataclass(frozen=True)
class TorsionalSeparation:
    """One torsional mode against its nearest excitation.

    Attributes
    ----------
    mode : int
        Index of the mode in :func:`torsional_modes` (0-based).
    natural_frequency : float
        Its undamped natural frequency [Hz].
    excitation : str
        The nearest excitation (smallest margin), e.g. ``"main rotor 2/rev"``.
    source : str
        ``"shaft"``, ``"tail_rotor"`` or ``"main_rotor"``.
    order : int
        Harmonic order of that excitation on its source's speed.
    band : tuple of 2 floats
        The excitation's frequencies over the operating speed range [Hz].
    margin : float
        The separation margin [-] (0: inside the band).
    required : float
        The required margin [-].
    """

    mode: int
    natural_frequency: float
    excitation: str
    source: str
    order: int
    band: tuple[float, float]
    margin: float
    required: float

    @property
    def passed(self) -> bool:
        """True when the margin meets the requirement."""
        return self.margin >= self.required

    @property
    def within_range(self) -> bool:
        """True when the natural frequency lies inside the excitation's band."""
        return self.band[0] <= self.natural_frequency <= self.band[1]


def torsional_separation(
    model: Model,
    modes: TorsionalModes | None = None,
    speed_range: tuple[float, float] | None = None,
    required: float | None = None,
) -> tuple[TorsionalSeparation, ...]:
    """Separation margin of every torsional mode below twice the highest excitation frequency
    (at least the lowest flexible mode) from its nearest excitation.

    Parameters
    ----------
    modes : TorsionalModes or None
        Default :func:`torsional_modes` of the model.
    speed_range : (float, float) or None
        Lowest and highest shaft speeds [rad/s]; default the design's
        (:attr:`~flexshaft.design.loads.Operating.speed_limits`).
    required : float or None
        Required margin [-]; default the design's ``[requirements] min_torsional_separation``
        (10 % unless the design sets it), the margin the verdict's check holds each mode to.
    """
    check_model(model)
    if model.design is None:
        raise ValueError("the model has no design: its excitations are not known")
    low, high = model.design.operating.speed_limits if speed_range is None else speed_range
    if required is None:
        required = model.design.requirements.min_torsional_separation
    if not (np.isfinite(low) and np.isfinite(high) and 0 < low <= high):
        raise ValueError(f"speed_range must be 0 < lowest <= highest [rad/s] (got ({low!r}, {high!r}))")
    if not (np.isfinite(required) and required >= 0):
        raise ValueError(f"required must be a finite fraction >= 0 (got {required!r})")
    modes = torsional_modes(model) if modes is None else modes
    bands = [(e, e.band(low, high)) for e in torsional_excitations(model.design)]
    ceiling = 2.0 * max(band[1] for _, band in bands)
    out: list[TorsionalSeparation] = []
    for k, f in enumerate(modes.natural_frequencies):
        if f == 0.0:
            continue  # a free rigid-body twist is no resonance
        if out and f > ceiling:
            break
        margins = [(separation_margin(float(f), *band), e, band) for e, band in bands]
        margin, excitation, band = min(margins, key=lambda item: item[0])
        out.append(
            TorsionalSeparation(
                k, float(f), excitation.name, excitation.source, excitation.order, band, float(margin), float(required)
            )
        )
    return tuple(out)


# ------------------------------------------------------------------------------------------------
# Forced response to the tail rotor's torque oscillation


@dataclass(frozen=True)
class TorqueHarmonic:
    """The response to one harmonic of the tail rotor's torque oscillation at one shaft speed.

    Attributes
    ----------
    order : int
        Harmonic of the tail-rotor speed (1 or N).
    fraction : float
        Its amplitude as a fraction of the mean torque [-].
    frequency : float
        Excitation frequency [Hz].
    excitation : float
        Torque amplitude applied on the rotor's twist, reflected to the shaft [N m].
    torque : float
        Largest dynamic torque amplitude in the shaft [N m].
    x : float
        Station of that largest torque (element midpoint) [m].
    shear_stress : float
        Largest wall shear stress amplitude |T| r_o/J [Pa].
    """

    order: int
    fraction: float
    frequency: float
    excitation: float
    torque: float
    x: float
    shear_stress: float

    @property
    def amplification(self) -> float:
        """Dynamic shaft torque per applied torque [-] (0 without excitation)."""
        return self.torque / self.excitation if self.excitation > 0 else 0.0


@dataclass(frozen=True)
class TorsionalForcedResponse:
    """Steady and oscillating shaft torque at the governing speed of the operating range.

    Attributes
    ----------
    speed : float
        Shaft speed [rad/s] where the peak torque is largest.
    steady_torque : float
        Mean shaft torque T = P/Ω [N m] (of the operating point).
    steady_shear_stress : float
        Largest wall shear stress of the mean torque [Pa].
    harmonics : tuple of TorqueHarmonic
        The 1/rev and N/rev responses at that speed.
    torque_factor : float
        Largest (T + Σ_k |T_k|)/T over the elements [-] (1 without power or excitation).
    peak_shear_stress : float
        Largest (T + Σ_k |T_k|) r_o/J over the elements [Pa].
    x : float
        Station of the largest peak stress (element midpoint; on a stepped shaft not always that
        of the largest peak torque) [m].
    """

    speed: float
    steady_torque: float
    steady_shear_stress: float
    harmonics: tuple[TorqueHarmonic, ...]
    torque_factor: float
    peak_shear_stress: float
    x: float

    @property
    def dynamic_torque(self) -> float:
        """Σ_k of the largest dynamic torque amplitudes [N m] (worst phase)."""
        return float(sum(h.torque for h in self.harmonics))


def _element_operator(model: Model, dofs: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(torque operator (n_elements, n_twist) [N m/rad], section modulus r_o/J per element
    [1/m³], element midpoints [m]) of the shaft elements on the twist vector ``dofs``."""
    dm = model.dofs
    nodes = dm.shaft_element_nodes
    ends = dm.shaft_element_x
    mid = 0.5 * (ends[:, 0] + ends[:, 1])
    segments = model.segments
    if segments:
        zone = np.searchsorted([seg.x_end for seg in segments[:-1]], mid)
        tubes = [segments[z].properties for z in zone]
    else:
        tubes = [model.shaft] * len(mid)
    outer = np.array([t.outer_diameter for t in tubes])
    inner = np.array([t.inner_diameter for t in tubes])
    polar = np.pi * (outer**4 - inner**4) / 32.0
    stiffness = np.array([t.shear_modulus for t in tubes]) * polar / (ends[:, 1] - ends[:, 0])
    position = {int(d): j for j, d in enumerate(dofs)}
    op = np.zeros((len(mid), dofs.size), dtype=complex)
    for e, (a, b) in enumerate(nodes):
        for node, sign in ((a, -1.0), (b, 1.0)):
            j = position.get(int(dm.shaft(int(node), "theta")))
            if j is not None:  # a held twist is 0
                op[e, j] += sign * stiffness[e]
    return op, 0.5 * outer / polar, mid


def torsional_forced_response(
    model: Model, speeds=None, n_speeds: int = 41, fractions: tuple[float, float] | None = None
) -> TorsionalForcedResponse:
    """Dynamic shaft torque and shear stress from the tail rotor's 1/rev and N/rev torque
    oscillation (module docstring), at the worst speed of the operating range.

    Parameters
    ----------
    speeds : array_like or None
        Shaft speeds [rad/s] (> 0); default ``n_speeds`` evenly over the design's speed range
        (the operating speed alone when the range is one speed).
    fractions : (float, float) or None
        1/rev and N/rev amplitudes as fractions of the mean torque; default the design's.

    Raises
    ------
    ValueError
        Without a ``[tail_rotor]``, or for speeds that are not finite and positive.
    """
    check_model(model)
    drive = model.drive
    if not drive.has_rotor:
        raise ValueError("the design has no [tail_rotor]: no tail-rotor torque oscillation to apply")
    if speeds is None:
        if model.design is None:
            raise ValueError("the model has no design: give the shaft speeds [rad/s]")
        low, high = model.design.operating.speed_limits
        speeds = np.array([low]) if high == low else np.linspace(low, high, check_count(n_speeds, "n_speeds"))
    speeds = np.atleast_1d(np.asarray(speeds, dtype=float))
    if speeds.size == 0 or not np.all(np.isfinite(speeds) & (speeds > 0)):
        raise ValueError(f"speeds must be finite and > 0 rad/s (got {speeds!r})")
    a1, an = drive.torque_oscillation if fractions is None else fractions
    if not all(np.isfinite(v) and v >= 0 for v in (a1, an)):
        raise ValueError(f"fractions must be finite and >= 0 (got {fractions!r})")
    system = torsional_system(model)
    op, modulus, mid = _element_operator(model, system.dofs)
    steady = model.power / model.speed if model.speed > 0 else 0.0
    load = np.zeros(system.dofs.size)
    load[int(np.flatnonzero(system.dofs == drive.rotor_dof)[0])] = 1.0
    assert drive.blades is not None  # a modelled tail rotor has its blade count (drive_terms)
    best: tuple[float, float, tuple[TorqueHarmonic, ...], float, float] | None = None
    for speed in speeds:
        harmonics: list[TorqueHarmonic] = []
        amplitudes = []
        for order, fraction in ((1, a1), (drive.blades, an)):
            omega = order * speed / drive.gearbox_ratio
            Z = system.K + 1j * system.K_loss + 1j * omega * system.C - omega**2 * system.M
            amplitude = np.abs(op @ np.linalg.solve(Z, fraction * steady * load))
            k = int(np.argmax(amplitude))
            harmonics.append(
                TorqueHarmonic(
                    int(order),
                    float(fraction),
                    float(omega / (2 * np.pi)),
                    float(fraction * steady),
                    float(amplitude[k]),
                    float(mid[k]),
                    float(amplitude[k] * modulus[k]),
                )
            )
            amplitudes.append(amplitude)
        peak = steady + np.sum(amplitudes, axis=0)
        e = int(np.argmax(peak * modulus))
        if best is None or peak[e] * modulus[e] > best[0]:
            best = (float(peak[e] * modulus[e]), float(speed), tuple(harmonics), float(np.max(peak)), float(mid[e]))
    assert best is not None  # speeds is not empty
    stress, speed, worst, peak_torque, x = best
    require_finite("torsional forced response", np.array([stress, peak_torque]))
    factor = peak_torque / steady if steady > 0 else 1.0
    return TorsionalForcedResponse(
        speed, float(steady), float(steady * np.max(modulus)), worst, float(factor), stress, x
    )

r"""Hysteretic loss of the driveline: one damping physics for every analysis.

The members' loss is hysteretic: a harmonic strain of frequency ν meets the force
``i η k sgn(ν)`` on top of the storage stiffness. The model carries three real loss matrices
(:class:`~flexshaft.assembly.model.Model`): ``F`` (tailboom, and the shaft's axial and
torsional strains: cycled at the excitation frequency in either frame), ``K_lat`` (the shaft's
bending and shear loss) and ``K_lat S`` (S rotates each shaft node's lateral pairs by −90°).
How the shaft's lateral loss acts is the model's ``internal_damping``:

``"rotating"`` (default; exact for an axisymmetric shaft)
    The rotating material sees the lateral motion relative to the spin. A harmonic response
    ``Re(X e^{iωt})`` (ω ≥ 0) splits into a forward circular part ``P_F X`` and a backward one
    ``P_B X``, ``P_F = (I + iS)/2``, ``P_B = (I − iS)/2``; in the rotating frame the forward
    part turns at ω − Ω and the backward part at −(ω + Ω). The loss force is therefore
    ``i K_lat (σ_B P_B + σ P_F) X`` with σ = sgn(ω − Ω) and σ_B = sgn(ω + Ω) (1 whenever
    the shaft spins or vibrates), i.e.

    .. math:: L(ω, Ω) = i\,\mathrm{sgn}(ω)\,F + i\,\tfrac{σ_B + σ}{2} K_{lat} + \tfrac{σ_B − σ}{2} K_{lat} S.

    Synchronous forward whirl (ω = Ω, σ = 0) is not damped by the shaft at all; backward whirl
    is damped at 2Ω; below the spin (σ = −1) the loss becomes the circulatory stiffness
    ``K_lat S`` that drives supercritical forward whirl unstable. A static load on the spinning
    shaft (ω = 0) meets ``K_lat S``: the sideways deflection of a shaft with internal damping.

``"thesis"`` (thesis eqs. 2.39-2.40)
    Fixed-frame complex stiffness: ``L(ω) = i sgn(ω) (F + K_lat)``. It damps synchronous
    forward whirl, which internal (rotating) damping cannot physically do, and never
    destabilises.

Eigen-analyses (modes, Campbell, stability) use the same complex weights, evaluated at each
mode's own frequency ω = Im(s) (:func:`eigen_coefficients`): the eigenvalues are the poles of
the frequency response continued from the positive-frequency axis (the complex-stiffness
eigenproblem ``[s² M + s D + K + L(Im s, Ω)] φ = 0``), so a uniformly hysteretic structure has
ζ = sin(½ atan η) ≈ η/2 in every mode and the half-power bandwidth of a forced-response peak
equals 2ζ of its mode. :mod:`flexshaft.analyses.hysteretic_roots` finds the roots consistent
with their own side of the synchronous line. The viscous Zorzi-Nelson model of the thesis's chapter 4 (one reference
frequency for every mode, damping ``(F + K_lat)/ω_ref`` and circulatory ``(Ω/ω_ref) K_lat S``)
is :func:`viscous_equivalent`.

References
----------
Zorzi, E. S., Nelson, H. D. (1977). Finite element simulation of rotor-bearing systems with
internal damping. J. Eng. Power 99, 71-76.
Genta, G. (2005). *Dynamics of Rotating Systems*, Springer, §4.6 (hysteretic damping in the
rotating frame).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "LossCoefficients",
    "frequency_coefficients",
    "frequency_coefficient_arrays",
    "eigen_coefficients",
    "viscous_equivalent",
    "whirl_sign",
]

#: Relative band around ω = Ω inside which σ = sgn(ω − Ω) counts as 0 (the synchronous line).
SYNCHRONOUS_TOLERANCE = 1e-9


@dataclass(frozen=True)
class LossCoefficients:
    """Scalar weights of the three loss matrices: ``fixed·F + lateral·K_lat + circulatory·K_lat S``.

    The weights of :func:`frequency_coefficients` and :func:`eigen_coefficients` are complex
    stiffness weights (the loss force); those of :func:`viscous_equivalent` are real: ``fixed``
    and ``lateral`` weigh damping matrices, ``circulatory`` a stiffness matrix.
    """

    fixed: complex
    lateral: complex
    circulatory: float


def whirl_sign(omega: float, speed: float) -> float:
    """σ = sgn(ω − Ω), 0 within a relative :data:`SYNCHRONOUS_TOLERANCE` of the spin speed."""
    difference = omega - speed
    if abs(difference) <= SYNCHRONOUS_TOLERANCE * max(abs(omega), abs(speed), 1.0):
        return 0.0
    return float(np.sign(difference))


def _check(internal_damping: str) -> None:
    if internal_damping not in ("rotating", "thesis"):
        raise ValueError(f"internal_damping must be 'rotating' or 'thesis', got {internal_damping!r}")


def frequency_coefficients(internal_damping: str, omega: float, speed: float) -> LossCoefficients:
    """Weights of the loss matrices in ``Z(ω, Ω)`` for an excitation ``e^{iωt}``, ω ≥ 0 [rad/s].

    Parameters
    ----------
    internal_damping : {"rotating", "thesis"}
        The model's internal-damping model.
    omega : float
        Excitation frequency ω ≥ 0 [rad/s] (0: static).
    speed : float
        Spin speed Ω [rad/s].
    """
    _check(internal_damping)
    if not (np.isfinite(omega) and omega >= 0):
        raise ValueError(f"excitation frequency must be a finite number >= 0 rad/s, got {omega!r}")
    if not np.isfinite(speed):
        raise ValueError(f"speed must be a finite number [rad/s], got {speed!r}")
    on = 1.0 if omega > 0 else 0.0
    if internal_damping == "thesis":
        return LossCoefficients(1j * on, 1j * on, 0.0)
    sigma = whirl_sign(omega, speed)
    sigma_backward = 1.0 if omega + speed > 0 else 0.0
    return LossCoefficients(1j * on, 0.5j * (sigma_backward + sigma), 0.5 * (sigma_backward - sigma))


def frequency_coefficient_arrays(internal_damping: str, omega, speed) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`frequency_coefficients` at many points at once: arrays (fixed, lateral,
    circulatory) over ``omega`` [rad/s], ``speed`` [rad/s] (broadcast together); the same
    arithmetic element by element, so the same numbers."""
    _check(internal_damping)
    omega, speed = np.broadcast_arrays(np.asarray(omega, dtype=float), np.asarray(speed, dtype=float))
    bad = ~(np.isfinite(omega) & (omega >= 0))
    if bad.any():
        raise ValueError(f"excitation frequency must be a finite number >= 0 rad/s, got {float(omega[bad][0])!r}")
    if not np.isfinite(speed).all():
        raise ValueError(f"speed must be a finite number [rad/s], got {float(speed[~np.isfinite(speed)][0])!r}")
    on = (omega > 0).astype(float)
    if internal_damping == "thesis":
        return 1j * on, 1j * on, np.zeros_like(on)
    difference = omega - speed
    band = SYNCHRONOUS_TOLERANCE * np.maximum(np.maximum(np.abs(omega), np.abs(speed)), 1.0)
    sigma = np.where(np.abs(difference) <= band, 0.0, np.sign(difference))
    sigma_backward = (omega + speed > 0).astype(float)
    return 1j * on, 0.5j * (sigma_backward + sigma), 0.5 * (sigma_backward - sigma)


def eigen_coefficients(
    internal_damping: str, omega: float, speed: float, sigma: float | None = None
) -> LossCoefficients:
    """Complex weights of the loss matrices for a mode of frequency ω = Im(s) > 0 [rad/s].

    The frequency-domain weights of :func:`frequency_coefficients` at ω; ``sigma`` overrides
    sgn(ω − Ω) (the weights of one side of the synchronous line, or of σ = 0 on it).
    """
    _check(internal_damping)
    if not (np.isfinite(omega) and omega > 0):
        raise ValueError(f"mode frequency must be a finite number > 0 rad/s, got {omega!r}")
    if internal_damping == "thesis" or sigma is None:
        return frequency_coefficients(internal_damping, omega, speed)
    return LossCoefficients(1j, 0.5j * (1.0 + sigma), 0.5 * (1.0 - sigma))


def viscous_equivalent(reference_frequency: float, speed: float) -> LossCoefficients:
    """Zorzi-Nelson viscous internal damping at one reference frequency ω_ref [rad/s].

    Damping ``(F + K_lat)/ω_ref`` (the whole shaft loss C_i = K''/ω_ref acting in the rotating
    frame, plus the boom's) and circulatory stiffness ``(Ω/ω_ref) K_lat S`` — the thesis's
    chapter-4 model, where every mode meets the loss at the same ω_ref.
    """
    if not (np.isfinite(reference_frequency) and reference_frequency > 0):
        raise ValueError(f"reference_frequency must be a finite number > 0 rad/s, got {reference_frequency!r}")
    if not np.isfinite(speed):
        raise ValueError(f"speed must be a finite number [rad/s], got {speed!r}")
    return LossCoefficients(1.0 / reference_frequency, 1.0 / reference_frequency, speed / reference_frequency)

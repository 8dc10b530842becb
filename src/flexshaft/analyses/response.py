"""Harmonic, synchronous (imbalance) and static response (thesis §2.3–2.5).

``q = H(ω) Q`` is never formed as an inverse: each frequency is one banded LU solve
(:class:`~flexshaft.analyses.banded.BandedHarmonicSolver`) for all load cases at once.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.banded import BandedHarmonicSolver, SingularSystemError
from flexshaft.assembly.model import Model

__all__ = [
    "SingularSystemError",
    "frequency_response",
    "imbalance_response",
    "orbit_amplitude",
    "bearing_forces",
    "static_response",
]


def _solve_many(model: Model, loads, points, solver: BandedHarmonicSolver | None = None) -> np.ndarray:
    """Solve at (ω, Ω, load scale) points; returns (ndof, ..., npoints)."""
    solver = solver or BandedHarmonicSolver(model)
    Q = np.asarray(loads)
    rhs = Q[solver.free].astype(complex)
    out = np.zeros(Q.shape + (len(points),), dtype=complex)
    for k, (omega, speed, scale) in enumerate(points):
        out[solver.free, ..., k] = scale * solver.solve(omega, rhs, speed)
    return out


def frequency_response(model: Model, loads, omega, speed: float | None = None) -> np.ndarray:
    """Complex amplitudes q(ω) for harmonic loads ``Q e^{iωt}`` at spin speed Ω.

    Parameters
    ----------
    loads : ndarray
        Load vector(s) on the full DOF vector, (ndof,) or (ndof, ncases) [N, N m].
    omega : float or array_like
        Excitation frequencies [rad/s].
    speed : float or None
        Spin speed Ω [rad/s] (the model's operating speed when None).

    Returns
    -------
    ndarray
        Same shape as ``loads`` for scalar ω, else with a trailing axis over ω [m, rad].

    Raises
    ------
    SingularSystemError
        When Z(ω) is singular (an undamped resonance).
    """
    speed = model.speed if speed is None else speed
    omegas = np.atleast_1d(np.asarray(omega, dtype=float))
    if not np.all(np.isfinite(omegas)) or np.any(omegas < 0):
        raise ValueError(f"excitation frequencies must be finite and >= 0 rad/s (got {omega!r})")
    if not np.isfinite(speed) or speed < 0:
        raise ValueError(f"speed must be a finite number >= 0 rad/s (got {speed!r})")
    out = _solve_many(model, loads, [(w, speed, 1.0) for w in omegas])
    return out[..., 0] if np.ndim(omega) == 0 else out


def imbalance_response(model: Model, speeds, loads_per_speed_squared) -> np.ndarray:
    """Synchronous response to a rotating load ``Ω² Q₁ e^{iΩt}`` at each speed Ω.

    Parameters
    ----------
    speeds : array_like
        Spin speeds Ω [rad/s]; the excitation frequency equals the speed.
    loads_per_speed_squared : ndarray
        Q₁ (ndof,) or (ndof, ncases) [N s²], e.g. from
        :func:`flexshaft.assembly.loads.imbalance_loads`.

    Returns
    -------
    ndarray
        (ndof, [ncases,] nspeeds) complex amplitudes [m, rad].
    """
    speeds = np.atleast_1d(np.asarray(speeds, dtype=float))
    if not np.all(np.isfinite(speeds)) or np.any(speeds < 0):
        raise ValueError(f"speeds must be finite and >= 0 rad/s (got {speeds!r})")
    return _solve_many(model, loads_per_speed_squared, [(s, s, s * s) for s in speeds])


def static_response(model: Model, loads, speed: float | None = None) -> np.ndarray:
    """Static displacement of the spinning driveline under constant loads [m, rad].

    ``(K + K_a + L(0, Ω)) q = Q`` with the storage stiffness K, the actuators' static stiffness
    K_a and the loss at zero frequency: nothing for the fixed-frame loss, but for the
    ``"rotating"`` internal-damping model the circulatory ``K_lat S`` of the spinning shaft,
    whose material is cycled at Ω by a constant deflection (the deflection then turns slightly
    sideways; :mod:`flexshaft.analyses.loss`).

    Parameters
    ----------
    loads : ndarray
        Load vector(s) on the full DOF vector (ndof,) or (ndof, ncases) [N, N m].
    speed : float or None
        Spin speed Ω [rad/s] (the model's operating speed when None).
    """
    from flexshaft.analyses.loss import frequency_coefficients
    from flexshaft.assembly.sparse import restrict
    import scipy.sparse.linalg as spla

    free = model.dofs.free
    speed = model.speed if speed is None else float(speed)
    if not np.isfinite(speed) or speed < 0:
        raise ValueError(f"speed must be a finite number >= 0 rad/s (got {speed!r})")
    K = model.K + model.Kp
    circulatory = frequency_coefficients(model.internal_damping, 0.0, speed).circulatory
    if circulatory:
        K = K + circulatory * model.loss_circulatory
    Q = np.asarray(loads, dtype=float)
    if not np.all(np.isfinite(Q)):
        raise ValueError("the load vector contains NaN or inf")
    try:
        lu = spla.splu(restrict(K.tocsr(), free).tocsc())
    except RuntimeError as exc:
        raise SingularSystemError("static stiffness is singular: the model has an unconstrained rigid-body motion") from exc
    out = np.zeros(Q.shape)
    out[free] = lu.solve(Q[free])
    return out


def orbit_amplitude(a, b) -> np.ndarray:
    """Largest excursion of the orbit ``(Re(a e^{iφ}), Re(b e^{iφ}))`` over φ: the major
    semi-axis ``√((|a|² + |b|² + |a² + b²|)/2)`` [same unit as a, b]."""
    a, b = np.asarray(a), np.asarray(b)
    return np.sqrt(0.5 * (np.abs(a) ** 2 + np.abs(b) ** 2 + np.abs(a * a + b * b)))


def bearing_forces(model: Model, q: np.ndarray, omega: float = 0.0) -> dict[str, np.ndarray]:
    """Forces carried by each bearing [N, N m] over (u, v, w, β, γ) for displacement ``q``.

    Contact bearings: ``(k + iωc) · rel``; active bearings: ``C(iω) · rel`` on v and w.
    ``q`` may carry trailing axes (cases); complex amplitudes give complex forces.
    """
    out = {}
    actuators = {a.name: a for a in model.actuators}
    for link in model.bearings:
        rel = link.rows @ q
        if link.name in actuators:
            gain = np.zeros(5, dtype=complex)
            gain[1:3] = actuators[link.name].controller(1j * omega)
        else:
            gain = link.stiffness + 1j * omega * link.damping
        out[link.name] = gain.reshape((5,) + (1,) * (np.ndim(rel) - 1)) * rel
    return out

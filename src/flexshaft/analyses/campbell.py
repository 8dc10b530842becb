"""Campbell diagram: damped eigenvalues against speed with tracked modes and whirl labels.

Fast path: the quadratic problem is projected once on the lowest ``basis_size`` undamped,
non-spinning modes Φ (mass-normalised), then solved per speed on that small basis:
``(s² I + s Φᵀ(ΩG + C + K_d)Φ + Λ) y = 0``. Modes are tracked between neighbouring speeds
by the modal assurance criterion on y (Hungarian assignment), so a curve keeps its identity
through veerings and crossings; each point carries its own whirl label from the orbit of the
shaft nodes. Critical speeds are the intersections of the tracked curves with the excitation
lines ``ω = kΩ`` (linear interpolation between speeds).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as la
from scipy.optimize import linear_sum_assignment

from flexshaft.analyses.modal import whirl_ratio
from flexshaft._threads import single_blas_thread
from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import restrict

__all__ = ["Campbell", "EigenvalueCurves", "CriticalSpeed", "campbell", "modal_basis", "track_modes", "whirl_labels"]

_WHIRL_THRESHOLD = 0.1


@dataclass(frozen=True)
class CriticalSpeed:
    """Intersection of a tracked mode with the excitation line ω = harmonic·Ω."""

    speed: float  # [rad/s]
    mode: int  # tracked-mode index
    harmonic: float
    whirl: str

    @property
    def speed_rpm(self) -> float:
        return self.speed * 60 / (2 * np.pi)


class EigenvalueCurves:
    """Derived quantities of an ``eigenvalues`` array (n_speeds, n_modes) of s [rad/s]."""

    eigenvalues: np.ndarray

    @property
    def frequencies(self) -> np.ndarray:
        """Damped natural frequencies Im(s)/2π [Hz]."""
        return self.eigenvalues.imag / (2 * np.pi)

    @property
    def real_parts(self) -> np.ndarray:
        """Re(s) [1/s]; positive is unstable."""
        return self.eigenvalues.real

    @property
    def damping_ratios(self) -> np.ndarray:
        """ζ = −Re(s)/|s|."""
        return -self.eigenvalues.real / np.abs(self.eigenvalues)

    @property
    def log_decrements(self) -> np.ndarray:
        """δ = 2π ζ/√(1 − ζ²)."""
        z = self.damping_ratios
        return 2 * np.pi * z / np.sqrt(np.maximum(1 - z * z, 1e-300))


@dataclass(frozen=True)
class Campbell(EigenvalueCurves):
    """Tracked damped eigenvalues over speed.

    Attributes
    ----------
    speeds : ndarray
        Ω [rad/s], (n_speeds,).
    eigenvalues : ndarray
        s [rad/s], (n_speeds, n_modes); column k is one tracked mode.
    whirl : ndarray of str
        "forward", "backward" or "planar" per point.
    whirl_ratios : ndarray
        Whirl ratio in [−1, 1] per point.
    """

    speeds: np.ndarray
    eigenvalues: np.ndarray
    whirl: np.ndarray
    whirl_ratios: np.ndarray
    critical_speeds: tuple[CriticalSpeed, ...]



def modal_basis(model: Model, basis_size: int):
    """Lowest undamped, non-spinning modes on the free DOFs: (ω², Φ) mass-normalised."""
    free = model.dofs.free
    M = restrict(model.M, free).toarray()
    K = restrict(model.K.real + model.Kp, free).toarray()
    n = min(basis_size, M.shape[0])
    return la.eigh(K, M, subset_by_index=[0, n - 1])


def _solve_reduced(Kr, Dr, n_keep):
    """Eigen-pairs of ``s² I + s Dr + Kr`` (mass-normalised modal coordinates), lowest first."""
    nb = Kr.shape[0]
    A = np.zeros((2 * nb, 2 * nb))
    A[:nb, nb:] = np.eye(nb)
    A[nb:, :nb] = -Kr
    A[nb:, nb:] = -Dr
    lam, vec = la.eig(A)
    keep = lam.imag > 1e-6 * np.abs(lam)  # oscillatory roots only (ζ < 1 − 5e-13)
    lam, vec = lam[keep], vec[:nb, keep]
    order = np.argsort(np.abs(lam))[:n_keep]  # by undamped natural frequency |s|
    y = vec[:, order]
    return lam[order], y / np.linalg.norm(y, axis=0)


def _mac(a, b):
    return np.abs(a.conj().T @ b) ** 2


def track_modes(solve, speeds, n_modes: int):
    """Follow ``n_modes`` eigenvalue curves over ``speeds``.

    ``solve(speed) -> (eigenvalues, vectors)`` returns more candidates than ``n_modes``, sorted
    by frequency, with unit-norm vectors in one fixed (modal) coordinate system. The first
    speed fixes the identities (lowest ``n_modes``); later speeds are matched by maximum MAC
    with a small frequency-distance penalty (Hungarian assignment).

    Returns ``(eigenvalues (n_speeds, n_modes), [vectors per speed])``.
    """
    eig = np.zeros((len(speeds), n_modes), dtype=complex)
    vectors = []
    prev = None
    for k, speed in enumerate(speeds):
        lam, y = solve(speed)
        if prev is None:
            idx = np.arange(n_modes)
        else:
            lam_prev, y_prev = prev
            scale = np.maximum(np.abs(lam_prev.imag)[:, None], 1e-12)
            cost = 1 - _mac(y_prev, y) + 0.1 * np.abs(lam_prev.imag[:, None] - lam.imag[None, :]) / scale
            _, idx = linear_sum_assignment(cost)
        eig[k] = lam[idx]
        prev = (lam[idx], y[:, idx])
        vectors.append(y[:, idx])
    return eig, vectors


def whirl_labels(model: Model, Phi: np.ndarray, vectors, speeds):
    """Whirl ratios and labels of tracked modes from their modal coordinates."""
    ratios = np.array([whirl_ratio(model.dofs, model.dofs.expand(Phi @ y)) for y in vectors])
    if len(speeds) > 1 and speeds[0] == 0.0:
        ratios[0] = ratios[1]  # at rest the pairs are degenerate: label by their continuation
    labels = np.where(ratios > _WHIRL_THRESHOLD, "forward", np.where(ratios < -_WHIRL_THRESHOLD, "backward", "planar"))
    return ratios, labels


@single_blas_thread
def campbell(model: Model, speeds, n_modes: int = 10, basis_size: int | None = None,
             harmonics=(1.0,), damped: bool = True) -> Campbell:
    """Damped eigenvalues at each speed, tracked into continuous mode curves.

    Parameters
    ----------
    speeds : array_like
        Ω [rad/s], increasing.
    n_modes : int
        Number of tracked modes (the lowest at the first speed).
    basis_size : int or None
        Size of the modal basis (default ``max(4 n_modes, 40)``); larger is more exact.
    harmonics : sequence of float
        Excitation orders k for the critical speeds (ω = kΩ).
    damped : bool
        Include bearing damping C and actuator K_d.
    """
    if not model.all_pd:
        raise ValueError("the Campbell diagram needs PD actuators (transfer functions: use the frequency response)")
    speeds = np.asarray(speeds, dtype=float)
    free = model.dofs.free
    nb = basis_size or max(4 * n_modes, 40)
    w2, Phi = modal_basis(model, nb)
    Gr = Phi.T @ (restrict(model.G, free) @ Phi)
    Dr = Phi.T @ (restrict(model.C + model.Kd, free) @ Phi) if damped else np.zeros_like(Gr)
    n_extra = min(n_modes + 6, w2.size)
    eig, vectors = track_modes(lambda sp: _solve_reduced(np.diag(w2), speed_matrix(Gr, Dr, sp), n_extra), speeds, n_modes)
    ratios, whirl = whirl_labels(model, Phi, vectors, speeds)
    return Campbell(speeds, eig, whirl, ratios, _critical_speeds(speeds, eig, whirl, harmonics))


def speed_matrix(Gr, Dr, speed):
    return speed * Gr + Dr


def _critical_speeds(speeds, eig, whirl, harmonics):
    out = []
    for h in harmonics:
        for m in range(eig.shape[1]):
            g = eig[:, m].imag - h * speeds
            for i in np.flatnonzero(np.sign(g[:-1]) * np.sign(g[1:]) < 0):
                t = g[i] / (g[i] - g[i + 1])
                out.append(CriticalSpeed(float(speeds[i] + t * (speeds[i + 1] - speeds[i])), m, float(h), str(whirl[i, m])))
    return tuple(sorted(out, key=lambda c: c.speed))

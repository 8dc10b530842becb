"""Whirl stability with internal (rotating) damping (thesis chapter 4, rebuilt).

Time-domain damping model. The hysteretic loss of the shaft, ``K'' = Im(K_shaft)``, becomes an
equivalent viscous damping ``C_i = K''/ω_ref`` acting in the rotating frame; in the fixed frame
it adds ``C_i`` to the damping and the circulatory stiffness ``Ω C_i S`` (Zorzi & Nelson 1977),
S rotating each node's lateral pairs (v, w) and (γ, −β) by −90° about x. The boom's structural
loss ``K''_boom/ω_ref`` is an ordinary fixed-frame damping. The eigenproblem is

    [s² M + s (C + K_d + ΩG + C_i + C_b) + K' + K_p + Ω C_i S] φ = 0.

Damping models:

* ``"viscous"``: one fixed ω_ref for every mode (``reference_frequency``);
* ``"hysteretic"``: the exact hysteretic law, whose loss sign follows the whirl relative to the
  spin. For a circular whirl ``s ≈ iω`` the rotating material is cycled at ``ω_signed − Ω``
  (``ω_signed = +ω`` forward, ``−ω`` backward); with ``ω_ref = |ω_signed − Ω|`` the viscous
  equivalent reproduces ``iηk sgn(ω_signed − Ω)`` exactly, so each mode is iterated to its
  own consistent ω_ref (boom: ``ω_ref = ω``).

Eigen-solutions use the modal basis of the non-spinning undamped model (as the Campbell
diagram); modes are tracked over speed by MAC.

References
----------
Zorzi, E. S., Nelson, H. D. (1977). Finite element simulation of rotor-bearing systems with
internal damping. J. Eng. Power 99, 71-76.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import scipy.sparse as sp

from flexshaft._threads import single_blas_thread
from flexshaft.analyses.campbell import EigenvalueCurves, _mac, _solve_reduced, modal_basis, track_modes, whirl_labels
from flexshaft.analyses.modal import whirl_ratio
from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import restrict

__all__ = ["DampingModel", "StabilityResult", "rotation_generator", "stability", "onset_speed"]

DampingModel = Literal["viscous", "hysteretic"]
_MAX_ITER = 40
_FLOOR = 1e-3  # ω_ref floor as a fraction of the mode's frequency (synchronous forward whirl)


def rotation_generator(model: Model) -> sp.csr_matrix:
    """S: per shaft node (v, w) → (w, −v) and (β, γ) → (γ, −β); zero on u, θ and the boom."""
    dm = model.dofs
    n = np.arange(dm.n_shaft_nodes)
    v, w, b, g = (dm.shaft(n, f) for f in ("v", "w", "beta", "gamma"))
    rows = np.concatenate([v, w, b, g])
    cols = np.concatenate([w, v, g, b])
    vals = np.concatenate([np.ones_like(v), -np.ones_like(v), np.ones_like(v), -np.ones_like(v)]).astype(float)
    return sp.csr_matrix((vals, (rows, cols)), shape=(dm.size, dm.size))


@dataclass(frozen=True)
class StabilityResult(EigenvalueCurves):
    """Tracked eigenvalues over speed with the onset of instability.

    Attributes
    ----------
    speeds : ndarray
        Ω [rad/s].
    eigenvalues : ndarray
        (n_speeds, n_modes) s [rad/s]; Re(s) > 0 is unstable.
    whirl : ndarray of str
        Whirl label per point.
    onset_speed : float or None
        Lowest speed where a tracked mode's Re(s) crosses zero [rad/s] (None: stable throughout).
    unstable_mode : int or None
        Tracked index of that mode.
    onset_shape : ndarray or None
        Its shape (full DOF vector) at the first unstable speed.
    """

    speeds: np.ndarray
    eigenvalues: np.ndarray
    whirl: np.ndarray
    damping_model: str
    onset_speed: float | None
    unstable_mode: int | None
    onset_shape: np.ndarray | None

    @property
    def stability_margin(self) -> np.ndarray:
        """Smallest damping ratio over the tracked modes at each speed (negative: unstable)."""
        return self.damping_ratios.min(axis=1)


def onset_speed(speeds, eigenvalues) -> tuple[float | None, int | None, int | None]:
    """First zero crossing of Re(s) from negative to positive: (speed, mode, index after it)."""
    re = np.asarray(eigenvalues).real
    best = (None, None, None)
    for m in range(re.shape[1]):
        pos = np.flatnonzero(re[:, m] > 0)
        if pos.size == 0:
            continue
        k = pos[0]
        if k == 0:
            crossing = float(speeds[0])
        else:
            t = re[k - 1, m] / (re[k - 1, m] - re[k, m])
            crossing = float(speeds[k - 1] + t * (speeds[k] - speeds[k - 1]))
        if best[0] is None or crossing < best[0]:
            best = (crossing, m, int(k))
    return best


class _Reduced:
    """The stability matrices projected on the modal basis."""

    def __init__(self, model: Model, basis_size: int):
        free = model.dofs.free
        w2, Phi = modal_basis(model, basis_size)
        self.Phi, self.w2 = Phi, w2
        proj = lambda A: Phi.T @ (restrict(A.tocsr(), free) @ Phi)
        self.G = proj(model.G)
        self.D = proj(model.C + model.Kd)
        Ki = model.shaft_loss_stiffness
        self.Ci = proj(Ki)
        self.Kc = proj((Ki @ rotation_generator(model)).tocsr())
        self.Cb = proj(model.boom_loss_stiffness)

    def matrices(self, speed, ref_shaft, ref_boom):
        D = speed * self.G + self.D + self.Ci / ref_shaft + self.Cb / ref_boom
        K = np.diag(self.w2) + (speed / ref_shaft) * self.Kc
        return K, D


def _signed_frequency(model, Phi, lam, y):
    r = whirl_ratio(model.dofs, model.dofs.expand(Phi @ y[:, None]))[0]
    return lam.imag if r >= 0 else -lam.imag


@single_blas_thread
def stability(model: Model, speeds, n_modes: int = 12, damping_model: DampingModel = "viscous",
              reference_frequency: float | None = None, basis_size: int | None = None) -> StabilityResult:
    """Eigenvalues of the linearized driveline with internal damping over speed.

    Parameters
    ----------
    speeds : array_like
        Ω [rad/s], increasing.
    n_modes : int
        Tracked modes.
    damping_model : {"viscous", "hysteretic"}
        See the module docstring.
    reference_frequency : float or None
        ω_ref [rad/s] of the viscous equivalent; default: the first lateral natural frequency
        of the shaft-dominated modes at rest (the lowest basis frequency above the boom modes is
        not known in general, so the default is the lowest frequency whose mode is > 50 % shaft).
    basis_size : int or None
        Modal basis size (default ``max(4 n_modes, 48)``).
    """
    if not model.all_pd:
        raise ValueError("stability analysis needs PD actuators")
    speeds = np.asarray(speeds, dtype=float)
    red = _Reduced(model, basis_size or max(4 * n_modes, 48))
    if reference_frequency is None:
        reference_frequency = _first_shaft_frequency(model, red)
    n_extra = min(n_modes + 6, red.w2.size)
    ref = float(reference_frequency)

    def solve_viscous(speed):
        K, D = red.matrices(speed, ref, ref)
        return _solve_reduced(K, D, n_extra)

    eig, vectors = track_modes(solve_viscous, speeds, n_modes)
    if damping_model == "hysteretic":
        for k, speed in enumerate(speeds):
            for m in range(n_modes):
                eig[k, m], vectors[k][:, m] = _iterate_mode(model, red, speed, eig[k, m], vectors[k][:, m], n_extra)
    elif damping_model != "viscous":
        raise ValueError(f"damping_model must be 'viscous' or 'hysteretic', got {damping_model!r}")
    _, whirl = whirl_labels(model, red.Phi, vectors, speeds)
    onset, mode, k = onset_speed(speeds, eig)
    shape = model.dofs.expand(red.Phi @ vectors[k][:, mode]) if onset is not None else None
    return StabilityResult(speeds, eig, whirl, damping_model, onset, mode, shape)


def _first_shaft_frequency(model, red) -> float:
    ns = 6 * model.dofs.n_shaft_nodes
    Phi_full = model.dofs.expand(red.Phi)
    Mphi = model.M @ Phi_full
    shaft = np.einsum("ij,ij->j", Phi_full[:ns], Mphi[:ns]) / np.einsum("ij,ij->j", Phi_full, Mphi)
    k = np.flatnonzero(shaft > 0.5)
    return float(np.sqrt(red.w2[k[0] if k.size else 0]))


def _iterate_mode(model, red, speed, lam, y, n_extra):
    """Fixed point ω_ref = |ω_signed − Ω| (shaft), |ω| (boom) for one mode."""
    for _ in range(_MAX_ITER):
        w_signed = _signed_frequency(model, red.Phi, lam, y)
        floor = _FLOOR * max(abs(lam.imag), 1.0)
        ref_s = max(abs(w_signed - speed), floor)
        ref_b = max(abs(lam.imag), floor)
        K, D = red.matrices(speed, ref_s, ref_b)
        lams, ys = _solve_reduced(K, D, n_extra)
        j = int(np.argmax(_mac(y[:, None], ys)[0]))
        converged = abs(lams[j] - lam) <= 1e-10 * abs(lam)
        lam, y = lams[j], ys[:, j]
        if converged:
            break
    return lam, y

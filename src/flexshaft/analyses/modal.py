"""Natural frequencies and mode shapes at a given spin speed.

* ``damped=False, speed=0``: the symmetric problem ``(K' + K_p) φ = ω² M φ`` (storage stiffness).
* otherwise the quadratic problem ``(s² M + s D + K' + K_p) φ = 0`` with
  ``D = Ω G`` (undamped, spinning) or ``D = Ω G + C + K_d`` (damped), solved in first-order form.

The hysteretic loss (imaginary stiffness) is not a viscous damping and is left out here; the
whirl-stability analysis converts it to an equivalent viscous model.

Whirl direction: with node orbits ``v = Re(V e^{iωt})``, ``w = Re(W e^{iωt})`` and spin about
+x (y towards z), a forward orbit has ``W = −iV``. The whirl ratio
``r = −2 Σ Im(V̄ W) / Σ(|V|² + |W|²)`` over the shaft nodes is +1 for a circular forward
orbit and −1 for a backward one.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as la

from flexshaft.assembly.dofs import DofMap
from flexshaft._threads import single_blas_thread
from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import restrict

__all__ = ["Modes", "modes", "whirl_ratio", "shaft_energy_fraction"]

_WHIRL_THRESHOLD = 0.1  # |r| below this: planar or mixed orbit


@dataclass(frozen=True)
class Modes:
    """Eigen-solution at one speed, sorted by natural frequency.

    Attributes
    ----------
    speed : float
        Spin speed Ω [rad/s].
    eigenvalues : ndarray
        s = −ζω_n ± iω_d [rad/s] (one per mode, Im s ≥ 0).
    shapes : ndarray
        Mode shapes on the full DOF vector, (ndof, n_modes), unit maximum translation.
    whirl : ndarray of str
        "forward", "backward" or "planar" (|whirl ratio| < 0.1).
    component : ndarray of str
        "shaft", "boom" or "coupled" from the kinetic-energy share of the shaft (> 0.9, < 0.1).
    """

    speed: float
    eigenvalues: np.ndarray
    shapes: np.ndarray
    whirl: np.ndarray
    whirl_ratios: np.ndarray
    shaft_fractions: np.ndarray
    dofs: DofMap

    @property
    def frequencies(self) -> np.ndarray:
        """Damped natural frequencies Im(s)/2π [Hz]."""
        return self.eigenvalues.imag / (2 * np.pi)

    @property
    def undamped_frequencies(self) -> np.ndarray:
        """|s|/2π [Hz]."""
        return np.abs(self.eigenvalues) / (2 * np.pi)

    @property
    def damping_ratios(self) -> np.ndarray:
        """ζ = −Re(s)/|s| (round-off below 1e-12 reported as exactly 0)."""
        zeta = -self.eigenvalues.real / np.abs(self.eigenvalues)
        return np.where(np.abs(zeta) < 1e-12, 0.0, zeta)

    @property
    def component(self) -> np.ndarray:
        f = self.shaft_fractions
        return np.where(f > 0.9, "shaft", np.where(f < 0.1, "boom", "coupled"))


def whirl_ratio(dofs: DofMap, shapes: np.ndarray) -> np.ndarray:
    """Whirl ratio r in [−1, 1] of each mode (column) from the shaft node orbits."""
    n = np.arange(dofs.n_shaft_nodes)
    V, W = shapes[dofs.shaft(n, "v")], shapes[dofs.shaft(n, "w")]
    power = np.sum(np.abs(V) ** 2 + np.abs(W) ** 2, axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        r = -2 * np.sum(np.imag(np.conj(V) * W), axis=0) / power
    return np.where(power > 0, r, 0.0)


def shaft_energy_fraction(model: Model, shapes: np.ndarray) -> np.ndarray:
    """Share of each mode's kinetic energy carried by shaft DOFs."""
    Mphi = model.M @ shapes
    total = np.real(np.sum(np.conj(shapes) * Mphi, axis=0))
    ns = 6 * model.dofs.n_shaft_nodes
    shaft = np.real(np.sum(np.conj(shapes[:ns]) * Mphi[:ns], axis=0))
    return shaft / total


def _normalise(dofs: DofMap, phi: np.ndarray) -> np.ndarray:
    trans = [dofs.shaft(np.arange(dofs.n_shaft_nodes), f) for f in ("u", "v", "w")]
    if dofs.n_boom_nodes:
        trans += [dofs.boom(np.arange(dofs.n_boom_nodes), f) for f in ("v", "w")]
    idx = np.concatenate(trans)
    k = np.argmax(np.abs(phi[idx]), axis=0)
    ref = phi[idx[k], np.arange(phi.shape[1])]
    ref = np.where(np.abs(ref) > 0, ref, 1.0)
    return phi / ref


@single_blas_thread
def modes(model: Model, speed: float = 0.0, n_modes: int = 10, damped: bool = True) -> Modes:
    """Natural frequencies and mode shapes at spin speed ``speed`` [rad/s].

    Parameters
    ----------
    model : Model
        Assembled model.
    speed : float
        Ω [rad/s].
    n_modes : int
        Number of lowest modes returned.
    damped : bool
        Include viscous damping C and the actuators' K_d (gyroscopic terms are always in).
    """
    dofs = model.dofs
    if not model.all_pd:
        raise ValueError("eigen-analysis needs PD actuators; transfer-function controllers are "
                         "supported by the frequency response only")
    free = dofs.free
    M = restrict(model.M, free).toarray()
    K = restrict(model.K.real + model.Kp, free).toarray()
    D = speed * restrict(model.G, free).toarray()
    if damped:
        D = D + restrict(model.C + model.Kd, free).toarray()
    n = M.shape[0]
    n_modes = min(n_modes, n)
    if not np.any(D):
        w2, phi = la.eigh(K, M, subset_by_index=[0, n_modes - 1])
        s = 1j * np.sqrt(np.maximum(w2, 0.0))
        phi = phi.astype(complex)
    else:
        cho = la.cho_factor(M)
        A = np.zeros((2 * n, 2 * n))
        A[:n, n:] = np.eye(n)
        A[n:, :n] = -la.cho_solve(cho, K)
        A[n:, n:] = -la.cho_solve(cho, D)
        lam, vec = la.eig(A)
        keep = lam.imag > 1e-6 * np.abs(lam)  # oscillatory roots only (ζ < 1 − 5e-13)
        lam, vec = lam[keep], vec[:n, keep]
        order = np.argsort(np.abs(lam))[:n_modes]  # by undamped natural frequency |s|
        s, phi = lam[order], vec[:, order]
    shapes = _normalise(dofs, dofs.expand(phi))
    r = whirl_ratio(dofs, shapes)
    whirl = np.where(r > _WHIRL_THRESHOLD, "forward", np.where(r < -_WHIRL_THRESHOLD, "backward", "planar"))
    return Modes(float(speed), s, shapes, whirl, r, shaft_energy_fraction(model, shapes), dofs)

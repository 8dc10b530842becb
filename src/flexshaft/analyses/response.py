"""Direct harmonic response ``q = H(ω) Q`` without forming H (thesis eqs. 2.38-2.40).

``Z(ω, Ω) = −ω² M + iω (Ω G + C) + K + Σ Bᵀ C_a(iω) B`` is factorized (sparse LU) on the free
DOFs for each ω and solved for all load vectors at once.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import restrict

__all__ = ["SingularSystemError", "dynamic_stiffness", "frequency_response"]

# LU pivots below this fraction of the largest pivot mean Z is singular to working precision.
_SINGULAR_PIVOT_RATIO = 1e-13


class SingularSystemError(ArithmeticError):
    """The dynamic stiffness is singular: an undamped system excited exactly at resonance."""


def dynamic_stiffness(model: Model, omega: float, speed: float | None = None) -> sp.csc_matrix:
    """Z(ω, Ω) on the free DOFs (complex sparse).

    Parameters
    ----------
    omega : float
        Excitation frequency ω [rad/s].
    speed : float or None
        Spin speed Ω [rad/s]; the model's operating speed when None.
    """
    speed = model.speed if speed is None else speed
    Z = (-(omega**2)) * model.M + 1j * omega * (speed * model.G + model.C) + model.K
    Z = Z + model.controller_matrix(1j * omega)
    return sp.csc_matrix(restrict(Z.tocsr(), model.dofs.free))


def frequency_response(model: Model, loads, omega, speed: float | None = None) -> np.ndarray:
    """Complex amplitudes q(ω) for harmonic loads ``Q e^{iωt}``.

    Parameters
    ----------
    model : Model
    loads : ndarray
        Load vector(s) on the full DOF vector, (ndof,) or (ndof, nrhs) [N, N m].
    omega : float or array_like
        Excitation frequencies [rad/s].
    speed : float or None
        Spin speed Ω [rad/s] (model's operating speed when None).

    Returns
    -------
    ndarray
        (ndof,) / (ndof, nrhs) for scalar ω, else with a trailing axis over ω.

    Raises
    ------
    SingularSystemError
        When Z(ω) is singular (undamped resonance).
    """
    Q = np.asarray(loads)
    free = model.dofs.free
    rhs = Q[free].astype(complex)
    omegas = np.atleast_1d(np.asarray(omega, dtype=float))
    out = np.zeros(Q.shape + (omegas.size,), dtype=complex)
    for k, w in enumerate(omegas):
        Z = dynamic_stiffness(model, w, speed)
        try:
            lu = spla.splu(Z)
        except RuntimeError as exc:  # "Factor is exactly singular"
            raise SingularSystemError(f"dynamic stiffness is singular at ω = {w:.6g} rad/s") from exc
        pivots = np.abs(lu.U.diagonal())
        if pivots.min() <= _SINGULAR_PIVOT_RATIO * pivots.max():
            raise SingularSystemError(
                f"dynamic stiffness is singular at ω = {w:.6g} rad/s (undamped resonance); "
                "add damping or move the frequency"
            )
        out[free, ..., k] = lu.solve(rhs)
    return out[..., 0] if np.ndim(omega) == 0 else out

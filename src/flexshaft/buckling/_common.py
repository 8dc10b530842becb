"""Shared pieces of the torsional buckling models: checks, stiffness, axial integrals, eigenvalues."""

from __future__ import annotations

from typing import Literal

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from flexshaft.laminate import Laminate, abd_matrices, transverse_shear_stiffness

__all__ = [
    "ShellTheory", "Kinematics", "shell_stiffness", "check_inputs", "axial_integrals", "default_terms",
    "extreme_torques", "helix_minima", "rank_two_torques", "THEORIES", "KINEMATICS",
]

#: Shell theory: classical Kirchhoff-Love, or first-order shear deformation (Reissner-Mindlin).
ShellTheory = Literal["shear", "classical"]
#: Kinematic relations: Sanders' first approximation, or Donnell's shallow-shell relations.
Kinematics = Literal["sanders", "donnell"]
THEORIES = ("shear", "classical")
KINEMATICS = ("sanders", "donnell")


def shell_stiffness(laminate: Laminate, theory: ShellTheory = "classical") -> NDArray[np.float64]:
    """Storage stiffness of the wall [N/m, N, N m].

    ``"classical"``: 6x6 [[A, B], [B, D]] relating (N, M) to (eps, kappa). ``"shear"``: 8x8, the
    same block followed by the transverse shear stiffness [[A55, A45], [A45, A44]] relating
    (Q_x, Q_y) to (gamma_xz, gamma_yz) (:func:`flexshaft.laminate.transverse_shear_stiffness`).
    """
    A, B, D = (matrix.real for matrix in abd_matrices(laminate.storage))
    membrane_bending = np.block([[A, B], [B, D]])
    if theory == "classical":
        return membrane_bending
    C = np.zeros((8, 8))
    C[:6, :6] = membrane_bending
    C[6:, 6:] = transverse_shear_stiffness(laminate.storage).real
    return C


def check_inputs(radius: float, theory: str, kinematics: str, length: float = 1.0) -> None:
    """Refuse a non-positive radius or length [m] and unknown theory or kinematics names."""
    for name, value in (("radius", radius), ("length", length)):
        if not np.isfinite(value) or value <= 0.0:
            raise ValueError(f"{name} must be positive and finite [m], got {value!r}")
    if theory not in THEORIES:
        raise ValueError(f"theory must be 'shear' or 'classical', got {theory!r}")
    if kinematics not in KINEMATICS:
        raise ValueError(f"kinematics must be 'sanders' or 'donnell', got {kinematics!r}")


def axial_integrals(m: NDArray[np.int_], length: float) -> dict[tuple[int, int], NDArray[np.float64]]:
    """int_0^L f(m_a pi x/L) g(m_b pi x/L) dx for f, g in (sin, cos); keys (0=sin, 1=cos)."""
    ma, mb = m[:, None], m[None, :]
    same = ma == mb
    odd = (ma + mb) % 2 == 1
    denominator = np.where(odd, ma * ma - mb * mb, 1)
    sin_cos = np.where(odd, 2.0 * length / np.pi * ma / denominator, 0.0)
    return {
        (0, 0): np.where(same & (ma > 0), length / 2.0, 0.0),
        (1, 1): np.where(same, np.where(ma == 0, length, length / 2.0), 0.0),
        (0, 1): sin_cos,
        (1, 0): sin_cos.T,
    }


def default_terms(axial_wavenumber: float, length: float) -> int:
    """Axial terms M for a helix of ``axial_wavenumber`` [rad/m] on ``length`` [m], plus end correction."""
    return int(np.clip(np.ceil(1.25 * abs(axial_wavenumber) * length / np.pi) + 16, 24, 400))


def extreme_torques(K: NDArray[np.complex128], G: NDArray[np.complex128]) -> tuple[float, float]:
    """Smallest positive torque and smallest negative-torque magnitude of K a = T G a [N m]."""
    mu = scipy.linalg.eigh(G, K, eigvals_only=True, driver="gvd")
    return (1.0 / mu[-1] if mu[-1] > 0.0 else np.inf), (-1.0 / mu[0] if mu[0] < 0.0 else np.inf)


def rank_two_torques(K: NDArray[np.complex128], beta_x: NDArray[np.complex128], beta_y: NDArray[np.complex128],
                     radius: float) -> NDArray[np.float64]:
    """(..., 2): positive-sense torque and negative-sense magnitude [N m] of stacked helices.

    The load matrix has rank 2: G = -c (x y^H + y x^H) with x = conj(beta_x), y = conj(beta_y)
    (the rotation rows of the helix's strain operator), c = 1/(2 pi R^2). The nonzero
    eigenvalues mu = 1/T of K^-1 G are those of the 2x2 matrix -c J S, S = W^H K^-1 W,
    W = [x, y], J = [[0, 1], [1, 0]]: mu = -c (rho -/+ sqrt(rho^2 + det S)) with rho = Re S_01.
    So T+ = 1/(c (sqrt(rho^2 + d) - rho)) and T- = 1/(c (sqrt(rho^2 + d) + rho)), one solve
    with two right-hand sides per helix. ``K`` (..., m, m), ``beta_x``, ``beta_y`` (..., m).
    """
    W = np.stack([beta_x.conj(), beta_y.conj()], axis=-1)  # (..., m, 2)
    S = np.swapaxes(W.conj(), -1, -2) @ np.linalg.solve(K, W)
    rho = S[..., 0, 1].real
    root = np.sqrt(rho**2 + np.maximum((S[..., 0, 0] * S[..., 1, 1]).real - np.abs(S[..., 0, 1]) ** 2, 0.0))
    c = 1.0 / (2.0 * np.pi * radius**2)
    with np.errstate(divide="ignore"):
        positive = np.where(root - rho > 0.0, 1.0 / (c * (root - rho)), np.inf)
        negative = np.where(root + rho > 0.0, 1.0 / (c * (root + rho)), np.inf)
    return np.stack([positive, negative], axis=-1)


def helix_minima(torques, radius: float, n: NDArray[np.int_], log_k_offsets: NDArray[np.float64],
                 refine: bool = True) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Minimum over the axial wavenumber k of an endless tube's helix torques, per n.

    ``torques(n, k)`` gives the (..., 2) torques (positive sense, negative-sense magnitude) of
    the helices exp(i(k x + n theta)), broadcast over n and k. The minimum is found on the log
    grid k = n/R exp(log_k_offsets), either sign of k, and, with ``refine``, zoomed four times
    by a factor 8 around the best point (17 points each): with a grid step h the final spacing
    is h/4096, which leaves a relative error of order (h/4096)^2 at a smooth minimum.

    Returns ``(torques, wavenumbers)``, each (len(n), 2): the minimum torque of each sense
    [N m] and its signed axial wavenumber [rad/m].
    """
    n = np.atleast_1d(np.asarray(n, dtype=int))
    rows = np.arange(n.size)[:, None]
    senses = np.arange(2)[None, :]
    best_torques = np.full((n.size, 2), np.inf)
    wavenumbers = np.zeros((n.size, 2))
    for hand in (1.0, -1.0):
        log_k = np.log(n / radius)[:, None] + log_k_offsets[None, :]
        values = torques(n[:, None], hand * np.exp(log_k))  # (n, k, 2)
        best = np.argmin(values, axis=1)  # (n, 2)
        centre, value = log_k[rows, best], values[rows, best, senses]
        step = log_k_offsets[1] - log_k_offsets[0]
        for _ in range(4 if refine else 0):
            local = centre[..., None] + np.linspace(-step, step, 17)  # (n, 2, 17)
            zoomed = torques(n[:, None, None], hand * np.exp(local))
            zoomed = np.take_along_axis(zoomed, np.broadcast_to(senses[..., None, None], local.shape + (1,)),
                                        axis=-1)[..., 0]  # each sense's own torque, (n, 2, 17)
            i = np.argmin(zoomed, axis=-1)
            better = zoomed[rows, senses, i] < value
            centre = np.where(better, local[rows, senses, i], centre)
            value = np.where(better, zoomed[rows, senses, i], value)
            step /= 8.0
        improved = value < best_torques
        best_torques = np.where(improved, value, best_torques)
        wavenumbers = np.where(improved, hand * np.exp(centre), wavenumbers)
    return best_torques, wavenumbers

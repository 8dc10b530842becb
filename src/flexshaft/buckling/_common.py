"""Shared pieces of the torsional buckling models: checks, stiffness, axial integrals, eigenvalues."""

from __future__ import annotations

from typing import Literal

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from flexshaft.laminate import Laminate, abd_matrices, transverse_shear_stiffness

__all__ = [
    "ShellTheory", "Kinematics", "shell_stiffness", "check_inputs", "axial_integrals", "default_terms",
    "extreme_torques", "THEORIES", "KINEMATICS",
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

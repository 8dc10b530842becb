"""Flexible-coupling element: springs between the two flanges of a shaft joint, and its hub.

A disc or diaphragm coupling joins the end node of one shaft piece (``a``) to the start node of
the next (``b``) at the same station. Both nodes carry ``[u, v, w, θ, β, γ]``; the element has
12 DOFs ``[a | b]``. The coupling is a set of springs on the relative motion of the flanges::

    V = ½ k_ax (u_b − u_a)² + ½ k_lat [(v_b − v_a)² + (w_b − w_a)²]
      + ½ k_t (θ_b − θ_a)² + ½ k_ang [(β_b − β_a)² + (γ_b − γ_a)²]

(axial, lateral/radial, torsional, angular in both bending planes). The angular stiffness is
the same about both bending axes (an axisymmetric disc pack), so the element is the same in
the rotating and the fixed frame. The hub (flanges, disc pack, bolts) is a rigid body of mass
m, diametral inertia I_d and polar inertia I_p, half on each flange node, with the gyroscopic
term of a disk (:func:`flexshaft.elements.inertia.disk_matrices`).

The angle between the two pieces, ``α = √((β_b − β_a)² + (γ_b − γ_a)²)``, is the coupling's
misalignment; the moment it transmits is ``k_ang α``.
"""

from __future__ import annotations

import numpy as np

from flexshaft.elements.inertia import disk_matrices

__all__ = ["COUPLING_FIELDS", "coupling_matrices", "coupling_stiffness", "relative_rotation_rows"]

#: Order of the per-direction stiffness vector of :func:`coupling_stiffness`.
COUPLING_FIELDS: tuple[str, ...] = ("u", "v", "w", "theta", "beta", "gamma")


def coupling_stiffness(axial: float, lateral: float, torsional: float, angular: float) -> np.ndarray:
    """Per-direction stiffness ``(k_u, k_v, k_w, k_θ, k_β, k_γ)`` [N/m, N m/rad] of a coupling."""
    return np.array([axial, lateral, lateral, torsional, angular, angular], dtype=float)


def relative_rotation_rows() -> np.ndarray:
    """Rows (6, 12): ``b − a`` for each of ``[u, v, w, θ, β, γ]`` on the element DOFs ``[a | b]``."""
    return np.hstack([-np.eye(6), np.eye(6)])


def coupling_matrices(stiffness, mass: float = 0.0, diametral_inertia: float = 0.0, polar_inertia: float = 0.0):
    """Stiffness, mass and gyroscopic matrices (12, 12) of a coupling on ``[a | b]``.

    Parameters
    ----------
    stiffness : array_like, shape (6,)
        ``(k_u, k_v, k_w, k_θ, k_β, k_γ)`` [N/m, N/m, N/m, N m/rad, N m/rad, N m/rad]
        (:func:`coupling_stiffness`).
    mass : float
        Hub mass m [kg], half on each flange.
    diametral_inertia, polar_inertia : float
        Hub I_d and I_p [kg m²], half on each flange.

    Returns
    -------
    K, M, G : ndarray
        Each (12, 12); ``K = Rᵀ diag(k) R`` with R of :func:`relative_rotation_rows`, M
        block-diagonal, G skew-symmetric per unit spin speed [kg m²].
    """
    k = np.asarray(stiffness, dtype=float)
    if k.shape != (6,):
        raise ValueError(f"stiffness: expected 6 values (u, v, w, theta, beta, gamma), got shape {k.shape}")
    R = relative_rotation_rows()
    K = R.T @ (k[:, None] * R)
    Mh, Gh = disk_matrices(mass / 2.0, diametral_inertia / 2.0, polar_inertia / 2.0)
    M = np.zeros((12, 12))
    G = np.zeros((12, 12))
    for block in (slice(0, 6), slice(6, 12)):
        M[block, block] = Mh
        G[block, block] = Gh
    return K, M, G

"""Lumped inertias: rigid disk on the shaft and the offset end mass on the boom tip.

End mass (thesis §2.2.4, eq. 2.37): the stabilizers, tail rotor and gearbox are a mass m at
offset ``e = (e_x, e_y, e_z)`` from the last boom node, ``r_m = r_b + θ_b × e``. With
``θ_b = (θ, β, γ)`` and ``r_b = (0, v, w)`` the kinetic energy ``½ m |ṙ_m|²`` gives
``M = m BᵀB`` on ``[v, w, θ, β, γ]`` with B of :func:`end_mass_kinematics`; the mass's own
rotary inertia adds to the rotation diagonal.
"""

from __future__ import annotations

import numpy as np

__all__ = ["disk_matrices", "end_mass_kinematics", "end_mass_matrix"]


def disk_matrices(mass: float, diametral_inertia: float, polar_inertia: float):
    """Mass and gyroscopic matrices of a rigid disk on a shaft node ``[u, v, w, θ, β, γ]``.

    Returns ``(M, G)``, each (6, 6); ``G[β, γ] = +I_p`` as in the shaft element.
    """
    M = np.diag([mass, mass, mass, polar_inertia, diametral_inertia, diametral_inertia])
    G = np.zeros((6, 6))
    G[4, 5], G[5, 4] = polar_inertia, -polar_inertia
    return M, G


def end_mass_kinematics(offset) -> np.ndarray:
    """B (3, 5): absolute displacement ``(x, y, z)`` of the mass from ``[v, w, θ, β, γ]``."""
    ex, ey, ez = (float(c) for c in offset)
    return np.array(
        [
            [0.0, 0.0, 0.0, ez, -ey],  # x: β e_z − γ e_y
            [1.0, 0.0, -ez, 0.0, ex],  # y: v + γ e_x − θ e_z
            [0.0, 1.0, ey, -ex, 0.0],  # z: w + θ e_y − β e_x
        ]
    )


def end_mass_matrix(mass: float, offset, inertia=(0.0, 0.0, 0.0)) -> np.ndarray:
    """5×5 inertia matrix of the end mass on the tip node ``[v, w, θ, β, γ]`` (eq. 2.37).

    Parameters
    ----------
    mass : float
        [kg].
    offset : sequence of 3 floats
        e = (e_x, e_y, e_z) from the boom tip node [m].
    inertia : sequence of 3 floats
        The mass's own (I_xx, I_yy, I_zz) about its centre of mass [kg m^2].
    """
    B = end_mass_kinematics(offset)
    M = mass * B.T @ B
    M[2:, 2:] += np.diag(np.asarray(inertia, dtype=float))
    return M

"""Bearing kinematics between arbitrary points of the shaft and the tailboom (thesis §2.2.3).

A bearing joins the shaft at ``x_s`` to the boom at ``x_b``; neither needs to be a node: the
displacement at the point is interpolated with the shape functions of the element containing
it (thesis eq. 2.34). The attachment point on the boom sits a height ``h`` above the boom's
neutral axis, so it moves by ``r_b + θ_b × (0, h, 0)``::

    u = −h γ_b,  v = v_b,  w = w_b + h θ_b,  β = β_b,  γ = γ_b

The relative displacement over ``(u, v, w, β, γ)`` is shaft minus attachment and the bearing
energy is ``½ Σ k_i rel_i²``. So boom bending loads the shaft axially and boom twist loads it
laterally.
"""

from __future__ import annotations

import numpy as np

from flexshaft.elements.boom import BOOM_COLUMNS

__all__ = ["RELATIVE_FIELDS", "attachment_transform", "point_rows", "relative_rows", "spring_matrix"]

_V_COLS = [1, 5, 7, 11]  # v-plane element columns [v1, γ1, v2, γ2]
_W_COLS = [2, 4, 8, 10]  # w-plane element columns [w1, β1, w2, β2]
_W_SIGN = (1.0, -1.0, 1.0, -1.0)

#: Components of the relative displacement a bearing acts on, in row order.
RELATIVE_FIELDS: tuple[str, ...] = ("u", "v", "w", "beta", "gamma")


def attachment_transform(h: float) -> np.ndarray:
    """Map boom-node motion ``[v, w, θ, β, γ]`` to attachment motion ``[u, v, w, β, γ]``."""
    T = np.zeros((5, 5))
    T[0, 4] = -h  # u = -h gamma
    T[1, 0] = 1.0  # v
    T[2, 1] = 1.0  # w
    T[2, 2] = h  # w += h theta
    T[3, 3] = 1.0  # beta
    T[4, 4] = 1.0  # gamma
    return T


def point_rows(xi: float, length: float) -> np.ndarray:
    """Rows ``(6, 12)`` giving ``[u, v, w, θ, β, γ]`` at local coordinate ``xi`` of an
    Euler-Bernoulli element (the shape functions of :func:`~flexshaft.elements.shape.beam_shape`
    with φ = 0, written out for one point: the bearings are evaluated at build time)."""
    x, L = float(xi), float(length)
    x2, x3 = x * x, x * x * x
    Nd = (1 - 3 * x2 + 2 * x3, L * (x - 2 * x2 + x3), 3 * x2 - 2 * x3, L * (x3 - x2))
    Nr = (6 * (x2 - x) / L, 1 - 4 * x + 3 * x2, 6 * (x - x2) / L, 3 * x2 - 2 * x)
    rows = np.zeros((6, 12))
    rows[0, (0, 6)] = 1 - x, x  # u
    rows[3, (3, 9)] = 1 - x, x  # θ
    rows[1, _V_COLS] = Nd  # v
    rows[5, _V_COLS] = Nr  # γ = dv/dx
    rows[2, _W_COLS] = np.multiply(Nd, _W_SIGN)  # w, with β = −dw/dx on the rotation columns
    rows[4, _W_COLS] = -np.multiply(Nr, _W_SIGN)  # β
    return rows


def relative_rows(shaft_xi: float, shaft_length: float, boom_xi=None, boom_length=None, h: float = 0.0) -> np.ndarray:
    """Relative-displacement rows of one bearing.

    Parameters
    ----------
    shaft_xi, shaft_length : float
        Local coordinate in [0, 1] and length [m] of the shaft element holding the point.
    boom_xi, boom_length : float or None
        The same for the boom element; ``None`` for a bearing to ground.
    h : float
        Height of the shaft axis above the boom's neutral axis [m].

    Returns
    -------
    ndarray
        ``(5, 12)`` over the shaft element DOFs, or ``(5, 22)`` over the shaft element DOFs
        followed by the boom element DOFs ``[v, w, θ, β, γ] × 2``.
    """
    rows_s = point_rows(shaft_xi, shaft_length)[[0, 1, 2, 4, 5]]
    if boom_xi is None:
        return rows_s
    rows_b = point_rows(boom_xi, boom_length)[1:, :][:, BOOM_COLUMNS]  # [v, w, θ, β, γ]
    return np.hstack([rows_s, -attachment_transform(h) @ rows_b])


def spring_matrix(rows: np.ndarray, coefficients) -> np.ndarray:
    """``Bᵀ diag(k) B``: stiffness (or damping) of the bearing on its element DOFs."""
    k = np.asarray(coefficients)
    return rows.T @ (k[:, None] * rows)

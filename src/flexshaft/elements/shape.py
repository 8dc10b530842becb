"""Shape functions of the two-node beam element, evaluated at arbitrary points.

One 12-DOF layout serves every element of the package; the tailboom element uses the same
functions with the axial columns dropped.

Local DOF order of a two-node element (docs/model.md, coordinates and DOFs)::

    [u1, v1, w1, theta1, beta1, gamma1, u2, v2, w2, theta2, beta2, gamma2]

u and theta are interpolated linearly. Bending uses the interdependent interpolation of
Reddy (1997): with the shear parameter ``phi = 12 EI / (kappa G A L^2)`` the functions are
exact for a Timoshenko element and reduce to the Hermite cubics of Euler-Bernoulli theory
when ``phi = 0`` (then ``gamma = dv/dx`` and ``beta = -dw/dx`` exactly).

References
----------
Reddy, J. N. (1997). On locking-free shear deformable beam finite elements. CMAME 149.
Nelson, H. D. (1980). A finite rotating shaft element using Timoshenko beam theory. J. Mech.
Des. 102.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

__all__ = ["FIELDS", "ShapeValues", "gauss_points", "beam_shape"]

#: Field names in the order of the 6 DOFs of a shaft node.
FIELDS: tuple[str, ...] = ("u", "v", "w", "theta", "beta", "gamma")


@dataclass(frozen=True)
class ShapeValues:
    """Shape-function rows at a set of points, each of shape ``(..., 12)``.

    ``N[f]`` gives the field ``f`` (one of :data:`FIELDS`) at the point; ``dudx``,
    ``dthetadx`` are the axial and twist strains; ``dbetadx``, ``dgammadx`` the curvatures;
    ``shear_v = dv/dx - gamma`` and ``shear_w = dw/dx + beta`` the transverse shear strains
    (identically zero when ``phi = 0``).
    """

    N: dict[str, np.ndarray]
    dudx: np.ndarray
    dthetadx: np.ndarray
    dvdx: np.ndarray
    dwdx: np.ndarray
    dbetadx: np.ndarray
    dgammadx: np.ndarray

    @property
    def shear_v(self) -> np.ndarray:
        return self.dvdx - self.N["gamma"]

    @property
    def shear_w(self) -> np.ndarray:
        return self.dwdx + self.N["beta"]


@functools.lru_cache(maxsize=16)
def _gauss(n: int) -> tuple[np.ndarray, np.ndarray]:
    x, w = np.polynomial.legendre.leggauss(n)
    x, w = 0.5 * (x + 1.0), 0.5 * w
    x.setflags(write=False)
    w.setflags(write=False)
    return x, w


def gauss_points(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre points and weights mapped to ``xi`` in [0, 1] (read-only arrays)."""
    return _gauss(int(n))


def _bending(xi: np.ndarray, L: np.ndarray, phi: np.ndarray):
    """Displacement and rotation functions of one bending plane (Reddy IIE).

    Returns ``(Nd, dNd, Nr, dNr)``, each ``(..., 4)`` over ``[d1, r1, d2, r2]`` where d is the
    deflection and r the cross-section rotation (``r = dd/dx`` when ``phi = 0``).
    """
    xi = np.asarray(xi, dtype=float)
    L = np.asarray(L, dtype=float)[..., None]
    phi = np.asarray(phi, dtype=float)[..., None]
    mu = 1.0 / (1.0 + phi)
    x2, x3 = xi * xi, xi * xi * xi
    Nd = np.stack(
        np.broadcast_arrays(
            mu * (1 - 3 * x2 + 2 * x3 + phi * (1 - xi)),
            mu * L * (xi - 2 * x2 + x3 + 0.5 * phi * (xi - x2)),
            mu * (3 * x2 - 2 * x3 + phi * xi),
            mu * L * (-x2 + x3 - 0.5 * phi * (xi - x2)),
        ),
        axis=-1,
    )
    dNd = np.stack(
        np.broadcast_arrays(
            mu * (-6 * xi + 6 * x2 - phi) / L,
            mu * (1 - 4 * xi + 3 * x2 + 0.5 * phi * (1 - 2 * xi)),
            mu * (6 * xi - 6 * x2 + phi) / L,
            mu * (-2 * xi + 3 * x2 - 0.5 * phi * (1 - 2 * xi)),
        ),
        axis=-1,
    )
    Nr = np.stack(
        np.broadcast_arrays(
            mu * 6 * (x2 - xi) / L,
            mu * (1 - 4 * xi + 3 * x2 + phi * (1 - xi)),
            mu * 6 * (xi - x2) / L,
            mu * (-2 * xi + 3 * x2 + phi * xi),
        ),
        axis=-1,
    )
    dNr = np.stack(
        np.broadcast_arrays(
            mu * 6 * (2 * xi - 1) / L**2,
            mu * (-4 + 6 * xi - phi) / L,
            mu * 6 * (1 - 2 * xi) / L**2,
            mu * (-2 + 6 * xi + phi) / L,
        ),
        axis=-1,
    )
    return Nd, dNd, Nr, dNr


def beam_shape(xi, L, phi=0.0) -> ShapeValues:
    """Shape functions of the 12-DOF element at local coordinates ``xi`` in [0, 1].

    Parameters
    ----------
    xi : array_like
        Local coordinates, any shape broadcastable with ``L[..., None]``-style leading axes.
    L : array_like
        Element lengths [m]; a leading axis of elements broadcasts against ``xi``.
    phi : array_like
        Shear parameter ``12 EI / (kappa G A L^2)`` [-]; 0 for Euler-Bernoulli.

    Returns
    -------
    ShapeValues
        Rows of shape ``broadcast(xi, L, phi) + (12,)``.
    """
    xi = np.asarray(xi, dtype=float)
    L = np.asarray(L, dtype=float)
    Nd, dNd, Nr, dNr = _bending(xi, L, phi)
    shape = Nd.shape[:-1]
    Lb = np.broadcast_to(L[..., None], shape)
    xib = np.broadcast_to(xi, shape)

    def row(cols, vals):
        out = np.zeros(shape + (12,))
        for c, v in zip(cols, vals):
            out[..., c] = v
        return out

    lin = (1.0 - xib, xib)
    dlin = (-1.0 / Lb, 1.0 / Lb)
    # v-plane: [v1, gamma1, v2, gamma2] at columns [1, 5, 7, 11]
    v_cols = (1, 5, 7, 11)
    # w-plane: w with rotation r = dw/dx = -beta, so beta columns take a minus sign.
    w_cols = (2, 4, 8, 10)
    w_sign = np.array([1.0, -1.0, 1.0, -1.0])
    N = {
        "u": row((0, 6), lin),
        "theta": row((3, 9), lin),
        "v": row(v_cols, np.moveaxis(Nd, -1, 0)),
        "gamma": row(v_cols, np.moveaxis(Nr, -1, 0)),
        "w": row(w_cols, np.moveaxis(Nd * w_sign, -1, 0)),
        "beta": row(w_cols, np.moveaxis(-Nr * w_sign, -1, 0)),
    }
    return ShapeValues(
        N=N,
        dudx=row((0, 6), dlin),
        dthetadx=row((3, 9), dlin),
        dvdx=row(v_cols, np.moveaxis(dNd, -1, 0)),
        dwdx=row(w_cols, np.moveaxis(dNd * w_sign, -1, 0)),
        dgammadx=row(v_cols, np.moveaxis(dNr, -1, 0)),
        dbetadx=row(w_cols, np.moveaxis(-dNr * w_sign, -1, 0)),
    )

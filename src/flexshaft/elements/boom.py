"""10-DOF tapered thin-walled elliptical tailboom element (thesis §2.2.2).

Node DOFs ``[v, w, theta, beta, gamma]`` (no axial DOF). Bending in the v–γ plane uses
``E I_z`` (``I_z = t ∮ y² ds``, y vertical), in the w–β plane ``E I_y``; torsion uses Bredt's
``G J = 4 G A_m² t / ∮ds``. Section properties vary along the element and are integrated with
Gauss points, so tapered members converge as the mesh is refined.

Complex moduli (``E(1 + iη)``) give a complex stiffness: structural damping of the boom.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.elements.shape import beam_shape, gauss_points

__all__ = ["BOOM_COLUMNS", "EllipseSection", "ellipse_section", "boom_element_matrices"]

#: Columns of the 12-DOF layout kept by the 10-DOF tailboom element (u1 and u2 dropped).
BOOM_COLUMNS = np.array([1, 2, 3, 4, 5, 7, 8, 9, 10, 11])

_N_GAUSS = 6
_N_PERIMETER = 128  # trapezoidal rule on a periodic integrand: exponential convergence (1e-12 at 6:1 axes)


@dataclass(frozen=True)
class EllipseSection:
    """Thin-walled ellipse properties (arrays over stations) [SI]."""

    area: np.ndarray
    I_z: np.ndarray  # about z: resists vertical (v) bending [m^4]
    I_y: np.ndarray  # about y: resists lateral (w) bending [m^4]
    torsion_constant: np.ndarray  # Bredt J [m^4]
    perimeter: np.ndarray


def ellipse_section(vertical_semi_axis, lateral_semi_axis, wall_thickness) -> EllipseSection:
    """Section properties of a thin-walled elliptical tube (mid-line semi-axes).

    Parameters
    ----------
    vertical_semi_axis, lateral_semi_axis : array_like
        Mid-line semi-axes a (along y) and b (along z) [m].
    wall_thickness : array_like
        Wall thickness t [m].
    """
    a = np.asarray(vertical_semi_axis, dtype=float)[..., None]
    b = np.asarray(lateral_semi_axis, dtype=float)[..., None]
    t = np.asarray(wall_thickness, dtype=float)
    psi = np.linspace(0.0, 2 * np.pi, _N_PERIMETER, endpoint=False)
    y, z = a * np.sin(psi), b * np.cos(psi)
    ds = np.sqrt((a * np.cos(psi)) ** 2 + (b * np.sin(psi)) ** 2) * (2 * np.pi / _N_PERIMETER)
    perimeter = ds.sum(-1)
    enclosed = np.pi * a[..., 0] * b[..., 0]
    return EllipseSection(
        area=t * perimeter,
        I_z=t * (y * y * ds).sum(-1),
        I_y=t * (z * z * ds).sum(-1),
        torsion_constant=4 * enclosed**2 * t / perimeter,
        perimeter=perimeter,
    )


def boom_element_matrices(x_nodes, section_at, youngs_modulus: complex, shear_modulus: complex, density: float):
    """Mass and stiffness of tailboom elements between consecutive ``x_nodes``.

    Parameters
    ----------
    x_nodes : array_like
        Node stations [m], increasing, shape (nel + 1,).
    section_at : callable
        ``section_at(x) -> EllipseSection`` for an array of stations [m].
    youngs_modulus, shear_modulus : complex
        E and G [Pa], complex for structural damping.
    density : float
        [kg/m^3].

    Returns
    -------
    M, K : ndarray
        (nel, 10, 10); M real, K complex, DOFs ``[v, w, θ, β, γ] × 2``.
    """
    x = np.asarray(x_nodes, dtype=float)
    L = np.diff(x)
    xi, w = gauss_points(_N_GAUSS)
    sec = section_at(x[:-1, None] + L[:, None] * xi)
    s = beam_shape(xi, L)
    c = BOOM_COLUMNS

    def integ(a, b, coef):
        return np.einsum("epi,epj,ep->eij", a[..., c], b[..., c], coef * w * L[:, None])

    E, G = complex(youngs_modulus), complex(shear_modulus)
    K = E * (integ(s.dgammadx, s.dgammadx, sec.I_z) + integ(s.dbetadx, s.dbetadx, sec.I_y))
    K = K + G * integ(s.dthetadx, s.dthetadx, sec.torsion_constant)
    N = s.N
    M = density * (
        integ(N["v"], N["v"], sec.area)
        + integ(N["w"], N["w"], sec.area)
        + integ(N["theta"], N["theta"], sec.I_y + sec.I_z)
        + integ(N["beta"], N["beta"], sec.I_y)
        + integ(N["gamma"], N["gamma"], sec.I_z)
    )
    return M, K

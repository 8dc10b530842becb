"""12-DOF rotating shaft element: uniform hollow circular tube (thesis §2.2.1).

Matrices come from Gauss integration of the energy expressions with the shape functions of
:mod:`flexshaft.elements.shape`, vectorized over elements:

* stiffness  ``K = E A ∫u'u' + G J ∫θ'θ' + E I ∫(γ'γ' + β'β') + κ G A ∫(s_v s_v + s_w s_w)``
* mass       ``M = ρA ∫(uu + vv + ww) + ρJ ∫θθ + ρI ∫(ββ + γγ)``
* gyroscopic ``G = ρJ ∫(βᵀγ − γᵀβ)`` so that ``M q̈ + Ω G q̇ + K q = Q``.

The sign of G follows from the angular momentum of a spinning slice: with the spin axis tilted
to ``(γ, −β)`` the moments are ``M_β = I_d β̈ + I_p Ω γ̇`` and ``M_γ = I_d γ̈ − I_p Ω β̇``, which
makes the forward-whirl frequency rise with speed (checked in the tests).

E and G may be complex (``E' + iE''``): the hysteretic loss of the composite is then carried by
a complex stiffness matrix (thesis §2.1.2). The shear parameter of the Timoshenko option uses
the storage moduli.

References
----------
Nelson, H. D. (1980). J. Mech. Des. 102, 793-803 (element and gyroscopic matrix).
Cowper, G. R. (1966). The shear coefficient in Timoshenko's beam theory. J. Appl. Mech. 33.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.elements.shape import beam_shape, gauss_points

__all__ = ["TubeSection", "cowper_shear_coefficient", "shaft_element_matrices"]

_N_GAUSS = 4  # exact for the degree-6 products of cubic shape functions


@dataclass(frozen=True)
class TubeSection:
    """Hollow circular section.

    Parameters
    ----------
    outer_diameter : float
        D_o [m].
    inner_diameter : float
        D_i [m], 0 for a solid section.
    """

    outer_diameter: float
    inner_diameter: float

    @property
    def area(self) -> float:
        """Cross-sectional area A_c [m^2]."""
        return np.pi * (self.outer_diameter**2 - self.inner_diameter**2) / 4.0

    @property
    def second_moment(self) -> float:
        """Diametral second moment of area I [m^4]."""
        return np.pi * (self.outer_diameter**4 - self.inner_diameter**4) / 64.0

    @property
    def polar_moment(self) -> float:
        """Polar second moment of area J = 2I [m^4]."""
        return 2.0 * self.second_moment


def cowper_shear_coefficient(section: TubeSection, poisson: float) -> float:
    """Timoshenko shear coefficient of a hollow circle (Cowper 1966, table 1)."""
    m2 = (section.inner_diameter / section.outer_diameter) ** 2
    nu = poisson
    return 6 * (1 + nu) * (1 + m2) ** 2 / ((7 + 6 * nu) * (1 + m2) ** 2 + (20 + 12 * nu) * m2)


def _integrate(a: np.ndarray, b: np.ndarray, weights: np.ndarray, L: np.ndarray) -> np.ndarray:
    """``L ∫ aᵀ c b dξ`` with per-point coefficients ``weights`` of shape (nel, npts)."""
    return np.einsum("epi,epj,ep->eij", a, b, weights * L[:, None])


def shaft_element_matrices(
    lengths,
    section: TubeSection,
    youngs_modulus: complex,
    shear_modulus: complex,
    density: float,
    shear_coefficient: float | None = None,
):
    """Mass, stiffness and gyroscopic matrices of uniform shaft elements.

    Parameters
    ----------
    lengths : array_like
        Element lengths [m], shape (nel,).
    section : TubeSection
        Cross-section.
    youngs_modulus, shear_modulus : complex
        Equivalent E*, G* [Pa]; complex values give a complex stiffness.
    density : float
        Mass density [kg/m^3].
    shear_coefficient : float or None
        Timoshenko shear coefficient κ; ``None`` for Euler-Bernoulli (the thesis default).

    Returns
    -------
    M, K, G : ndarray
        Shapes (nel, 12, 12); M and G real, K complex. G is per unit spin speed [kg m^2/m·m].
    """
    L = np.atleast_1d(np.asarray(lengths, dtype=float))
    A, I, J = section.area, section.second_moment, section.polar_moment
    E, Gs = complex(youngs_modulus), complex(shear_modulus)
    if shear_coefficient is None:
        phi = np.zeros_like(L)
    else:
        phi = 12.0 * E.real * I / (shear_coefficient * Gs.real * A * L**2)
    xi, w = gauss_points(_N_GAUSS)
    s = beam_shape(xi, L, phi)
    ones = np.broadcast_to(w, (L.size, w.size))

    K = (E * A) * _integrate(s.dudx, s.dudx, ones, L).astype(complex)
    K += (Gs * J) * _integrate(s.dthetadx, s.dthetadx, ones, L)
    K += (E * I) * (_integrate(s.dgammadx, s.dgammadx, ones, L) + _integrate(s.dbetadx, s.dbetadx, ones, L))
    if shear_coefficient is not None:
        kGA = shear_coefficient * Gs * A
        K += kGA * (_integrate(s.shear_v, s.shear_v, ones, L) + _integrate(s.shear_w, s.shear_w, ones, L))

    N = s.N
    M = density * A * sum(_integrate(N[f], N[f], ones, L) for f in ("u", "v", "w"))
    M += density * J * _integrate(N["theta"], N["theta"], ones, L)
    M += density * I * (_integrate(N["beta"], N["beta"], ones, L) + _integrate(N["gamma"], N["gamma"], ones, L))

    Gb = density * J * _integrate(N["beta"], N["gamma"], ones, L)
    G = Gb - np.swapaxes(Gb, -1, -2)
    return M, K, G

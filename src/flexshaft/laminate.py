"""Classical lamination theory with complex (hysteretic) moduli.

A :class:`Lamina` (orthotropic ply, plane stress) stacked into a :class:`Laminate` gives the
A, B, D stiffness (thesis eq. 2.1-2.3), the equivalent shaft moduli (eq. 2.4: axial with a free
hoop, N_y = 0, and shear) and the ply strains and stresses of the strength check (eq. 2.46-2.47).

Conventions
-----------
* x is the shaft axis, y circumferential, z the outward normal. Ply angles go from x towards y,
  in [rad] inside the package, in degrees only in :func:`parse_layup` (the edge).
* Plies are listed inner to outer; ``z`` is measured from the mid-surface, positive outward.
* Shear strains are engineering strains (gamma = 2 epsilon_12); the transformation is the
  standard one of Jones (1999, sec. 2.6) and Daniel & Ishai (2006, sec. 4.4).
* Moduli may be complex, E* = E'(1 + i eta): A, B, D and the equivalent moduli are then complex.
  Ply stresses for strength use the storage (real) part (docs/model.md, forced response and strength).

References
----------
Ocalan, M. (2002). MS thesis, Penn State, eq. 2.1-2.4 and 2.46-2.47.
Jones, R. M. (1999). *Mechanics of Composite Materials*, 2nd ed., Taylor & Francis, ch. 2 and 4.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from flexshaft.design.layup import parse_layup
from flexshaft.design.materials import DEFAULT_NU_23, DEFAULT_SHEAR_CORRECTION

__all__ = [
    "Lamina",
    "Laminate",
    "parse_layup",
    "reduced_stiffness",
    "strain_transformation",
    "transformed_stiffness",
    "abd_matrices",
    "equivalent_moduli",
    "equivalent_density",
    "hoop_strain_free",
    "ply_strains",
    "ply_stresses",
    "transverse_shear_stiffness",
    "membrane_strains",
    "spin_hoop_resultant",
    "thermal_ply_stresses",
    "DEFAULT_NU_23",
    "DEFAULT_SHEAR_CORRECTION",
]


def _check_positive(name: str, value: complex) -> None:
    if not np.isfinite(value) or not np.real(value) > 0.0:
        raise ValueError(f"{name} must be finite with a positive storage part, got {value!r}")


@dataclass(frozen=True)
class Lamina:
    """Orthotropic ply in plane stress, with possibly complex moduli.

    Parameters
    ----------
    E_L : complex
        Longitudinal (fibre-direction) Young's modulus [Pa]; E' + iE''.
    E_T : complex
        Transverse Young's modulus [Pa].
    G_LT : complex
        In-plane shear modulus [Pa].
    nu_LT : float
        Major Poisson ratio [-] (strain in T per strain in L under stress along L).
    density : float
        Mass density [kg/m^3].
    G_13 : complex, optional
        Transverse shear modulus in the fibre-thickness plane [Pa]; default G_LT (a
        transversely isotropic ply: the 1-3 plane is equivalent to the 1-2 plane).
    G_23 : complex, optional
        Transverse shear modulus across the fibres [Pa]; default E_T / (2 (1 + nu_23)) with
        nu_23 = :data:`DEFAULT_NU_23` = 0.5, i.e. E_T / 3 (typical of polymer-matrix plies; a
        nearly incompressible elastomer matrix pushes nu_23 towards 1, i.e. E_T / 4). The design
        schema also requires nu_23 = E_T/(2 G_23) - 1 < 1 - 2 nu_LT nu_TL (a positive-definite
        transversely isotropic ply); here only G_13, G_23 > 0 are checked, so that the shell
        models can be driven to their limits.
    shear_correction : float
        Transverse shear correction factor k in (0, 1] [-]; default 5/6.
    alpha_L, alpha_T : float
        Coefficients of thermal expansion along and across the fibres [1/K]; default 0 (no
        thermal strain).
    """

    E_L: complex
    E_T: complex
    G_LT: complex
    nu_LT: float
    density: float
    G_13: complex | None = None
    G_23: complex | None = None
    shear_correction: float = DEFAULT_SHEAR_CORRECTION
    alpha_L: float = 0.0
    alpha_T: float = 0.0

    def __post_init__(self) -> None:
        for name in ("E_L", "E_T", "G_LT"):
            _check_positive(name, getattr(self, name))
        _check_positive("density", self.density)
        nu_TL = self.nu_LT * np.real(self.E_T) / np.real(self.E_L)
        if not np.isfinite(self.nu_LT) or not self.nu_LT * nu_TL < 1.0:
            limit = float(np.sqrt(np.real(self.E_L) / np.real(self.E_T)))
            raise ValueError(
                f"nu_LT = {self.nu_LT!r} makes the ply stiffness indefinite; "
                f"allowed |nu_LT| < sqrt(E_L/E_T) = {limit:.4g}"
            )
        if self.G_13 is None:
            object.__setattr__(self, "G_13", self.G_LT)
        if self.G_23 is None:
            object.__setattr__(self, "G_23", self.E_T / (2.0 * (1.0 + DEFAULT_NU_23)))
        for name in ("G_13", "G_23"):
            _check_positive(name, getattr(self, name))
        if not np.isfinite(self.shear_correction) or not 0.0 < self.shear_correction <= 1.0:
            raise ValueError(f"shear_correction must lie in (0, 1], got {self.shear_correction!r}")
        for name in ("alpha_L", "alpha_T"):
            if not np.isfinite(getattr(self, name)):
                raise ValueError(
                    f"{name} must be a finite thermal expansion coefficient [1/K], got {getattr(self, name)!r}"
                )

    @classmethod
    def from_loss_factors(
        cls,
        E_L: float,
        E_T: float,
        G_LT: float,
        nu_LT: float,
        density: float,
        loss_E_L: float = 0.0,
        loss_E_T: float = 0.0,
        loss_G_LT: float = 0.0,
        *,
        G_13: float | None = None,
        G_23: float | None = None,
        shear_correction: float = DEFAULT_SHEAR_CORRECTION,
        alpha_L: float = 0.0,
        alpha_T: float = 0.0,
    ) -> Lamina:
        """Build a lamina from storage moduli [Pa] and loss factors [-], E* = E'(1 + i eta).

        ``G_13`` and ``G_23`` [Pa] are storage values (None: the defaults of :class:`Lamina`); they
        take the loss factor of G_LT and E_T respectively. ``shear_correction`` [-], ``alpha_L``,
        ``alpha_T`` [1/K] as in :class:`Lamina`.
        """
        for name, eta in (("loss_E_L", loss_E_L), ("loss_E_T", loss_E_T), ("loss_G_LT", loss_G_LT)):
            if not np.isfinite(eta) or eta < 0.0:
                raise ValueError(f"{name} must be a finite loss factor >= 0, got {eta!r}")
        return cls(
            E_L * (1 + 1j * loss_E_L),
            E_T * (1 + 1j * loss_E_T),
            G_LT * (1 + 1j * loss_G_LT),
            float(nu_LT),
            float(density),
            G_13=None if G_13 is None else G_13 * (1 + 1j * loss_G_LT),
            G_23=None if G_23 is None else G_23 * (1 + 1j * loss_E_T),
            shear_correction=float(shear_correction),
            alpha_L=float(alpha_L),
            alpha_T=float(alpha_T),
        )

    @property
    def transverse_shear_moduli(self) -> tuple[complex, complex]:
        """(G_13, G_23) [Pa], the defaults filled in: never None once constructed."""
        assert self.G_13 is not None and self.G_23 is not None  # __post_init__ sets them
        return self.G_13, self.G_23

    @property
    def storage(self) -> Lamina:
        """The same lamina with its storage (real) moduli only."""
        G13, G23 = self.transverse_shear_moduli
        return replace(
            self, E_L=self.E_L.real, E_T=self.E_T.real, G_LT=self.G_LT.real, G_13=np.real(G13), G_23=np.real(G23)
        )

    @classmethod
    def isotropic(cls, E: float, G: float, density: float, loss_factor: float = 0.0, alpha: float = 0.0) -> Lamina:
        """Isotropic material as a lamina: E_L = E_T = E [Pa], G_LT = G_13 = G_23 = G [Pa].

        nu = E/(2G) - 1; ``density`` [kg/m^3]; ``loss_factor`` [-] multiplies every modulus by
        (1 + i eta); ``alpha`` [1/K] is the thermal expansion coefficient.
        """
        nu = E / (2.0 * G) - 1.0
        if not -1.0 < nu < 0.5:
            raise ValueError(f"E/(2G) - 1 = {nu:.4g} is not a Poisson ratio in (-1, 0.5); check E and G")
        return cls.from_loss_factors(
            E, E, G, nu, density, loss_factor, loss_factor, loss_factor, G_13=G, G_23=G, alpha_L=alpha, alpha_T=alpha
        )


def _read_only(values: ArrayLike) -> NDArray[np.float64]:
    array = np.array(values, dtype=float, ndmin=1)
    array.setflags(write=False)
    return array


@dataclass(frozen=True, eq=False)
class Laminate:
    """A stack of plies of one lamina.

    Parameters
    ----------
    angles : array_like
        Ply angles from the x axis towards y [rad], inner to outer.
    thicknesses : array_like
        Ply thicknesses [m], same length as ``angles``.
    lamina : Lamina
        The ply material.
    """

    angles: NDArray[np.float64]
    thicknesses: NDArray[np.float64]
    lamina: Lamina = field(repr=False)

    def __post_init__(self) -> None:
        angles = _read_only(self.angles)
        thicknesses = _read_only(self.thicknesses)
        if angles.ndim != 1 or angles.shape != thicknesses.shape:
            raise ValueError(
                f"angles and thicknesses must be 1-D of equal length, got shapes {angles.shape} and {thicknesses.shape}"
            )
        if not np.all(np.isfinite(angles)) or np.any(np.abs(angles) > np.pi / 2 + 1e-12):
            raise ValueError(f"ply angles must be finite and within [-pi/2, pi/2] rad, got {angles}")
        if not np.all(np.isfinite(thicknesses)) or np.any(thicknesses <= 0.0):
            raise ValueError(f"ply thicknesses must be positive and finite [m], got {thicknesses}")
        object.__setattr__(self, "angles", angles)
        object.__setattr__(self, "thicknesses", thicknesses)

    @classmethod
    def from_layup(cls, layup: str | Sequence[float], thickness: float, lamina: Lamina) -> Laminate:
        """Equal plies sharing the total ``thickness`` [m], from a layup in DEGREES.

        ``layup`` is a string for :func:`parse_layup` (e.g. ``"(55/-55/0/0)s"``) or a sequence of
        angles [deg], inner to outer.
        """
        degrees = parse_layup(layup) if isinstance(layup, str) else tuple(float(a) for a in layup)
        _check_positive("thickness", thickness)
        if not degrees or max(abs(a) for a in degrees) > 90.0:
            raise ValueError(f"layup needs at least one ply with angles in [-90, 90] deg, got {degrees}")
        n_plies = len(degrees)
        return cls(np.radians(degrees), np.full(n_plies, thickness / n_plies), lamina)

    @property
    def storage(self) -> Laminate:
        """The same stack with the storage (real) moduli of the lamina."""
        return Laminate(self.angles, self.thicknesses, self.lamina.storage)

    @property
    def thickness(self) -> float:
        """Total thickness [m]."""
        return float(self.thicknesses.sum())

    @property
    def z_interfaces(self) -> NDArray[np.float64]:
        """Ply interface coordinates from the mid-surface [m], inner to outer, n_plies + 1."""
        return np.concatenate(([0.0], np.cumsum(self.thicknesses))) - 0.5 * self.thickness


# --------------------------------------------------------------------------------------------
# Stiffness


def reduced_stiffness(lamina: Lamina) -> NDArray[np.complex128]:
    """Plane-stress reduced stiffness Q of a ply in its material axes (Jones eq. 2.61).

    Returns
    -------
    ndarray, shape (3, 3), complex
        Q [Pa] relating (sigma_1, sigma_2, tau_12) to (eps_1, eps_2, gamma_12).
    """
    nu_TL = lamina.nu_LT * lamina.E_T / lamina.E_L
    denominator = 1.0 - lamina.nu_LT * nu_TL
    Q11 = lamina.E_L / denominator
    Q22 = lamina.E_T / denominator
    Q12 = lamina.nu_LT * lamina.E_T / denominator
    return np.array([[Q11, Q12, 0.0], [Q12, Q22, 0.0], [0.0, 0.0, lamina.G_LT]], dtype=complex)


def strain_transformation(angles: ArrayLike) -> NDArray[np.float64]:
    """Engineering-strain transformation T_eps (n, 3, 3) from laminate to ply axes.

    (eps_1, eps_2, gamma_12) = T_eps(alpha) (eps_x, eps_y, gamma_xy) for ``angles`` (n,) [rad];
    thesis eq. 2.3.2 with the Reuter matrix folded in.
    """
    alpha = np.atleast_1d(np.asarray(angles, dtype=float))
    c, s = np.cos(alpha), np.sin(alpha)
    cc, ss, cs = c * c, s * s, c * s
    rows = ([cc, ss, cs], [ss, cc, -cs], [-2.0 * cs, 2.0 * cs, cc - ss])
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def transformed_stiffness(Q: ArrayLike, angles: ArrayLike) -> NDArray[np.complex128]:
    """Transformed reduced stiffness Q_bar = T_eps^T Q T_eps of each ply (thesis eq. 2.3).

    Q (3, 3) [Pa] in material axes and ``angles`` (n,) [rad] give Q_bar (n, 3, 3) [Pa] in
    laminate axes (engineering shear strain); equal to Jones eq. 2.84 term by term.
    """
    T = strain_transformation(angles)
    return np.einsum("nji,jk,nkl->nil", T, np.asarray(Q, dtype=complex), T)


def abd_matrices(laminate: Laminate) -> tuple[NDArray[np.complex128], NDArray[np.complex128], NDArray[np.complex128]]:
    """Extensional A [N/m], coupling B [N], bending D [N m] stiffness (thesis eq. 2.1-2.3).

    A = sum Q_bar_k (z_k - z_{k-1}), B = 1/2 sum Q_bar_k (z_k^2 - z_{k-1}^2),
    D = 1/3 sum Q_bar_k (z_k^3 - z_{k-1}^3), z from the mid-surface, positive outward.
    """
    Q_bar = transformed_stiffness(reduced_stiffness(laminate.lamina), laminate.angles)
    z = laminate.z_interfaces
    weights = np.stack([np.diff(z), np.diff(z**2) / 2.0, np.diff(z**3) / 3.0])
    A, B, D = np.einsum("pn,nij->pij", weights, Q_bar)
    return A, B, D


def transverse_shear_stiffness(laminate: Laminate) -> NDArray[np.complex128]:
    """Transverse shear stiffness of first-order shear deformation theory [N/m].

    Each ply's shear moduli G_13 (fibre-thickness plane) and G_23 (across the fibres) rotate with
    the ply angle alpha like a vector (Reddy 2004, eq. 3.3.9; Jones 1999, sec. 4.6):
    Q_55 = G_13 cos^2 + G_23 sin^2, Q_44 = G_13 sin^2 + G_23 cos^2, Q_45 = (G_13 - G_23) cos sin,
    and A_ij = k sum Q_ij,k (z_k - z_{k-1}) with the lamina's shear correction factor k.

    Returns
    -------
    ndarray, shape (2, 2), complex
        [[A55, A45], [A45, A44]] relating (Q_x, Q_y) to the transverse shear strains
        (gamma_xz, gamma_yz) [-] (x axial, y circumferential, z outward).
    """
    lamina = laminate.lamina
    c, s = np.cos(laminate.angles), np.sin(laminate.angles)
    h = laminate.thicknesses
    G13, G23 = (complex(G) for G in lamina.transverse_shear_moduli)
    A55 = np.sum((G13 * c * c + G23 * s * s) * h)
    A44 = np.sum((G13 * s * s + G23 * c * c) * h)
    A45 = np.sum((G13 - G23) * c * s * h)
    return lamina.shear_correction * np.array([[A55, A45], [A45, A44]], dtype=np.complex128)


def equivalent_moduli(laminate: Laminate) -> tuple[complex, complex]:
    """Equivalent axial and shear moduli of the shaft wall (thesis eq. 2.4).

    With a = A^-1 and wall thickness t: E* = 1/(t a11) (axial, free hoop N_y = 0 and
    N_xy = 0) and G* = 1/(t a66).

    Returns
    -------
    E_x, G_xy : complex
        Equivalent Young's and shear moduli [Pa]; complex when the lamina moduli are.
    """
    A, _, _ = abd_matrices(laminate)
    compliance = np.linalg.inv(A)
    t = laminate.thickness
    return complex(1.0 / (t * compliance[0, 0])), complex(1.0 / (t * compliance[2, 2]))


def equivalent_density(laminate: Laminate) -> float:
    """Thickness-averaged density of the laminate [kg/m^3]."""
    return float(laminate.lamina.density)


# --------------------------------------------------------------------------------------------
# Ply strains and stresses


def hoop_strain_free(laminate: Laminate, eps_x: ArrayLike, gamma_xy: ArrayLike) -> NDArray[np.float64]:
    """Hoop strain [-] for a zero hoop stress resultant, N_y = 0 (thesis eq. 2.46).

    eps_y = -(A12 eps_x + A26 gamma_xy) / A22 with the storage A; ``eps_x`` and the engineering
    shear strain ``gamma_xy`` [-] broadcast together.
    """
    A = abd_matrices(laminate.storage)[0].real
    return -(A[0, 1] * np.asarray(eps_x, dtype=float) + A[1, 2] * np.asarray(gamma_xy, dtype=float)) / A[1, 1]


def ply_strains(laminate: Laminate, eps_x: ArrayLike, eps_y: ArrayLike, gamma_xy: ArrayLike) -> NDArray[np.float64]:
    """Strains of every ply in its material axes (thin wall: one laminate strain for all plies).

    ``eps_x, eps_y, gamma_xy`` [-] (engineering shear) broadcast to a shape S; the result has
    shape S + (n_plies, 3) holding (eps_1, eps_2, gamma_12) [-].
    """
    arrays = np.broadcast_arrays(*(np.asarray(e, dtype=float) for e in (eps_x, eps_y, gamma_xy)))
    strains = np.stack(arrays, axis=-1)
    return np.tensordot(strains, strain_transformation(laminate.angles), axes=([-1], [2]))


def ply_stresses(laminate: Laminate, eps_x: ArrayLike, eps_y: ArrayLike, gamma_xy: ArrayLike) -> NDArray[np.float64]:
    """Stresses of every ply in its material axes from the storage moduli (thesis eq. 2.47).

    ``eps_x, eps_y, gamma_xy`` [-] (engineering shear) broadcast to a shape S; the result has
    shape S + (n_plies, 3) holding (sigma_1, sigma_2, tau_12) [Pa].
    """
    Q = reduced_stiffness(laminate.lamina.storage).real
    stress_per_strain = np.einsum("ij,kjl->kil", Q, strain_transformation(laminate.angles))
    arrays = np.broadcast_arrays(*(np.asarray(e, dtype=float) for e in (eps_x, eps_y, gamma_xy)))
    return np.tensordot(np.stack(arrays, axis=-1), stress_per_strain, axes=([-1], [2]))


def membrane_strains(laminate: Laminate, resultants: ArrayLike) -> NDArray[np.float64]:
    """Mid-surface strains (eps_x, eps_y, gamma_xy) [-] under membrane resultants alone.

    ``resultants`` (..., 3) holds (N_x, N_y, N_xy) [N/m]; the strains are A^-1 N with the storage
    A (no curvature: a closed thin tube wall, symmetric laminate).
    """
    A = abd_matrices(laminate.storage)[0].real
    return np.linalg.solve(A, np.asarray(resultants, dtype=float)[..., None])[..., 0]


def spin_hoop_resultant(density: float, thickness: float, radius: float, speed: ArrayLike) -> NDArray[np.float64]:
    """Hoop stress resultant N_y [N/m] of a thin tube spinning at ``speed`` [rad/s], free ends.

    Radial equilibrium of a ring element of mass rho t per unit area at radius r [m] spinning at
    Omega: the hoop force per unit length supplies the centripetal force, N_y / r = rho t Omega^2 r,
    so N_y = rho t Omega^2 r^2 (thin ring, Timoshenko & Goodier 1970 sec. 32 for t << r). Free ends
    mean N_x = N_xy = 0 from the spin. ``density`` [kg/m^3], ``thickness`` [m].
    """
    return density * thickness * np.asarray(speed, dtype=float) ** 2 * radius**2


def thermal_ply_stresses(laminate: Laminate, temperature_change: float) -> NDArray[np.float64]:
    """Residual ply stresses [Pa] of a free laminate after a uniform temperature change [K].

    Each ply would expand by (alpha_L, alpha_T, 0) dT in its material axes; the plies are bonded,
    so the laminate takes the strain eps0 = A^-1 N_T with N_T = sum Q_bar_k alpha_bar_k dT t_k
    (N = 0: no external resultant; no curvature: the closed tube wall cannot curl, and B = 0 for
    a symmetric laminate) and each ply carries Q (T_eps eps0 - alpha dT) (Jones 1999, sec. 4.5;
    Daniel & Ishai 2006, sec. 10.4). Storage moduli, elastic (no relaxation of the matrix).

    Returns
    -------
    ndarray, shape (n_plies, 3)
        (sigma_1, sigma_2, tau_12) [Pa] of each ply in its material axes.
    """
    storage = laminate.storage
    lamina = storage.lamina
    free = np.array([lamina.alpha_L, lamina.alpha_T, 0.0]) * float(temperature_change)
    T = strain_transformation(storage.angles)
    free_laminate_axes = np.linalg.solve(T, np.broadcast_to(free, (T.shape[0], 3))[..., None])[..., 0]
    Q_bar = transformed_stiffness(reduced_stiffness(lamina), storage.angles).real
    thermal_resultant = np.einsum("kij,kj,k->i", Q_bar, free_laminate_axes, storage.thicknesses)
    eps0 = membrane_strains(storage, thermal_resultant)
    Q = reduced_stiffness(lamina).real
    return np.einsum("ij,kj->ki", Q, np.einsum("kij,j->ki", T, eps0) - free)

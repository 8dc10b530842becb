"""Tsai-Wu ply failure criterion solved for the safety factor (thesis eq. 2.48-2.53).

The criterion in the ply material axes (Jones 1999, eq. 2.159) is

    F1 s1 + F2 s2 + F11 s1^2 + F22 s2^2 + F66 t12^2 + 2 F12 s1 s2 = 1,

with F1 = 1/X_t - 1/X_c, F11 = 1/(X_t X_c), F2 = 1/Y_t - 1/Y_c, F22 = 1/(Y_t Y_c),
F66 = 1/S^2 and, unless given, F12 = -1/2 sqrt(F11 F22) (Tsai & Hahn). Scaling every stress by
the safety factor R turns it into the quadratic a R^2 + b R - 1 = 0 (thesis eq. 2.48) with
a = F11 s1^2 + F22 s2^2 + F66 t12^2 + 2 F12 s1 s2 and b = F1 s1 + F2 s2. R = 1 at failure.

A residual stress state s_r that does not grow with the load (thermal curing stresses) is
added unscaled, F(s_r + R s) = 1, as in Tsai (1992, ch. 9): the quadratic gains the constant
c = F(s_r) and the cross term 2 s_r^T H s in b.

Load shares: the index of a state s = sum_j s_j made of several loads splits exactly as
F(s) = sum_j (f . s_j + s_j^T H s), with f = (F1, F2, 0) and H the quadratic form; this is the
Aumann-Shapley (integrated-gradient) attribution along the straight path from zero stress to s,
the only additive split of a quadratic that is linear in each part and symmetric among parts
that enter the same way. See :func:`tsai_wu_shares`.

Compressive strength of soft-matrix plies (fibre microbuckling and kinking)
--------------------------------------------------------------------------
A datasheet X_c is a fibre property only while the matrix holds the fibres straight. The
fibres buckle in phase, shearing the matrix, at Rosen's (1965) shear-mode stress

    sigma_c = G_LT                    (ply form; Rosen's own form G_m / (1 - V_f), see below),

and an initial fibre misalignment phi lowers it. Budiansky & Fleck (1993) give for a composite
that is elastic-perfectly plastic in longitudinal shear (shear modulus G_LT, shear yield strain
gamma_y = tau_y / G_LT), to first order in the small angles,

    sigma_c = G_LT / (1 + phi / gamma_y),

with Argon's (1972) rigid-perfectly plastic limit sigma_c = tau_y / phi (G_LT -> inf at fixed
tau_y) and Rosen's bound sigma_c = G_LT as phi -> 0 or gamma_y -> inf. With G_LT ~ 0.1 GPa
(an elastomer matrix) the kink-band strength is ~0.1 GPa, far below a datasheet's 2 GPa;
:func:`compressive_strength` takes the smaller of the two and says which governs, and
:func:`effective_strengths` gives the :class:`Strengths` the ply check uses with ``kinking=True``.

References
----------
Ocalan, M. (2002). MS thesis, Penn State, eq. 2.48-2.53.
Jones, R. M. (1999). *Mechanics of Composite Materials*, 2nd ed., sec. 2.9.
Tsai, S. W. and Hahn, H. T. (1980). *Introduction to Composite Materials*, Technomic.
Tsai, S. W. (1992). *Theory of Composites Design*, Think Composites, ch. 9 (strength ratio with
residual stresses).
Aumann, R. J. and Shapley, L. S. (1974). *Values of Non-Atomic Games*, Princeton.
Budiansky, B. and Fleck, N. A. (1993). Compressive failure of fibre composites. *J. Mech. Phys.
Solids* 41(1), 183-211: plastic kinking from an initial misalignment is the dominant mode of
polymer-matrix composites (abstract read; the elastic-perfectly plastic formula is taken as
stated in docs/model.md and checked against an independent calculator, tests/test_kinking.py).
Rosen, B. W. (1965). Mechanics of composite strengthening, in *Fiber Composite Materials*, ASM:
shear-mode microbuckling, sigma_c = G_m / (1 - V_f) (read in secondary sources only: its
derivation as reproduced in a thesis chapter on fibre microbuckling, and Hull 1992 as quoted
in Princeton MAE 324 notes: the formula overestimates measured strengths about twofold).
Argon, A. S. (1972). Fracture of composites, *Treatise on Materials Science and Technology* 1:
sigma_c = tau_y / phi (not read; here it is the rigid-plastic limit of the formula above).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "StressLabel",
    "Strengths",
    "TsaiWuCoefficients",
    "tsai_wu_coefficients",
    "tsai_wu_quadratic",
    "tsai_wu_safety_factor",
    "tsai_wu_contributions",
    "tsai_wu_index",
    "tsai_wu_shares",
    "dominant_stress",
    "DEFAULT_FIBRE_MISALIGNMENT_DEG",
    "CompressiveStrength",
    "argon_strength",
    "budiansky_fleck_strength",
    "compressive_strength",
    "compressive_strength_note",
    "datasheet_strengths",
    "effective_strengths",
    "rosen_matrix_strength",
    "rosen_strength",
]

StressLabel = Literal["sigma1", "sigma2", "tau12"]
_LABELS = np.array(["sigma1", "sigma2", "tau12"])


@dataclass(frozen=True)
class Strengths:
    """Ply strengths, all positive magnitudes [Pa].

    Parameters
    ----------
    X_t, X_c : float
        Fibre-direction tensile and compressive strength [Pa].
    Y_t, Y_c : float
        Transverse tensile and compressive strength [Pa].
    S : float
        In-plane shear strength [Pa].
    F12 : float, optional
        Interaction coefficient [1/Pa^2]; default -1/2 sqrt(F11 F22). Must satisfy
        F12^2 < F11 F22 so that the failure surface is closed.
    """

    X_t: float
    X_c: float
    Y_t: float
    Y_c: float
    S: float
    F12: float | None = None

    def __post_init__(self) -> None:
        for name in ("X_t", "X_c", "Y_t", "Y_c", "S"):
            value = getattr(self, name)
            if not np.isfinite(value) or value <= 0.0:
                raise ValueError(f"{name} must be a positive strength magnitude [Pa], got {value!r}")
        if self.F12 is not None:
            bound = np.sqrt(1.0 / (self.X_t * self.X_c * self.Y_t * self.Y_c))
            if not np.isfinite(self.F12) or not abs(self.F12) < bound:
                raise ValueError(
                    f"F12 = {self.F12!r} 1/Pa^2 opens the Tsai-Wu surface; allowed |F12| < "
                    f"sqrt(F11 F22) = {bound:.4g} 1/Pa^2"
                )


@dataclass(frozen=True)
class TsaiWuCoefficients:
    """Tsai-Wu strength tensor components (thesis eq. 2.49-2.53) [1/Pa], [1/Pa^2]."""

    F1: float
    F2: float
    F11: float
    F22: float
    F66: float
    F12: float


def tsai_wu_coefficients(strengths: Strengths) -> TsaiWuCoefficients:
    """Tsai-Wu coefficients from the ply strengths (thesis eq. 2.49-2.53)."""
    F11 = 1.0 / (strengths.X_t * strengths.X_c)
    F22 = 1.0 / (strengths.Y_t * strengths.Y_c)
    F12 = -0.5 * np.sqrt(F11 * F22) if strengths.F12 is None else strengths.F12
    return TsaiWuCoefficients(
        F1=1.0 / strengths.X_t - 1.0 / strengths.X_c,
        F2=1.0 / strengths.Y_t - 1.0 / strengths.Y_c,
        F11=F11,
        F22=F22,
        F66=1.0 / strengths.S**2,
        F12=float(F12),
    )


def tsai_wu_quadratic(
    sigma1: ArrayLike, sigma2: ArrayLike, tau12: ArrayLike, strengths: Strengths
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Coefficients (a, b) of a R^2 + b R - 1 = 0 (thesis eq. 2.48), broadcast over the stresses.

    Parameters
    ----------
    sigma1, sigma2, tau12 : array_like
        Ply stresses in material axes [Pa].

    Returns
    -------
    a : ndarray
        Quadratic coefficient [-], >= 0.
    b : ndarray
        Linear coefficient [-].
    """
    F = tsai_wu_coefficients(strengths)
    s1, s2, t12 = np.broadcast_arrays(*(np.asarray(s, dtype=float) for s in (sigma1, sigma2, tau12)))
    a = F.F11 * s1**2 + F.F22 * s2**2 + F.F66 * t12**2 + 2.0 * F.F12 * s1 * s2
    b = F.F1 * s1 + F.F2 * s2
    return a, b


def tsai_wu_safety_factor(
    sigma1: ArrayLike,
    sigma2: ArrayLike,
    tau12: ArrayLike,
    strengths: Strengths,
    residual: tuple[ArrayLike, ArrayLike, ArrayLike] | None = None,
) -> NDArray[np.float64]:
    """Tsai-Wu safety factor R: the load multiplier that brings the ply to failure.

    The positive root of a R^2 + b R - 1 = 0, written R = 2 / (b + sqrt(b^2 + 4a)) so that it
    is exact when a = 0 (linear terms only) and free of cancellation. All-zero stress gives
    R = inf, without warnings. With a ``residual`` state s_r, F(s_r + R s) = 1 is solved:
    R = 2 (1 - c) / (b' + sqrt(b'^2 + 4 a (1 - c))) with c = F(s_r), b' = b + 2 s_r^T H s; R = 0
    where the residual alone reaches the envelope (c >= 1).

    Parameters
    ----------
    sigma1, sigma2, tau12 : array_like
        Ply stresses in material axes [Pa] that scale with the load, broadcast together.
    strengths : Strengths
    residual : tuple of array_like, optional
        (sigma1, sigma2, tau12) [Pa] that do not scale with the load (e.g. thermal residual
        stresses), broadcast with the others.

    Returns
    -------
    ndarray
        R [-] of the broadcast shape (R = 1 at failure, R > 1 safe).
    """
    a, b = tsai_wu_quadratic(sigma1, sigma2, tau12, strengths)
    margin = np.ones_like(a)
    if residual is not None:
        F = tsai_wu_coefficients(strengths)
        r1, r2, r6 = (np.asarray(s, dtype=float) for s in residual)
        s1, s2, t12 = (np.asarray(s, dtype=float) for s in (sigma1, sigma2, tau12))
        b = b + 2.0 * (F.F11 * r1 * s1 + F.F22 * r2 * s2 + F.F66 * r6 * t12 + F.F12 * (r1 * s2 + r2 * s1))
        margin = 1.0 - tsai_wu_index(r1, r2, r6, strengths)
        a, b, margin = np.broadcast_arrays(a, b, margin)
    failed = margin <= 0.0
    margin = np.maximum(margin, 0.0)
    denominator = b + np.sqrt(b * b + 4.0 * np.maximum(a, 0.0) * margin)
    safe = (denominator > 0.0) & ~failed
    R = np.divide(2.0 * margin, denominator, out=np.full(denominator.shape, np.inf), where=safe)
    return np.where(failed, 0.0, R)


def tsai_wu_index(sigma1: ArrayLike, sigma2: ArrayLike, tau12: ArrayLike, strengths: Strengths) -> NDArray[np.float64]:
    """Tsai-Wu failure index F(s) = f . s + s^T H s [-] (1 on the failure envelope)."""
    a, b = tsai_wu_quadratic(sigma1, sigma2, tau12, strengths)
    return a + b


def tsai_wu_shares(parts: ArrayLike, strengths: Strengths) -> NDArray[np.float64]:
    """Split of the Tsai-Wu index of s = sum_j s_j among the parts s_j (Aumann-Shapley).

    phi_j = f . s_j + s_j^T H s, with f = (F1, F2, 0) and H = [[F11, F12, 0], [F12, F22, 0],
    [0, 0, F66]]: the integral of the index gradient along the straight path from zero stress to
    s, projected on part j. The shares sum to F(s) exactly (to 1 on the failure envelope); a
    share may be negative (a load that relieves the critical ply).

    Parameters
    ----------
    parts : array_like, shape (..., J, 3)
        Ply stresses (sigma1, sigma2, tau12) [Pa] of each part, in material axes.

    Returns
    -------
    ndarray, shape (..., J)
        phi_j [-].
    """
    F = tsai_wu_coefficients(strengths)
    parts = np.asarray(parts, dtype=float)
    f = np.array([F.F1, F.F2, 0.0])
    H = np.array([[F.F11, F.F12, 0.0], [F.F12, F.F22, 0.0], [0.0, 0.0, F.F66]])
    total = parts.sum(axis=-2, keepdims=True)
    return parts @ f + np.einsum("...ji,ik,...k->...j", parts, H, total[..., 0, :])


def tsai_wu_contributions(
    sigma1: ArrayLike, sigma2: ArrayLike, tau12: ArrayLike, strengths: Strengths
) -> NDArray[np.float64]:
    """Share of each stress in the Tsai-Wu failure index at the failure load.

    With every stress scaled by R, the index equals 1 and splits into
    H1 = F1 s1 R + F11 (s1 R)^2 + F12 s1 s2 R^2, H2 = F2 s2 R + F22 (s2 R)^2 + F12 s1 s2 R^2 and
    H6 = F66 (t12 R)^2 (the interaction term is shared equally by sigma1 and sigma2), so
    H1 + H2 + H6 = 1. A share may be negative (a stress that delays failure).

    Returns
    -------
    ndarray, shape S + (3,)
        (H1, H2, H6) [-]; zeros where the stress is zero.
    """
    F = tsai_wu_coefficients(strengths)
    R = tsai_wu_safety_factor(sigma1, sigma2, tau12, strengths)
    scale = np.where(np.isfinite(R), R, 0.0)
    s1, s2, t12 = (np.broadcast_to(np.asarray(s, dtype=float), R.shape) * scale for s in (sigma1, sigma2, tau12))
    interaction = F.F12 * s1 * s2
    return np.stack(
        [F.F1 * s1 + F.F11 * s1**2 + interaction, F.F2 * s2 + F.F22 * s2**2 + interaction, F.F66 * t12**2], axis=-1
    )


def dominant_stress(sigma1: ArrayLike, sigma2: ArrayLike, tau12: ArrayLike, strengths: Strengths) -> NDArray[np.str_]:
    """Label of the stress with the largest share of the Tsai-Wu index at failure.

    The criterion is the largest of H1, H2, H6 from :func:`tsai_wu_contributions`: the part of
    the failure index, evaluated at the failure load, carried by sigma1, sigma2 or tau12.

    Returns
    -------
    ndarray of str
        ``"sigma1"``, ``"sigma2"`` or ``"tau12"`` per broadcast stress state (``"sigma1"`` by
        convention where all stresses are zero).
    """
    shares = tsai_wu_contributions(sigma1, sigma2, tau12, strengths)
    return _LABELS[np.argmax(shares, axis=-1)]


# ------------------------------------------------------------------------------------------------
# Compressive strength of soft-matrix plies: microbuckling and kink bands

#: Default initial fibre misalignment [deg] (assumed): the middle of the 1-3 deg usually quoted for
#: aligned polymer-matrix composites after Budiansky & Fleck (1993) (docs/model.md).
DEFAULT_FIBRE_MISALIGNMENT_DEG = 2.0


def _positive(name: str, value: float, unit: str) -> float:
    value = float(value)
    if not math.isfinite(value) or value <= 0.0:
        raise ValueError(f"{name} must be finite and > 0 [{unit}], got {value!r}")
    return value


def rosen_strength(shear_modulus: float) -> float:
    """Rosen's (1965) shear-mode microbuckling stress of a ply, sigma_c = G_LT [Pa].

    The in-phase (shear-mode) buckling of perfectly straight fibres on the matrix; in the ply
    form the composite's longitudinal shear modulus ``shear_modulus`` = G_LT [Pa] stands for
    Rosen's G_m / (1 - V_f) (:func:`rosen_matrix_strength`). An upper bound: any misalignment
    lowers it (:func:`budiansky_fleck_strength`).
    """
    return _positive("shear_modulus", shear_modulus, "Pa")


def rosen_matrix_strength(matrix_shear_modulus: float, fibre_volume_fraction: float) -> float:
    """Rosen's (1965) shear-mode stress from the constituents, sigma_c = G_m / (1 - V_f) [Pa].

    Parameters
    ----------
    matrix_shear_modulus : float
        G_m [Pa].
    fibre_volume_fraction : float
        V_f in [0, 1) [-].
    """
    G_m = _positive("matrix_shear_modulus", matrix_shear_modulus, "Pa")
    V_f = float(fibre_volume_fraction)
    if not 0.0 <= V_f < 1.0:
        raise ValueError(f"fibre_volume_fraction must lie in [0, 1), got {fibre_volume_fraction!r}")
    return G_m / (1.0 - V_f)


def budiansky_fleck_strength(shear_modulus: float, misalignment: float, shear_yield_strain: float) -> float:
    """Kink-band strength of an elastic-perfectly plastic ply, sigma_c = G / (1 + phi/gamma_y) [Pa].

    Budiansky & Fleck (1993), small-angle form: a band of fibres with initial misalignment phi
    rotates under the compressive stress until the longitudinal shear stress reaches the yield
    stress tau_y = G gamma_y. ``misalignment`` = 0 gives Rosen's G (:func:`rosen_strength`);
    G -> inf at fixed tau_y gives Argon's tau_y / phi (:func:`argon_strength`).

    Parameters
    ----------
    shear_modulus : float
        Longitudinal (in-plane) shear modulus G_LT of the ply [Pa].
    misalignment : float
        Initial fibre misalignment phi [rad], >= 0.
    shear_yield_strain : float
        gamma_y = tau_y / G_LT [-], > 0.
    """
    G = _positive("shear_modulus", shear_modulus, "Pa")
    gamma_y = _positive("shear_yield_strain", shear_yield_strain, "-")
    phi = float(misalignment)
    if not math.isfinite(phi) or phi < 0.0:
        raise ValueError(f"misalignment must be finite and >= 0 [rad], got {misalignment!r}")
    return G / (1.0 + phi / gamma_y)


def argon_strength(shear_yield_stress: float, misalignment: float) -> float:
    """Argon's (1972) rigid-perfectly plastic kinking stress, sigma_c = tau_y / phi [Pa].

    ``shear_yield_stress`` tau_y [Pa]; ``misalignment`` phi [rad], > 0 (phi -> 0 has no finite
    rigid-plastic kinking stress: the elastic composite buckles at G first).
    """
    return _positive("shear_yield_stress", shear_yield_stress, "Pa") / _positive("misalignment", misalignment, "rad")


@dataclass(frozen=True)
class CompressiveStrength:
    """Fibre-direction compressive strength of a ply: the datasheet value against kinking.

    Attributes
    ----------
    datasheet : float
        X_c of the material file [Pa].
    kink_band : float
        Budiansky-Fleck kink-band strength G_LT / (1 + phi/gamma_y) [Pa].
    rosen : float
        Rosen's shear-mode bound G_LT [Pa] (phi = 0).
    shear_modulus : float
        G_LT [Pa] (storage value).
    misalignment : float
        Initial fibre misalignment phi [rad].
    shear_yield_strain : float
        gamma_y [-].
    shear_yield_strain_source : str
        ``"file"`` (the lamina's ``shear_yield_strain``) or ``"S/G_LT"`` (derived default).
    """

    datasheet: float
    kink_band: float
    rosen: float
    shear_modulus: float
    misalignment: float
    shear_yield_strain: float
    shear_yield_strain_source: str

    @property
    def effective(self) -> float:
        """min(X_c, kink-band strength) [Pa]: the X_c the ply strength check uses."""
        return min(self.datasheet, self.kink_band)

    @property
    def governs(self) -> Literal["kink_band", "datasheet"]:
        """Which bound sets :attr:`effective`: ``"kink_band"`` or ``"datasheet"`` (a tie is the datasheet)."""
        return "kink_band" if self.kink_band < self.datasheet else "datasheet"


def compressive_strength(material: Any) -> CompressiveStrength:
    """The fibre-direction compressive strength of a lamina, datasheet X_c against kinking.

    ``material`` is a design-file lamina (:class:`flexshaft.design.materials.Lamina`) or any
    object with ``X_c``, ``G_LT``, ``S`` [Pa], ``fibre_misalignment_deg`` [deg] and
    ``shear_yield_strain`` [-] (None: gamma_y = S / G_LT, the ply's shear strength taken as
    its shear yield stress; assumed, see docs/model.md).
    """
    G = float(material.G_LT)
    phi = math.radians(float(material.fibre_misalignment_deg))
    given = material.shear_yield_strain
    gamma_y = float(material.S) / G if given is None else float(given)
    return CompressiveStrength(
        datasheet=float(material.X_c),
        kink_band=budiansky_fleck_strength(G, phi, gamma_y),
        rosen=rosen_strength(G),
        shear_modulus=G,
        misalignment=phi,
        shear_yield_strain=gamma_y,
        shear_yield_strain_source="S/G_LT" if given is None else "file",
    )


def datasheet_strengths(material: Any) -> Strengths:
    """The :class:`Strengths` of a lamina as the file gives them (X_c unchanged)."""
    return Strengths(material.X_t, material.X_c, material.Y_t, material.Y_c, material.S, material.F12)


def effective_strengths(material: Any) -> Strengths:
    """The :class:`Strengths` of a lamina with X_c = min(X_c, kink-band strength).

    What the ply strength check uses (:func:`flexshaft.analyses.shaft_strength.shaft_strengths`);
    :func:`compressive_strength` says which bound governs.
    """
    return Strengths(
        material.X_t, compressive_strength(material).effective, material.Y_t, material.Y_c, material.S, material.F12
    )


def compressive_strength_note(strength: CompressiveStrength, name: str = "the lamina") -> str | None:
    """A verdict note when the file's X_c exceeds its own kink-band bound, else None.

    E.g. "X_c = 2000 MPa of t700_adiprene exceeds its kink-band strength 85.1 MPa
    (Budiansky-Fleck: G_LT 100 MPa, misalignment 2 deg, gamma_y 0.2 = S/G_LT); the ply strength
    check uses 85.1 MPa".
    """
    if strength.governs != "kink_band":
        return None
    mpa = 1e-6
    return (
        f"X_c = {strength.datasheet * mpa:.4g} MPa of {name} exceeds its kink-band strength "
        f"{strength.kink_band * mpa:.3g} MPa (Budiansky-Fleck: G_LT {strength.shear_modulus * mpa:.4g} MPa, "
        f"misalignment {math.degrees(strength.misalignment):.3g} deg, gamma_y {strength.shear_yield_strain:.3g}"
        f"{' = S/G_LT' if strength.shear_yield_strain_source == 'S/G_LT' else ''}); "
        f"the ply strength check uses {strength.effective * mpa:.3g} MPa"
    )

"""Strength of metal (isotropic) shaft segments: von Mises yield and modified-Goodman fatigue.

For every element end of every isotropic segment whose material gives ``yield_strength``,
``ultimate_strength`` and ``fatigue_strength`` (S_y, S_ut, S_e [Pa]), the outer-fibre stress
state of the rotating tube under the static loads (external + torque) and the imbalance
response at the operating speed:

* the static bending curvature κ_s (fixed in space) is seen by the spinning material as fully
  reversed bending at 1/rev: alternating σ = E r κ_s, r = D_o/2;
* the synchronous imbalance response κ = Re((κ_v, κ_w) e^{iΩt}) splits into a forward circular
  part ``a_f = (κ_v + iκ_w)/2``, frozen in the material (a mean stress E r |a_f| on the worst
  fibre), and a backward part ``a_b = (κ_v − iκ_w)/2`` that the material sees at 2/rev
  (alternating E r |a_b|); the conventions are those of :mod:`flexshaft.assembly.loads`
  (forward whirl W = −iV);
* axial strain: static u' is a mean stress, the response's u' alternates;
* torsion: τ_m = G r θ'_s (the steady torque), τ_a = G r |θ'_d|;
* the centrifugal hoop stress of a thin ring, σ_θ = ρ Ω² r_m² (mean).

The alternating amplitudes of 1/rev and 2/rev are added (conservative: their peaks need not
coincide) and the worst fibre is taken for the mean (``σ_m`` with the sign that maximises its
von Mises stress with σ_θ). Then, after Budynas & Nisbett, *Shigley's Mechanical Engineering
Design*, 10th ed. (2015), §7-4, the distortion-energy (DE) combination

    σ_a' = √(σ_a² + 3 τ_a²),   σ_m' = √(σ_m² + σ_m σ_θ + σ_θ² + 3 τ_m²)

gives the DE-Goodman fatigue safety factor (eq. 7-7) and the first-cycle yield factor (eqs.
7-15, 7-16)::

    1/n_f = σ_a'/S_e + σ_m'/S_ut,        n_y = S_y / σ'_max,
    σ'_max = √((σ_m + σ_a)² + (σ_m + σ_a) σ_θ + σ_θ² + 3 (τ_m + τ_a)²).

S_e is the fully reversed fatigue strength of the part at its design life with the Marin
factors (surface, size, reliability) already applied: a material field, stated in the design
file. Stress concentrations at end fittings are not modelled.

Each isotropic segment is also checked for torsional buckling between its ends (simply
supported, the classical Sanders shell of :mod:`flexshaft.buckling` with the isotropic wall):
T_cr / T.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from flexshaft.analyses.results import ResultMixin, new_dataset
from flexshaft.analyses.shaft_strength import shaft_strains
from flexshaft.assembly.model import Model
from flexshaft.buckling import buckling_safety_factor, torsional_buckling_torque
from flexshaft.laminate import Lamina, Laminate

__all__ = ["MetalStrength", "SegmentBuckling", "goodman_safety_factor", "metal_strength", "von_mises_yield_factor"]

#: Criteria, as reported.
FATIGUE_CRITERION = "modified Goodman (DE-Goodman, Shigley eq. 7-7)"
YIELD_CRITERION = "von Mises first-cycle yield (Shigley eq. 7-16)"


def goodman_safety_factor(
    sigma_a, sigma_m, tau_a, tau_m, fatigue_strength: float, ultimate_strength: float, hoop=0.0
) -> np.ndarray:
    """DE-Goodman fatigue safety factor n_f [-] (Shigley, 10th ed., eq. 7-7, with a mean hoop stress).

    Parameters
    ----------
    sigma_a, sigma_m : array_like
        Alternating and mean axial stress [Pa] (σ_m >= 0: the worst fibre's magnitude).
    tau_a, tau_m : array_like
        Alternating and mean shear stress [Pa].
    fatigue_strength, ultimate_strength : float
        S_e and S_ut [Pa].
    hoop : array_like
        Mean hoop stress σ_θ [Pa].

    Returns
    -------
    ndarray
        ``1/(σ_a'/S_e + σ_m'/S_ut)``; inf for a stress-free point.
    """
    alternating = np.sqrt(np.square(sigma_a) + 3.0 * np.square(tau_a))
    mean = _von_mises(np.asarray(sigma_m, dtype=float), hoop, tau_m)
    damage = alternating / fatigue_strength + mean / ultimate_strength
    return np.divide(1.0, damage, out=np.full(np.shape(damage), np.inf), where=damage > 0)


def von_mises_yield_factor(sigma_a, sigma_m, tau_a, tau_m, yield_strength: float, hoop=0.0) -> np.ndarray:
    """First-cycle yield safety factor S_y/σ'_max [-] (Shigley, 10th ed., eqs. 7-15, 7-16)."""
    peak = _von_mises(
        np.asarray(sigma_m, dtype=float) + np.asarray(sigma_a, dtype=float),
        hoop,
        np.asarray(tau_m, dtype=float) + np.asarray(tau_a, dtype=float),
    )
    return np.divide(yield_strength, peak, out=np.full(np.shape(peak), np.inf), where=peak > 0)


def _von_mises(sigma, hoop, tau) -> np.ndarray:
    """Worst-sign von Mises stress of an axial magnitude σ >= 0 with hoop σ_θ >= 0 and shear τ."""
    return np.sqrt(np.square(sigma) + sigma * hoop + np.square(hoop) + 3.0 * np.square(tau))


@dataclass(frozen=True)
class SegmentBuckling:
    """Torsional buckling of one isotropic segment: T_cr [N m] (weaker sense), T [N m], T_cr/T."""

    segment: str
    length: float
    critical_torque: float
    torque: float
    safety_factor: float
    wave_number: int | None


@dataclass(frozen=True)
class MetalStrength(ResultMixin):
    """Yield and fatigue safety factors along the isotropic segments.

    Arrays are (n_elements, 2) over the element ends of the isotropic segments with strengths,
    stresses [Pa] of the worst imbalance case at each end.

    Attributes
    ----------
    x : ndarray
        Stations [m].
    segment : ndarray of str
        Segment of each element.
    sigma_alternating, sigma_mean, tau_alternating, tau_mean, hoop : ndarray
        σ_a, σ_m (worst fibre), τ_a, τ_m, σ_θ [Pa].
    fatigue_safety_factor, yield_safety_factor : ndarray
        n_f and n_y [-].
    buckling : tuple of SegmentBuckling
    notes : tuple of str
        Isotropic segments left out (a strength not given).
    """

    x: np.ndarray
    segment: np.ndarray
    sigma_alternating: np.ndarray
    sigma_mean: np.ndarray
    tau_alternating: np.ndarray
    tau_mean: np.ndarray
    hoop: np.ndarray
    fatigue_safety_factor: np.ndarray
    yield_safety_factor: np.ndarray
    buckling: tuple[SegmentBuckling, ...] = ()
    notes: tuple[str, ...] = field(default_factory=tuple)

    def __repr__(self) -> str:
        if not self.x.size:
            return "MetalStrength(no isotropic segment with strengths)"
        return (
            f"MetalStrength(fatigue n_f {self.fatigue_safety_factor.min():.3g}, yield n_y "
            f"{self.yield_safety_factor.min():.3g}, {len(np.unique(self.segment))} segments)"
        )

    @property
    def evaluated(self) -> bool:
        """True when at least one element was checked."""
        return bool(self.x.size)

    def worst(self, criterion: str, segment: str | None = None) -> dict:
        """The smallest safety factor of ``criterion`` ("fatigue" or "yield"), optionally within
        one segment: ``{"safety_factor", "station", "segment", "sigma_alternating", ...}`` [SI]."""
        values = self.fatigue_safety_factor if criterion == "fatigue" else self.yield_safety_factor
        mask = np.ones(values.shape, bool) if segment is None else (self.segment == segment)[:, None]
        masked = np.where(mask, values, np.inf)
        e, end = np.unravel_index(int(np.argmin(masked)), masked.shape)
        return {
            "safety_factor": float(values[e, end]),
            "station": float(self.x[e, end]),
            "segment": str(self.segment[e]),
            **{
                name: float(getattr(self, name)[e, end])
                for name in ("sigma_alternating", "sigma_mean", "tau_alternating", "tau_mean", "hoop")
            },
        }

    @property
    def segments(self) -> tuple[str, ...]:
        """Names of the segments checked, in order along the shaft."""
        names = list(dict.fromkeys(self.segment.tolist()))
        return tuple(names)

    def along_shaft(self) -> tuple[np.ndarray, np.ndarray]:
        """Stations [m] and the smaller of the two safety factors, element end by element end,
        for a line plot (flattened in order)."""
        return self.x.reshape(-1), np.minimum(self.fatigue_safety_factor, self.yield_safety_factor).reshape(-1)

    def to_dataset(self):
        """Safety factors and stresses at each element end (xarray)."""

        def ends(values, units, long_name):
            return (("element", "end"), np.asarray(values, float), {"units": units, "long_name": long_name})

        return new_dataset(
            {
                "x": ends(self.x, "m", "station"),
                "fatigue_safety_factor": ends(self.fatigue_safety_factor, "1", FATIGUE_CRITERION),
                "yield_safety_factor": ends(self.yield_safety_factor, "1", YIELD_CRITERION),
                "sigma_alternating": ends(self.sigma_alternating, "Pa", "alternating axial stress"),
                "sigma_mean": ends(self.sigma_mean, "Pa", "mean axial stress (worst fibre)"),
                "tau_alternating": ends(self.tau_alternating, "Pa", "alternating shear stress"),
                "tau_mean": ends(self.tau_mean, "Pa", "mean shear stress"),
                "hoop": ends(self.hoop, "Pa", "centrifugal hoop stress"),
            },
            {"segment": ("element", self.segment.astype(str), {"long_name": "shaft segment"})},
            "metal shaft strength",
            buckling_safety_factor=np.array([b.safety_factor for b in self.buckling], float),
            buckling_segments=" ".join(b.segment for b in self.buckling),
        )


def metal_strength(
    model: Model, static: np.ndarray, dynamic: np.ndarray | None = None, buckling: bool = True
) -> MetalStrength:
    """Yield and fatigue safety factors of the isotropic shaft segments.

    Parameters
    ----------
    model : Model
    static : ndarray, shape (ndof,)
        Static response [m, rad] to the external loads and the torque (real).
    dynamic : ndarray, shape (ndof,) or (ndof, n_cases), optional
        Complex amplitude of the imbalance response at the operating speed (one column per
        imbalance case; the worst case is kept at each element end).
    buckling : bool
        Also compute each isotropic segment's torsional-buckling safety factor (strengths or not).

    Returns
    -------
    MetalStrength
        Empty (``evaluated`` False) when no isotropic segment gives its strengths.
    """
    design = model.design
    ends = model.dofs.shaft_element_x
    mid = ends.mean(axis=1)
    segments = model.segments
    zone = np.searchsorted([s.x_end for s in segments[:-1]], mid)
    use = np.zeros(len(mid), bool)
    notes = []
    strengths = {}
    isotropic = []
    for index, seg in enumerate(segments):
        material = design.materials[seg.material]
        if material.kind != "isotropic":
            continue
        isotropic.append(index)
        names = ("yield_strength", "ultimate_strength", "fatigue_strength")
        given = [getattr(material, f) for f in names]
        if any(v is None for v in given):
            missing = ", ".join(f for f, v in zip(names, given) if v is None)
            notes.append(
                f"segment {seg.name}: material {seg.material} does not give all of yield_strength, "
                f"ultimate_strength and fatigue_strength (missing: {missing}); its strength is not checked"
            )
            continue
        strengths[index] = given
        use |= zone == index
    if dynamic is None:
        dynamic = np.zeros((model.dofs.size, 1), complex)
    dynamic = np.asarray(dynamic).reshape(model.dofs.size, -1)
    s_static = shaft_strains(model, np.real(np.asarray(static)))
    s_dyn = shaft_strains(model, dynamic)  # (nel, 2, n_cases)
    speed = model.speed
    rows = np.flatnonzero(use)
    out = {k: np.zeros((rows.size, 2)) for k in ("sa", "sm", "ta", "tm", "hoop", "nf", "ny")}
    for i, e in enumerate(rows):
        seg = segments[zone[e]]
        p = seg.properties
        E, G, r = p.youngs_modulus.real, p.shear_modulus.real, p.outer_diameter / 2
        r_mid = (p.outer_diameter + p.inner_diameter) / 4
        S_y, S_ut, S_e = strengths[zone[e]]
        kappa_static = np.hypot(s_static.curvature_v[e], s_static.curvature_w[e])  # (2,)
        kv, kw = s_dyn.curvature_v[e], s_dyn.curvature_w[e]  # (2, n_cases)
        forward, backward = np.abs(kv + 1j * kw) / 2, np.abs(kv - 1j * kw) / 2
        sigma_a = E * (r * (kappa_static[:, None] + backward) + np.abs(s_dyn.axial[e]))
        sigma_m = E * (np.abs(s_static.axial[e])[:, None] + r * forward)
        tau_a = G * r * np.abs(s_dyn.twist[e])
        tau_m = np.broadcast_to(G * r * np.abs(s_static.twist[e])[:, None], sigma_a.shape)
        hoop = p.density * speed**2 * r_mid**2
        nf = goodman_safety_factor(sigma_a, sigma_m, tau_a, tau_m, S_e, S_ut, hoop)
        ny = von_mises_yield_factor(sigma_a, sigma_m, tau_a, tau_m, S_y, hoop)
        worst = np.argmin(np.minimum(nf, ny), axis=1)  # worst imbalance case at each end
        pick = (np.arange(2), worst)
        for key, value in (("sa", sigma_a), ("sm", sigma_m), ("ta", tau_a), ("tm", tau_m), ("nf", nf), ("ny", ny)):
            out[key][i] = value[pick]
        out["hoop"][i] = hoop
    return MetalStrength(
        x=ends[rows],
        segment=np.array([segments[zone[e]].name for e in rows], dtype=object),
        sigma_alternating=out["sa"],
        sigma_mean=out["sm"],
        tau_alternating=out["ta"],
        tau_mean=out["tm"],
        hoop=out["hoop"],
        fatigue_safety_factor=out["nf"],
        yield_safety_factor=out["ny"],
        buckling=tuple(_segment_buckling(model, index) for index in isotropic) if buckling else (),
        notes=tuple(notes),
    )


def _segment_buckling(model: Model, index: int) -> SegmentBuckling:
    """Torsional buckling of segment ``index`` (isotropic wall, simply supported between its ends)."""
    seg = model.segments[index]
    p = seg.properties
    material = model.design.materials[seg.material]
    wall = (p.outer_diameter - p.inner_diameter) / 2
    lamina = Lamina.isotropic(material.E, material.G, material.density)
    laminate = Laminate(angles=np.zeros(1), thicknesses=np.array([wall]), lamina=lamina)
    result = torsional_buckling_torque(laminate, (p.outer_diameter - wall) / 2, seg.length, theory="classical")
    torque = model.power / model.speed if model.speed > 0 else 0.0
    safety = float(buckling_safety_factor(result, torque)) if torque > 0 else float("inf")
    n = result.n_positive if result.torque_positive <= result.torque_negative else result.n_negative
    return SegmentBuckling(seg.name, float(seg.length), float(result.critical_torque), float(torque), safety, n)

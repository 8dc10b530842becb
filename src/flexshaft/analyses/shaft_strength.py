"""Ply-level Tsai-Wu safety factor along the shaft for the superposed response (thesis §2.5-2.6).

Loads
-----
* static responses (external loads, torque; :func:`static_load_parts` solves them separately)
  and the synchronous imbalance response at an artificial phase φ swept over [0, 2π):
  ``q(φ) = Σ q_static + Re(q_dyn e^{iφ})``;
* the centrifugal hoop stress of the spinning wall: free thin tube, hoop resultant
  ``N_y = ρ t Ω² r²`` (r the mid-surface radius), ``N_x = N_xy = 0``, strains ``A⁻¹ N``;
* the thermal residual stresses of the cured laminate at the operating temperature (plies of
  different angle and anisotropic thermal expansion, free laminate, ``ΔT = T − T_stress_free``).

Free ends for both: the hangers' axial restraint of the spin's Poisson contraction (ε_x ≈ −9e-6
on the baseline, negligible) and of the shaft's thermal strain relative to the boom are left out.

Outer-wall strains of the beam loads at both ends of every shaft element (curvature is linear
inside a cubic element, so its extremes are at the ends)::

    ε_x  = u' ± (D_o/2) √(κ_v² + κ_w²)      (κ_v = dγ/dx, κ_w = −dβ/dx; both signs checked,
    γ_xy = (D_o/2) θ'                          every fibre passes the extreme once per turn)
    ε_y  from N_y = 0 (eq. 2.46); the spin's own hoop resultant is added as above.

Ply stresses from the storage moduli; Tsai-Wu (eq. 2.48-2.53) solved for R per ply, with the
file's strengths (the thesis's check) or, with ``kinking=True``, with the fibre-direction
compressive strength X_c = min(X_c of the file, kink-band strength)
(:func:`flexshaft.strength.effective_strengths`, docs/model.md: a soft matrix lets the fibres
kink far below a datasheet X_c). R multiplies
the mechanical loads (static, imbalance, centrifugal) together, as in the thesis; the thermal
residual stress is a fixed initial state that R does not scale (Tsai 1992), F(σ_T + R σ) = 1.
The design value is the minimum; where it occurs (element end, ply, φ, sign) and the dominant
stress are reported.

Load shares
-----------
At the critical ply and instant the failure state σ* = R Σ_j σ_j + σ_T splits the Tsai-Wu index
(= 1 there) into one share per load, φ_j = f·σ*_j + σ*_jᵀ H σ* (:func:`flexshaft.strength.
tsai_wu_shares`, the Aumann-Shapley split: linear term of the load plus its part of the quadratic
term, the interaction with every other load shared half and half). The shares sum to 1; a
negative share is a load that relieves the critical ply. The bending strain of each beam load is
taken at the critical fibre (the direction of the total curvature), so the parts add up exactly.
Beside it, ``safety_factor_without`` gives, on request, the leave-one-out safety factor (minimum
over the shaft with that load removed).
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from flexshaft.analyses.datasets import strength_dataset
from flexshaft.analyses.guards import NonFiniteResultError, check_count, check_finite_array, check_model
from flexshaft.analyses.response import static_response
from flexshaft.analyses.results import ResultMixin
from flexshaft.assembly.loads import external_static_load, torque_load
from flexshaft.assembly.model import Model
from flexshaft.elements.shape import beam_shape
from flexshaft.laminate import (
    Laminate,
    hoop_strain_free,
    membrane_strains,
    ply_stresses,
    spin_hoop_resultant,
    thermal_ply_stresses,
)
from flexshaft.plot.driveline import load_shares_figure, safety_factor_figure
from flexshaft.strength import (
    Strengths,
    datasheet_strengths,
    dominant_stress,
    effective_strengths,
    tsai_wu_safety_factor,
    tsai_wu_shares,
)

__all__ = [
    "ShaftStrains",
    "StrengthResult",
    "shaft_strains",
    "shaft_safety_factor",
    "shaft_strengths",
    "static_load_parts",
    "LOAD_NAMES",
]

#: Names of the loads in ``load_shares`` / ``safety_factor_without``: the static parts given (by
#: default from :func:`static_load_parts`; ``"static"`` for a single static response), then these.
LOAD_NAMES = ("external", "torque", "imbalance", "centrifugal", "thermal")


@dataclass(frozen=True)
class ShaftStrains:
    """Generalised strains at the element ends: arrays (n_elements, 2, ...) [-, 1/m]."""

    x: np.ndarray
    axial: np.ndarray  # u'
    curvature_v: np.ndarray  # dγ/dx
    curvature_w: np.ndarray  # −dβ/dx
    twist: np.ndarray  # θ'


def shaft_strains(model: Model, q: np.ndarray) -> ShaftStrains:
    """u', κ_v, κ_w, θ' at both ends of each shaft element for displacement(s) ``q``.

    ``q`` may carry trailing axes (load cases, phases); they are kept.
    """
    dm = model.dofs
    x = dm.shaft_element_x  # (nel, 2): a coupling joint is not an element
    dudx, dgammadx, dbetadx, dthetadx = _end_derivatives((x[:, 1] - x[:, 0]).tobytes())
    qe = np.asarray(q)[dm.element_dofs("shaft")]  # (nel, 12, ...)

    def apply(rows):
        return np.einsum("epi,ei...->ep...", rows, qe)

    return ShaftStrains(
        x=x, axial=apply(dudx), curvature_v=apply(dgammadx), curvature_w=-apply(dbetadx), twist=apply(dthetadx)
    )


@functools.lru_cache(maxsize=16)
def _end_derivatives(lengths: bytes) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Rows (nel, 2, 12) of u', γ', β', θ' at both ends of shaft elements of ``lengths``
    (float64 bytes) [m], cached (read-only): a sweep's points, and a point's static and
    imbalance evaluations, share the mesh."""
    s = beam_shape(np.array([0.0, 1.0]), np.frombuffer(lengths))
    rows = (s.dudx, s.dgammadx, s.dbetadx, s.dthetadx)
    for row in rows:
        row.flags.writeable = False
    return rows


def shaft_strengths(model: Model, kinking: bool = False) -> tuple[Laminate, Strengths]:
    """The shaft laminate and ply strengths from the design (lamina materials only).

    ``kinking``: X_c = min(X_c, kink-band strength) (:func:`flexshaft.strength.effective_strengths`);
    False (default): the file's X_c (:func:`flexshaft.strength.datasheet_strengths`).
    """
    mat = model.design.materials[model.design.shaft.material]
    if model.shaft.laminate is None or mat.kind != "lamina":
        raise ValueError("ply strength needs a laminated (lamina) shaft material")
    return model.shaft.laminate, (effective_strengths(mat) if kinking else datasheet_strengths(mat))


def static_load_parts(model: Model) -> dict[str, np.ndarray]:
    """Static responses [m, rad] to the external loads and to the torque, solved separately.

    Their sum is the static response of the thesis; keeping them apart lets
    :func:`shaft_safety_factor` report each one's share.
    """

    return {
        "external": static_response(model, external_static_load(model)),
        "torque": static_response(model, torque_load(model)),
    }


@dataclass(frozen=True)
class StrengthResult(ResultMixin):
    """Minimum Tsai-Wu safety factor, where it occurs, and what each load contributes.

    ``along_shaft`` is the minimum over plies, phases and signs at each element end
    (``x_along`` [m]). ``stresses`` are the critical ply's (σ1, σ2, τ12) [Pa] at the operating
    loads (residual included); ``stress_parts`` the same per load. ``load_shares`` split the
    failure index at the critical point among the loads (sum 1, see the module docstring);
    ``safety_factor_without`` is the minimum safety factor with one load removed (empty unless
    asked for with ``leave_one_out=True``).
    ``hoop_resultant`` [N/m] is the spin's N_y at ``spin_speed`` [rad/s]; ``temperature_change``
    [K] is T − T_stress_free of the thermal residual (0 when left out).
    """

    safety_factor: float
    x: float
    element: int
    ply: int
    ply_angle_deg: float
    phase_deg: float
    bending_sign: int
    dominant_stress: str
    stresses: tuple[float, float, float]
    x_along: np.ndarray
    along_shaft: np.ndarray
    load_shares: dict[str, float] = field(default_factory=dict)
    safety_factor_without: dict[str, float] = field(default_factory=dict)
    stress_parts: dict[str, tuple[float, float, float]] = field(default_factory=dict)
    spin_speed: float = 0.0
    hoop_resultant: float = 0.0
    temperature_change: float = 0.0

    plots = {"along_shaft": "plot_along_shaft", "load_shares": "plot_load_shares"}

    @property
    def critical_description(self) -> str:
        """E.g. "ply 3 (+55°), φ = 120°, sigma2 dominates"."""
        return (
            f"ply {self.ply + 1} ({self.ply_angle_deg:+.0f}°), φ = {self.phase_deg:.0f}°, "
            f"{self.dominant_stress} dominates"
        )

    def plot_along_shaft(self, ax=None, **kwargs):
        """Smallest safety factor along the shaft [m], the critical point annotated (keywords to
        :func:`flexshaft.plot.driveline.safety_factor_figure`)."""

        kwargs.setdefault("critical_r", self.safety_factor)
        return safety_factor_figure(self.x_along, self.along_shaft, self.x, self.critical_description, ax=ax, **kwargs)

    def plot_load_shares(self, ax=None, **kwargs):
        """Each load's share of the failure index at the critical point (bars)."""

        if not self.load_shares:
            raise ValueError("this result has no load shares")
        kwargs.setdefault("title", f"Shares of the failure index at x = {self.x:.2f} m, {self.critical_description}")
        return load_shares_figure(self.load_shares, ax=ax, **kwargs)

    def __repr__(self) -> str:
        return (
            f"StrengthResult(Tsai-Wu safety factor {self.safety_factor:.3g} at x = {self.x:.3g} m, ply {self.ply + 1} "
            f"({self.ply_angle_deg:+.0f}°), {self.dominant_stress} dominates)"
        )

    def to_dataset(self):
        """The safety factor along the shaft, with the critical point in the attributes (xarray)."""

        return strength_dataset(self)


def _components(stress) -> tuple[Any, Any, Any]:
    """(σ1, σ2, τ12) of a ply stress state whose first axis holds the three components."""
    sigma1, sigma2, tau12 = stress
    return sigma1, sigma2, tau12


def _floats(stress) -> tuple[float, float, float]:
    """(σ1, σ2, τ12) [Pa] of one ply's stress state as floats."""
    sigma1, sigma2, tau12 = stress
    return float(sigma1), float(sigma2), float(tau12)


def _unit_ply_stresses(laminate: Laminate) -> tuple[np.ndarray, np.ndarray]:
    """Ply stresses (n_ply, 3) [Pa] per unit axial strain and per unit shear strain, N_y = 0."""
    per_axial = ply_stresses(laminate, 1.0, hoop_strain_free(laminate, 1.0, 0.0), 0.0)
    per_shear = ply_stresses(laminate, 0.0, hoop_strain_free(laminate, 0.0, 1.0), 1.0)
    return per_axial, per_shear


def _wall_strains(
    strains: Mapping[str, ShaftStrains], radius: float, shape: tuple[int, ...]
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Outer-wall (eps_x, gamma_xy) of the sum of the beam loads, grid ``shape`` + (2 signs,).

    ``shape`` is (nel, 2, n_phase). Also returns the unit vector (e_v, e_w) (nel, 2, n_phase) of the
    total curvature: the extreme fibres lie along it, and each load's bending strain there is
    r (kappa . e).
    """
    zero = np.zeros(shape)
    axial = sum((s.axial for s in strains.values()), zero)
    kv = sum((s.curvature_v for s in strains.values()), zero)
    kw = sum((s.curvature_w for s in strains.values()), zero)
    magnitude = np.hypot(kv, kw)
    safe = magnitude > 0.0
    ev = np.divide(kv, magnitude, out=np.ones_like(magnitude), where=safe)
    ew = np.divide(kw, magnitude, out=np.zeros_like(magnitude), where=safe)
    eps_x = axial[..., None] + _SIGNS * (radius * magnitude)[..., None]
    gamma = np.broadcast_to((radius * sum((s.twist for s in strains.values()), zero))[..., None], eps_x.shape)
    return eps_x, gamma, ev, ew


_SIGNS = np.array([1.0, -1.0])  # the two extreme fibres of the bending strain


def _distinct_plies(*tables: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(index of each distinct ply, each ply's distinct one): plies whose rows of every table
    (n_ply, 3) are the same compute the same safety factors, which are then computed once (the
    copy is exact: R of ``first[copies]`` is R of every ply)."""
    _, first, copies = np.unique(np.hstack(tables), axis=0, return_index=True, return_inverse=True)
    return first, copies.reshape(-1)  # numpy 2.0.0 gave the inverse the input's rank


def shaft_safety_factor(
    model: Model,
    q_static: np.ndarray | Mapping[str, np.ndarray],
    q_dynamic: np.ndarray | None = None,
    n_phases: int = 72,
    *,
    speed: float | None = None,
    temperature: float | None = None,
    thermal_residual: bool = True,
    leave_one_out: bool = False,
    kinking: bool = False,
    residual_stress: np.ndarray | None = None,
) -> StrengthResult:
    """Tsai-Wu safety factor of the superposed response.

    Parameters
    ----------
    q_static : ndarray or mapping of str to ndarray
        Real static displacement (external loads + torque) [m, rad], or several named static
        responses (e.g. :func:`static_load_parts`) whose shares are reported separately.
    q_dynamic : ndarray or None
        Complex synchronous (imbalance) amplitude [m, rad]; None for static only.
    n_phases : int
        Number of phases φ in [0, 2π).
    speed : float, optional
        Spin speed Ω [rad/s] of the centrifugal hoop stress; default the model's operating speed,
        0 leaves it out.
    temperature : float, optional
        Operating wall temperature [K] of the thermal residual stress; default the design's
        ambient temperature (``[thermal] ambient_temperature_c``).
    thermal_residual : bool
        Include the thermal residual ply stresses (from the lamina's ``alpha_L``, ``alpha_T``
        and ``stress_free_temperature_c``).
    leave_one_out : bool
        Also compute ``safety_factor_without`` (one more evaluation of the whole shaft per load;
        off by default for sweeps).
    kinking : bool
        Use X_c = min(X_c, kink-band strength) (:func:`flexshaft.strength.effective_strengths`);
        False (default) keeps the file's X_c, the thesis's check.
    residual_stress : ndarray or None
        Thermal residual ply stresses (n_plies, 3) [Pa] in material axes to use instead of the
        ones computed here from ``temperature`` with the laminate's present moduli (e.g. the
        incremental ones of :func:`flexshaft.thermal.residual.residual_ply_stresses`, which
        integrate the moduli over the cool-down); ignored with ``thermal_residual=False``.
    """
    check_model(model)
    n_phases = check_count(n_phases, "n_phases")
    for name, value in (dict(q_static) if isinstance(q_static, Mapping) else {"q_static": q_static}).items():
        check_finite_array(name, value, "m, rad")
    if q_dynamic is not None:
        check_finite_array("q_dynamic", q_dynamic, "m, rad")
    laminate, strengths = shaft_strengths(model, kinking)
    laminate = laminate.storage
    design = model.design
    material = design.materials[design.shaft.material]
    r = model.shaft.outer_diameter / 2
    phases = np.arange(n_phases) * 2 * np.pi / n_phases if q_dynamic is not None else np.zeros(1)
    statics = {"static": q_static} if isinstance(q_static, np.ndarray) else dict(q_static)
    beam_parts = {name: np.asarray(q, dtype=float)[:, None] * np.ones(phases.size) for name, q in statics.items()}
    if q_dynamic is not None:
        beam_parts["imbalance"] = np.real(np.asarray(q_dynamic)[:, None] * np.exp(1j * phases)[None, :])

    spin = model.speed if speed is None else float(speed)
    if not np.isfinite(spin) or spin < 0.0:
        raise ValueError(f"speed must be a finite spin speed >= 0 [rad/s], got {speed!r}")
    thickness = laminate.thickness
    hoop = float(spin_hoop_resultant(laminate.lamina.density, thickness, r - thickness / 2, spin))
    uniform = {}  # loads that are the same at every point of the grid: (n_ply, 3)
    if hoop != 0.0:
        uniform["centrifugal"] = ply_stresses(laminate, *membrane_strains(laminate, [0.0, hoop, 0.0]))
    if temperature is None:
        delta_T = design.thermal.ambient_temperature_c - material.stress_free_temperature_c
    else:
        if not np.isfinite(temperature) or temperature <= 0.0:
            raise ValueError(f"temperature must be a positive absolute temperature [K], got {temperature!r}")
        delta_T = float(temperature) - material.stress_free_temperature
    residual: np.ndarray | None  # the plies' thermal residual stresses (n_ply, 3) [Pa]; None when none
    if residual_stress is not None and thermal_residual:
        residual = check_finite_array("residual_stress", residual_stress, "Pa")
        if residual.shape != (laminate.angles.size, 3):
            raise ValueError(
                f"residual_stress must have shape (n_plies, 3) = ({laminate.angles.size}, 3) (got {residual.shape})"
            )
    else:
        residual = thermal_ply_stresses(laminate, delta_T) if thermal_residual else None
    if residual is not None and not np.any(residual):
        residual = None

    x_ends = model.dofs.shaft_element_x
    per_axial, per_shear = _unit_ply_stresses(laminate)
    strains = {name: shaft_strains(model, q) for name, q in beam_parts.items()}
    # plies of one angle carry the same stresses everywhere: the grid is evaluated once per
    # distinct ply (3 of the embedded designs' 8 and 12) and copied to the others
    first, copies = _distinct_plies(per_axial, per_shear, *uniform.values(), *([] if residual is None else [residual]))

    def evaluate(leave_out: str | None = None) -> tuple[np.ndarray, tuple]:
        """R over the grid (nel, 2, n_phase, 2 signs, n_ply) and the total wall strains."""
        wall = _wall_strains({k: v for k, v in strains.items() if k != leave_out}, r, x_ends.shape + (phases.size,))
        factored = wall[0][..., None, None] * per_axial[first] + wall[1][..., None, None] * per_shear[first]
        for name, stress in uniform.items():
            if name != leave_out:
                factored = factored + stress[first]
        fixed = None if residual is None or leave_out == "thermal" else _components(residual[first].T)
        sigma1, sigma2, tau12 = np.moveaxis(factored, -1, 0)
        return tsai_wu_safety_factor(sigma1, sigma2, tau12, strengths, residual=fixed)[..., copies], wall

    R, (_, _, ev, ew) = evaluate()
    k = np.unravel_index(np.argmin(R), R.shape)
    e, end, ph, sg, ply = k
    parts = {}
    for name, st in strains.items():
        point = (e, end, ph)
        bend = r * (st.curvature_v[point] * ev[point] + st.curvature_w[point] * ew[point])
        eps_x, gamma = st.axial[point] + _SIGNS[sg] * bend, r * st.twist[point]
        parts[name] = eps_x * per_axial[ply] + gamma * per_shear[ply]
    parts.update({name: stress[ply] for name, stress in uniform.items()})
    if residual is not None:
        parts["thermal"] = residual[ply]
    R_min = float(R[k])
    if np.isnan(R_min):  # inf is a result (no stress); NaN is not
        raise NonFiniteResultError(
            "the Tsai-Wu safety factor came out NaN: some combination of the design's "
            "numbers overflows double precision (see docs/limits.md)"
        )
    scale = R_min if np.isfinite(R_min) else 0.0
    at_failure = np.array([parts[name] * (1.0 if name == "thermal" else scale) for name in parts])
    shares = tsai_wu_shares(at_failure, strengths) if np.isfinite(R_min) else np.zeros(len(parts))
    total = sum(parts.values())
    failure_state = at_failure.sum(axis=0)
    without = {name: float(evaluate(name)[0].min()) for name in parts} if leave_one_out else {}
    return StrengthResult(
        safety_factor=R_min,
        x=float(x_ends[e, end]),
        element=int(e),
        ply=int(ply),
        ply_angle_deg=float(np.degrees(laminate.angles[ply])),
        phase_deg=float(np.degrees(phases[ph])),
        bending_sign=int(_SIGNS[sg]),
        dominant_stress=str(dominant_stress(*_components(failure_state if np.isfinite(R_min) else total), strengths)),
        stresses=_floats(total),
        x_along=x_ends.ravel(),
        along_shaft=R.min(axis=(2, 3, 4)).ravel(),
        load_shares={name: float(v) for name, v in zip(parts, shares)},
        safety_factor_without=without,
        stress_parts={name: _floats(stress) for name, stress in parts.items()},
        spin_speed=spin,
        hoop_resultant=hoop,
        temperature_change=float(delta_T) if residual is not None else 0.0,
    )

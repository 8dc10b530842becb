"""Ply-level Tsai-Wu safety factor along the shaft for the superposed response (thesis §2.5-2.6).

Total response at an artificial phase φ: ``q(φ) = q_static + Re(q_dyn e^{iφ})``, φ swept over
[0, 2π). Outer-wall strains at both ends of every shaft element (curvature is linear inside a
cubic element, so its extremes are at the ends)::

    ε_x  = u' ± (D_o/2) √(κ_v² + κ_w²)      (κ_v = dγ/dx, κ_w = −dβ/dx; both signs checked,
    γ_xy = (D_o/2) θ'                          every fibre passes the extreme once per turn)
    ε_y  from N_y = 0 (eq. 2.46)

Ply stresses from the storage moduli, Tsai-Wu solved for R per ply (eq. 2.48-2.53). The design
value is the minimum; where it occurs (element end, ply, φ, sign) and the dominant stress are
reported.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.assembly.model import Model
from flexshaft.elements.shape import beam_shape
from flexshaft.laminate import Lamina, Laminate, hoop_strain_free, ply_stresses
from flexshaft.strength import Strengths, dominant_stress, tsai_wu_safety_factor

__all__ = ["ShaftStrains", "StrengthResult", "shaft_strains", "shaft_safety_factor", "shaft_strengths"]


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
    x = dm.shaft_x
    L = np.diff(x)
    s = beam_shape(np.array([0.0, 1.0]), L)  # rows (nel, 2, 12)
    qe = np.asarray(q)[dm.element_dofs("shaft")]  # (nel, 12, ...)

    def apply(rows):
        return np.einsum("epi,ei...->ep...", rows, qe)

    return ShaftStrains(
        x=np.stack([x[:-1], x[1:]], axis=1),
        axial=apply(s.dudx),
        curvature_v=apply(s.dgammadx),
        curvature_w=-apply(s.dbetadx),
        twist=apply(s.dthetadx),
    )


def shaft_strengths(model: Model) -> tuple[Laminate, Strengths]:
    """The shaft laminate and ply strengths from the design (lamina materials only)."""
    mat = model.design.materials[model.design.shaft.material]
    if model.shaft.laminate is None or mat.kind != "lamina":
        raise ValueError("ply strength needs a laminated (lamina) shaft material")
    return model.shaft.laminate, Strengths(mat.X_t, mat.X_c, mat.Y_t, mat.Y_c, mat.S, getattr(mat, "F12", None))


@dataclass(frozen=True)
class StrengthResult:
    """Minimum Tsai-Wu safety factor and where it occurs.

    ``along_shaft`` is the minimum over plies, phases and signs at each element end
    (``x_along`` [m]).
    """

    safety_factor: float
    x: float
    element: int
    ply: int
    ply_angle_deg: float
    phase_deg: float
    bending_sign: int
    dominant_stress: str
    stresses: tuple[float, float, float]  # σ1, σ2, τ12 of the critical ply [Pa]
    x_along: np.ndarray
    along_shaft: np.ndarray


def shaft_safety_factor(model: Model, q_static: np.ndarray, q_dynamic: np.ndarray | None = None,
                        n_phases: int = 72) -> StrengthResult:
    """Tsai-Wu safety factor of the superposed response.

    Parameters
    ----------
    q_static : ndarray
        Real static displacement (external loads + torque) [m, rad].
    q_dynamic : ndarray or None
        Complex synchronous (imbalance) amplitude [m, rad]; None for static only.
    n_phases : int
        Number of phases φ in [0, 2π).
    """
    laminate, strengths = shaft_strengths(model)
    r = model.shaft.outer_diameter / 2
    phases = np.arange(n_phases) * 2 * np.pi / n_phases if q_dynamic is not None else np.zeros(1)
    q = np.asarray(q_static, dtype=float)[:, None] * np.ones(phases.size)
    if q_dynamic is not None:
        q = q + np.real(np.asarray(q_dynamic)[:, None] * np.exp(1j * phases)[None, :])
    st = shaft_strains(model, q)  # (nel, 2, nphase)
    bend = r * np.hypot(st.curvature_v, st.curvature_w)
    signs = np.array([1.0, -1.0])
    eps_x = st.axial[..., None] + signs * bend[..., None]  # (nel, 2, nphase, 2)
    gamma = np.broadcast_to((r * st.twist)[..., None], eps_x.shape)
    eps_y = hoop_strain_free(laminate, eps_x, gamma)
    sig = ply_stresses(laminate, eps_x, eps_y, gamma)  # (..., nply, 3)
    R = tsai_wu_safety_factor(sig[..., 0], sig[..., 1], sig[..., 2], strengths)
    k = np.unravel_index(np.argmin(R), R.shape)
    e, end, ph, sg, ply = k
    s1, s2, t12 = (float(v) for v in sig[k])
    return StrengthResult(
        safety_factor=float(R[k]),
        x=float(st.x[e, end]),
        element=int(e),
        ply=int(ply),
        ply_angle_deg=float(np.degrees(laminate.angles[ply])),
        phase_deg=float(np.degrees(phases[ph])),
        bending_sign=int(signs[sg]),
        dominant_stress=str(dominant_stress(s1, s2, t12, strengths)),
        stresses=(s1, s2, t12),
        x_along=st.x.ravel(),
        along_shaft=R.min(axis=(2, 3, 4)).ravel(),
    )

r"""Hysteretic heat generation in the rotating shaft (thesis §2.8.2, eq. 2.60).

Harmonic loss
-------------
For an element displacement ``x(t) = Re(X e^{iωt})`` and the hysteretic force
``f = (K' + i K'') X e^{iωt}``, the energy dissipated per cycle is
``∮ ẋᵀ f dt = π Xᴴ K'' X`` (the K' part is conservative), so the mean power is

.. math:: P = \frac{\omega}{2\pi}\,\pi\,X^H K'' X = \frac{\omega}{2}\,\mathrm{Re}(X^H K'' X)

which is eq. 2.60 with the per-cycle energy ``π Xᴴ K'' X`` (the PDF's garbled factor reads
``ω/2π``; the extra π comes from the cycle integral). Checked in the tests against the direct
time integral of ``ẋ · f``.

Loss models
-----------
``"thesis"`` (fixed frame, as in the thesis): (1) the imbalance response at Ω dissipates
``(Ω/2) Xᴴ K'' X``; (2) the static bending deflection ``X_s`` is treated as a vibration of
amplitude ``X_s`` at Ω: ``(Ω/2) X_sᵀ K'' X_s``.

``"rotating"`` (rotating-frame consistent): the material only dissipates what it sees cycled.
Each node's lateral amplitudes split into circular whirl components. With
``v = Re(V e^{iΩt})``, ``w = Re(W e^{iΩt})`` and spin from +y to +z, forward whirl has
``W = −iV`` (``flexshaft.analyses.modal``), so

    forward  V_F = (V + iW)/2, W_F = −i V_F;   backward V_B = (V − iW)/2, W_B = +i V_B,

and for the rotations the pair (γ, −β) = ∂(v, w)/∂x splits the same way. In the rotating frame
the forward part is frozen (no loss), the backward part turns at 2Ω
(``P = (2Ω/2) X_Bᴴ K'' X_B``), axial and torsional parts stay at Ω, and a static bending
deflection becomes a circular orbit at Ω: ``P = (Ω/2) X_cᴴ K'' X_c`` with the circular vector
``X_c`` of the same radius, which equals ``Ω X_sᵀ K'' X_s``: twice the thesis value, because in
the rotating shaft every fibre passes the extreme strain each revolution, whereas in a planar
vibration of the same amplitude a fibre at angle ψ sees only |cos ψ| of it.
Static axial and torsional strains (torque) are not cycled in either model.

Which model a design uses is its ``[analysis] internal_damping`` (the same choice as every
other analysis of the model); ``loss_model=None`` in the functions below means that choice,
and an explicit ``"thesis"`` or ``"rotating"`` overrides it for a comparison.

Segmented shafts
----------------
A segmented shaft (``[[shaft.segments]]``, ``[[couplings]]``) has two nodes at each coupling,
one on each side, and no shaft element between them: the elements are those of
:meth:`~flexshaft.assembly.dofs.DofMap.element_dofs` (never consecutive nodes), each with the
tube of its own segment (:func:`element_tubes`). The couplings themselves dissipate nothing
here (their stiffness is real). The stations of the heat and temperature are the element ends,
a coupling's two nodes counted once (:func:`thermal_stations`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from flexshaft.analyses.response import imbalance_response, static_response
from flexshaft.assembly.dofs import SHAFT_FIELDS
from flexshaft.assembly.loads import external_static_load, imbalance_loads, torque_load
from flexshaft.assembly.model import Model
from flexshaft.elements import TubeSection, cowper_shear_coefficient, shaft_element_matrices

__all__ = [
    "LossModel",
    "LOSS_MODELS",
    "resolve_loss_model",
    "HeatSources",
    "harmonic_loss_power",
    "split_whirl",
    "static_circular_amplitude",
    "shaft_loss_matrices",
    "shaft_stiffness_matrices",
    "element_segments",
    "element_tubes",
    "thermal_stations",
    "element_amplitudes",
    "shaft_response_amplitudes",
    "heat_sources",
]

LossModel = Literal["thesis", "rotating"]
LOSS_MODELS: tuple[str, ...] = ("thesis", "rotating")

_IDX = {f: (SHAFT_FIELDS.index(f), SHAFT_FIELDS.index(f) + 6) for f in SHAFT_FIELDS}


def _cols(*fields: str) -> list[int]:
    return [i for f in fields for i in _IDX[f]]


_BENDING = _cols("v", "w", "beta", "gamma")
_AXIAL_TORSION = _cols("u", "theta")


def resolve_loss_model(model: Model, loss_model: LossModel | None = None) -> LossModel:
    """The loss model to use: ``loss_model`` when given, else the model's design choice
    ``design.analysis.internal_damping``.

    Raises
    ------
    ValueError
        For an unknown name, or ``None`` with a model that carries no design.
    """
    if loss_model is None:
        design = model.design
        if design is None:
            raise ValueError(
                "loss_model: the model carries no design to take [analysis] internal_damping from; "
                "give 'thesis' or 'rotating'"
            )
        loss_model = design.analysis.internal_damping
    if loss_model not in LOSS_MODELS:
        raise ValueError(f"loss_model must be 'thesis' or 'rotating', got {loss_model!r}")
    return loss_model


def harmonic_loss_power(X: np.ndarray, loss_stiffness: np.ndarray, omega: float) -> np.ndarray:
    """Mean dissipated power ``(ω/2) Re(Xᴴ K'' X)`` [W] per element.

    Parameters
    ----------
    X : ndarray
        Complex element amplitudes (nel, 12) [m, rad].
    loss_stiffness : ndarray
        K'' = Im(K_e), (nel, 12, 12) [N/m, N m/rad].
    omega : float
        Frequency at which the material is cycled [rad/s].
    """
    X = np.asarray(X)
    return 0.5 * abs(omega) * np.einsum("ei,eij,ej->e", X.conj(), loss_stiffness, X).real


def split_whirl(X: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Split element amplitudes into (axial-torsion, forward, backward) parts, summing to X.

    Works on the last axis in the shaft element DOF order ``[u v w θ β γ]×2``.
    """
    X = np.asarray(X, dtype=complex)
    axial = np.zeros_like(X)
    axial[..., _AXIAL_TORSION] = X[..., _AXIAL_TORSION]
    fwd, bwd = np.zeros_like(X), np.zeros_like(X)
    for node in (0, 6):
        v, w, th_b, th_g = (node + SHAFT_FIELDS.index(f) for f in ("v", "w", "beta", "gamma"))
        V, W = X[..., v], X[..., w]
        VF, VB = (V + 1j * W) / 2, (V - 1j * W) / 2
        fwd[..., v], fwd[..., w] = VF, -1j * VF
        bwd[..., v], bwd[..., w] = VB, 1j * VB
        a, b = X[..., th_g], -X[..., th_b]  # (γ, −β) = ∂(v, w)/∂x
        aF, aB = (a + 1j * b) / 2, (a - 1j * b) / 2
        fwd[..., th_g], fwd[..., th_b] = aF, -(-1j * aF)
        bwd[..., th_g], bwd[..., th_b] = aB, -(1j * aB)
    return axial, fwd, bwd


def static_circular_amplitude(X_static: np.ndarray) -> np.ndarray:
    """Rotating-frame amplitude of a static bending deflection: the circular orbit of the same
    radius at frequency Ω (complex, element DOF order); axial and torsion parts dropped."""
    Xs = np.asarray(X_static, dtype=float)
    out = np.zeros(Xs.shape, dtype=complex)
    for node in (0, 6):
        v, w, th_b, th_g = (node + SHAFT_FIELDS.index(f) for f in ("v", "w", "beta", "gamma"))
        Vc = Xs[..., v] - 1j * Xs[..., w]
        out[..., v], out[..., w] = Vc, 1j * Vc
        ac = Xs[..., th_g] + 1j * Xs[..., th_b]  # a − i b with (a, b) = (γ, −β)
        out[..., th_g], out[..., th_b] = ac, -1j * ac
    return out


def element_segments(model: Model) -> np.ndarray:
    """The index in ``model.segments`` of every shaft element's segment, (nel,) int: the one
    holding the element's midpoint (all 0 with at most one segment)."""
    ends = model.dofs.shaft_element_x
    segments = model.segments
    if len(segments) <= 1:
        return np.zeros(len(ends), dtype=int)
    zone = np.searchsorted([seg.x_end for seg in segments[:-1]], 0.5 * (ends[:, 0] + ends[:, 1]))
    return zone


def element_tubes(model: Model) -> tuple:
    """The tube of every shaft element, (nel,) tuple of
    :class:`~flexshaft.assembly.model.ShaftProperties`: its segment's (:func:`element_segments`;
    the ``[shaft]`` tube for a model without segments)."""
    segments = model.segments
    if not segments:
        return (model.shaft,) * len(model.dofs.shaft_element_x)
    return tuple(segments[k].properties for k in element_segments(model))


def thermal_stations(model: Model) -> np.ndarray:
    """Stations of the shaft elements' ends (nel + 1,) [m], increasing: the node stations with
    the two nodes of each coupling joint counted once."""
    x = np.asarray(model.dofs.shaft_x, dtype=float)
    joints = np.asarray(model.dofs.shaft_joints, dtype=int)
    return np.delete(x, joints + 1) if joints.size else x


def shaft_loss_matrices(model: Model, youngs_moduli=None, shear_moduli=None) -> np.ndarray:
    """Loss stiffness Im(K_e) of every shaft element, (nel, 12, 12) [N/m, N m/rad].

    ``youngs_moduli``/``shear_moduli`` (nel,) complex [Pa] give per-element moduli (default:
    each element's tube, :func:`element_tubes`).
    """
    return shaft_stiffness_matrices(model, youngs_moduli, shear_moduli).imag


def shaft_stiffness_matrices(model: Model, youngs_moduli=None, shear_moduli=None) -> np.ndarray:
    """Complex stiffness K_e of every shaft element (the elements of
    :meth:`~flexshaft.assembly.dofs.DofMap.element_dofs`), (nel, 12, 12), each with its own
    tube's section and optional per-element moduli (nel,) [Pa]; the shear option follows the
    design as in the assembly."""
    ends = model.dofs.shaft_element_x
    L = ends[:, 1] - ends[:, 0]
    tubes = element_tubes(model)
    E = np.array([t.youngs_modulus for t in tubes], dtype=complex)
    G = np.array([t.shear_modulus for t in tubes], dtype=complex)
    if youngs_moduli is not None:
        E = np.broadcast_to(np.asarray(youngs_moduli, dtype=complex), L.shape)
    if shear_moduli is not None:
        G = np.broadcast_to(np.asarray(shear_moduli, dtype=complex), L.shape)
    shear = bool(getattr(getattr(model.design, "shaft", None), "shear_deformation", False))
    out = np.empty((L.size, 12, 12), dtype=complex)
    tube_index: dict[int, int] = {}
    index = [tube_index.setdefault(id(t), len(tube_index)) for t in tubes]  # the segments' tubes
    table = np.column_stack([np.asarray(index, dtype=float).reshape(-1), E.real, E.imag, G.real, G.imag])
    uniq, inverse = np.unique(table, axis=0, return_inverse=True)
    for k, row in enumerate(uniq):
        sel = np.flatnonzero(inverse.ravel() == k)
        tube = tubes[sel[0]]
        Ek, Gk = complex(row[1], row[2]), complex(row[3], row[4])
        section = TubeSection(tube.outer_diameter, tube.inner_diameter)
        kappa = None
        if shear:
            nu = float(np.clip(Ek.real / (2 * Gk.real) - 1, 0.0, 0.5))
            kappa = cowper_shear_coefficient(section, nu)
        out[sel] = shaft_element_matrices(L[sel], section, Ek, Gk, tube.density, kappa)[1]
    return out


def element_amplitudes(model: Model, q: np.ndarray) -> np.ndarray:
    """Shaft element DOF values (nel, 12, ...) from a global vector (leading axis = DOF)."""
    return np.asarray(q)[model.dofs.element_dofs("shaft")]


def shaft_response_amplitudes(model: Model, imbalance_scale: float = 1.0, static_scale: float = 1.0):
    """Imbalance response at the operating speed (ndof, ncases) and static deflection (ndof,).

    Static = external loads (manoeuvre, thrust) + torque, from the storage stiffness.
    """

    q_imb = imbalance_response(model, [model.speed], imbalance_loads(model))[..., 0] * imbalance_scale
    Q = torque_load(model)
    if model.design is not None and model.design.loads is not None:
        Q = Q + external_static_load(model)
    q_static = static_response(model, Q) * static_scale
    return q_imb, q_static


@dataclass(frozen=True)
class HeatSources:
    """Heat generated in each shaft element [W].

    Attributes
    ----------
    x : ndarray
        Stations of the elements' ends (nel + 1,) [m] (:func:`thermal_stations`).
    vibration : ndarray
        Mechanism 1, the imbalance response (nel,) [W] (worst load case when several).
    static : ndarray
        Mechanism 2, the static deflection cycled by the rotation (nel,) [W].
    loss_model : str
        "thesis" or "rotating".
    speed : float
        Ω [rad/s].
    """

    x: np.ndarray
    vibration: np.ndarray
    static: np.ndarray
    loss_model: str
    speed: float

    @property
    def total(self) -> np.ndarray:
        """Total heat per element [W]."""
        return self.vibration + self.static

    @property
    def per_length(self) -> np.ndarray:
        """Total heat per unit length of each element [W/m]."""
        return self.total / np.diff(self.x)


def heat_sources(
    model: Model,
    loss_model: LossModel | None = None,
    q_imbalance=None,
    q_static=None,
    loss_stiffness: np.ndarray | None = None,
) -> HeatSources:
    """Heat generated per shaft element by the imbalance response and the static deflection.

    Parameters
    ----------
    model : Model
        Assembled model; its operating speed Ω is the cycling frequency.
    loss_model : {"thesis", "rotating"} or None
        See the module docstring; None: the design's ``[analysis] internal_damping``.
    q_imbalance, q_static : ndarray, optional
        Global response vectors (imbalance: complex, (ndof,) or (ndof, ncases); static: real
        (ndof,)); computed from the design when omitted.
    loss_stiffness : ndarray, optional
        Im(K_e), (nel, 12, 12); the model's uniform one when omitted.
    """
    loss_model = resolve_loss_model(model, loss_model)
    if q_imbalance is None or q_static is None:
        qi, qs = shaft_response_amplitudes(model)
        q_imbalance = qi if q_imbalance is None else q_imbalance
        q_static = qs if q_static is None else q_static
    Kpp = shaft_loss_matrices(model) if loss_stiffness is None else loss_stiffness
    Omega = model.speed
    Xi = element_amplitudes(model, np.asarray(q_imbalance).reshape(model.dofs.size, -1))  # (nel, 12, ncases)
    Xs = element_amplitudes(model, np.asarray(q_static, dtype=float))
    per_case = []
    for c in range(Xi.shape[-1]):
        X = Xi[..., c]
        if loss_model == "thesis":
            per_case.append(harmonic_loss_power(X, Kpp, Omega))
        else:
            axial, _, bwd = split_whirl(X)
            per_case.append(harmonic_loss_power(axial, Kpp, Omega) + harmonic_loss_power(bwd, Kpp, 2 * Omega))
    vib_cases = np.array(per_case)
    vibration = vib_cases[int(np.argmax(vib_cases.sum(axis=1)))]
    if loss_model == "thesis":
        Xb = np.zeros_like(Xs)
        Xb[:, _BENDING] = Xs[:, _BENDING]
        static = harmonic_loss_power(Xb, Kpp, Omega)
    else:
        static = harmonic_loss_power(static_circular_amplitude(Xs), Kpp, Omega)
    return HeatSources(thermal_stations(model), vibration, static, loss_model, Omega)

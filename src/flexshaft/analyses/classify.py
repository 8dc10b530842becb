"""Mode labels shared by every eigen-analysis: kind, whirl direction and component.

Kind. The kinetic energy ``φᴴ M φ`` of a mode is split over DOF groups by the block partition
``E_g = Re(φ_gᴴ (M φ)_g)``: shaft axial (u), shaft torsion (θ, with the drive train's own
twist DOFs: the tail rotor behind its drive spring, :mod:`flexshaft.assembly.drive`), shaft
lateral (v, w, β, γ) and tailboom. A mode is ``"torsional"`` when the shaft's twist holds more than
:data:`KIND_THRESHOLD` of its kinetic energy, ``"axial"`` when the shaft's axial motion does,
and ``"lateral"`` otherwise: bending of the shaft and/or the tailboom (whose twist belongs to
its lateral dynamics: through the bearing offset and the end mass it moves the shaft
laterally). Only lateral modes can be excited by the rotating imbalance, so only they make 1×
critical speeds.

Whirl (lateral modes only; others are ``"none"``). With node orbits ``v = Re(V e^{iωt})``,
``w = Re(W e^{iωt})`` and spin about +x (y towards z), a forward orbit has ``W = −iV``. The
whirl ratio ``r = −2 Σ Im(V̄ W) / Σ(|V|² + |W|²)`` over the shaft nodes is +1 for a circular
forward orbit and −1 for a backward one; ``|r| <`` :data:`WHIRL_THRESHOLD` is ``"planar"``.

Degenerate pairs. The two whirls of an axisymmetric mode without gyroscopic coupling (a
symmetric rotor at rest, or its pure translation at any speed) share one eigenvalue, and any
combination of the pair is a mode: the eigen-solver's choice is arbitrary. Such a pair
(eigenvalues equal to :data:`DEGENERATE` relative) is resolved into its most forward and most
backward combinations (:func:`circular_pairs`), so the labels do not depend on round-off.

Component: ``"shaft"`` when the shaft holds more than 90 % of the kinetic energy, ``"boom"``
below 10 %, else ``"coupled"``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as la

from flexshaft.assembly.dofs import DofMap
from flexshaft.assembly.model import Model

__all__ = [
    "KIND_THRESHOLD",
    "WHIRL_THRESHOLD",
    "EnergyShares",
    "energy_shares",
    "whirl_ratio",
    "ModeLabels",
    "label_modes",
    "ModalLabeler",
    "DEGENERATE",
    "circular_pairs",
    "degenerate_groups",
]

#: Share of kinetic energy in the shaft's twist (or axial motion) that makes a mode torsional (axial).
KIND_THRESHOLD = 0.5
#: |whirl ratio| below which a lateral mode is planar.
WHIRL_THRESHOLD = 0.1
#: Relative distance of two eigenvalues below which they are one degenerate root (the Newton
#: refinement converges each to 1e-10, :mod:`flexshaft.analyses.eigen`).
DEGENERATE = 1e-8


@dataclass(frozen=True)
class EnergyShares:
    """Kinetic-energy shares of modes (columns) by DOF group; they sum to 1."""

    shaft_axial: np.ndarray
    shaft_torsion: np.ndarray
    shaft_lateral: np.ndarray
    boom: np.ndarray

    @property
    def shaft(self) -> np.ndarray:
        """Share of the shaft (all its DOFs)."""
        return self.shaft_axial + self.shaft_torsion + self.shaft_lateral


def energy_shares(model: Model, shapes: np.ndarray) -> EnergyShares:
    """Kinetic-energy shares of full-DOF ``shapes`` (ndof, n_modes) by DOF group."""
    dm = model.dofs
    Mphi = model.M @ shapes
    density = np.real(np.conj(shapes) * Mphi)
    total = density.sum(axis=0)
    total = np.where(total > 0, total, 1.0)
    nodes = np.arange(dm.n_shaft_nodes)

    def share(index) -> np.ndarray:
        index = dm.unique(index) if len(dm.tied) else np.asarray(index, dtype=int)  # a tied DOF counts once
        return density[index].sum(axis=0) / total

    lateral = np.concatenate([dm.shaft(nodes, f) for f in ("v", "w", "beta", "gamma")])
    return EnergyShares(
        shaft_axial=share(dm.shaft(nodes, "u")),
        shaft_torsion=share(np.concatenate([dm.shaft(nodes, "theta"), dm.extra_dofs])),
        shaft_lateral=share(lateral),
        boom=share(dm.boom_dofs),
    )


def whirl_ratio(dofs: DofMap, shapes: np.ndarray) -> np.ndarray:
    """Whirl ratio r in [−1, 1] of each mode (column) from the shaft node orbits."""
    n = np.arange(dofs.n_shaft_nodes)
    V, W = shapes[dofs.shaft(n, "v")], shapes[dofs.shaft(n, "w")]
    power = np.sum(np.abs(V) ** 2 + np.abs(W) ** 2, axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        r = -2 * np.sum(np.imag(np.conj(V) * W), axis=0) / power
    return np.where(power > 0, r, 0.0)


def circular_pairs(s: np.ndarray, Y: np.ndarray, V: np.ndarray, W: np.ndarray) -> np.ndarray:
    """``Y`` with each group of degenerate modes resolved by whirl (see the module docstring).

    Parameters
    ----------
    s : ndarray
        Eigenvalues (n_modes,) [rad/s].
    Y : ndarray
        Their vectors (n, n_modes), in any coordinates.
    V, W : ndarray
        The shaft nodes' v and w of each vector (n_nodes, n_modes).

    Returns
    -------
    ndarray
        Y with the columns of every group of eigenvalues within :data:`DEGENERATE` of each other
        replaced by the combinations that make the whirl ratio stationary, most forward first
        (the generalised eigenvectors of the ratio's Hermitian forms on the group), with the
        norms of the original columns. Other columns are unchanged.
    """
    s = np.asarray(s)
    Y = np.array(Y, dtype=complex)
    for group in degenerate_groups(s):
        Vg, Wg = V[:, group], W[:, group]
        power = Vg.conj().T @ Vg + Wg.conj().T @ Wg  # Σ(|V|² + |W|²) as a Hermitian form
        ratio = 1j * (Vg.conj().T @ Wg - Wg.conj().T @ Vg)  # −2 Σ Im(V̄W) as a Hermitian form
        floor = np.finfo(float).eps * max(float(np.trace(power).real), np.finfo(float).tiny)
        if np.linalg.eigvalsh(power)[0] <= 1e3 * floor:
            continue  # a combination without shaft motion (a boom mode): nothing to resolve
        _, C = la.eigh(0.5 * (ratio + ratio.conj().T), 0.5 * (power + power.conj().T))
        combined = Y[:, group] @ C[:, ::-1]
        norms = np.linalg.norm(Y[:, group], axis=0)
        Y[:, group] = combined * (norms / np.linalg.norm(combined, axis=0))
    return Y


def degenerate_groups(s: np.ndarray) -> list[np.ndarray]:
    """Indices of every group of two or more eigenvalues ``s`` within :data:`DEGENERATE` of each
    other (relative to the group's first, in the order of ``s``): the groups
    :func:`circular_pairs` resolves."""
    s = np.asarray(s)
    near = np.abs(s[None, :] - s[:, None]) <= DEGENERATE * np.abs(s)[:, None]  # (k, j): the loop's test
    np.fill_diagonal(near, False)
    if not near.any():  # no eigenvalue has another within its tolerance (the usual case): no group
        return []
    done = np.zeros(s.size, dtype=bool)
    groups = []
    for k in range(s.size):
        if done[k]:
            continue
        group = np.flatnonzero(~done & (np.abs(s - s[k]) <= DEGENERATE * np.abs(s[k])))
        done[group] = True
        if group.size >= 2:
            groups.append(group)
    return groups


@dataclass(frozen=True)
class ModeLabels:
    """Labels of modes (arrays over the modes)."""

    kind: np.ndarray  # "lateral" | "torsional" | "axial"
    whirl: np.ndarray  # "forward" | "backward" | "planar" | "none"
    whirl_ratio: np.ndarray
    component: np.ndarray  # "shaft" | "boom" | "coupled"
    shares: EnergyShares


def label_modes(model: Model, shapes: np.ndarray) -> ModeLabels:
    """Kind, whirl and component of full-DOF mode ``shapes`` (ndof, n_modes)."""
    return _labels(energy_shares(model, shapes), whirl_ratio(model.dofs, shapes))


class ModalLabeler:
    """:func:`label_modes` for shapes ``Φ y`` given by modal coordinates y, without expanding
    them: the group energies ``yᴴ (Φ_gᵀ (M Φ)_g) y`` and the shaft node orbits ``Φ_v y``,
    ``Φ_w y`` come from matrices projected once."""

    def __init__(self, model: Model, Phi: np.ndarray):
        dm = model.dofs
        full = dm.expand(Phi)
        MPhi = model.M @ full
        nodes = np.arange(dm.n_shaft_nodes)
        groups = {
            "shaft_axial": dm.shaft(nodes, "u"),
            "shaft_torsion": np.concatenate([dm.shaft(nodes, "theta"), dm.extra_dofs]),
            "shaft_lateral": np.concatenate([dm.shaft(nodes, f) for f in ("v", "w", "beta", "gamma")]),
            "boom": dm.boom_dofs,
        }
        if len(dm.tied):  # a tied DOF (rigid coupling direction) counts once
            groups = {g: dm.unique(idx) for g, idx in groups.items()}
        self._energy = {g: full[idx].T @ MPhi[idx] for g, idx in groups.items()}
        self._v, self._w = full[dm.shaft(nodes, "v")], full[dm.shaft(nodes, "w")]

    def circular(self, s: np.ndarray, Y: np.ndarray) -> np.ndarray:
        """:func:`circular_pairs` of modes with eigenvalues ``s`` and modal coordinates ``Y``."""
        return circular_pairs(s, Y, self._v @ Y, self._w @ Y)

    def __call__(self, Y: np.ndarray) -> ModeLabels:
        """Labels of the modes with modal coordinates ``Y`` (nb, n_modes)."""
        parts = {g: np.real(np.sum(Y.conj() * (P @ Y), axis=0)) for g, P in self._energy.items()}
        total = sum(parts.values())
        total = np.where(total > 0, total, 1.0)
        shares = EnergyShares(**{g: e / total for g, e in parts.items()})
        V, W = self._v @ Y, self._w @ Y
        power = np.sum(np.abs(V) ** 2 + np.abs(W) ** 2, axis=0)
        with np.errstate(invalid="ignore", divide="ignore"):
            r = -2 * np.sum(np.imag(np.conj(V) * W), axis=0) / power
        return _labels(shares, np.where(power > 0, r, 0.0))


def _labels(shares: EnergyShares, r: np.ndarray) -> ModeLabels:
    kind = np.where(
        shares.shaft_torsion > KIND_THRESHOLD,
        "torsional",
        np.where(shares.shaft_axial > KIND_THRESHOLD, "axial", "lateral"),
    )
    whirl = np.where(r > WHIRL_THRESHOLD, "forward", np.where(r < -WHIRL_THRESHOLD, "backward", "planar"))
    whirl = np.where(kind == "lateral", whirl, "none")
    f = shares.shaft
    component = np.where(f > 0.9, "shaft", np.where(f < 0.1, "boom", "coupled"))
    return ModeLabels(kind.astype(object).astype(str), whirl.astype(str), r, component.astype(str), shares)

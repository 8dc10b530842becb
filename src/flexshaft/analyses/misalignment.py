"""Coupling misalignment: the angle, offsets and loads at each flexible coupling.

At a coupling between shaft nodes a (forward) and b (aft), the misalignment angle is the angle
between the two shaft axes, ``α = √((β_b − β_a)² + (γ_b − γ_a)²)`` [rad] (small rotations). The
static angle comes from the static response (boom deflection under the external loads and the
torque: the hangers carry the segments along with the bending boom). The imbalance response at
the operating speed adds a whirling angle ``Re((Δβ, Δγ) e^{iΩt})``, whose largest excursion is
the major semi-axis of its ellipse (:func:`flexshaft.analyses.response.orbit_amplitude`).

Loads the angles put on the coupling: the bending moment ``M = k_ang α`` [N m] (fixed in
space under the static angle, so it is a rotating bending moment on the adjacent shafts, already
in their static response and their fatigue check), the axial force ``k_ax Δu`` [N] and the
torque ``k_t Δθ`` [N m]. A rigid direction has no angle (or offset) and carries whatever
moment equilibrium needs; it is reported as not applicable (NaN).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.response import orbit_amplitude
from flexshaft.analyses.results import ResultMixin, new_dataset
from flexshaft.assembly.model import Model

__all__ = ["CouplingMisalignment", "coupling_misalignment"]


@dataclass(frozen=True)
class CouplingMisalignment(ResultMixin):
    """Angles and loads at every coupling (arrays over the couplings, in order of station).

    Attributes
    ----------
    names : tuple of str
    stations : ndarray
        [m].
    static_angle : ndarray
        Misalignment angle under the static loads [rad].
    dynamic_angle : ndarray
        Largest whirling angle of the imbalance response at the operating speed [rad] (worst
        imbalance case; 0 without a response).
    allowable_angle : ndarray
        The coupling's allowable angle [rad] (NaN: not given).
    static_moment : ndarray
        Bending moment k_ang α under the static angle [N m] (NaN for a rigid joint).
    axial_offset, axial_force : ndarray
        Static Δu [m] and k_ax Δu [N] (NaN force for a rigid direction).
    twist, torque : ndarray
        Static Δθ [rad] and k_t Δθ [N m] (the transmitted torque when the coupling is flexible).
    """

    names: tuple[str, ...]
    stations: np.ndarray
    static_angle: np.ndarray
    dynamic_angle: np.ndarray
    allowable_angle: np.ndarray
    static_moment: np.ndarray
    axial_offset: np.ndarray
    axial_force: np.ndarray
    twist: np.ndarray
    torque: np.ndarray

    def __repr__(self) -> str:
        if not self.names:
            return "CouplingMisalignment(no couplings)"
        k = int(np.argmax(self.total_angle))
        return (
            f"CouplingMisalignment({len(self.names)} couplings, largest {np.degrees(self.total_angle[k]):.3g}° "
            f"at {self.names[k]})"
        )

    @property
    def total_angle(self) -> np.ndarray:
        """Static plus whirling angle [rad] (the largest angle the coupling sees)."""
        return self.static_angle + self.dynamic_angle

    def to_dataset(self):
        """One row per coupling (xarray)."""

        def row(values, units, long_name):
            return ("coupling", np.asarray(values, float), {"units": units, "long_name": long_name})

        return new_dataset(
            {
                "static_angle": row(self.static_angle, "rad", "static misalignment angle"),
                "dynamic_angle": row(self.dynamic_angle, "rad", "whirling angle at the operating speed"),
                "allowable_angle": row(self.allowable_angle, "rad", "allowable misalignment angle"),
                "static_moment": row(self.static_moment, "N m", "bending moment k_ang x static angle"),
                "axial_offset": row(self.axial_offset, "m", "static axial offset"),
                "axial_force": row(self.axial_force, "N", "static axial force"),
                "twist": row(self.twist, "rad", "static twist across the coupling"),
                "torque": row(self.torque, "N m", "torque carried by the coupling spring"),
            },
            {
                "coupling": ("coupling", list(self.names), {"long_name": "coupling"}),
                "x": ("coupling", np.asarray(self.stations, float), {"units": "m", "long_name": "station"}),
            },
            "coupling misalignment",
        )


def coupling_misalignment(model: Model, static: np.ndarray, dynamic: np.ndarray | None = None) -> CouplingMisalignment:
    """Angles and loads at the model's couplings.

    Parameters
    ----------
    model : Model
    static : ndarray, shape (ndof,)
        Static response [m, rad] (external loads + torque).
    dynamic : ndarray, shape (ndof,) or (ndof, n_cases), optional
        Complex imbalance response at the operating speed; the worst case is kept.
    """
    dm = model.dofs
    q = np.real(np.asarray(static))
    d = None if dynamic is None else np.asarray(dynamic).reshape(dm.size, -1)
    fields = ("u", "theta", "beta", "gamma")
    rows: dict[str, list[float]] = {name: [] for name in ("static", "dynamic", "offset", "twist")}
    for c in model.couplings:
        delta = {f: q[dm.shaft(c.node_b, f)] - q[dm.shaft(c.node_a, f)] for f in fields}
        rows["static"].append(float(np.hypot(delta["beta"], delta["gamma"])))
        rows["offset"].append(float(delta["u"]))
        rows["twist"].append(float(delta["theta"]))
        if d is None:
            rows["dynamic"].append(0.0)
        else:
            db = d[dm.shaft(c.node_b, "beta")] - d[dm.shaft(c.node_a, "beta")]
            dg = d[dm.shaft(c.node_b, "gamma")] - d[dm.shaft(c.node_a, "gamma")]
            rows["dynamic"].append(float(np.max(orbit_amplitude(dg, db))))
    stiffness = np.array([c.stiffness for c in model.couplings]).reshape(-1, 6)
    flexible = np.isfinite(stiffness)

    def load(column: int, values) -> np.ndarray:
        finite = np.where(flexible[:, column], stiffness[:, column], 0.0)
        return np.where(flexible[:, column], finite * np.asarray(values, float), np.nan)

    return CouplingMisalignment(
        names=tuple(c.name for c in model.couplings),
        stations=np.array([c.x for c in model.couplings], float),
        static_angle=np.array(rows["static"], float),
        dynamic_angle=np.array(rows["dynamic"], float),
        allowable_angle=np.array(
            [np.nan if c.allowable_angle is None else c.allowable_angle for c in model.couplings], float
        ),
        static_moment=load(4, rows["static"]),
        axial_offset=np.array(rows["offset"], float),
        axial_force=load(0, rows["offset"]),
        twist=np.array(rows["twist"], float),
        torque=load(3, rows["twist"]),
    )

"""Random imbalance samples and their responses, cheap by linearity (see
:mod:`flexshaft.montecarlo.steady` for the method and its references).

The eccentricity distribution (scaled by a balance grade's permissible eccentricity, ISO
21940-11:2016 §5.3: ``e_per Ω = G``, :func:`flexshaft.assembly.balance.permissible_eccentricity`),
the unit responses to a rotating unit unbalance at the Lagrange stations of every shaft element
(solved once per speed), the draws of one sample and its outputs.

Each bay b carries ``U_b = e_b m_b`` with m_b the bay's rotating mass of ISO 21940-11
(:func:`flexshaft.assembly.balance.bay_rotating_masses`: its tubes, disks and coupling hubs, the
overhangs with the end bays), the same balanced rotor as the run's imbalance force ``e_c m Ω²``
(Σ m_b = m). With every e_b = e_c the bays' unbalances add up to the run's e_c m; the run shares
it equally among the bays (the thesis's convention), the samples by mass, so the two load
vectors are equal where the bays' masses are (tests/test_montecarlo_iso.py).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from flexshaft.analyses.banded import BandedHarmonicSolver
from flexshaft.analyses.reactions import bearing_reactions
from flexshaft.analyses.response import orbit_amplitude, static_response
from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.assembly.balance import bay_rotating_masses, permissible_eccentricity
from flexshaft.assembly.loads import external_static_load, imbalance_bays, point_load, torque_load
from flexshaft.assembly.model import Model
from flexshaft.resolution import SLOW_START

__all__ = [
    "actuator_static_state",
    "EccentricityDistribution",
    "ImbalanceDraws",
    "Placement",
    "UnitResponses",
    "bay_unbalances",
    "combine",
    "draw_imbalance",
    "sample_outputs",
    "unit_responses",
]

Placement = Literal["mid_bay", "uniform"]
_STATIONS = np.array([0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0])  # Lagrange stations per element (ξ)


@dataclass(frozen=True)
class EccentricityDistribution:
    """Distribution of each bay's mass eccentricity e_b [m].

    ``kind``:

    * ``"fixed"``: e = scale (the tolerance itself; only angles and positions vary);
    * ``"disk"``: the eccentricity vector is uniform over the disk of radius ``scale``
      (e = scale √u): a part balanced to tolerance, its residual anywhere inside it;
    * ``"uniform"``: e uniform on [0, scale];
    * ``"rayleigh"``: both components normal with deviation ``scale`` (e Rayleigh, σ = scale).
    """

    kind: Literal["fixed", "disk", "uniform", "rayleigh"]
    scale: float

    def __post_init__(self) -> None:
        if self.kind not in ("fixed", "disk", "uniform", "rayleigh"):
            raise ValueError(f"kind must be 'fixed', 'disk', 'uniform' or 'rayleigh', got {self.kind!r}")
        if not (np.isfinite(self.scale) and self.scale >= 0):
            raise ValueError(f"scale must be a finite eccentricity >= 0 m, got {self.scale!r}")

    @classmethod
    def from_grade(
        cls, grade_mm_s: float, speed: float, kind: Literal["fixed", "disk", "uniform", "rayleigh"] = "disk"
    ) -> EccentricityDistribution:
        """Scaled by the permissible eccentricity e_per = G/Ω of balance grade G [mm/s] at the
        maximum service speed Ω [rad/s] (ISO 21940-11 §5.3,
        :func:`flexshaft.assembly.balance.permissible_eccentricity`, the run's definition)."""
        return cls(kind, permissible_eccentricity(grade_mm_s, speed))

    def sample(self, rng: np.random.Generator, size: int) -> np.ndarray:
        """``size`` eccentricities [m]."""
        if self.kind == "fixed":
            return np.full(size, self.scale)
        if self.kind == "disk":
            return self.scale * np.sqrt(rng.random(size))
        if self.kind == "uniform":
            return self.scale * rng.random(size)
        return self.scale * np.hypot(rng.standard_normal(size), rng.standard_normal(size))


# ---------------------------------------------------------------------------------------------
# Unit responses


@dataclass(frozen=True)
class UnitResponses:
    """Responses to a rotating unit unbalance (1 kg m) at every station, per speed.

    Attributes
    ----------
    speeds : ndarray
        Ω [rad/s] (n_s,).
    bays : ndarray
        Bay ends [m] (n_bays, 2) and ``bay_mass`` [kg] (n_bays,), each bay's rotating mass
        (:func:`flexshaft.assembly.balance.bay_rotating_masses`).
    stations : ndarray
        Station positions [m] (n_st,); ``elements`` (n_el, 2) the element ends of each bay's
        elements, ``element_stations`` (n_el, 4) their station indices, ``element_bay`` (n_el,).
    shaft : ndarray
        (n_s, 2, n_nodes, n_st) complex64: shaft v and w per unit unbalance [m/(kg m)].
    actuator : ndarray
        (n_s, 2, n_act, n_st) complex64: lateral relative displacement at each active bearing.
    actuator_force : ndarray
        (n_s, 2, n_act, n_st) complex64: the force each active bearing carries, its whole law
        ``G(iΩ) d_s − k_s d_a`` (:meth:`~flexshaft.assembly.model.Actuator.carried_force`) [N
        per kg m]; linear in the imbalance like the displacement.
    operating : ndarray
        (ndof, n_st) complex response at the operating speed [m/(kg m)].
    static : ndarray
        Static response to the external loads and torque (ndof,) [m, rad].
    static_offset, static_force : ndarray
        Static lateral offset [m] at each active bearing's magnet and its static force [N] (the
        bearing's static reaction; an integrator's constraint force too), (n_act,): the verdict's
        actuator checks add them to the spin-up peaks, and so do the exceedances.
    """

    speeds: np.ndarray
    bays: np.ndarray
    bay_mass: np.ndarray
    stations: np.ndarray
    elements: np.ndarray
    element_stations: np.ndarray
    element_bay: np.ndarray
    shaft: np.ndarray
    actuator: np.ndarray
    actuator_force: np.ndarray
    operating: np.ndarray
    static: np.ndarray
    actuator_names: tuple[str, ...]
    placement: str
    static_offset: np.ndarray = field(default_factory=lambda: np.zeros(0))
    static_force: np.ndarray = field(default_factory=lambda: np.zeros(0))

    @property
    def n_bays(self) -> int:
        return self.bays.shape[0]


def _station_layout(model: Model, placement: str):
    bays = imbalance_bays(model) or [(float(model.dofs.shaft_x[0]), float(model.dofs.shaft_x[-1]))]
    x_nodes = np.asarray(model.dofs.shaft_x, dtype=float)
    stations: list[float] = []
    elements: list[tuple[float, float]] = []
    element_stations: list[tuple[int, ...]] = []  # the station index of each of an element's 4 points
    element_bay: list[int] = []

    def station(x: float) -> int:
        for k, s in enumerate(stations):
            if abs(s - x) <= 1e-12 * max(1.0, abs(x)):
                return k
        stations.append(x)
        return len(stations) - 1

    for b, (a, c) in enumerate(bays):
        if placement == "mid_bay":
            k = station(0.5 * (a + c))
            elements.append((0.5 * (a + c), 0.5 * (a + c)))
            element_stations.append((k, k, k, k))
            element_bay.append(b)
            continue
        inside = x_nodes[(x_nodes > a) & (x_nodes < c)]
        ends = np.concatenate([[a], inside, [c]])
        for lo, hi in zip(ends[:-1], ends[1:]):
            elements.append((lo, hi))
            element_stations.append(tuple(station(lo + xi * (hi - lo)) for xi in _STATIONS))
            element_bay.append(b)
    lengths = np.array([c - a for a, c in bays])
    return (
        np.array(bays, dtype=float),
        lengths,
        np.array(stations),
        np.array(elements),
        np.array(element_stations, dtype=int),
        np.array(element_bay, dtype=int),
    )


def _station_loads(model: Model, stations: np.ndarray) -> np.ndarray:
    """Rotating unit-unbalance load vectors per unit Ω² at the stations (ndof, n_st)."""
    cols = []
    for x in stations:
        cols.append(
            point_load(model, "shaft", (0.0, 1.0, 0.0), x=float(x))
            - 1j * point_load(model, "shaft", (0.0, 0.0, 1.0), x=float(x))
        )
    return np.array(cols).T


def _peak_refined_speeds(proxy, speeds: np.ndarray, width: float = 2e-6, keep: int = 12) -> np.ndarray:
    """``speeds`` plus, around every interior local maximum of ``proxy`` (a function of one
    speed), the last ``keep`` points of a golden-section search narrowed to ``width`` times
    the speed (resolves a peak of half-power width ~4e-5 Ω with ~20 evaluations)."""
    values = np.array([proxy(s) for s in speeds])
    extra = []
    ratio = (np.sqrt(5.0) - 1.0) / 2.0
    for k in range(1, speeds.size - 1):
        if not (values[k] >= values[k - 1] and values[k] >= values[k + 1]):
            continue
        lo, hi = speeds[k - 1], speeds[k + 1]
        x1, x2 = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
        f1, f2 = proxy(x1), proxy(x2)
        visited = []
        while hi - lo > width * speeds[k]:
            if f1 >= f2:
                hi, x2, f2 = x2, x1, f1
                x1 = hi - ratio * (hi - lo)
                f1 = proxy(x1)
                visited.append(x1)
            else:
                lo, x1, f1 = x1, x2, f2
                x2 = lo + ratio * (hi - lo)
                f2 = proxy(x2)
                visited.append(x2)
        extra.extend(visited[-keep:])
    return np.unique(np.concatenate([speeds, np.array(extra)]))


def actuator_static_state(model: Model) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The static state the verdict's actuator checks add to the dynamic peaks: the static
    displacement (dofs,) under the external loads and the torque, each active bearing's lateral
    offset at its magnet [m] and its static lateral force [N] (the run's static reaction: the
    constraint force of an integrating law too), in the order of ``model.actuators``."""
    static_loads = external_static_load(model) + torque_load(model)
    static = static_response(model, static_loads)
    reactions = bearing_reactions(model, static, np.zeros((model.dofs.size, 1), complex), loads=static_loads)
    offset = np.array([float(np.hypot(*np.real(a.lateral_rows @ static))) for a in model.actuators])
    force = np.array([float(reactions[a.name].static_lateral) for a in model.actuators])
    return static, offset, force


def unit_responses(
    model: Model, speeds=None, placement: Placement = "uniform", *, n_speeds: int = 150, refine: bool = True
) -> UnitResponses:
    """Unit responses of ``model`` for Monte-Carlo imbalance (see the module docstring).

    Parameters
    ----------
    speeds : array_like, optional
        Spin-up speeds [rad/s]; default ``n_speeds`` from a slow start
        (:data:`~flexshaft.resolution.SLOW_START`, 2 %) to 100 % of the operating speed.
    placement : {"uniform", "mid_bay"}
        Unbalance position: anywhere along its bay, or at mid-bay.
    refine : bool
        Add speeds around every local peak of the response (golden-section search).
    """
    if placement not in ("uniform", "mid_bay"):
        raise ValueError(f"placement must be 'uniform' or 'mid_bay', got {placement!r}")
    bays, _, stations, elements, element_stations, element_bay = _station_layout(model, placement)
    loads = _station_loads(model, stations)
    solver = BandedHarmonicSolver(model)
    free = solver.free
    rhs = loads[free]
    dm = model.dofs
    pos = np.full(dm.size, -1)
    pos[free] = np.arange(free.size)
    nodes = np.arange(dm.n_shaft_nodes)
    rows = [pos[dm.shaft(nodes, f)] for f in ("v", "w")]
    B = [a.lateral_rows.tocsr()[:, free] for a in model.actuators]

    def shaft_of(x):
        out = np.zeros((2, nodes.size) + x.shape[1:], complex)
        for k, r in enumerate(rows):
            ok = r >= 0
            out[k, ok] = x[r[ok]]
        return out

    probes = rhs @ np.exp(2j * np.pi * np.random.default_rng(0).random((rhs.shape[1], 3)))

    def proxy(speed):
        """Largest shaft response over the nodes to three fixed random combinations of the
        stations (every mode the stations excite shows its peak in at least one)."""
        return float(np.abs(shaft_of(solver.solve(speed, probes, speed) * speed * speed)).max())

    if speeds is None:
        speeds = np.linspace(SLOW_START, 1.0, n_speeds) * max(model.speed, 1.0)
    speeds = np.asarray(speeds, dtype=float)
    if speeds.ndim != 1 or speeds.size < 1 or not np.all(np.isfinite(speeds)) or np.any(speeds < 0):
        raise ValueError("speeds must be a 1-D array of finite speeds >= 0 rad/s")
    if refine and speeds.size >= 3:
        speeds = _peak_refined_speeds(proxy, np.sort(speeds))
    n_act = len(model.actuators)
    shaft = np.empty((speeds.size, 2, nodes.size, stations.size), np.complex64)
    actuator = np.empty((speeds.size, 2, n_act, stations.size), np.complex64)
    carried = np.empty_like(actuator)
    q = np.zeros((dm.size, stations.size), complex)
    for k, s in enumerate(speeds):
        x = solver.solve(s, rhs, s) * (s * s)
        shaft[k] = shaft_of(x)
        q[free] = x
        for a, (act, b) in enumerate(zip(model.actuators, B)):
            actuator[k, :, a] = b @ x
            carried[k, :, a] = act.carried_force(q, 1j * s)  # G d_s − k_s d_a: the verdict's force
    operating = np.zeros((dm.size, stations.size), complex)
    operating[free] = solver.solve(model.speed, rhs, model.speed) * model.speed**2
    static, static_offset, static_force = actuator_static_state(model)
    return UnitResponses(
        speeds=speeds,
        bays=bays,
        bay_mass=bay_rotating_masses(model),
        stations=stations,
        elements=elements,
        element_stations=element_stations,
        element_bay=element_bay,
        shaft=shaft,
        actuator=actuator,
        actuator_force=carried,
        operating=operating,
        static=static,
        actuator_names=tuple(a.name for a in model.actuators),
        placement=placement,
        static_offset=static_offset,
        static_force=static_force,
    )


# ---------------------------------------------------------------------------------------------
# Samples


@dataclass(frozen=True)
class ImbalanceDraws:
    """Per-sample, per-bay unbalance draws: eccentricity [m], angle [rad], position (fraction
    of the bay), each (n_samples, n_bays)."""

    eccentricity: np.ndarray
    angle: np.ndarray
    position: np.ndarray


def draw_imbalance(
    indices: Sequence[int], n_bays: int, distribution: EccentricityDistribution, placement: Placement, seed: int
) -> ImbalanceDraws:
    """The draws of samples ``indices``: sample k uses ``default_rng([seed, k])`` alone, in the
    order eccentricities, angles, positions (so a sample never depends on the others)."""
    e, a, p = [], [], []
    for k in indices:
        rng = np.random.default_rng([int(seed), int(k)])
        e.append(distribution.sample(rng, n_bays))
        a.append(rng.uniform(0.0, 2 * np.pi, n_bays))
        p.append(rng.random(n_bays) if placement == "uniform" else np.full(n_bays, 0.5))
    return ImbalanceDraws(
        np.array(e).reshape(-1, n_bays), np.array(a).reshape(-1, n_bays), np.array(p).reshape(-1, n_bays)
    )


def bay_unbalances(bay_mass, draws: ImbalanceDraws) -> np.ndarray:
    """Complex unbalance of each bay in each sample, ``U_b e^{iψ_b} = e_b m_b e^{iψ_b}`` [kg m],
    (n_samples, n_bays), from the bays' rotating masses ``bay_mass`` [kg]."""
    return draws.eccentricity * np.asarray(bay_mass, dtype=float) * np.exp(1j * draws.angle)


def combine(units: UnitResponses, draws: ImbalanceDraws) -> tuple[np.ndarray, np.ndarray]:
    """Station indices (n, n_bays·4) and complex weights [kg m] of each sample."""
    n = draws.eccentricity.shape[0]
    unbalances = bay_unbalances(units.bay_mass, draws)
    idx = np.zeros((n, units.n_bays, 4), int)
    weights = np.zeros((n, units.n_bays, 4), complex)
    for b in range(units.n_bays):
        mine = np.flatnonzero(units.element_bay == b)
        lo, hi = units.bays[b]
        x = lo + draws.position[:, b] * (hi - lo)
        ends = units.elements[mine]
        e = mine[np.clip(np.searchsorted(ends[:, 1], x, side="left"), 0, mine.size - 1)]
        span = units.elements[e, 1] - units.elements[e, 0]
        xi = np.where(span > 0, (x - units.elements[e, 0]) / np.where(span > 0, span, 1.0), 0.0)
        basis = np.zeros((n, 4))
        basis[:, 0] = 1.0  # mid-bay: the single station
        if units.placement == "uniform":
            for j in range(4):  # cubic Lagrange weights on ξ = 0, ⅓, ⅔, 1
                basis[:, j] = 1.0
                for m in range(4):
                    if m != j:
                        basis[:, j] *= (xi - _STATIONS[m]) / (_STATIONS[j] - _STATIONS[m])
        idx[:, b] = units.element_stations[e]
        weights[:, b] = unbalances[:, b, None] * basis
    return idx.reshape(n, -1), weights.reshape(n, -1)


#: Names of the per-sample outputs besides the per-actuator and per-bay ones.
BASE_OUTPUTS: dict[str, tuple[str, str]] = {  # name -> (SI unit, long name)
    "shaft_peak": ("m", "peak steady-state spin-up deflection over the shaft"),
    "shaft_peak_speed": ("rad/s", "speed of the peak deflection"),
    "actuator_orbit_max": ("m", "largest peak lateral relative orbit over the active bearings"),
    "actuator_force_max": ("N", "largest peak force over the active bearings"),
    "actuator_excursion_max": ("m", "largest static offset + peak orbit over the active bearings"),
    "actuator_load_max": ("N", "largest static + peak force over the active bearings"),
    "safety_factor": ("1", "Tsai-Wu safety factor at the operating speed"),
}


def sample_outputs(
    model: Model,
    units: UnitResponses,
    draws: ImbalanceDraws,
    *,
    strength: bool = True,
    n_phases: int = 36,
    memory: float = 5e7,
) -> dict[str, np.ndarray]:
    """Outputs of each sample (arrays over samples) [SI]: ``shaft_peak`` [m] and
    ``shaft_peak_speed`` [rad/s], ``actuator_orbit_<name>`` [m] and ``actuator_force_<name>``
    [N] (peaks over speed), their largest over the actuators, ``actuator_excursion_<name>`` [m]
    and ``actuator_load_<name>`` [N] (static offset / force plus the peak: the values of the
    verdict's actuator checks) and their largest, ``actuator_excursion_max`` and
    ``actuator_load_max``, and ``safety_factor`` (Tsai-Wu at
    the operating speed; NaN when ``strength`` is False or the shaft is not laminated).
    Samples are combined in blocks of about ``memory`` bytes."""
    idx, weights = combine(units, draws)
    n, width = weights.shape
    out: dict[str, np.ndarray] = {name: np.full(n, np.nan) for name in BASE_OUTPUTS}
    out.update(
        {
            f"actuator_{kind}_{name}": np.full(n, np.nan)
            for name in units.actuator_names
            for kind in ("orbit", "force", "excursion", "load")
        }
    )
    laminated = strength and model.shaft.laminate is not None
    block = int(max(1, memory // (units.shaft[..., 0].size * width * 8)))
    for start in range(0, n, block):
        sl = slice(start, min(start + block, n))
        cols, w = idx[sl], weights[sl].astype(np.complex64)
        shaft = np.einsum("abcnj,nj->nabc", units.shaft[..., cols], w)  # (n, n_s, 2, n_nodes)
        per_speed = orbit_amplitude(shaft[:, :, 0], shaft[:, :, 1]).max(axis=2)  # (n, n_s)
        k = np.argmax(per_speed, axis=1)
        out["shaft_peak"][sl] = per_speed[np.arange(k.size), k]
        out["shaft_peak_speed"][sl] = units.speeds[k]
        if units.actuator_names:
            act = np.einsum("abcnj,nj->nabc", units.actuator[..., cols], w)  # (n, n_s, 2, n_act)
            orbit = orbit_amplitude(act[:, :, 0], act[:, :, 1])  # (n, n_s, n_act)
            carried = np.einsum("abcnj,nj->nabc", units.actuator_force[..., cols], w)
            force = orbit_amplitude(carried[:, :, 0], carried[:, :, 1])  # the force's major semi-axis
            for a, name in enumerate(units.actuator_names):
                out[f"actuator_orbit_{name}"][sl] = orbit[..., a].max(axis=1)
                out[f"actuator_force_{name}"][sl] = force[..., a].max(axis=1)
                # static + peak dynamic, as the verdict's actuator checks
                out[f"actuator_excursion_{name}"][sl] = orbit[..., a].max(axis=1) + units.static_offset[a]
                out[f"actuator_load_{name}"][sl] = force[..., a].max(axis=1) + units.static_force[a]
            out["actuator_orbit_max"][sl] = orbit.max(axis=(1, 2))
            out["actuator_force_max"][sl] = force.max(axis=(1, 2))
            # static + peak dynamic, per actuator, as the verdict's actuator checks
            out["actuator_excursion_max"][sl] = (orbit.max(axis=1) + units.static_offset).max(axis=1)
            out["actuator_load_max"][sl] = (force.max(axis=1) + units.static_force).max(axis=1)
    if laminated:
        for s in range(n):
            q = units.operating[:, idx[s]] @ weights[s]
            out["safety_factor"][s] = shaft_safety_factor(model, units.static, q, n_phases=n_phases).safety_factor
    return out

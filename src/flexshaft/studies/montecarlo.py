r"""Monte-Carlo imbalance: random residual unbalance per bay, on the sweep engine.

Each shaft bay b (the span between consecutive bearings) carries a point unbalance
``U_b = e_b m_b`` [kg m] (m_b the bay's share of the shaft mass, in proportion to its length)
at angle ψ_b, uniform on [0, 2π), at axial position x_b, mid-bay or uniform along the bay.
The eccentricity e_b follows an :class:`EccentricityDistribution`, typically scaled by the
permissible residual specific unbalance of a balance quality grade (ISO 21940-11:2016, §5.3,
formerly ISO 1940-1): ``e_per Ω = G``, G the grade in mm/s (G 6.3 for most machinery, G 2.5
for turbines and high-speed drives), Ω the maximum service speed.

Linearity makes each sample cheap. The response is a linear combination of unit responses:
a point force inside an element is a cubic in x (Hermite shape functions), so the
response to a rotating unit unbalance at any x of an element is the cubic Lagrange
interpolant of the responses at four stations of that element (ξ = 0, ⅓, ⅔, 1), exact to
round-off. Those responses are solved once per speed (banded LU, all stations at once,
:class:`~flexshaft.analyses.banded.BandedHarmonicSolver`) and cached per worker process; a
sample is then a weighted sum of 4 columns per bay. Speeds: a uniform spin-up grid refined
around every local peak of the unit responses by golden-section search, so that a lightly damped
critical (the baseline's 55-Hz forward mode meets almost no damping in synchronous whirl:
half-power width ~4e-5 Ω) is not missed between grid points.

Per sample: peak steady-state spin-up deflection over the shaft (and its speed), peak
lateral relative orbit and force ``|C(iΩ)| × orbit`` at each active bearing, and the ply
Tsai-Wu safety factor at the operating speed (static loads and torque plus the sample's
imbalance response, :func:`~flexshaft.analyses.shaft_strength.shaft_safety_factor`).
Samples run on :func:`flexshaft.sweep.run_sweep` (processes locally, Dask beyond); sample k
draws from ``numpy.random.default_rng([seed, k])``, so results do not depend on chunking,
workers or backend.

References
----------
ISO 21940-11:2016. Mechanical vibration — Rotor balancing — Part 11: Procedures and
tolerances for rotors with rigid behaviour. §5.3 (balance quality grades G, e_per Ω = G).
"""

from __future__ import annotations

import hashlib
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np

from flexshaft.analyses.response import orbit_amplitude
from flexshaft.assembly.model import Model

__all__ = [
    "EccentricityDistribution",
    "ImbalanceDraws",
    "MonteCarloResult",
    "MonteCarloSampler",
    "RunupSamples",
    "UnitResponses",
    "balance_grade_eccentricity",
    "draw_imbalance",
    "montecarlo_study",
    "run_montecarlo",
    "runup_montecarlo",
    "sample_outputs",
    "unit_responses",
]

Placement = Literal["mid_bay", "uniform"]
_STATIONS = np.array([0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0])  # Lagrange stations per element (ξ)


def balance_grade_eccentricity(grade_mm_s: float, speed: float) -> float:
    """Permissible residual specific unbalance e_per [m] of balance grade G at speed Ω.

    ISO 21940-11 §5.3: ``e_per Ω = G`` with G [mm/s] (e.g. G 6.3) and Ω [rad/s] the maximum
    service speed, so ``e_per = G/Ω``: G 6.3 at 4800 rpm gives 12.5 µm.
    """
    if not (np.isfinite(grade_mm_s) and grade_mm_s > 0):
        raise ValueError(f"grade_mm_s must be a positive balance grade in mm/s (e.g. 6.3), got {grade_mm_s!r}")
    if not (np.isfinite(speed) and speed > 0):
        raise ValueError(f"speed must be > 0 rad/s, got {speed!r}")
    return grade_mm_s * 1e-3 / speed


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
    def from_grade(cls, grade_mm_s: float, speed: float, kind: str = "disk") -> "EccentricityDistribution":
        """Scaled by the balance grade's e_per = G/Ω (:func:`balance_grade_eccentricity`)."""
        return cls(kind, balance_grade_eccentricity(grade_mm_s, speed))

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
        Bay ends [m] (n_bays, 2) and ``bay_mass`` [kg] (n_bays,).
    stations : ndarray
        Station positions [m] (n_st,); ``elements`` (n_el, 2) the element ends of each bay's
        elements, ``element_stations`` (n_el, 4) their station indices, ``element_bay`` (n_el,).
    shaft : ndarray
        (n_s, 2, n_nodes, n_st) complex64: shaft v and w per unit unbalance [m/(kg m)].
    actuator : ndarray
        (n_s, 2, n_act, n_st) complex64: lateral relative displacement at each active bearing.
    actuator_gain : ndarray
        |C(iΩ)| (n_s, n_act) [N/m].
    operating : ndarray
        (ndof, n_st) complex response at the operating speed [m/(kg m)].
    static : ndarray
        Static response to the external loads and torque (ndof,) [m, rad].
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
    actuator_gain: np.ndarray
    operating: np.ndarray
    static: np.ndarray
    actuator_names: tuple[str, ...]
    placement: str

    @property
    def n_bays(self) -> int:
        return self.bays.shape[0]


def _station_layout(model: Model, placement: str):
    from flexshaft.assembly.loads import imbalance_bays

    bays = imbalance_bays(model) or [(float(model.dofs.shaft_x[0]), float(model.dofs.shaft_x[-1]))]
    x_nodes = np.asarray(model.dofs.shaft_x, dtype=float)
    stations, elements, element_stations, element_bay = [], [], [], []

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
    return (np.array(bays, dtype=float), lengths, np.array(stations), np.array(elements),
            np.array(element_stations, dtype=int), np.array(element_bay, dtype=int))


def _station_loads(model: Model, stations: np.ndarray) -> np.ndarray:
    """Rotating unit-unbalance load vectors per unit Ω² at the stations (ndof, n_st)."""
    from flexshaft.assembly.loads import point_load

    cols = []
    for x in stations:
        cols.append(point_load(model, "shaft", (0.0, 1.0, 0.0), x=float(x)) - 1j * point_load(model, "shaft", (0.0, 0.0, 1.0), x=float(x)))
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


def unit_responses(model: Model, speeds=None, placement: Placement = "uniform", *, n_speeds: int = 150,
                   refine: bool = True) -> UnitResponses:
    """Unit responses of ``model`` for Monte-Carlo imbalance (see the module docstring).

    Parameters
    ----------
    speeds : array_like, optional
        Spin-up speeds [rad/s]; default ``n_speeds`` from 2 % to 100 % of the operating speed.
    placement : {"uniform", "mid_bay"}
        Unbalance position: anywhere along its bay, or at mid-bay.
    refine : bool
        Add speeds around every local peak of the response (golden-section search).
    """
    from flexshaft.analyses import static_response
    from flexshaft.analyses.banded import BandedHarmonicSolver
    from flexshaft.assembly.loads import external_static_load, torque_load

    if placement not in ("uniform", "mid_bay"):
        raise ValueError(f"placement must be 'uniform' or 'mid_bay', got {placement!r}")
    bays, lengths, stations, elements, element_stations, element_bay = _station_layout(model, placement)
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
        speeds = np.linspace(0.02, 1.0, n_speeds) * max(model.speed, 1.0)
    speeds = np.asarray(speeds, dtype=float)
    if speeds.ndim != 1 or speeds.size < 1 or not np.all(np.isfinite(speeds)) or np.any(speeds < 0):
        raise ValueError("speeds must be a 1-D array of finite speeds >= 0 rad/s")
    if refine and speeds.size >= 3:
        speeds = _peak_refined_speeds(proxy, np.sort(speeds))
    n_act = len(model.actuators)
    shaft = np.empty((speeds.size, 2, nodes.size, stations.size), np.complex64)
    actuator = np.empty((speeds.size, 2, n_act, stations.size), np.complex64)
    for k, s in enumerate(speeds):
        x = solver.solve(s, rhs, s) * (s * s)
        shaft[k] = shaft_of(x)
        for a, b in enumerate(B):
            actuator[k, :, a] = b @ x
    gain = np.array([[abs(complex(a.controller(1j * s))) for a in model.actuators] for s in speeds]).reshape(speeds.size, n_act)
    operating = np.zeros((dm.size, stations.size), complex)
    operating[free] = solver.solve(model.speed, rhs, model.speed) * model.speed**2
    static = static_response(model, external_static_load(model) + torque_load(model))
    return UnitResponses(
        speeds=speeds, bays=bays, bay_mass=model.shaft_mass * lengths / lengths.sum(), stations=stations,
        elements=elements, element_stations=element_stations, element_bay=element_bay, shaft=shaft,
        actuator=actuator, actuator_gain=gain, operating=operating, static=static,
        actuator_names=tuple(a.name for a in model.actuators), placement=placement,
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


def draw_imbalance(indices: Sequence[int], n_bays: int, distribution: EccentricityDistribution, placement: Placement,
                   seed: int) -> ImbalanceDraws:
    """The draws of samples ``indices``: sample k uses ``default_rng([seed, k])`` alone, in the
    order eccentricities, angles, positions (so a sample never depends on the others)."""
    e, a, p = [], [], []
    for k in indices:
        rng = np.random.default_rng([int(seed), int(k)])
        e.append(distribution.sample(rng, n_bays))
        a.append(rng.uniform(0.0, 2 * np.pi, n_bays))
        p.append(rng.random(n_bays) if placement == "uniform" else np.full(n_bays, 0.5))
    return ImbalanceDraws(np.array(e).reshape(-1, n_bays), np.array(a).reshape(-1, n_bays), np.array(p).reshape(-1, n_bays))


def _combination(units: UnitResponses, draws: ImbalanceDraws) -> tuple[np.ndarray, np.ndarray]:
    """Station indices (n, n_bays·4) and complex weights [kg m] of each sample."""
    n = draws.eccentricity.shape[0]
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
        unbalance = draws.eccentricity[:, b] * units.bay_mass[b] * np.exp(1j * draws.angle[:, b])
        idx[:, b] = units.element_stations[e]
        weights[:, b] = unbalance[:, None] * basis
    return idx.reshape(n, -1), weights.reshape(n, -1)


#: Names of the per-sample outputs besides the per-actuator and per-bay ones.
BASE_OUTPUTS = ("shaft_peak", "shaft_peak_speed", "actuator_orbit_max", "actuator_force_max", "safety_factor")


def sample_outputs(model: Model, units: UnitResponses, draws: ImbalanceDraws, *, strength: bool = True,
                   n_phases: int = 36, memory: float = 5e7) -> dict[str, np.ndarray]:
    """Outputs of each sample (arrays over samples) [SI]: ``shaft_peak`` [m] and
    ``shaft_peak_speed`` [rad/s], ``actuator_orbit_<name>`` [m] and ``actuator_force_<name>``
    [N] (peaks over speed), their largest over the actuators, and ``safety_factor`` (Tsai-Wu at
    the operating speed; NaN when ``strength`` is False or the shaft is not laminated).
    Samples are combined in blocks of about ``memory`` bytes."""
    from flexshaft.analyses.shaft_strength import shaft_safety_factor

    idx, weights = _combination(units, draws)
    n, width = weights.shape
    out: dict[str, np.ndarray] = {name: np.full(n, np.nan) for name in BASE_OUTPUTS}
    out.update({f"actuator_{kind}_{name}": np.full(n, np.nan) for name in units.actuator_names for kind in ("orbit", "force")})
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
            force = units.actuator_gain * orbit
            for a, name in enumerate(units.actuator_names):
                out[f"actuator_orbit_{name}"][sl] = orbit[..., a].max(axis=1)
                out[f"actuator_force_{name}"][sl] = force[..., a].max(axis=1)
            out["actuator_orbit_max"][sl] = orbit.max(axis=(1, 2))
            out["actuator_force_max"][sl] = force.max(axis=(1, 2))
    if laminated:
        for s in range(n):
            q = units.operating[:, idx[s]] @ weights[s]
            out["safety_factor"][s] = shaft_safety_factor(model, units.static, q, n_phases=n_phases).safety_factor
    return out


# ---------------------------------------------------------------------------------------------
# The sweep-engine study

_CACHE: dict[str, UnitResponses] = {}


@dataclass(frozen=True)
class MonteCarloSampler:
    """The :class:`~flexshaft.sweep.Study` output function of one Monte-Carlo run (picklable;
    its repr, with every setting, enters the study's fingerprint)."""

    seed: int
    distribution: EccentricityDistribution
    placement: str = "uniform"
    n_speeds: int = 150
    n_phases: int = 36
    strength: bool = True

    def units(self, point) -> UnitResponses:
        """Unit responses of the point's design, computed once per worker process."""
        key = hashlib.sha256((point.design.model_dump_json() + repr((self.placement, self.n_speeds))).encode()).hexdigest()
        if key not in _CACHE:
            _CACHE.clear()
            _CACHE[key] = unit_responses(point.model, placement=self.placement, n_speeds=self.n_speeds)
        return _CACHE[key]

    def __call__(self, point) -> dict[str, float]:
        units = self.units(point)
        k = int(point.axes["sample"])
        draws = draw_imbalance([k], units.n_bays, self.distribution, self.placement, self.seed)
        out = {name: float(v[0]) for name, v in sample_outputs(point.model, units, draws, strength=self.strength,
                                                               n_phases=self.n_phases).items()}
        for b in range(units.n_bays):
            out[f"eccentricity_bay{b + 1}"] = float(draws.eccentricity[0, b])
            out[f"angle_bay{b + 1}"] = float(draws.angle[0, b])
            out[f"position_bay{b + 1}"] = float(draws.position[0, b])
        return out


def montecarlo_study(design, n_samples: int, sampler: MonteCarloSampler):
    """The :class:`~flexshaft.sweep.Study` of ``n_samples`` imbalance samples of ``design``."""
    from flexshaft.assembly import build_model
    from flexshaft.assembly.loads import imbalance_bays
    from flexshaft.sweep import Output, Study, Variable

    if int(n_samples) < 1:
        raise ValueError(f"n_samples must be >= 1, got {n_samples!r}")
    model = build_model(design)
    n_bays = max(len(imbalance_bays(model)), 1)
    outputs = [
        Output("shaft_peak", "m", "peak steady-state spin-up deflection over the shaft"),
        Output("shaft_peak_speed", "rad/s", "speed of the peak deflection"),
        Output("actuator_orbit_max", "m", "largest peak lateral relative orbit over the active bearings"),
        Output("actuator_force_max", "N", "largest peak force over the active bearings"),
        Output("safety_factor", "1", "Tsai-Wu safety factor at the operating speed"),
    ]
    for a in model.actuators:
        outputs += [Output(f"actuator_orbit_{a.name}", "m", f"peak lateral relative orbit at {a.name}"),
                    Output(f"actuator_force_{a.name}", "N", f"peak force at {a.name}")]
    for b in range(1, n_bays + 1):
        outputs += [Output(f"eccentricity_bay{b}", "m"), Output(f"angle_bay{b}", "rad"), Output(f"position_bay{b}", "1",
                                                                                           "fraction of the bay")]
    return Study(name=f"Monte-Carlo imbalance ({n_samples} samples, seed {sampler.seed})",
                 variables=[Variable("sample", list(range(int(n_samples))), long_name="sample index")],
                 outputs=outputs, evaluate=sampler, base=design)


@dataclass(frozen=True)
class MonteCarloResult:
    """Samples (an :class:`xarray.Dataset` over ``sample``) and exceedance probabilities."""

    dataset: object
    gap: float | None = None
    force_limit: float | None = None

    def exceedance(self, name: str, limit: float) -> tuple[float, float]:
        """P(output > limit) and its standard error √(p(1−p)/N)."""
        values = np.asarray(self.dataset[name].values, dtype=float)
        values = values[np.isfinite(values)]
        p = float(np.mean(values > limit)) if values.size else float("nan")
        return p, float(np.sqrt(max(p * (1 - p), 0.0) / max(values.size, 1)))

    @property
    def gap_exceedance(self) -> tuple[float, float] | None:
        """P(largest actuator orbit > gap) with its standard error (None without a gap)."""
        return None if self.gap is None else self.exceedance("actuator_orbit_max", self.gap)

    @property
    def force_exceedance(self) -> tuple[float, float] | None:
        """P(largest actuator force > force limit) with its standard error."""
        return None if self.force_limit is None else self.exceedance("actuator_force_max", self.force_limit)

    def plot(self):
        """Histograms and exceedance curves (:func:`flexshaft.plot.transient.montecarlo_figure`)."""
        from flexshaft.plot.transient import montecarlo_figure

        return montecarlo_figure(self.dataset, gap=self.gap, force_limit=self.force_limit)


def run_montecarlo(design, n_samples: int, *, seed: int = 0, grade_mm_s: float | None = None,
                   distribution: EccentricityDistribution | None = None, placement: Placement = "uniform",
                   gap: float | None = None, force_limit: float | None = None, n_speeds: int = 150,
                   strength: bool = True, jobs: int = 1, client=None, run_dir=None, chunk_size: int | None = None,
                   progress: bool = False) -> MonteCarloResult:
    """Run ``n_samples`` imbalance samples of ``design`` on the sweep engine.

    Parameters
    ----------
    grade_mm_s : float, optional
        Balance grade G [mm/s]: each bay's eccentricity is drawn from
        ``EccentricityDistribution.from_grade(G, operating speed)`` ("disk").
    distribution : EccentricityDistribution, optional
        Instead of a grade (one of the two is required).
    placement : {"uniform", "mid_bay"}
    gap, force_limit : float, optional
        Actuator radial gap [m] and force capacity [N] for the exceedance probabilities.
    jobs, client, run_dir, chunk_size, progress
        As for :func:`flexshaft.sweep.run_sweep`.
    """
    from flexshaft.sweep import run_sweep

    if (grade_mm_s is None) == (distribution is None):
        raise ValueError("give exactly one of grade_mm_s (balance grade, mm/s) or distribution")
    if distribution is None:
        distribution = EccentricityDistribution.from_grade(grade_mm_s, design.operating.speed_rad_s)
    for name, value in (("gap", gap), ("force_limit", force_limit)):
        if value is not None and not (np.isfinite(value) and value > 0):
            raise ValueError(f"{name} must be > 0, got {value!r}")
    sampler = MonteCarloSampler(int(seed), distribution, placement, int(n_speeds), strength=bool(strength))
    study = montecarlo_study(design, n_samples, sampler)
    ds = run_sweep(study, run_dir, jobs=jobs, client=client, chunk_size=chunk_size, progress=progress)
    ds.attrs.update({"seed": int(seed), "distribution": distribution.kind, "eccentricity_scale_m": distribution.scale,
                     "placement": placement})
    return MonteCarloResult(ds, gap, force_limit)


# ---------------------------------------------------------------------------------------------
# Monte Carlo over a run-up


@dataclass(frozen=True)
class RunupSamples:
    """Peaks of each sample over a run-up transient (arrays over samples) [SI]."""

    shaft_peak: np.ndarray
    shaft_peak_speed: np.ndarray
    actuator_orbit_max: np.ndarray
    actuator_force_max: np.ndarray
    draws: ImbalanceDraws

    def exceedance(self, name: str, limit: float) -> tuple[float, float]:
        """P(output > limit) and its standard error √(p(1−p)/N)."""
        values = np.asarray(getattr(self, name), dtype=float)
        p = float(np.mean(values > limit))
        return p, float(np.sqrt(p * (1 - p) / values.size))


def runup_montecarlo(model: Model, profile, n_samples: int, *, seed: int = 0,
                     distribution: EccentricityDistribution, basis_size: int | None = None,
                     rtol: float = 1e-5, output_step: float | None = None, block: int = 256) -> RunupSamples:
    """Monte-Carlo imbalance over a run-up (mid-bay unbalances, random magnitude and angle).

    The run-up is linear in the load, so one transient per bay
    (:func:`flexshaft.analyses.transient.transient_response` with a unit unbalance at the
    bay's middle, from rest or the steady state at Ω(0)) gives every sample as a weighted sum
    of the bays' complex envelopes; each sample's peaks are those of its envelopes over the
    run. Sample k uses the same draws as the steady study (``default_rng([seed, k])``).

    Parameters
    ----------
    profile : SpeedProfile
        Ω(t) of the run.
    n_samples, seed, distribution
        As for :func:`run_montecarlo`.
    basis_size, rtol, output_step
        Passed to ``transient_response`` (default output step π/(2 Ω_max): 4 samples per
        period of the fastest envelope content).
    """
    from flexshaft.analyses.eigen import reduce
    from flexshaft.analyses.transient import default_basis_size, transient_response
    from flexshaft.assembly.loads import imbalance_bays, per_bay_imbalance_loads

    bays = imbalance_bays(model) or [(float(model.dofs.shaft_x[0]), float(model.dofs.shaft_x[-1]))]
    n_bays = len(bays)
    lengths = np.array([b - a for a, b in bays])
    bay_mass = model.shaft_mass * lengths / lengths.sum()
    red = reduce(model, default_basis_size(model, profile.max_speed) if basis_size is None else int(basis_size))
    output_step = np.pi / (2 * max(profile.max_speed, 1e-3)) if output_step is None else output_step
    shaft, act, force = [], [], []
    for b in range(n_bays):
        unit = np.zeros(n_bays)
        unit[b] = 1.0
        run = transient_response(model, profile, loads_per_speed_squared=per_bay_imbalance_loads(model, unit),
                                 reduced=red, rtol=rtol, output_step=output_step)
        shaft.append(run.shaft_envelope)
        act.append(run.actuator_envelope)
        force.append(run.actuator_force_envelope)
    n_t = shaft[0].shape[-1]
    shaft = np.stack(shaft, -1).astype(np.complex64).reshape(-1, n_bays)  # (2·n_nodes·n_t, n_bays)
    act = np.stack(act, -1).astype(np.complex64).reshape(-1, n_bays)  # (n_act·2·n_t, n_bays)
    force = np.stack(force, -1).astype(np.complex64).reshape(-1, n_bays)
    n_act = act.shape[0] // (2 * n_t)
    draws = draw_imbalance(range(int(n_samples)), n_bays, distribution, "mid_bay", seed)
    weights = (draws.eccentricity * bay_mass * np.exp(1j * draws.angle)).T.astype(np.complex64)  # (n_bays, n) [kg m]
    n = weights.shape[1]
    out = {k: np.zeros(n) for k in ("shaft_peak", "shaft_peak_speed", "actuator_orbit_max", "actuator_force_max")}
    for start in range(0, n, block):
        w = weights[:, start : start + block]
        sl = slice(start, start + w.shape[1])
        envelope = (shaft @ w).reshape(2, -1, n_t, w.shape[1])  # (2, n_nodes, n_t, n)
        per_time = orbit_amplitude(envelope[0], envelope[1]).max(axis=0)  # (n_t, n)
        k = np.argmax(per_time, axis=0)
        out["shaft_peak"][sl] = per_time[k, np.arange(k.size)]
        out["shaft_peak_speed"][sl] = run.speed[k]
        if n_act:
            d = (act @ w).reshape(n_act, 2, n_t, -1)
            f = (force @ w).reshape(n_act, 2, n_t, -1)
            out["actuator_orbit_max"][sl] = orbit_amplitude(d[:, 0], d[:, 1]).max(axis=(0, 1))
            out["actuator_force_max"][sl] = orbit_amplitude(f[:, 0], f[:, 1]).max(axis=(0, 1))
    return RunupSamples(draws=draws, **out)

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
from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.response import orbit_amplitude
from flexshaft.assembly.model import Model
from flexshaft.studies.imbalance_samples import (  # re-exported here
    BASE_OUTPUTS,
    EccentricityDistribution,
    ImbalanceDraws,
    Placement,
    UnitResponses,
    balance_grade_eccentricity,
    draw_imbalance,
    sample_outputs,
    unit_responses,
)

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
        key = hashlib.sha256(
            (point.design.model_dump_json() + repr((self.placement, self.n_speeds))).encode()
        ).hexdigest()
        if key not in _CACHE:
            _CACHE.clear()
            _CACHE[key] = unit_responses(point.model, placement=self.placement, n_speeds=self.n_speeds)
        return _CACHE[key]

    def __call__(self, point) -> dict[str, float]:
        units = self.units(point)
        k = int(point.axes["sample"])
        draws = draw_imbalance([k], units.n_bays, self.distribution, self.placement, self.seed)
        out = {
            name: float(v[0])
            for name, v in sample_outputs(
                point.model, units, draws, strength=self.strength, n_phases=self.n_phases
            ).items()
        }
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
    outputs = [Output(name, unit, text) for name, (unit, text) in BASE_OUTPUTS.items()]
    for a in model.actuators:
        outputs += [
            Output(f"actuator_orbit_{a.name}", "m", f"peak lateral relative orbit at {a.name}"),
            Output(f"actuator_force_{a.name}", "N", f"peak force at {a.name}"),
        ]
    for b in range(1, n_bays + 1):
        outputs += [
            Output(f"eccentricity_bay{b}", "m"),
            Output(f"angle_bay{b}", "rad"),
            Output(f"position_bay{b}", "1", "fraction of the bay"),
        ]
    return Study(
        name=f"Monte-Carlo imbalance ({n_samples} samples, seed {sampler.seed})",
        variables=[Variable("sample", list(range(int(n_samples))), long_name="sample index")],
        outputs=outputs,
        evaluate=sampler,
        base=design,
    )


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
        """P(static offset + peak orbit > gap) at the worst actuator, with its standard error (None
        without a gap): the verdict's actuator-excursion check, sample by sample."""
        return None if self.gap is None else self.exceedance("actuator_excursion_max", self.gap)

    @property
    def force_exceedance(self) -> tuple[float, float] | None:
        """P(static + peak force > force limit) at the worst actuator, with its standard error: the
        verdict's actuator-force check, sample by sample."""
        return None if self.force_limit is None else self.exceedance("actuator_load_max", self.force_limit)

    def plot(self):
        """Histograms and exceedance curves (:func:`flexshaft.plot.transient.montecarlo_figure`)."""
        from flexshaft.plot.transient import montecarlo_figure

        return montecarlo_figure(self.dataset, gap=self.gap, force_limit=self.force_limit)


def run_montecarlo(
    design,
    n_samples: int,
    *,
    seed: int = 0,
    grade_mm_s: float | None = None,
    distribution: EccentricityDistribution | None = None,
    placement: Placement = "uniform",
    gap: float | None = None,
    force_limit: float | None = None,
    n_speeds: int = 150,
    strength: bool = True,
    jobs: int = 1,
    client=None,
    run_dir=None,
    chunk_size: int | None = None,
    progress: bool = False,
) -> MonteCarloResult:
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
    ds.attrs.update(
        {
            "seed": int(seed),
            "distribution": distribution.kind,
            "eccentricity_scale_m": distribution.scale,
            "placement": placement,
        }
    )
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


def runup_montecarlo(
    model: Model,
    profile,
    n_samples: int,
    *,
    seed: int = 0,
    distribution: EccentricityDistribution,
    basis_size: int | None = None,
    rtol: float = 1e-5,
    output_step: float | None = None,
    block: int = 256,
) -> RunupSamples:
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
        run = transient_response(
            model,
            profile,
            loads_per_speed_squared=per_bay_imbalance_loads(model, unit),
            reduced=red,
            rtol=rtol,
            output_step=output_step,
        )
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

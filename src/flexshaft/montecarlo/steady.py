r"""Monte-Carlo imbalance: random residual unbalance per bay, on the sweep engine (the steady
spin-up; :mod:`flexshaft.montecarlo.runup` the same samples over a run-up).

Each shaft bay b (the span between consecutive bearings) carries a point unbalance
``U_b = e_b m_b`` [kg m] (m_b the bay's rotating mass by ISO 21940-11,
:func:`flexshaft.assembly.balance.bay_rotating_masses`: its tubes, disks and coupling hubs, the
overhangs with the end bays; Σ m_b = m, the rotor's rotating mass) at angle ψ_b, uniform on
[0, 2π), at axial position x_b, mid-bay or uniform along the bay.
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
lateral relative orbit and carried force ``G(iΩ) d_s − k_s d_a`` at each active bearing (with the static
offset and force added, as the verdict's actuator checks do), and the ply Tsai-Wu safety factor
at the operating speed (static loads and torque plus the sample's
imbalance response, :func:`~flexshaft.analyses.shaft_strength.shaft_safety_factor`).
Samples run on :func:`flexshaft.sweep.run_sweep` (processes locally, Dask beyond); sample k
draws from ``numpy.random.default_rng([seed, k])``, so results do not depend on chunking,
workers or backend. The probabilities of exceeding the gap and the force capacity judge each
sample as the verdict's actuator checks judge the design: each active bearing's static + peak
value against its own limit (:func:`flexshaft.verdict.gather.actuator_limits`).

References
----------
ISO 21940-11:2016. Mechanical vibration — Rotor balancing — Part 11: Procedures and
tolerances for rotors with rigid behaviour. §5.3 (balance quality grades G, e_per Ω = G).
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from flexshaft.analyses.guards import RefusedInputError, check_count
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_bays
from flexshaft.design import Design
from flexshaft.montecarlo.confidence import Exceedance
from flexshaft.montecarlo.samples import (
    BASE_OUTPUTS,
    EccentricityDistribution,
    Placement,
    UnitResponses,
    draw_imbalance,
    sample_outputs,
    unit_responses,
)
from flexshaft.plot.transient import montecarlo_figure
from flexshaft.sweep import Output, Study, Variable, run_sweep
from flexshaft.verdict.gather import ActuatorLimits, actuator_limits

if TYPE_CHECKING:
    from xarray import Dataset

__all__ = ["MAX_SEED", "MonteCarloResult", "MonteCarloSampler", "montecarlo_study", "run_montecarlo"]

#: Largest seed (numpy's generators take any non-negative integer; the sample k of seed s uses
#: ``default_rng([s, k])``).
MAX_SEED = 2**63 - 1


# ---------------------------------------------------------------------------------------------
# The sweep-engine study


@functools.lru_cache(maxsize=1)  # one design per run: every chunk a worker computes reuses it
def _unit_responses(design_json: str, placement: Placement, n_speeds: int) -> UnitResponses:
    """Unit responses of the design of ``design_json``, computed once per worker process."""
    return unit_responses(build_model(Design.model_validate_json(design_json)), placement=placement, n_speeds=n_speeds)


@dataclass(frozen=True)
class MonteCarloSampler:
    """The :class:`~flexshaft.sweep.Study` output function of one Monte-Carlo run (picklable;
    its repr, with every setting, enters the study's fingerprint)."""

    seed: int
    distribution: EccentricityDistribution
    placement: Placement = "uniform"
    n_speeds: int = 150
    n_phases: int = 36
    strength: bool = True

    def units(self, point) -> UnitResponses:
        """Unit responses of the point's design, computed once per worker process."""
        return _unit_responses(point.design.model_dump_json(), self.placement, self.n_speeds)

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


def montecarlo_study(design, n_samples: int, sampler: MonteCarloSampler) -> Study:
    """The :class:`~flexshaft.sweep.Study` of ``n_samples`` imbalance samples of ``design``."""
    n_samples = check_count(n_samples, "n_samples")
    model = build_model(design)
    n_bays = max(len(imbalance_bays(model)), 1)
    outputs = [Output(name, unit, text) for name, (unit, text) in BASE_OUTPUTS.items()]
    for a in model.actuators:
        outputs += [
            Output(f"actuator_orbit_{a.name}", "m", f"peak lateral relative orbit at {a.name}"),
            Output(f"actuator_force_{a.name}", "N", f"peak force at {a.name}"),
            Output(f"actuator_excursion_{a.name}", "m", f"static offset + peak orbit at {a.name}"),
            Output(f"actuator_load_{a.name}", "N", f"static + peak force at {a.name}"),
        ]
    for b in range(1, n_bays + 1):
        outputs += [
            Output(f"eccentricity_bay{b}", "m"),
            Output(f"angle_bay{b}", "rad"),
            Output(f"position_bay{b}", "1", "fraction of the bay"),
        ]
    return Study(
        name=f"Monte-Carlo imbalance ({n_samples} samples, seed {sampler.seed})",
        variables=(Variable("sample", list(range(int(n_samples))), long_name="sample index"),),
        outputs=tuple(outputs),
        evaluate=sampler,
        base=design,
    )


@dataclass(frozen=True)
class MonteCarloResult:
    """Samples (an :class:`xarray.Dataset` over ``sample``) and exceedance probabilities.

    ``limits`` are each active bearing's gap [m] and force capacity [N] the exceedances use (the
    verdict's, :func:`~flexshaft.verdict.gather.actuator_limits`, unless overridden).
    """

    dataset: Dataset
    limits: Mapping[str, ActuatorLimits]

    def exceedance(self, name: str, limit: float) -> tuple[float, float]:
        """P(output > limit) and its standard error √(p(1−p)/N)."""
        values = np.asarray(self.dataset[name].values, dtype=float)
        values = values[np.isfinite(values)]
        events = Exceedance(int(np.sum(values > limit)), int(values.size))
        return events.probability, events.standard_error

    def _count_exceeding(self, output: str, limit_of) -> Exceedance | None:
        """Samples in which some active bearing's ``output_<name>`` exceeds its own limit (of
        the samples with a finite value at every judged bearing); None when no bearing has a
        limit."""
        judged = {name: limit_of(lim) for name, lim in self.limits.items() if limit_of(lim) is not None}
        if not judged:
            return None
        over = np.zeros(self.dataset.sizes["sample"], bool)
        finite = np.ones_like(over)
        for name, limit in judged.items():
            values = np.asarray(self.dataset[f"{output}_{name}"].values, dtype=float)
            finite &= np.isfinite(values)
            over |= values > limit
        return Exceedance(int(np.sum(over & finite)), int(finite.sum()))

    @property
    def gap_events(self) -> Exceedance | None:
        """Samples with static offset + peak orbit > gap at some active bearing (None without a
        gap): the verdict's actuator-excursion check, sample by sample; with the exact upper
        confidence bound of the probability (:class:`~flexshaft.montecarlo.confidence.Exceedance`)."""
        return self._count_exceeding("actuator_excursion", lambda lim: lim.gap)

    @property
    def force_events(self) -> Exceedance | None:
        """Samples with static + peak force > force capacity at some active bearing: the
        verdict's actuator-force check, sample by sample, with its upper confidence bound."""
        return self._count_exceeding("actuator_load", lambda lim: lim.force_capacity)

    @property
    def gap_exceedance(self) -> tuple[float, float] | None:
        """P(static offset + peak orbit > gap at some active bearing) and its standard error
        (None without a gap). With no exceedance both are 0: report :attr:`gap_events`'s upper
        bound instead."""
        events = self.gap_events
        return None if events is None else (events.probability, events.standard_error)

    @property
    def force_exceedance(self) -> tuple[float, float] | None:
        """P(static + peak force > force capacity at some active bearing) and its standard
        error (see :attr:`force_events` for the upper confidence bound)."""
        events = self.force_events
        return None if events is None else (events.probability, events.standard_error)

    @property
    def gap(self) -> float | None:
        """The smallest gap of the active bearings [m] (None: none given)."""
        gaps = [lim.gap for lim in self.limits.values() if lim.gap is not None]
        return min(gaps) if gaps else None

    @property
    def force_limit(self) -> float | None:
        """The smallest force capacity of the active bearings [N] (None: none given)."""
        capacities = [lim.force_capacity for lim in self.limits.values() if lim.force_capacity is not None]
        return min(capacities) if capacities else None

    def plot(self):
        """Histograms and exceedance curves (:func:`flexshaft.plot.transient.montecarlo_figure`),
        each limit's exceedance count with its 95 % upper confidence bound written at the limit."""
        events = {}
        for key, found in (("gap", self.gap_events), ("force", self.force_events)):
            if found is not None and found.samples:
                events[key] = (found.events, found.samples, found.upper_bound())
        return montecarlo_figure(self.dataset, gap=self.gap, force_limit=self.force_limit, exceedances=events)


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
        ``EccentricityDistribution.from_grade(G, Ω_max)`` ("disk"), Ω_max the highest operating
        speed (``[operating] speed_range``), as the design's own ``balance_grade``
        (:func:`flexshaft.assembly.balance.design_eccentricity`).
    distribution : EccentricityDistribution, optional
        Instead of a grade (one of the two is required).
    placement : {"uniform", "mid_bay"}
    gap, force_limit : float, optional
        Actuator radial gap [m] and force capacity [N] of every active bearing for the
        exceedance probabilities; default each bearing's own (the verdict's,
        :func:`~flexshaft.verdict.gather.actuator_limits`).
    jobs, client, run_dir, chunk_size, progress
        As for :func:`flexshaft.sweep.run_sweep`.
    """
    if (grade_mm_s is None) == (distribution is None):
        raise ValueError("give exactly one of grade_mm_s (balance grade, mm/s) or distribution")
    n_samples = check_count(n_samples, "n_samples")  # 2.5 samples used to run 2
    n_speeds = check_count(n_speeds, "n_speeds", minimum=2)  # a spin-up of one speed has no peak to find
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= seed <= MAX_SEED:
        raise RefusedInputError(f"seed must be a whole number from 0 to 2^63 - 1 (got {seed!r})")
    if distribution is None and not design.operating.speed_rad_s > 0:
        raise RefusedInputError(
            "a balance grade G = e Ω needs an operating speed (operating.speed_rpm = 0); give the "
            "eccentricity distribution instead"
        )
    if distribution is None:
        assert grade_mm_s is not None  # exactly one of the two is given (refused above otherwise)
        distribution = EccentricityDistribution.from_grade(grade_mm_s, design.operating.speed_limits[1])
    for name, value in (("gap", gap), ("force_limit", force_limit)):
        if value is not None and not (np.isfinite(value) and value > 0):
            raise ValueError(f"{name} must be > 0, got {value!r}")
    model = build_model(design)
    limits = {
        name: replace(
            lim,
            gap=lim.gap if gap is None else float(gap),
            force_capacity=lim.force_capacity if force_limit is None else float(force_limit),
        )
        for name, lim in actuator_limits(model).items()
    }
    sampler = MonteCarloSampler(int(seed), distribution, placement, int(n_speeds), strength=bool(strength))
    study = montecarlo_study(design, n_samples, sampler)
    ds = run_sweep(study, run_dir, jobs=jobs, client=client, chunk_size=chunk_size, progress=progress)
    ds.attrs.update(
        {
            # as text: netCDF3 attributes hold at most 32-bit integers (a seed of 2^31 failed to
            # write after every sample was computed)
            "seed": str(int(seed)),
            "distribution": distribution.kind,
            "eccentricity_scale_m": distribution.scale,
            "placement": placement,
        }
    )
    _mark_not_applicable(ds, has_actuators=bool(limits), laminated=bool(strength) and model.shaft.laminate is not None)
    return MonteCarloResult(ds, limits)


def _mark_not_applicable(ds: Dataset, *, has_actuators: bool, laminated: bool) -> None:
    """Say why an output is NaN in every sample (in its ``comment``, as CF has it): the
    actuator outputs of a design without an active bearing and the Tsai-Wu safety factor of a
    shaft that is not laminated (or not asked for) are not applicable; samples.nc used to
    carry them as bare NaN columns."""
    reasons = {}
    if not has_actuators:
        reasons.update(
            {name: "the design has no active bearing" for name in ds.data_vars if str(name).startswith("actuator_")}
        )
    if not laminated and "safety_factor" in ds.data_vars:
        reasons["safety_factor"] = "the shaft is not laminated (Tsai-Wu), or strength was not asked for"
    for name, why in reasons.items():
        ds[name].attrs["comment"] = f"not applicable, NaN in every sample: {why}"

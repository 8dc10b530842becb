"""Monte-Carlo imbalance over a run-up transient: the random residual unbalance of
:mod:`flexshaft.montecarlo.steady` through a run-up at finite acceleration.

The run-up is linear in the load, so one transient per bay (a unit unbalance at the bay's
middle) gives every sample as a weighted sum of the bays' complex envelopes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.response import orbit_amplitude
from flexshaft.analyses.transient import default_basis_size, transient_response
from flexshaft.assembly.balance import bay_rotating_masses
from flexshaft.assembly.loads import imbalance_bays, per_bay_imbalance_loads
from flexshaft.assembly.model import Model
from flexshaft.montecarlo.samples import (
    EccentricityDistribution,
    ImbalanceDraws,
    actuator_static_state,
    bay_unbalances,
    draw_imbalance,
)

__all__ = ["RunupSamples", "runup_montecarlo"]


@dataclass(frozen=True)
class RunupSamples:
    """Peaks of each sample over a run-up transient (arrays over samples) [SI].

    ``actuator_orbit_max`` and ``actuator_force_max`` are the dynamic peaks alone (largest over
    the active bearings); ``actuator_excursion_max`` and ``actuator_load_max`` add each bearing's
    static offset and static force before the largest is taken, as the verdict's actuator
    checks and the steady Monte-Carlo (:mod:`flexshaft.montecarlo.steady`) do: the values to
    hold against the gap and the force capacity (zero without active bearings)."""

    shaft_peak: np.ndarray
    shaft_peak_speed: np.ndarray
    actuator_orbit_max: np.ndarray
    actuator_force_max: np.ndarray
    draws: ImbalanceDraws
    actuator_excursion_max: np.ndarray
    actuator_load_max: np.ndarray

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
    run. Sample k uses the same draws as the steady study (``default_rng([seed, k])``) and the
    same unbalance per bay, ``U_b = e_b m_b`` with m_b the bay's rotating mass
    (:func:`flexshaft.assembly.balance.bay_rotating_masses`).

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
    bays = imbalance_bays(model) or [(float(model.dofs.shaft_x[0]), float(model.dofs.shaft_x[-1]))]
    n_bays = len(bays)
    bay_mass = bay_rotating_masses(model)
    red = reduce(model, default_basis_size(model, profile.max_speed) if basis_size is None else int(basis_size))
    output_step = np.pi / (2 * max(profile.max_speed, 1e-3)) if output_step is None else output_step
    shaft_runs: list[np.ndarray] = []  # the complex envelopes of each bay's unit imbalance
    act_runs: list[np.ndarray] = []
    force_runs: list[np.ndarray] = []
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
        shaft_runs.append(run.shaft_envelope)
        act_runs.append(run.actuator_envelope)
        force_runs.append(run.actuator_force_envelope)
    n_t = shaft_runs[0].shape[-1]
    shaft = np.stack(shaft_runs, -1).astype(np.complex64).reshape(-1, n_bays)  # (2·n_nodes·n_t, n_bays)
    act = np.stack(act_runs, -1).astype(np.complex64).reshape(-1, n_bays)  # (n_act·2·n_t, n_bays)
    force = np.stack(force_runs, -1).astype(np.complex64).reshape(-1, n_bays)
    n_act = act.shape[0] // (2 * n_t)
    draws = draw_imbalance(range(int(n_samples)), n_bays, distribution, "mid_bay", seed)
    weights = bay_unbalances(bay_mass, draws).T.astype(np.complex64)  # (n_bays, n) [kg m]
    n = weights.shape[1]
    names = ("shaft_peak", "shaft_peak_speed", "actuator_orbit_max", "actuator_force_max")
    out = {k: np.zeros(n) for k in (*names, "actuator_excursion_max", "actuator_load_max")}
    offset = static_force = np.zeros(n_act)
    if n_act:
        _, offset, static_force = actuator_static_state(model)
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
            orbit = orbit_amplitude(d[:, 0], d[:, 1]).max(axis=1)  # (n_act, n): each bearing's peak
            load = orbit_amplitude(f[:, 0], f[:, 1]).max(axis=1)
            out["actuator_orbit_max"][sl] = orbit.max(axis=0)
            out["actuator_force_max"][sl] = load.max(axis=0)
            # static + peak dynamic, per bearing, as the verdict's actuator checks
            out["actuator_excursion_max"][sl] = (orbit + offset[:, None]).max(axis=0)
            out["actuator_load_max"][sl] = (load + static_force[:, None]).max(axis=0)
    return RunupSamples(draws=draws, **out)

"""The command bounds (flexshaft.cli.bounds) at their edges, against counts worked by hand.

* A run-up records its output samples at t = 0, Δt, 2Δt, ... up to the end of the run, so a
  run of duration D holds ceil(D/Δt) + 1 samples (fence posts), with Δt = 2π/(8 Ω_max) (8 samples
  per period of the fastest content: at 4800 rev/min, Δt = 60/(8 × 4800) s = 1/640 s). At most
  200,000 samples are allowed (docs/limits.md: the run-up "refuses, before integrating, more
  than 200,000 output samples"):
  D = 199,998.5 Δt gives exactly 200,000 samples and runs, D = 199,999.5 Δt gives 200,001 and
  is refused. The rest of the run-up bound is stubbed (one basis vector, two nodes), so that only
  the sample count decides.
* An eigen-solve's basis cannot exceed the free DOFs of the model (a basis of n-vectors has at
  most n independent vectors), so a 30-DOF model asked for 40 modes has 30 vectors, first and
  largest.
* A resumable command's limit is per worker (module docstring: "MAX_RESUMABLE_SECONDS per
  worker"): its samples are shared among the workers, so the time a worker takes is the model's
  fixed part plus the samples' part divided by the workers, T(w) = a + b/w, and
  (T(1) − T(2)) / (T(2) − T(4)) = (b/2)/(b/4) = 2 whatever the measured constants.

No analysis is run: the baseline's mesh is counted (problem_size) and nothing else (< 0.5 s).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from flexshaft.cli import bounds
from flexshaft.cli.bounds import MAX_RESUMABLE_SECONDS, check_montecarlo, check_runup, eigen_basis_range
from flexshaft.cli.common import UserError


@pytest.fixture
def tiny_run(monkeypatch):
    """A stand-in model for the run-up bound: one basis vector, no controller states, two shaft
    nodes, no actuators (the time and memory of 200,000 samples are then far below the limits)."""
    import flexshaft.analyses.transient as transient

    monkeypatch.setattr(transient, "default_basis_size", lambda model, top: 1)
    monkeypatch.setattr(bounds, "_model_size", lambda design: SimpleNamespace(controller_states=0))
    return SimpleNamespace(design=None, dofs=SimpleNamespace(n_shaft_nodes=2), actuators=())


def test_a_run_up_of_exactly_the_maximum_samples_runs_one_more_is_refused(tiny_run):
    top = 4800.0 * 2.0 * math.pi / 60.0  # rad/s
    step = 1.0 / 640.0  # s: 2π / (8 × 4800 × 2π/60)
    check_runup(tiny_run, 199_998.5 * step, 0.0, top)  # 200,000 samples: no refusal
    check_runup(tiny_run, 99_999.0 * step, 99_999.5 * step, top)  # the dwell counts as the duration
    with pytest.raises(UserError, match=r"200,001 output samples"):
        check_runup(tiny_run, 199_999.5 * step, 0.0, top)


def test_the_basis_is_capped_by_the_free_dofs():
    assert eigen_basis_range(40, 30) == (30, 30)
    first, largest = eigen_basis_range(40, 10_000)
    assert 40 <= first <= largest <= 10_000


def test_a_resumable_command_shares_its_samples_among_the_workers(monkeypatch):
    """T(w) = a + b/w: (T(1) − T(2)) / (T(2) − T(4)) = 2, against the per-worker limit."""
    from flexshaft.design import baseline_design

    asked = {}

    def record(what, seconds, memory, change, limit=bounds.MAX_SECONDS, per_worker=""):
        asked[per_worker] = (seconds, limit)

    monkeypatch.setattr(bounds, "_refuse_if_large", record)
    design = baseline_design()
    for workers in (1, 2, 4):
        check_montecarlo(design, 1_000_000, workers)
    t1, t2, t4 = (asked[f" on {w} worker(s)"][0] for w in (1, 2, 4))
    assert t1 > t2 > t4 > 0.0
    assert (t1 - t2) / (t2 - t4) == pytest.approx(2.0, rel=1e-9)
    assert {limit for _, limit in asked.values()} == {MAX_RESUMABLE_SECONDS}
